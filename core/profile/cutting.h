// Cutting data beside the C-constant calculator (handbook ch. 13: the cutting
// conditions a program's S and F come from), and the trial part's correction
// of a tool's offset (handbook 13.8).
//
//   n = 1000·v / (π·D)      spindle speed, rev/min, from the cutting speed v
//                           (m/min) at the diameter D (mm)
//   v = π·D·n / 1000        the cutting speed back from n
//   F = f·n                 feed per minute (mm/min) from the feed per revolution f (mm/rev)
//   vк = π·Dк·nк / 60000    the wheel's surface speed (m/s) from its diameter Dк
//                           (mm) and its speed nк (rev/min); Dк is R207 «ТЕК.ДИАМЕТР
//                           КРУГА» (appendix Л, screen УСТ 5), in discretes of X
//
// The trial part: the setter measures the part the program made and compares
// it with the drawing. The tool's offset is what the correction R226/R227
// holds (profile/tools.h): the program's coordinate is machine − offset, so
// a size that came out larger by e was cut with an offset larger by e than
// the tool's true one: the new offset is the old one minus e. On the lathe
// X is measured as a diameter (a micrometer across the part); on an axis
// that shows X as a diameter (C7 ИНД.ДИАМЕТР = 1, the training lathe) that is
// the axis' own unit, on a radius axis half of it. Z is a length along the axis.
#pragma once

#include "catalog/cparams.h"
#include "profile/profile.h"
#include "profile/tools.h"

#include <cstdint>
#include <stdexcept>

namespace k528::profile::cutting {

// What is wrong as a problem of core's catalog (problem.h: "cutting.*"); what() its English.
struct CuttingError : std::invalid_argument {
    explicit CuttingError(Problem p) : std::invalid_argument(p.text()), problem(std::move(p)) {}
    Problem problem;
};

// Each throws CuttingError for a value that is not positive (or not finite).
double spindleSpeedRpm(double cuttingSpeedMPerMin, double diameterMm);
double cuttingSpeedMPerMin(double spindleRpm, double diameterMm);
double feedPerMinute(double feedPerRevMm, double spindleRpm);
double wheelSurfaceSpeedMPerS(double wheelDiameterMm, double wheelRpm);
// The wheel's diameter in mm from R207 (discretes of X) of a machine.
double wheelDiameterMm(const MachineProfile& p, std::int64_t r207);
// The R207 the machine presets; CuttingError when it presets none.
std::int64_t presetR207(const MachineProfile& p);

// The trial part's change to a tool's offset R-parameter.
struct TrialCorrection {
    int rNumber = 0;               // the offset R-parameter changed (offset_r for X, offset_r + 1 for Z)
    std::int64_t oldValue = 0;     // discretes, as preset (0 when not preset)
    std::int64_t newValue = 0;
    double errorMm = 0;            // measured − drawing, as measured (X: a diameter)
    double changeMm = 0;           // the change of the offset, in the axis' unit (X: as the axis shows it)
};
// `measuredMm` and `drawingMm` of axis X (a diameter) or Z (a length) cut
// by `tool`. Throws CuttingError when the tool has no offset R-parameters,
// the values are not finite, or the new value leaves the R range.
TrialCorrection trialCorrection(const MachineProfile& p, const Tool& tool, catalog::Axis axis,
                                double measuredMm, double drawingMm);

} // namespace k528::profile::cutting
