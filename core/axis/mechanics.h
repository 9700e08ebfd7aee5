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

#include <cstdint>

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
        if (code != dacCode_ || !targetFresh_) {
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
    // last tick: it found the plant at rest, and nothing that changes them
    // (a fault, a push) happened since. A reader that copied them then need
    // not copy them again.
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
        settled_ = quiet_ = false;
    }
    void setJammed(bool jammed) { // the slide cannot move
        jammed_ = jammed;
        settled_ = quiet_ = false;
    }
    // Moves the slide by hand / external force while the drive is off.
    void pushSlide(double deltaMm);

private:
    void updateEncoder(double previousMotorMm);
    bool encoderWithinRevolution(double previousMotorMm);
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
    double targetSpeed_ = 0;          // mm/ms of slide travel the DAC code asks for
    bool targetFresh_ = false;        // targetSpeed_ matches dacCode_
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

} // namespace k528::axis
