// The machine side of one feed axis: the drive (DAC volts -> motor speed with
// a first-order lag and a current-limited acceleration), the ball screw with
// mechanical play between screw and slide, and the motor-mounted incremental
// encoder (4 counts per line, one zero mark per motor revolution).
//
// This is the physical plant the positioner's servo (axis/servo.h) controls.
// It knows nothing of machine constants: wiring and mechanics are settings,
// so a mistuned or miswired machine behaves as it would on the shop floor.
// Units: slide and motor positions in mm of slide travel, speeds in mm/min,
// time in ms.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace k528::axis {

struct MechanicsSettings {
    double screwLeadMm = 5.0;             // slide travel per motor revolution
    int encoderLines = 2500;              // lines per motor revolution (×4 counts)
    double speedPerVoltMmPerMin = 1000.0; // slide speed per volt of drive input
    double timeConstantMs = 20.0;         // first-order lag of the drive's speed loop
    double maxAccelMmPerS2 = 5000.0;      // current limit, as slide acceleration
    double brakeAccelMmPerS2 = 8000.0;    // deceleration when the drive is disabled
    double backlashMm = 0.0;              // play between screw and slide
    double driftVolts = 0.0;              // offset at the drive input
    double zeroMarkPhaseMm = 0.0;         // motor position of a zero mark (mod lead)
    bool encoderWiredInverted = false;    // encoder counts down when moving +
    bool dacWiredInverted = false;        // positive volts drive the slide -
    double startSlideMm = 0.0;            // slide position at power-on

    double mmPerCount() const { return screwLeadMm / (4.0 * encoderLines); }
};

class Mechanics {
public:
    explicit Mechanics(const MechanicsSettings& s = {});

    // Inputs from the positioner, held until changed.
    void setDacCode(int code) {
        if (code != dacCode_) {
            dacCode_ = code;
            refreshTarget();
        }
    }
    void setDriveEnabled(bool on) {
        settled_ = settled_ && on == driveEnabled_;
        driveEnabled_ = on;
    }

    // Advances the plant by dtMs.
    void tick(double dtMs);

    // Encoder as seen at the positioner's input (raw counts, wiring applied).
    std::int64_t encoderCount() const { return count_; }
    bool channelOk(int channel) const { return channel == 1 ? !channel1Broken_ : !channel2Broken_; }
    // Whether a zero mark passed during the last tick, and its count.
    bool zeroMarkCrossed() const { return markCrossed_; }
    std::int64_t zeroMarkCount() const { return markCount_; }
    // The encoder's outputs (count, lines, zero mark) are those before the
    // last tick: it found the plant at rest, and nothing changed them since
    // (a broken channel, a push; a frozen encoder or a jammed slide acts in
    // the next tick, which is not quiet). A reader that copied them then
    // need not copy them again.
    bool quiet() const { return quiet_; }

    double motorMm() const { return motorMm_; }
    double slideMm() const { return slideMm_; }
    double motorSpeedMmPerMin() const { return motorSpeed_ * 60000.0; }
    double driveVolts() const;
    const MechanicsSettings& settings() const { return s_; }

    // Faults for training (machine side).
    void setChannelBroken(int channel, bool broken);
    void setEncoderFrozen(bool frozen) { // reads a constant value
        encoderFrozen_ = frozen;
        encoderBlocked_ = encoderFrozen_ || channel1Broken_ || channel2Broken_;
        settled_ = false;
    }
    void setJammed(bool jammed) { // the slide cannot move
        jammed_ = jammed;
        settled_ = false;
    }
    // Moves the slide by hand / external force while the drive is off.
    void pushSlide(double deltaMm);

private:
    void setTickLength(double dtMs); // alpha_ and the speed steps of a tick of dtMs
    void updateEncoder(double previousMotorMm);
    bool encoderWithinRevolution();
    void refreshTarget(); // targetSpeed_ from the DAC code


    MechanicsSettings s_;
    int dacCode_ = 0;
    bool driveEnabled_ = false;
    double motorMm_ = 0, slideMm_ = 0;
    double motorSpeed_ = 0; // mm/ms
    std::int64_t count_ = 0;
    bool markCrossed_ = false;
    std::int64_t markCount_ = 0;
    bool channel1Broken_ = false, channel2Broken_ = false;
    bool encoderFrozen_ = false;
    bool encoderBlocked_ = false; // frozen or a channel broken: the counter stands
    bool jammed_ = false;
    double alpha_ = 0, alphaDt_ = -1; // lag factor cached per tick length
    double brakeStep_ = 0, accelStep_ = 0; // speed change limits per tick (of alphaDt_)
    double targetSpeed_ = 0;          // mm/ms of slide travel the DAC code asks for (of dacCode_)
    // targetSpeed_ of each code of a 12-bit DAC (-2048..2047) once computed;
    // NaN: not yet (refreshTarget). On the heap: 32 KB.
    static constexpr int kCodeOffset = 2048, kCodeSlots = 4096;
    std::vector<double> speedOfCode_ =
        std::vector<double>(kCodeSlots, std::numeric_limits<double>::quiet_NaN());
    // The last tick left the motor at rest and nothing changed since: a
    // tick with no drive speed asked changes nothing.
    bool settled_ = false;
    bool quiet_ = false;                // quiet()
    double halfBacklashMm_ = 0;         // s_.backlashMm / 2
    double perCountMm_ = 0;                  // s_.mmPerCount()
    double perCountInverse_ = 0;             // 1 / perCountMm_ (updateEncoder)
    double markRevMotorMm_ = 0, markRev_ = 0; // revolution index (zero marks) of a motor position
    double markRevLoMm_ = 0, markRevHiMm_ = 0; // motor positions safely inside revolution markRev_
    bool markRevFresh_ = false;
    bool countFresh_ = false;         // count_ matches motorMm_ (skip the work while it stands)
};

// updateEncoder's result for a move that stays well inside the revolution
// of the last update (no zero mark), the counter following the motor and
// the count away from a boundary — the common case of a moving axis, inline
// in its tick. False, with nothing changed, when updateEncoder must do it.
// Every change of motorMm_ is followed by updateEncoder or this, so the
// revolution of the last update is that of the motor position before the
// move (markRevFresh_, markRevMotorMm_ == the previous position: updateEncoder
// checks this, here it holds).
inline bool Mechanics::encoderWithinRevolution() {
    if (encoderBlocked_ ||
        !(motorMm_ >= markRevLoMm_ && motorMm_ <= markRevHiMm_ && markRevHiMm_ > markRevLoMm_))
        return false;
    // The floor of the count as updateEncoder takes it from the reciprocal
    // (up to 2^28 counts the truncation, one less below zero), where it
    // takes it: a millionth of a count or more from an integer.
    const double approx = motorMm_ * perCountInverse_;
    if (!(std::fabs(approx) < 268435456.0))
        return false;
    std::int64_t c = static_cast<std::int64_t>(approx);
    double whole = static_cast<double>(c);
    if (whole > approx) {
        --c;
        whole -= 1.0;
    }
    const double frac = approx - whole;
    if (!(frac > 1e-6 && frac < 1.0 - 1e-6))
        return false;
    markCrossed_ = false;
    markRevMotorMm_ = motorMm_; // same revolution: markRev_ stays
    countFresh_ = true;
    count_ = s_.encoderWiredInverted ? -c : c;
    return true;
}

// Inline: every moving axis runs it every tick; the rare parts are calls.
inline void Mechanics::tick(double dt) {
    if (dt != alphaDt_)
        setTickLength(dt);
    // At rest with nothing to move it (no drive speed asked, nothing
    // changed by hand): the same state, the same count, no mark.
    if (settled_ && countFresh_ && (!driveEnabled_ || targetSpeed_ == 0.0)) {
        quiet_ = !markCrossed_; // a mark of the tick before is gone now
        markCrossed_ = false;
        return;
    }
    quiet_ = false;
    // Target motor speed in mm/ms of slide travel.
    double accelLimit = brakeStep_;
    if (driveEnabled_) {
        const double target = targetSpeed_;
        accelLimit = accelStep_;
        const double change = std::clamp((target - motorSpeed_) * alpha_, -accelLimit, accelLimit);
        motorSpeed_ += change;
    } else {
        // Regulator blocked: the motor coasts down against the brake.
        if (std::fabs(motorSpeed_) <= accelLimit)
            motorSpeed_ = 0;
        else
            motorSpeed_ -= motorSpeed_ > 0 ? accelLimit : -accelLimit;
    }
    // Flush speeds far below one encoder count per hour: the lag would
    // otherwise decay into subnormal numbers, which are very slow to compute.
    if (jammed_ || std::fabs(motorSpeed_) < 1e-12)
        motorSpeed_ = 0;
    const double before = motorMm_;
    motorMm_ += motorSpeed_ * dt;
    // The slide follows the screw once the play is taken up.
    const double half = halfBacklashMm_;
    if (motorMm_ - slideMm_ > half)
        slideMm_ = motorMm_ - half;
    else if (slideMm_ - motorMm_ > half)
        slideMm_ = motorMm_ + half;
    if (!encoderWithinRevolution())
        updateEncoder(before);
    settled_ = motorSpeed_ == 0.0;
}

} // namespace k528::axis
