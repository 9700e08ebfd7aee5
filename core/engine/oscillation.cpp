#include "engine/oscillation.h"

namespace k528::engine {

bool Oscillation::move(axis::Servo& s) {
    if (!s.moveTo(towardsHi_ ? hi_ : lo_, speed_)) {
        phase_ = Phase::Off;
        return false;
    }
    phase_ = Phase::Travel;
    return true;
}

bool Oscillation::start(axis::Servo& s, double lo, double hi, double speed, bool towardsHi,
                        const OscillationPresets& p) {
    lo_ = lo;
    hi_ = hi;
    speed_ = speed;
    towardsHi_ = towardsHi;
    p_ = p;
    stopRequested_ = counting_ = false;
    sparkLeft_ = strokes_ = 0;
    waitMs_ = 0;
    return move(s);
}

void Oscillation::requestStop(const OscillationPresets& p) {
    if (!active() || stopRequested_)
        return;
    stopRequested_ = true;
    sparkLeft_ = p.sparkOut > 0 ? p.sparkOut : 0;
    p_.endPoint = p.endPoint;
    // Standing at a reverse point: the stroke in progress is over.
    counting_ = phase_ == Phase::Reverse;
    if (counting_) {
        const bool atHi = !towardsHi_; // already turned towards the other end
        const bool endOk =
            p_.endPoint == 0 || (p_.endPoint == 1 && !atHi) || (p_.endPoint == 2 && atHi);
        if (sparkLeft_ == 0 && endOk)
            phase_ = Phase::Off;
    }
}

void Oscillation::abort(axis::Servo& s) {
    if (phase_ == Phase::Travel)
        s.stop();
    phase_ = Phase::Off;
    stopRequested_ = false;
}

void Oscillation::pause(axis::Servo& s) {
    if (phase_ == Phase::Travel || phase_ == Phase::Reverse) {
        s.stop();
        phase_ = Phase::Paused;
    }
}

bool Oscillation::resume(axis::Servo& s) {
    if (phase_ != Phase::Paused)
        return true;
    return move(s);
}

bool Oscillation::arrived(const axis::Servo& s) const {
    const double target = towardsHi_ ? hi_ : lo_;
    if (s.target() != target)
        return false;
    const bool exact = towardsHi_ ? p_.exactPlus : p_.exactMinus;
    if (exact)
        return s.inPosition() && !s.moving();
    return s.setpoint() == target && s.commandVelocity() == 0.0;
}

void Oscillation::atReversePoint(axis::Servo& s) {
    ++strokes_;
    const bool atHi = towardsHi_;
    if (stopRequested_) {
        if (counting_ && sparkLeft_ > 0)
            --sparkLeft_;
        counting_ = true;
        const bool endOk =
            p_.endPoint == 0 || (p_.endPoint == 1 && !atHi) || (p_.endPoint == 2 && atHi);
        if (sparkLeft_ == 0 && endOk) {
            phase_ = Phase::Off;
            return;
        }
    }
    towardsHi_ = !towardsHi_;
    waitMs_ = static_cast<double>(p_.reverseDelayMs);
    phase_ = Phase::Reverse;
    if (waitMs_ <= 0)
        move(s);
}

void Oscillation::tick(axis::Servo& s, double dtMs) {
    switch (phase_) {
    case Phase::Off:
    case Phase::Paused:
        return;
    case Phase::Travel:
        if (!s.loopClosed() || s.fault() != axis::Fault::None) {
            phase_ = Phase::Off;
            return;
        }
        if (arrived(s))
            atReversePoint(s);
        return;
    case Phase::Reverse:
        waitMs_ -= dtMs;
        if (waitMs_ <= 0)
            move(s);
        return;
    }
}

} // namespace k528::engine
