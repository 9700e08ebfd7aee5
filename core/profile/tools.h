// The tools of a machine's turret stations (карта наладки, handbook 14.3),
// kept with the machine in its simulation settings as `tool.<station>.<key>`
// (docs/profile-format.md, "Tools"): so a machine file, the database, its
// revisions and diffs keep them as they keep every setting.
//
//   tool.2.kind=boring          turning facing grooving boring drill threading
//   tool.2.name=Резец расточной  for people (the setup sheet)
//   tool.2.tip_radius_mm=0.4    the nose radius
//   tool.2.orientation=+z-x     where the tool's body lies from its tip: ±z (along Z) and ±x
//                               (outwards/inwards); "+z+x" an outside tool held from above
//   tool.2.width_mm=3           the body along Z from the tip
//   tool.2.height_mm=10         the body along X (radially) from the tip
//   tool.2.max_depth_mm=2       the deepest cut the tool takes (its cutting edge), 0 no limit
//   tool.2.offset_r=102         the R-parameters of its offsets: X in R102, Z in R103
//
// A tool's offsets are what the controller's correction (R226/R227) must hold
// for the tool's tip to show the programmed coordinates: the tip lies at
// machine − offset (X as a diameter on a diameter axis). They are the values
// of the R-parameters `offset_r`, `offset_r + 1` — preset with the machine
// and copied into R226/R227 by the program after a tool change, as the
// K528-05 does it: it has no tool table of its own.
#pragma once

#include "profile/problem.h"
#include "profile/profile.h"

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace k528::profile {

enum class ToolKind { Turning, Facing, Grooving, Boring, Drill, Threading };
std::string_view toolKindName(ToolKind k); // "turning", …
std::optional<ToolKind> parseToolKind(std::string_view s);

struct Tool {
    int station = 0; // 1..8
    ToolKind kind = ToolKind::Turning;
    std::string name;
    double tipRadiusMm = 0;
    int zDirection = +1, xDirection = +1; // where the body lies from the tip ("+z+x")
    double widthMm = 3;
    double heightMm = 1000;
    double maxDepthMm = 0; // 0: no limit
    int offsetR = -1;      // -1: no offset R-parameters

    std::string orientation() const; // "+z+x"
    bool operator==(const Tool&) const = default;
};

inline constexpr int kMaxToolStations = 8;

// what() is the English of problem() (problem.h).
struct ToolError : std::runtime_error {
    explicit ToolError(Problem p) : std::runtime_error(p.text()), problem_(std::move(p)) {}
    const Problem& problem() const { return problem_; }

private:
    Problem problem_;
};

// The tools of a profile's settings, by station; throws ToolError naming the
// key of a value that is not a tool's.
std::vector<Tool> tools(const MachineProfile& p);
// Writes `t` into the settings (replacing the station's keys).
void setTool(MachineProfile& p, const Tool& t);
// The tool at `station`, nullopt if none.
std::optional<Tool> toolAt(const std::vector<Tool>& tools, int station);
// The tool's offsets (mm, X as the axis shows it) from the R presets `r`
// (0 when the tool has no offset R-parameters or they are not preset).
struct ToolOffsets {
    double xMm = 0, zMm = 0;
};
ToolOffsets toolOffsets(const Tool& t, const MachineProfile& p,
                        const std::map<int, std::int64_t>& extraR = {});

} // namespace k528::profile
