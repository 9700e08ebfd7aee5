// The setup sheet (карта наладки, handbook 14.3): what the setter needs at the
// machine before the first part — the machine, the blank, the tools with
// their stations and offsets, the programs with their cycle times, the
// R-parameters to preset. This is its content, computed from the same data
// `k528 check --profile` and `k528 path` read (no Qt, no clock: the same
// machine and file give the same sheet). The studio and `k528 setup-sheet`
// render it (app/studio/sheet); the labels in Russian and English are here,
// so both say the same.
#pragma once

#include "profile/profile.h"
#include "profile/tools.h"
#include "program/model.h"
#include "stock/stock.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace k528::proveout {

struct SheetTool {
    profile::Tool tool;                  // tool.name: its Russian name
    std::string nameEn;                  // its English (profile::toolName), the Russian when the machine gives none
    double offsetXMm = 0, offsetZMm = 0; // from the R presets it names (X as the axis shows it)

    const std::string& name(bool russian) const { return russian ? tool.name : nameEn; }
};

struct SheetProgram {
    int number = 0;
    std::string title;                  // "%L1 (title)"
    bool main = true;                   // no program of the file calls it
    std::optional<double> cycleSeconds; // main programs whose run on the simulated machine completed
    std::string run;                    // how that run ended: completed, alarm, timeout, blocked, not_run; "" subprogram
    std::int64_t frames = 0;            // frames executed by the preview
};

struct SheetPreset {
    int number = 0;
    std::int64_t value = 0;          // as the controller holds it (discretes for coordinates)
    std::optional<double> mm;        // the value in mm (mm/min) when it is a coordinate or a feed of an axis
    std::string meaningRu, meaningEn; // a tool's offset, appendix Л, or "" (a user parameter)
};

struct SetupSheet {
    std::string machineName;
    std::string machineTitle, machineTitleEn; // the English as profile::titleText gives it
    std::string file;        // the program file's name, as given
    bool xDiameter = false;  // X shown (and measured) as a diameter (C7)
    std::optional<stock::Blank> blank;
    std::string ucg;         // the blank's UCG line, "" none
    std::vector<SheetTool> tools;
    std::vector<SheetProgram> programs;
    std::vector<SheetPreset> presets;
};

// The sheet of `file` (its programs `store`, its text for the blank's UCG
// comment unless `blank` is given) on the machine `profile` with `rPresets`
// over the machine's own presets. Cycle times: machine::cycleTime of each
// main program whose preview completes (`withCycleTimes` false: none, a quick
// sheet). Throws profile::ToolError for a bad tool table,
// plc::DescriptionError for a bad machine description.
SetupSheet setupSheet(const profile::MachineProfile& profile, const program::ProgramStore& store,
                      std::string_view fileText, std::string file,
                      const std::map<int, std::int64_t>& rPresets = {},
                      const std::optional<stock::Blank>& blank = std::nullopt, bool withCycleTimes = true);

// The sheet as JSON (util/json) and back: what `k528 setup-sheet` hands its
// renderer. sheetFromJson throws std::runtime_error for text that is not one.
std::string sheetJson(const SetupSheet& s);
SetupSheet sheetFromJson(std::string_view text);

// The sheet's labels.
enum class SheetText {
    Title,          // "Setup sheet"
    Machine,
    File,
    Blank,
    NoBlank,
    BlankOuter,     // "outside Ø%1 × %2 mm"
    BlankBore,      // "bore Ø%1 × %2 mm"
    Tools,
    NoTools,
    Station,
    Kind,
    Name,
    TipRadius,
    Orientation,
    OffsetR,
    OffsetX,
    OffsetZ,
    XDiameterNote,  // "X is a diameter"
    XRadiusNote,
    Programs,
    Program,
    ProgramTitle,
    CycleTime,
    Subprogram,
    NoCycleTime,    // "none (the run: %1)"
    Presets,
    NoPresets,
    Parameter,
    Value,
    ValueMm,
    Meaning,
    ToolOffsetX,    // "tool %1: X offset"
    ToolOffsetZ,
    UserParameter,
    Seconds,        // "%1 s"
    Total,          // "Total of the main programs"
    Setter,         // "Set up by"
    Checked,
    Date,
};
std::string_view sheetText(SheetText t, bool russian);
// The tool kind for people ("проходной", "turning").
std::string_view toolKindText(profile::ToolKind k, bool russian);
// Millimetres with up to `decimals` places, trailing zeros dropped ("40", "0.8", "-3.5").
std::string sheetMm(double v, int decimals = 3);

} // namespace k528::proveout
