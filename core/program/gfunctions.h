// What the K528-05 knows about G- and M-functions (manual 2.7.1.1, table 5):
// the one place that classifies a G number. The validator, the formatter,
// the interpreter of the engine and the editor all ask here.
//
// `x` in Gx.. is the axis digit: 1 = X, 2 = Z (G110, G236, G192, G281 ...).
// G numbers are 0..299; a number that is not in table 5 is unknown
// (message 47 «G?»).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace k528::program {

enum class Axis : std::uint8_t { None, X, Z };

// Group numbers as in table 5 (there is no group 2 or 10). At most one
// function of a group may stand in a frame.
enum class GGroup : std::uint8_t {
    None = 0,         // unknown G
    Motion = 1,       // G00, G01
    Dwell = 3,        // G04
    Handwheel = 4,    // Gx10
    StopOnSignal = 5, // Gx36..Gx39
    Components = 6,   // G50..G54
    Override = 7,     // G55, Gx56
    Dimensions = 8,   // G90, G91
    SetPosition = 9,  // Gx92
    Oscillation = 11, // Gx80, Gx81
};

enum class GFunction : std::uint8_t {
    Unknown,
    Rapid,                // G00: rapid at the axis' F УСК.АВТ.
    Feed,                 // G01: motion at the programmed feed (power-on default)
    Dwell,                // G04: dwell, seconds in X
    Handwheel,            // Gx10: handwheel motion on axis x
    StopOnSignal,         // Gx36..Gx39: move until signal 1..4, erase the rest of the path
    OmitHandwheelOffset,  // G50: leave out the handwheel offset (DRF, СМА)
    OmitCorrection,       // G51: leave out the correction
    OmitDressing,         // G52: leave out the dressing sum
    OmitZeroOffset,       // G53: leave out the zero offset
    AllComponents,        // G54: every component active (power-on default)
    OverrideAllAxes,      // G55: the feed override acts on all axes (power-on default)
    NoOverride,           // Gx56: no override on axis x (100 %)
    Absolute,             // G90: absolute X, Z
    Incremental,          // G91: incremental X, Z
    SetPosition,          // Gx92: set the actual position of axis x
    OscillationStop,      // Gx80: stop oscillation of axis x
    OscillationStart,     // Gx81: start oscillation of axis x (stroke in X/Z, speed in FX/FZ)
};

struct GInfo {
    GGroup group = GGroup::None;
    GFunction function = GFunction::Unknown;
    Axis axis = Axis::None; // the axis of a Gx.. function
    std::uint8_t signal = 0; // 1..4 for Gx36..Gx39
    bool modal = false;      // stays active after the frame (table 5: no '*')
    bool powerOnDefault = false; // set at power-on and «СБРОС» (table 5: '**')

    bool known() const { return function != GFunction::Unknown; }
};

// Classifies any integer (negative or above 299 gives an unknown G).
constexpr GInfo classifyG(int g) {
    GInfo i;
    auto set = [&](GGroup group, GFunction f, bool modal, Axis axis = Axis::None) {
        i.group = group;
        i.function = f;
        i.modal = modal;
        i.axis = axis;
    };
    switch (g) {
    case 0:
        set(GGroup::Motion, GFunction::Rapid, true);
        return i;
    case 1:
        set(GGroup::Motion, GFunction::Feed, true);
        i.powerOnDefault = true;
        return i;
    case 4:
        set(GGroup::Dwell, GFunction::Dwell, false);
        return i;
    case 50:
        set(GGroup::Components, GFunction::OmitHandwheelOffset, true);
        return i;
    case 51:
        set(GGroup::Components, GFunction::OmitCorrection, true);
        return i;
    case 52:
        set(GGroup::Components, GFunction::OmitDressing, true);
        return i;
    case 53:
        set(GGroup::Components, GFunction::OmitZeroOffset, true);
        return i;
    case 54:
        set(GGroup::Components, GFunction::AllComponents, true);
        i.powerOnDefault = true;
        return i;
    case 55:
        set(GGroup::Override, GFunction::OverrideAllAxes, true);
        i.powerOnDefault = true;
        return i;
    case 90:
        set(GGroup::Dimensions, GFunction::Absolute, true);
        return i;
    case 91:
        set(GGroup::Dimensions, GFunction::Incremental, true);
        return i;
    default:
        break;
    }
    if (g < 100 || g > 299)
        return i;
    const Axis axis = g / 100 == 1 ? Axis::X : Axis::Z;
    switch (g % 100) {
    case 10:
        set(GGroup::Handwheel, GFunction::Handwheel, false, axis);
        break;
    case 36:
    case 37:
    case 38:
    case 39:
        set(GGroup::StopOnSignal, GFunction::StopOnSignal, false, axis);
        i.signal = static_cast<std::uint8_t>(g % 100 - 35);
        break;
    case 56:
        set(GGroup::Override, GFunction::NoOverride, true, axis);
        break;
    case 80:
        set(GGroup::Oscillation, GFunction::OscillationStop, true, axis);
        break;
    case 81:
        set(GGroup::Oscillation, GFunction::OscillationStart, true, axis);
        break;
    case 92:
        set(GGroup::SetPosition, GFunction::SetPosition, false, axis);
        break;
    default:
        break;
    }
    return i;
}

constexpr int groupNumber(GGroup g) { return static_cast<int>(g); }

// "G00", "G04", "G110", "G281": the G number as table 5 prints it (two
// digits at least). Canonical program text writes the plain number (G0, G4).
std::string gName(int g);

// Short meaning of a known G, for tooltips and messages.
std::string_view gMeaningRu(GFunction f);
std::string_view gMeaningEn(GFunction f);

// The letter of an axis: 'X', 'Z' (or '?').
constexpr char axisLetter(Axis a) { return a == Axis::X ? 'X' : a == Axis::Z ? 'Z' : '?'; }

// M-functions with a built-in meaning (manual 2.7.1.1 and app. М). Every
// other M number is passed to the PLC only.
namespace mfunc {
inline constexpr int kStop = 0;         // M00: stop until «Пуск»
inline constexpr int kEnd = 2;          // M02: end of program
inline constexpr int kSubprogramEnd = 17; // M17: end of subprogram
inline constexpr int kEndRewind = 30;   // M30: end of program
} // namespace mfunc

} // namespace k528::program
