// Units of the K528-05, and every conversion between them, in one place.
//
// The manual's quantities (appendix Е):
//   display discrete  – the step of an axis' displayed and programmed value:
//                       0.0001, 0.001 or 0.01 mm (C4..6 / C56..58). On an axis
//                       with diameter display (C7 / C59) the value shown and
//                       programmed is the diameter, so one display discrete is
//                       half a discrete of actual motion.
//   motion discrete   – «дискрета задания перемещения»: one discrete of actual
//                       slide motion. Encoder pulses are converted to motion
//                       discretes by the ratio L/N (C19/C20, C71/C72).
//   internal unit     – «внутрисистемная единица»: half a motion discrete
//                       (note * of table Е.1). МАКС.ОШИБКА, ДОПУСК ПОЗ.,
//                       ДОПУСК КП and the diagnostic ABS/ERR are in these.
//   speed constants   – C40..44 / C92..96 in 10·discrete/min.
//   acceleration      – C22/23, C74/75 in the unit of the manual's formulas 2
//                       and 3: value = 25600·A/Kd with A in m/s² (formula 1
//                       gives twice that value for the same motion; see
//                       docs/units.md).
//   R-parameters      – coordinates in display discretes of the axis, feeds in
//                       display discretes per minute (program-language.md).
//
// Names carry their unit: ...Mm, ...MmPerMin, ...Disc (display discretes),
// ...Internal, ...Ms, ...S.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>

namespace k528::units {

enum class Discrete { Mm0_0001, Mm0_001, Mm0_01 };

// The scale of one axis: its display discrete and diameter display.
struct AxisScale {
    Discrete discrete = Discrete::Mm0_001;
    bool diameter = false;

    // Millimetres per display discrete: 0.0001, 0.001 or 0.01.
    constexpr double discreteMm() const {
        switch (discrete) {
        case Discrete::Mm0_0001:
            return 0.0001;
        case Discrete::Mm0_001:
            return 0.001;
        case Discrete::Mm0_01:
            return 0.01;
        }
        return 0.001;
    }
    // Display discretes per millimetre: 10000, 1000 or 100.
    constexpr std::int64_t discretesPerMm() const {
        switch (discrete) {
        case Discrete::Mm0_0001:
            return 10000;
        case Discrete::Mm0_001:
            return 1000;
        case Discrete::Mm0_01:
            return 100;
        }
        return 1000;
    }
    // Kd of the manual's formulas: 10 at 0.01 mm, 1 at 0.001 mm, 0.1 at 0.0001 mm.
    constexpr double kd() const { return discreteMm() * 1000.0; }
    // Digits after the decimal point on the panel: 4, 3 or 2.
    constexpr int decimals() const {
        switch (discrete) {
        case Discrete::Mm0_0001:
            return 4;
        case Discrete::Mm0_001:
            return 3;
        case Discrete::Mm0_01:
            return 2;
        }
        return 3;
    }
    // Internal units per display discrete: 2, or 1 on a diameter axis.
    constexpr std::int64_t internalPerDisc() const { return diameter ? 1 : 2; }
    // Its reciprocal (exact: 1 or 1/2), for conversions without a division.
    constexpr double discPerInternal() const { return diameter ? 1.0 : 0.5; }
    // Millimetres of actual slide motion per internal unit (half a motion
    // discrete; a motion discrete is one display discrete of slide travel).
    constexpr double internalMotionMm() const { return discreteMm() / 2.0; }
};

// Rounds half away from zero (how typed and programmed values are rounded).
inline std::int64_t roundHalfAway(double v) {
    return static_cast<std::int64_t>(v < 0 ? std::ceil(v - 0.5) : std::floor(v + 0.5));
}

// Programmed/displayed millimetres <-> display discretes.
inline std::int64_t mmToDisc(double mm, const AxisScale& s) {
    return roundHalfAway(mm * static_cast<double>(s.discretesPerMm()));
}
inline double discToMm(std::int64_t disc, const AxisScale& s) {
    return static_cast<double>(disc) / static_cast<double>(s.discretesPerMm());
}
// A fractional number of display discretes (a following error, a trace) in mm.
inline double fractionalDiscToMm(double disc, const AxisScale& s) {
    return disc / static_cast<double>(s.discretesPerMm());
}

// Display discretes <-> internal units.
constexpr std::int64_t discToInternal(std::int64_t disc, const AxisScale& s) {
    return disc * s.internalPerDisc();
}
inline double internalToDisc(double internal, const AxisScale& s) {
    // internal / internalPerDisc(): the reciprocal is exact (1 or 1/2), so
    // the product is the quotient bit for bit (without a division's latency).
    return internal * s.discPerInternal();
}

// Speed constants (C40..44, C92..96) are in 10·display discretes per minute.
inline double speedParamToMmPerMin(std::int64_t param, const AxisScale& s) {
    return static_cast<double>(param) * 10.0 * s.discreteMm();
}
inline std::int64_t mmPerMinToSpeedParam(double mmPerMin, const AxisScale& s) {
    return roundHalfAway(mmPerMin / (10.0 * s.discreteMm()));
}

// Acceleration constants (C22/23, C74/75): value = 25600·A/Kd, A in m/s²
// (formulas 2 and 3 of parameter 22).
inline double accelParamToMPerS2(std::int64_t param, const AxisScale& s) {
    return static_cast<double>(param) * s.kd() / 25600.0;
}
inline double accelParamToMmPerS2(std::int64_t param, const AxisScale& s) {
    return accelParamToMPerS2(param, s) * 1000.0;
}
inline std::int64_t mPerS2ToAccelParam(double a, const AxisScale& s) {
    return roundHalfAway(25600.0 * a / s.kd());
}

// "234.567", "-0.020", "1205.1240": display discretes with the axis' decimals.
std::string formatDisc(std::int64_t disc, const AxisScale& s);

// "1.25", "-3", "0": `v` with `decimals` fixed decimals (as printf rounds),
// then its trailing zeros and point removed; never "-0". For texts where a
// length or a number reads best without padding (notes, the setup sheet).
std::string formatTrimmed(double v, int decimals);

// Time.
constexpr double msToS(std::int64_t ms) { return static_cast<double>(ms) / 1000.0; }
inline std::int64_t sToMs(double s) { return roundHalfAway(s * 1000.0); }
constexpr double perMinToPerS(double v) { return v / 60.0; }

// The feed override steps of table 3 / C139..142 / Z1001.12-15: code 0..10.
inline constexpr int overrideStepsPercent[11] = {0, 1, 2, 5, 10, 20, 35, 50, 75, 90, 100};
// Percent for a code (codes above 10 are clamped to 10).
constexpr int overrideCodeToPercent(int code) {
    return overrideStepsPercent[code < 0 ? 0 : (code > 10 ? 10 : code)];
}
// Code for a percent that is one of the steps, or -1.
constexpr int overridePercentToCode(int percent) {
    for (int i = 0; i <= 10; ++i)
        if (overrideStepsPercent[i] == percent)
            return i;
    return -1;
}

} // namespace k528::units
