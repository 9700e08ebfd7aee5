// Proving a program before the machine runs it (handbook 13.7: collisions,
// "the most dangerous" of the errors that reach the machine): the one
// interpreter's preview (toolpath::programmedPath) read against the part's
// material, the machine's geometry (geometry.h) and its tools
// (profile/tools.h). Deterministic; no Qt.
//
// The rules, each with a stable id (docs/proveout.md):
//   rapid-into-material   a rapid (G00) whose tool enters the material of the
//                         blank, the positioner's dogleg included (the corner
//                         where one axis arrives first); on a grinder the
//                         wheel into the ring
//   tool-into-chuck       the tool into the chuck's jaws or body
//   turret-into-chuck     the turret into the chuck's jaws or body
//   feed-spindle-stopped  a feed that cuts while the spindle stands
//   feed-wheel-stopped    on a grinder: a feed into the ring while the wheel stands
//   cut-too-deep          a cut deeper (across the motion) than the tool's
//                         max_depth_mm
// (rules.h: the rules and the contacts shared with the grade of an attempt,
// which adds manual-into-material for the operator's moves.)
// A finding names its rule, the frame (program, N, source line), the segment
// of the path and the place (the tool's tip where it first happens, in the
// path's coordinates: what the backplot marks). A frame that meets a rule
// again (a loop) is one finding with its count.
#pragma once

#include "profile/tools.h"
#include "proveout/geometry.h"
#include "proveout/rules.h"
#include "stock/stock.h"
#include "toolpath/programmed_path.h"

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace k528::proveout {

enum class Severity : std::uint8_t { Error, Warning };

struct Finding {
    Rule rule = Rule::RapidIntoMaterial;
    Severity severity = Severity::Error;
    int program = 0, line = 0, n = 0;
    std::uint32_t segment = 0; // the path's segment where it first happens
    toolpath::PointMm at;      // the tool's tip there (the path's coordinates)
    std::string_view text;     // the id of its text in texts() ("tool-into-chuck.jaws")
    std::vector<std::string> args; // the text's %1, %2 …
    int occurrences = 1;

    bool isError() const { return severity == Severity::Error; }
    std::string message(bool russian) const;
};

// One text of the catalog: an id, its Russian and English template (%1..%9).
struct Text {
    std::string_view id, ru, en;
};
std::span<const Text> texts();

struct Options {
    // The part: a lathe's blank (part coordinates); none: the material rules
    // of a lathe stay silent.
    std::optional<stock::Blank> blank;
    double resolutionMm = 0.01; // of the material's columns (material.h)
    // The tools by station and their offsets (mm, X as the axis shows it),
    // the offsets as the machine's R presets hold them. Without a tool at the
    // station in use: an outside turning tool 3 mm wide, and the correction
    // in effect (R226/R227) taken as its offsets.
    std::vector<profile::Tool> tools;
    std::map<int, profile::ToolOffsets> offsets; // by station
    // Spindles turning when the program starts (by name).
    std::vector<std::string> spindlesRunning;
};

struct Result {
    std::vector<Finding> findings; // in the order the program meets them
    bool material = false;         // the material rules ran (a blank, or the grinder's ring)
    bool chuck = false;            // the chuck rules ran
    double removedMm2 = 0;         // of the half profile, by the program's feeds
    std::size_t errors() const;
};

Result prove(const toolpath::ProgrammedPath& path, const MachineGeometry& g, const Options& o);

// The options for a machine profile: its tools (settings tool.N.*) and their
// offsets from its R presets with `rPresets` over them. Throws
// profile::ToolError for a bad tool table.
Options optionsFor(const profile::MachineProfile& p, const std::map<int, std::int64_t>& rPresets,
                   std::optional<stock::Blank> blank);

// The programs of a store that none of its programs calls (L): what a check
// proves, each from its first frame, in the order of their numbers.
std::vector<int> mainPrograms(const program::ProgramStore& store);

// Program `number` of `programs` (over the machine's own) in preview, proved
// against the machine of `profile` (its description's geometry, its tools).
// Throws plc::DescriptionError or profile::ToolError when the machine's data
// is bad.
struct Proof {
    toolpath::ProgrammedPath path;
    Result result;
};
Proof proveProgram(const profile::MachineProfile& profile, const program::ProgramStore& programs,
                   int number, const engine::PreviewOptions& preview,
                   std::optional<stock::Blank> blank);

// Every main program of `programs` (mainPrograms) proved as proveProgram
// does, in the order of their numbers; a frame that breaks a rule in several
// of them (a subprogram they share) is one finding, the first met; `material`
// and `chuck` when their rules ran for one of them at least. What
// `k528 check --profile` and the studio's prove-out pane report for a file.
Result proveStore(const profile::MachineProfile& profile,
                                const program::ProgramStore& programs,
                                const engine::PreviewOptions& preview,
                                const std::optional<stock::Blank>& blank);

} // namespace k528::proveout
