// One axis as the engine runs it: the servo and reference-point cycle of
// core/axis, the axis' machine constants and scale, the signals decoded for
// it this tick (limit switches, cam, drive ready, gauge signals), and who
// owns its motion (a program frame, an oscillation, a jog, a handwheel, the
// reference-point cycle).
//
// Positions: the servo works in internal units of the machine system;
// `ipd` converts display discretes to internal units (2 on a radius axis, 1
// on a diameter axis, docs/axis.md).
#pragma once

#include "axis/constants.h"
#include "axis/homing.h"
#include "axis/servo.h"

#include <array>
#include <cmath>
#include <cstdint>

namespace k528::engine {

// Rounds half away from zero, inline (llround is a library call; this runs
// several times a tick). Exact for |v| < 2^52.
inline std::int64_t roundToInt(double v) {
    // v ± 0.5 by the sign of v, without a branch (the same sums: v - 0.5 is
    // v + (-0.5)); -0.0 gives -0.5, truncated to 0 as +0.5 would be.
    return static_cast<std::int64_t>(v + std::copysign(0.5, v));
}

enum class MotionOwner : std::uint8_t {
    None,
    Program,        // a frame's positioning move (G00/G01, Gx36..39)
    HandwheelFrame, // Gx10
    Oscillation,    // Gx81
    Jog,            // «ПЕРЕМЕЩЕНИЕ В +/-» in РУЧНОЙ
    Handwheel,      // handwheel in РУЧНОЙ (and DRF)
    Homing,         // reference-point cycle
};

// Motion that a program started (held by «Стоп», resumed by «Пуск»).
constexpr bool programMotion(MotionOwner o) {
    return o == MotionOwner::Program || o == MotionOwner::HandwheelFrame ||
           o == MotionOwner::Oscillation;
}

struct AxisUnit {
    AxisUnit(axis::AxisId axisId, const axis::Constants& constants)
        : id(axisId), index(static_cast<int>(axisId)), k(constants), servo(axisId, constants) {
        configure(constants);
    }

    // New constants: servo, scale, soft limits.
    void configure(const axis::Constants& constants) {
        k = constants;
        present = k.present;
        servo.setConstants(k);
        ipd = k.scale.internalPerDisc();
        // 1/ipd is exact (ipd is 1 or 2): a product gives the quotient's bits.
        perIpd = 1.0 / static_cast<double>(ipd);
        softMin = static_cast<double>(k.softMinusDisc * ipd);
        softMax = static_cast<double>(k.softPlusDisc * ipd);
        inputsKnown = false; // the fast-input functions may have changed with C
        encoderChannel = k.encoderChannel >= 1 && k.encoderChannel <= 4 ? k.encoderChannel - 1 : -1;
        const axis::ServoInputs none;
        servoIn.encoderCount = none.encoderCount; // no channel: what a missing encoder reads
        servoIn.channel1Ok = none.channel1Ok;
        servoIn.channel2Ok = none.channel2Ok;
        servoIn.zeroMark = none.zeroMark;
        servoIn.zeroMarkCount = none.zeroMarkCount;
    }

    // Soft limits act once the axis is referenced (C10/C62 ВКЛ.ПРГ.КОН).
    bool softLimitsActive() const { return k.softLimitsOn && referenced; }
    // «Базовая точка достигнута»: referenced, or homing blocked by АВТ.БЕЗ ПБТ.
    bool referenceOk() const { return referenced || k.autoWithoutHoming; }

    // Display discretes <-> internal units (machine system).
    std::int64_t toDisc(double internal) const { return roundToInt(internal * perIpd); }
    double toInternal(std::int64_t disc) const { return static_cast<double>(disc * ipd); }
    std::int64_t machineDisc() const { return toDisc(servo.actual()); }
    // Display discretes per minute -> internal units per ms.
    double speedFromDiscPerMin(double discPerMin) const {
        return discPerMin * static_cast<double>(ipd) / 60000.0;
    }
    double discPerMinFromSpeed(double internalPerMs) const {
        return internalPerMs * 60000.0 / static_cast<double>(ipd);
    }

    // Whether a motion in direction `dir` is blocked by a limit switch.
    bool directionLocked(int dir) const {
        return (dir > 0 && limitPlus) || (dir < 0 && limitMinus);
    }

    axis::AxisId id;
    int index;
    bool present = true;
    axis::Constants k;
    axis::Servo servo;
    axis::HomingCycle homing;
    std::int64_t ipd = 2;
    double perIpd = 0.5; // 1 / ipd
    double softMin = 0, softMax = 0; // internal units

    bool referenced = false;
    std::int64_t homeDistanceDisc = 0; // R246/R247

    // Signals of this tick (PLC bit OR fast input).
    bool limitPlus = false, limitMinus = false, cam = false, driveReady = true, displayMode = false;
    std::array<bool, 4> erase{};
    // The words and fast-input byte the signals above were decoded from
    // (decoded again only when one of them changes, or the constants did).
    bool inputsKnown = false;
    std::uint16_t inputsW0 = 0, inputsW1 = 0, inputsZ1000 = 0;
    std::uint8_t inputsFast = 0;
    bool inputsPlcLink = true;
    // The servo's inputs as the engine hands them over each tick: the
    // encoder's from its pulse channel (C17/C69, 0..3, -1: none), the rest
    // decoded with the signals above; feed enable of Z1000.1 and Z1005.2.
    int encoderChannel = 0;
    axis::ServoInputs servoIn;
    bool feedEnableWords = true;

    // Motion.
    MotionOwner owner = MotionOwner::None;
    double moveTarget = 0;   // program move target, internal (machine system)
    double moveSpeed = 0;    // its speed, internal/ms
    bool rapid = false;      // G00 or rapid jog (Z2005.5)
    bool noOverride = false; // Gx56 in effect
    int commandDir = 0;      // Z2005.1/.2: manual command + / -
    int jogDir = 0;
    bool jogRapid = false;
    bool softLimitStop = false;              // a jog stopped at a soft limit (message 12/28 shown)
    std::int64_t programmedDisc = 0;         // programmed position (machine system), for G91
    int eraseSignal = 0;                     // Gx36..39 of the current frame: 1..4, 0 = none
    bool erased = false;                     // the signal came; the rest of the path was dropped
    // A mode change interrupted the program: the axis is free for РУЧНОЙ;
    // «Пуск» gives it back to the frame (the move again to moveTarget, or the
    // Gx10 frame).
    bool resumeMove = false, resumeWheel = false;
    double wheelMin = 0, wheelMax = 0;       // Gx10: the handwheel may move the target within these
    std::array<std::int64_t, 2> wheelLast{}; // handwheel counters at the last tick
    double overrideFactor = 1.0;
};

} // namespace k528::engine
