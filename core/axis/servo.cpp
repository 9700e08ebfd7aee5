#include "axis/servo.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace k528::axis {

int faultMessage(Fault f, AxisId axis) {
    const bool x = axis == AxisId::X;
    switch (f) {
    case Fault::None:
        return 0;
    case Fault::RegulatorNotEnabled:
        return x ? 1 : 17;
    case Fault::Channel1Break:
        return x ? 4 : 20;
    case Fault::Channel2Break:
        return x ? 5 : 21;
    case Fault::DacLimit:
        return x ? 6 : 22;
    case Fault::FollowingError:
        return x ? 7 : 23;
    case Fault::Standstill:
        return x ? 8 : 24;
    case Fault::RatioError:
        return x ? 13 : 29;
    case Fault::DriveNotReady:
        return x ? 16 : 32;
    case Fault::EncoderStall:
        return x ? 56 : 57;
    }
    return 0;
}

Servo::Servo(AxisId id, const Constants& k) : id_(id) { setConstants(k); }

void Servo::setConstants(const Constants& k) {
    steady_ = false;
    // Keep the machine-system position across a change of L/N.
    const double before = actual_;
    k_ = k;
    if (!k_.ratioValid()) {
        fault_ = Fault::RatioError;
        ipc_ = 1;
    } else {
        ipc_ = k_.internalPerCount();
        if (fault_ == Fault::RatioError)
            fault_ = Fault::None;
    }
    if (k_.encoderCheckMs > 0) {
        const double threshold = 4.0 * ipc_ / static_cast<double>(k_.encoderCheckMs);
        stallSpeedLo_ = threshold * (1.0 - 1e-9);
        stallSpeedHi_ = threshold * (1.0 + 1e-9);
    }
    // The constants as the loop computes with them (exact conversions).
    ksD_ = static_cast<double>(k_.ks);
    keD_ = static_cast<double>(k_.ke);
    driftD_ = static_cast<double>(k_.driftCompDac);
    maxErrorD_ = k_.maxErrorInternal > 0 ? static_cast<double>(k_.maxErrorInternal)
                                         : std::numeric_limits<double>::infinity();
    posToleranceD_ = static_cast<double>(k_.posToleranceInternal);
    clampToleranceD_ = static_cast<double>(k_.clampToleranceInternal);
    clampDelayD_ = static_cast<double>(k_.effectiveClampDelayMs());
    dacLimit_ = k_.dacLimit > 0 ? k_.dacLimit : std::numeric_limits<std::int64_t>::max();
    if (haveCount_) {
        offset_ = before - static_cast<double>(lastCount_) * ipc_;
        actual_ = before;
    }
}

double Servo::accelFor(bool accel2) const {
    const std::int64_t a = accel2 ? k_.emergencyAccel() : k_.accel1;
    const double v = k_.accelToInternalPerMs2(a);
    return v > 0 ? v : 1e-6; // a zero acceleration would never move: crawl instead
}

bool Servo::moveTo(double target, double speed) {
    steady_ = false;
    if (fault_ != Fault::None)
        return false;
    if (!regulatorOn_) {
        raise(Fault::RegulatorNotEnabled);
        return false;
    }
    if (!loopClosed_)
        return false;
    jogDir_ = 0;
    traj_.moveTo(target, speed, accelFor(accel2Input_));
    inPosition_ = false;
    return true;
}

bool Servo::jog(int dir, double speed, const double* limit) {
    steady_ = false;
    if (dir == 0) {
        if (jogDir_ != 0)
            stop();
        return true;
    }
    if (fault_ != Fault::None)
        return false;
    if (!regulatorOn_) {
        raise(Fault::RegulatorNotEnabled);
        return false;
    }
    if (!loopClosed_)
        return false;
    // Far beyond any travel (±10 m in internal units at 0.0001 mm is 2e8).
    double target = dir > 0 ? 1e12 : -1e12;
    if (limit)
        target = dir > 0 ? std::min(target, *limit) : std::max(target, *limit);
    jogDir_ = dir;
    traj_.moveTo(target, speed, accelFor(accel2Input_));
    inPosition_ = false;
    return true;
}

bool Servo::nudge(double delta, double speed) {
    steady_ = false;
    if (fault_ != Fault::None || !loopClosed_)
        return false;
    jogDir_ = 0;
    traj_.moveTo(traj_.target() + delta, speed, accelFor(accel2Input_));
    inPosition_ = false;
    return true;
}

void Servo::stop(bool emergency) {
    steady_ = false;
    jogDir_ = 0;
    traj_.stop(accelFor(emergency || accel2Input_));
}

void Servo::setActualValue(double value) {
    steady_ = false;
    const double shift = value - actual_;
    offset_ += shift;
    actual_ += shift;
    traj_.reset(traj_.position() + shift);
    clampRef_ += shift;
    if (markSeen_)
        markInternal_ += shift;
}

double Servo::countToInternal(std::int64_t rawCount) const {
    const std::int64_t c = k_.encoderInvert ? -rawCount : rawCount;
    return static_cast<double>(c) * ipc_ + offset_ - backlashOffset_;
}

void Servo::resetFault() {
    steady_ = false;
    if (fault_ == Fault::RatioError && !k_.ratioValid())
        return; // stays until the constants are corrected
    fault_ = Fault::None;
    stallTimerMs_ = 0;
    clampWatch_ = regulatorOn_ ? false : clampWatch_;
    if (!regulatorOn_)
        clampRef_ = actual_;
}

void Servo::raise(Fault f) {
    steady_ = false;
    if (fault_ == Fault::None)
        fault_ = f;
}

void Servo::openLoop() {
    loopClosed_ = false;
    jogDir_ = 0;
    traj_.reset(actual_); // follow-up: the setpoint tracks the actual position
    dacRaw_ = 0;
    restTimerMs_ = 0;
    inPosition_ = true;
}

void Servo::superviseEncoder(const ServoInputs& in, double dt) {
    if (!in.channel1Ok)
        raise(Fault::Channel1Break);
    else if (!in.channel2Ok)
        raise(Fault::Channel2Break);
    // T контроля ДОС: the encoder must change while the drive is on and motion
    // is demanded (always during a commanded move; at rest when C14 is set and
    // the loop is correcting an error beyond ДОПУСК КП). Slow feeds that give
    // fewer than 4 counts within T are not checked (they would trip falsely).
    if (k_.encoderCheckMs <= 0 || !regulatorOn_ || !loopClosed_ || pulses_ != 0) {
        stallTimerMs_ = 0; // not checked, or the encoder moved this tick
        return;
    }
    // At least 4 counts within the check time; the division is taken only
    // near the threshold (a speed well above or below it decides alike).
    const double speed = std::fabs(traj_.velocity());
    const bool moveDemanded =
        traj_.velocity() != 0.0 &&
        (speed > stallSpeedHi_ ||
         (speed >= stallSpeedLo_ && speed * static_cast<double>(k_.encoderCheckMs) / ipc_ >= 4.0));
    const bool restDemanded = k_.encoderCheckAtRest && traj_.velocity() == 0.0 &&
                              std::fabs(followingError()) > clampToleranceD_;
    if (moveDemanded || restDemanded) {
        stallTimerMs_ += dt;
        if (stallTimerMs_ >= static_cast<double>(k_.encoderCheckMs))
            raise(Fault::EncoderStall);
    } else {
        stallTimerMs_ = 0;
    }
}

bool Servo::settled(double e) const {
    return loopClosed_ && regulatorOn_ && fault_ == Fault::None && haveCount_ && traj_.atTarget() &&
           !traj_.stopping() && pulses_ == 0 && jogDir_ == 0 && stallTimerMs_ == 0 &&
           std::fabs(e) <= clampToleranceD_ && (inPosition_ || std::fabs(e) > posToleranceD_);
}

void Servo::tick(const ServoInputs& in, double dt) {
    if (steady_ && dt == lastDt_ && in == lastIn_) {
        // At rest, same inputs: the same count, regulator state, setpoint and
        // DAC code; only the time at rest grows.
        restTimerMs_ += dt;
        quietTick_ = true;
        return;
    }
    quietTick_ = false;
    steady_ = false;
    accel2Input_ = in.accel2;
    // --- encoder -> actual position ---
    const std::int64_t count = k_.encoderInvert ? -in.encoderCount : in.encoderCount;
    if (!haveCount_) {
        lastCount_ = count;
        haveCount_ = true;
        offset_ = actual_ - static_cast<double>(count) * ipc_;
    }
    pulses_ = count - lastCount_;
    lastCount_ = count;
    actual_ = static_cast<double>(count) * ipc_ + offset_ - backlashOffset_;
    markSeen_ = in.zeroMark;
    if (in.zeroMark)
        markInternal_ = countToInternal(in.zeroMarkCount);

    // --- regulator enable / blocking (Z1005.0, Z1005.1, Z1000.0) ---
    const bool wantOn = in.regulatorEnable && !in.loopOff && !in.emergencyStop && fault_ == Fault::None;
    if (in.regulatorEnable && !in.driveReady && fault_ == Fault::None)
        raise(Fault::DriveNotReady);
    if (wantOn && fault_ == Fault::None) {
        if (!regulatorOn_)
            traj_.reset(actual_);
        regulatorOn_ = true;
        offTimerMs_ = -1;
        clampWatch_ = false;
    } else if (regulatorOn_) {
        if (offTimerMs_ < 0)
            offTimerMs_ = 0;
        offTimerMs_ += dt;
        if (offTimerMs_ >= static_cast<double>(k_.regulatorOffDelayMs)) {
            regulatorOn_ = false;
            offTimerMs_ = -1;
            // Z1005.1 = 0 (not E-stop, not loop-off): watch the clamped axis.
            clampWatch_ = !in.regulatorEnable && !in.emergencyStop && !in.loopOff;
            clampRef_ = actual_;
        }
    }
    if (!regulatorOn_ && clampWatch_ && fault_ == Fault::None &&
        std::fabs(actual_ - clampRef_) > clampToleranceD_)
        raise(Fault::Standstill);

    const bool closed = regulatorOn_ && wantOn && fault_ == Fault::None;
    if (!closed) {
        if (loopClosed_ || traj_.position() != actual_)
            openLoop();
        superviseEncoder(in, dt);
        dacRaw_ = 0;
        dacOut_ = 0;
        return;
    }
    if (!loopClosed_) {
        traj_.reset(actual_);
        loopClosed_ = true;
        inPosition_ = true;
    }

    // --- setpoint ---
    traj_.setScale(in.feedEnable ? std::clamp(override_, 0.0, 1.0) : 0.0);
    const bool wasAtTarget = traj_.atTarget();
    traj_.tick(dt);
    const double v = traj_.velocity();

    // --- backlash compensation: half the play on each side of the travel ---
    const int dir = v > 0 ? 1 : (v < 0 ? -1 : 0);
    if (dir != 0 && dir != lastDir_) {
        lastDir_ = dir;
        // КОМП.ЛЮФТА is in discretes of motion (2 internal units each); half
        // of it on either side of the travel makes a reversal add all of it.
        const double newOffset = dir * static_cast<double>(k_.backlashDisc);
        actual_ -= newOffset - backlashOffset_;
        backlashOffset_ = newOffset;
    }

    // --- position loop ---
    const double e = traj_.position() - actual_;
    const double dac = v * ksD_ * (3.0 / 128.0) + e * keD_ / 256.0 + driftD_;
    // Round half away from zero, inline (std::lround is a library call, once a tick per axis).
    // (d ± 0.5 by the sign of d: d - 0.5 is d + (-0.5); -0.0 gives -0.5,
    // truncated to 0 as +0.5 would be.)
    const double dacClamped = std::clamp(dac, -1e9, 1e9);
    dacRaw_ = static_cast<int>(dacClamped + std::copysign(0.5, dacClamped));
    const int clamped = static_cast<int>(std::clamp<std::int64_t>(dacRaw_, -k_.dacMax, k_.dacMax));
    dacOut_ = k_.dacInvert ? -clamped : clamped;
    if (std::abs(dacRaw_) > dacLimit_)
        raise(Fault::DacLimit);

    // --- following error, end of move, standstill ---
    const bool atTarget = traj_.atTarget();
    if (!atTarget) {
        restTimerMs_ = 0;
        inPosition_ = false;
        if (std::fabs(e) > maxErrorD_)
            raise(Fault::FollowingError);
    } else {
        if (!wasAtTarget)
            restTimerMs_ = 0;
        restTimerMs_ += dt;
        if (!inPosition_ && std::fabs(e) <= posToleranceD_)
            inPosition_ = true;
        if (restTimerMs_ >= clampDelayD_ && std::fabs(e) > clampToleranceD_)
            raise(Fault::Standstill);
    }
    if (jogDir_ != 0 && atTarget)
        jogDir_ = 0; // reached the jog limit

    if (in.channel1Ok && in.channel2Ok && pulses_ != 0)
        stallTimerMs_ = 0; // what superviseEncoder() does while the encoder moves
    else
        superviseEncoder(in, dt);
    if (fault_ != Fault::None) {
        // A loop error opens the loop at once: zero volts, then the
        // regulator blocks after ЗАДЕРЖКА БР.
        dacRaw_ = 0;
        dacOut_ = 0;
        loopClosed_ = false;
        jogDir_ = 0;
    }
    steady_ = atTarget && wasAtTarget && settled(e);
    if (steady_) {
        // Only a steady servo compares its inputs with the last ones (and the
        // copy here, long after `in` was built, costs no store forwarding).
        lastIn_ = in;
        lastDt_ = dt;
    }
}

} // namespace k528::axis
