// The positioner's control of one axis (БП, manual appendix Е and И):
//   encoder counts ×(2·L/N) -> actual position in internal units,
//   setpoint generator (axis/trajectory.h) with acceleration 1 or 2,
//   position loop  DAC = V·Ks·3/128 + E·Ke/256 + КОМП.ДРЕЙФА, clamped to
//   ±МАКС.ЦАП, with backlash compensation on reversal,
//   regulator enable with ЗАДЕРЖКА БР, and the supervision that raises the
//   manual's messages (regulator, encoder channels, DAC limit, following
//   error, standstill/clamp, drive ready, encoder stall).
//
// Scaling of the loop (docs/axis.md): with V in internal units per ms and E
// in internal units, the factors 3/128 and 1/256 are exactly those for which
// the manual's formulas Ks = 262·Kd·Umax/Vmax and Ke = 26.2·Kd·Kv·Umax/Vmax
// give Umax at Vmax and a lag of V/Kv (a 12-bit DAC, 2048 codes = 10 V).
//
// Limit switches, soft limits and modes are the engine's business; the servo
// offers the motions (move, jog, handwheel, stop) and reports what happened.
#pragma once

#include <cmath>
#include <cstdint>

#include "axis/constants.h"
#include "axis/trajectory.h"

namespace k528::axis {

// Per-tick inputs from the PLC interface words, fast inputs and encoder.
struct ServoInputs {
    std::int64_t encoderCount = 0;   // raw counts as wired
    bool channel1Ok = true;          // encoder line monitoring of the CP34.23
    bool channel2Ok = true;
    bool zeroMark = false;           // a zero mark passed during this tick
    std::int64_t zeroMarkCount = 0;  // ... at this raw count
    bool emergencyStop = false;      // Z1000.0 = 0
    bool loopOff = false;            // Z1005.0 «Выключение регулятора положения»
    bool regulatorEnable = true;     // Z1005.1 «Деблокировка регулятора привода»
    bool feedEnable = true;          // Z1000.1 and Z1005.2 «Деблокировка подачи»
    bool accel2 = false;             // Z1005.4 acceleration 2 for all motion
    bool driveReady = true;          // fast input function 3 (true when not wired)
    friend bool operator==(const ServoInputs&, const ServoInputs&) = default;
};

enum class Fault : std::uint8_t {
    None,
    RegulatorNotEnabled, // 1 / 17
    Channel1Break,       // 4 / 20
    Channel2Break,       // 5 / 21
    DacLimit,            // 6 / 22
    FollowingError,      // 7 / 23
    Standstill,          // 8 / 24  (position/clamp check at rest)
    RatioError,          // 13 / 29 (L/N unusable)
    DriveNotReady,       // 16 / 32
    EncoderStall,        // 56 / 57
};

// The manual's message number (appendix М) of a fault on an axis; 0 for None.
int faultMessage(Fault f, AxisId axis);

class Servo {
public:
    Servo(AxisId id, const Constants& k);

    // New constants (e.g. after editing C-parameters); keeps the position.
    void setConstants(const Constants& k);
    const Constants& constants() const { return k_; }
    AxisId id() const { return id_; }

    // --- motion commands (internal units, internal/ms) -------------------
    // Positioning move. Returns false (and latches RegulatorNotEnabled) when
    // the regulator is not enabled; false without a fault while the loop is
    // open for another reason or a fault is latched.
    bool moveTo(double targetInternal, double speed);
    // Continuous motion in direction `dir` (+1/-1) until stop()/jog(0,..).
    // `limitInternal` (optional): the axis stops there (soft limit).
    bool jog(int dir, double speed, const double* limitInternal = nullptr);
    // Handwheel increment (electric shaft): the target moves by `delta`.
    bool nudge(double deltaInternal, double speed);
    // Decelerate and drop the rest of the path. `emergency`: acceleration 2.
    void stop(bool emergency = false);
    // Speed factor: feed override (0..1). Feed hold comes from the inputs.
    void setOverride(double factor) {
        if (factor != override_) {
            steady_ = false;
            override_ = factor;
        }
    }
    // Preview (engine/preview.h): the axis stands at `internal` at once.
    void place(double internal) {
        traj_.reset(internal);
        actual_ = internal;
        inPosition_ = true;
        steady_ = false;
    }

    // --- reference -------------------------------------------------------
    // Shifts the machine system so that the current actual position reads
    // `valueInternal` (reference point, manual 2.6.4).
    void setActualValue(double valueInternal);
    // Machine-system position of a raw encoder count (zero-mark latches).
    double countToInternal(std::int64_t rawCount) const;

    // --- supervision -----------------------------------------------------
    Fault fault() const { return fault_; }
    // Acknowledge: clears the fault; the loop closes again on the next tick
    // if the regulator is enabled (the setpoint takes the actual position).
    void resetFault();
    // Latches a fault raised from outside (e.g. by the engine).
    void raise(Fault f);

    // --- one control period ----------------------------------------------
    void tick(const ServoInputs& in, double dtMs);

    // --- state -----------------------------------------------------------
    double actual() const { return actual_; }           // machine system, internal units
    double setpoint() const { return traj_.position(); }
    double target() const { return traj_.target(); }
    // The rest of the path to the target; 0 for a jog without a limit
    // (its target is an open end, not a path).
    double remaining() const { return jogDir_ != 0 && std::fabs(traj_.target()) >= kOpenEnd ? 0.0 : traj_.remaining(); }
    static constexpr double kOpenEnd = 1e11;
    double followingError() const { return traj_.position() - actual_; }
    double commandVelocity() const { return traj_.velocity(); } // internal/ms
    int dac() const { return dacOut_; }                          // as sent (ЗНАК ЦАП applied)
    int dacUnclamped() const { return dacRaw_; }
    std::int64_t pulsesLastTick() const { return pulses_; }
    bool regulatorOn() const { return regulatorOn_; }
    bool loopClosed() const { return loopClosed_; }
    bool moving() const { return loopClosed_ && !traj_.atTarget(); }
    bool jogging() const { return jogDir_ != 0; }
    int direction() const { return traj_.velocity() > 0 ? 1 : (traj_.velocity() < 0 ? -1 : 0); }
    // The move is over and the axis is inside ДОПУСК ПОЗ.
    bool inPosition() const { return inPosition_; }
    bool zeroMarkSeen() const { return markSeen_; }
    double zeroMarkInternal() const { return markInternal_; }
    double backlashOffset() const { return backlashOffset_; }
    // The last tick changed nothing a caller can see (settled at rest, the
    // same inputs: only the rest timer ran) and no command came since: every
    // value above is what it was before that tick.
    bool quiet() const { return quietTick_ && steady_; }
    // The tick of a quiet servo whose inputs are those of its last tick, as
    // tick() would do it (the controller's settled tick, engine/positioner.h).
    void quietTick(double dt) {
        restTimerMs_ += dt;
        quietTick_ = true;
    }

private:
    void openLoop();
    // Whether the tick that just ended left a state that the same inputs
    // would leave unchanged (closed loop at rest, no timer about to act).
    bool settled(double e) const;
    void superviseEncoder(const ServoInputs& in, double dt);
    double accelFor(bool accel2) const;

    AxisId id_;
    Constants k_;
    Trajectory traj_;
    double ipc_ = 1;          // internal units per count (2L/N)
    double stallSpeedLo_ = 0, stallSpeedHi_ = 0; // about 4 counts per ЗАДЕРЖКА ДАТЧИКА (superviseEncoder)
    // The constants as the loop computes with them, converted once
    // (setConstants): K(СКОР), K(ОШИБ), КОМП.ДРЕЙФА; МАКС.ОШИБКА (infinite
    // when off), ДОПУСК ПОЗ., ДОПУСК КП, ЗАДЕРЖКА КП; ПРЕДЕЛ ЦАП (the
    // largest integer when off).
    double ksD_ = 0, keD_ = 0, driftD_ = 0;
    double maxErrorD_ = 0, posToleranceD_ = 0, clampToleranceD_ = 0, clampDelayD_ = 0;
    std::int64_t dacLimit_ = 0;
    double offset_ = 0;       // machine system = counts·ipc + offset
    double actual_ = 0;
    std::int64_t lastCount_ = 0;
    bool haveCount_ = false;
    std::int64_t pulses_ = 0;
    Fault fault_ = Fault::None;
    bool regulatorOn_ = false;
    bool loopClosed_ = false;
    double offTimerMs_ = -1;      // running while the regulator waits to block
    double clampRef_ = 0;         // position when the regulator blocked
    bool clampWatch_ = false;
    double override_ = 1;
    bool accel2Input_ = false;
    int jogDir_ = 0;
    bool inPosition_ = true;
    double restTimerMs_ = 0;      // time since the setpoint came to rest
    double stallTimerMs_ = 0;     // time the count has not changed while motion is demanded
    int lastDir_ = 0;
    double backlashOffset_ = 0;
    int dacRaw_ = 0, dacOut_ = 0;
    bool markSeen_ = false;
    double markInternal_ = 0;
    // The last tick left the axis settled and no command came since: a tick
    // with the same inputs changes nothing but the rest timer.
    bool steady_ = false;
    bool quietTick_ = false; // the last tick was such a tick
    ServoInputs lastIn_;
    double lastDt_ = 0;
};

} // namespace k528::axis
