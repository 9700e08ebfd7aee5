// The C-constant calculator: machine constants from physical quantities, by
// the formulas of table Е.1 (parameters 22/23, 26, 27, 19/20, 28, 40..44).
//
// Integer results are the integer part of the formula, as appendix Ж writes
// them (2133.25 -> 2133, 4266.5 -> 4266, 26.2 -> 26). The acceleration unit of
// K528 Studio is that of formulas 2 and 3 (value = 25600·A/Kd, A in m/s²;
// core/units/units.h); formula 1 as printed gives twice that value for the
// same motion, and formula 2's coefficient 3.556 is 25600/7200 = 3.5556
// rounded. Every acceleration result carries both the value as printed and
// the consistent value. See docs/machine-constants.md.
#pragma once

#include "catalog/cparams.h"
#include "profile/problem.h"
#include "profile/profile.h"
#include "units/units.h"

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace k528::profile::calc {

// What is wrong with the inputs, as a problem of core's catalog (problem.h:
// "calc.*", or "c.range" for a result outside its constant's range); what()
// is its English.
struct CalcError : std::runtime_error {
    explicit CalcError(Problem p) : std::runtime_error(p.text()), problem(std::move(p)) {}
    Problem problem;
};

// Coefficients as printed in table Е.1 and their exact values.
inline constexpr double kFormula1Printed = 0.8533;               // ·Vmax[disc/min] / T[ms]
inline constexpr double kFormula2Printed = 3.556e-6;             // ·Vmax² / S[disc]
inline constexpr double kFormula1Exact = 25600.0 / 60000.0;      // 0.42667: half of 0.8533
inline constexpr double kFormula2Exact = 25600.0 / 7200.0 / 1e6; // 3.5556e-6
inline constexpr double kKsCoefficient = 262.0;                  // ·Kd·Umax/Vmax[m/min]
inline constexpr double kKeCoefficient = 26.2;                   // ·Kd·Kv·Umax/Vmax[m/min]

struct AccelResult {
    int formula = 0;                  // 1, 2 or 3 of parameter 22
    double printedRaw = 0;            // the formula as printed, before truncation
    std::int64_t printedValue = 0;    // its integer part (appendix Ж's figures)
    double consistentRaw = 0;         // 25600·A/Kd for the motion the inputs describe
    std::int64_t consistentValue = 0; // its integer part: enter this in K528 Studio
    double describedMPerS2 = 0;       // the acceleration the inputs describe
    double printedMPerS2 = 0;         // what printedValue means in K528 Studio's unit
    // printedMPerS2 / describedMPerS2: 2.0 for formula 1, 1.0001 for formula 2, 1 for formula 3.
    double printedFactor() const {
        return describedMPerS2 > 0 ? printedMPerS2 / describedMPerS2 : 0;
    }
};

// Formula 1: run-up from 0 to `vmaxDiscPerMin` (discretes of motion per
// minute) in `runUpMs`.
AccelResult accelByRunUp(double vmaxDiscPerMin, double runUpMs, const units::AxisScale& s);
// Formula 2: braking from `vmaxDiscPerMin` to 0 over `brakingDisc` discretes.
AccelResult accelByBraking(double vmaxDiscPerMin, double brakingDisc, const units::AxisScale& s);
// Formula 3: acceleration `aMPerS2`.
AccelResult accelByValue(double aMPerS2, const units::AxisScale& s);

// K(СКОР) = 262·Kd·Umax/Vmax and K(ОШИБ) = 26.2·Kd·Kv·Umax/Vmax, Vmax in m/min
// (the drive's speed at Umax volts), integer part.
std::int64_t speedGain(double umaxVolts, double vmaxMPerMin, const units::AxisScale& s);
std::int64_t errorGain(double kv, double umaxVolts, double vmaxMPerMin, const units::AxisScale& s);

// L ИМП.ДОС / N ИМП.ДОС: discretes of motion per encoder pulses (4 per line),
// reduced. `gearRatio` is motor (encoder) revolutions per screw revolution.
// Diameter display does not change L/N: the ratio gives discretes of slide
// motion (appendix Ж: X on the diameter and Z both have 1/2). When the exact
// fraction does not fit 1..32767, the closest one that fits is returned with
// exact = false.
struct EncoderRatio {
    std::int64_t l = 0;
    std::int64_t n = 0;
    bool exact = true;
    double errorPpm = 0;     // (L/N − exact ratio) / exact ratio · 1e6
    double discPerPulse = 0; // exact ratio
};
EncoderRatio encoderRatio(double screwLeadMm, double gearRatio, std::int64_t encoderLines,
                          const units::AxisScale& s);

// Speed constant (10·discretes/min) of a slide speed in mm/min.
std::int64_t speedParam(double mmPerMin, const units::AxisScale& s);
// ПРЕДЕЛ ЦАП `percent` above МАКС.ЦАП (the manual: 15-20 %), rounded.
std::int64_t dacLimit(std::int64_t dacMax, double percent = 17.0);

// A whole axis from physical data.
struct AccelSpec {
    enum class By { RunUp, Braking, Value } by = By::Value;
    double vmaxMmPerMin = 0; // RunUp, Braking: the speed ramped (slide mm/min)
    double runUpMs = 0;      // RunUp
    double brakingMm = 0;    // Braking
    double aMPerS2 = 0;      // Value
    // false: enter the consistent value (25600·A/Kd); true: the formula as
    // printed (formula 1 then doubles the acceleration, as appendix Ж does).
    bool asPrinted = false;
};

struct AxisDesign {
    units::AxisScale scale;
    double screwLeadMm = 5;
    double gearRatio = 1;
    std::int64_t encoderLines = 2500;
    double driveMaxVolts = 10;
    double driveMaxSpeedMmPerMin = 10000;
    double kv = 1;
    double feedNormalMmPerMin = 0;    // F ОБЫЧНАЯ
    double feedRapidMmPerMin = 0;     // F УСКОРЕН.
    double feedAutoRapidMmPerMin = 0; // F УСК.АВТ.
    double feedHomeStartMmPerMin = 0; // F СТАРТ БТ
    double feedHomeCreepMmPerMin = 0; // F ОТКЛ.БТ
    AccelSpec accel1;                 // УСКОРЕНИЕ 1
    std::optional<AccelSpec> accel2;  // УСКОРЕНИЕ 2 (none: 0, i.e. УСКОРЕНИЕ 1)
    std::int64_t dacMax = 2047;
    double dacLimitPercent = 17;
};

// How one value was obtained: an id of stepTexts() and its arguments (the
// numbers as printed); `param` (X numbering, 0 for none) names the constant
// the line begins with, in the language the step is said in.
struct Step {
    std::string id;
    int param = 0;
    std::vector<std::string> args;
};

struct AxisConstants {
    // X numbers (1..52) -> value: 4..7, 19, 20, 22, 23, 26..29, 40..44.
    std::map<int, std::int64_t> values;
    EncoderRatio ratio;
    AccelResult accel1;
    std::optional<AccelResult> accel2;
    std::vector<Step> steps; // how each value was obtained (stepText)
};

// The steps' texts in Russian and English (%1 the constant's panel name).
util::TextCatalog stepTexts();
// `s` in a language, e.g. «УСКОРЕНИЕ 1: разгон 0 -> 5000 мм/мин за 2000 мс: …»;
// `axis` numbers the constant.
std::string stepText(const Step& s, catalog::Axis axis, bool russian);

// Throws CalcError when an input is out of its domain or a result does not
// fit its parameter's range.
AxisConstants designAxis(const AxisDesign& d);

// The physical data of an axis from a profile's simulation settings
// ("x.screw_lead_mm", ...) and its discrete/diameter constants; feeds and
// accelerations are left 0. Throws SettingError for missing keys.
AxisDesign designFromSettings(const MachineProfile& p, catalog::Axis axis);

// What an axis' constants mean physically.
struct AxisSummary {
    units::AxisScale scale;
    double feedNormalMmPerMin = 0, feedRapidMmPerMin = 0, feedAutoRapidMmPerMin = 0;
    double feedHomeStartMmPerMin = 0, feedHomeCreepMmPerMin = 0;
    double accel1MPerS2 = 0, accel2MPerS2 = 0; // УСКОРЕНИЕ 2 = 0 -> УСКОРЕНИЕ 1's
    double runUpToAutoRapidMs = 0;             // 0 -> F УСК.АВТ. with УСКОРЕНИЕ 1
    double brakingFromAutoRapidMm = 0;         // F УСК.АВТ. -> 0 with УСКОРЕНИЕ 1
    double emergencyBrakingFromRapidMm = 0;    // F УСКОРЕН. -> 0 with УСКОРЕНИЕ 2
    double motionMmPerPulse = 0;               // L/N in mm of slide motion
    double limitMinusMm = 0, limitPlusMm = 0, homeValueMm = 0; // display mm
};
AxisSummary summarizeAxis(const MachineProfile& p, catalog::Axis axis);

} // namespace k528::profile::calc
