#include "axis/trajectory.h"

#include <algorithm>
#include <cmath>

namespace k528::axis {

void Trajectory::reset(double pos) {
    pos_ = target_ = pos;
    vel_ = 0;
    stopping_ = false;
    noteAtTarget();
}

void Trajectory::moveTo(double target, double vmax, double accel) {
    target_ = target;
    vmax_ = vmax;
    accel_ = accel;
    stopping_ = false;
    stepDt_ = kNoStep;
    noteAtTarget();
}

void Trajectory::prepareStep(double dt) {
    a_ = accel_ > 0 ? accel_ : 1e-9;
    limit_ = std::max(0.0, vmax_ * scale_);
    aadtdt_ = a_ * a_ * dt * dt;
    eightA_ = 8.0 * a_;
    dvMax_ = a_ * dt;
    dvMaxDt_ = dvMax_ * dt;
    const double cruiseBound = 2.0 * limit_ + dvMax_;
    cruiseSq_ = cruiseBound * cruiseBound * (1.0 + 1e-9);
    stepDt_ = dt;
}

void Trajectory::stop(double accel) {
    if (vel_ == 0.0) {
        target_ = pos_;
        stopping_ = false;
        noteAtTarget();
        return;
    }
    stopping_ = true;
    stopAccel_ = accel > 0 ? accel : accel_;
}

void Trajectory::tick(double dt) {
    if (stopping_) {
        const double dv = stopAccel_ * dt;
        double v;
        if (std::fabs(vel_) <= dv) {
            v = 0;
        } else {
            v = vel_ > 0 ? vel_ - dv : vel_ + dv;
        }
        pos_ += (vel_ + v) * 0.5 * dt;
        vel_ = v;
        if (vel_ == 0.0) {
            stopping_ = false;
            target_ = pos_;
        }
        noteAtTarget();
        return;
    }
    const double r = target_ - pos_;
    if (r == 0.0 && vel_ == 0.0)
        return;
    if (dt != stepDt_)
        prepareStep(dt);
    const double a = a_;
    const double limit = limit_;
    // The fastest speed v' from which the target can still be reached
    // braking with `a`, counting this step's own travel (v + v')·dt/2:
    // v'²/(2a) + v'·dt/2 <= |r| - v·dt/2; never above the (scaled) limit.
    const double dir = r > 0 ? 1.0 : (r < 0 ? -1.0 : 0.0);
    const double room = vel_ * dir >= 0 ? std::max(0.0, std::fabs(r) - std::fabs(vel_) * dt * 0.5) : std::fabs(r);
    // The speed from which the axis still stops at the target. While it is
    // clearly above the speed limit (the usual case in a long move) the
    // square root cannot change the result and is not taken: sqrt(disc) >=
    // 2·limit + a·dt, with a margin far above any rounding, gives braking >=
    // limit, so min() picks the limit either way — bit for bit the same.
    const double disc = aadtdt_ + eightA_ * room;
    const double braking = disc > cruiseSq_ ? limit : 0.5 * (-a * dt + std::sqrt(disc));
    const double desired = dir * std::min(limit, braking);
    const double dvMax = dvMax_;
    const double v = vel_ + std::clamp(desired - vel_, -dvMax, dvMax);
    double p = pos_ + (vel_ + v) * 0.5 * dt;
    double vNew = v;
    // Arrival: the step reaches or passes the target while moving towards it,
    // or the target is closer than one step at a speed that can stop at once.
    // A target moved behind a fast axis is overshot and approached again.
    const bool passed = (r > 0 && p >= target_) || (r < 0 && p <= target_);
    const bool slow = std::fabs(vNew) <= dvMax;
    if (dir != 0.0 && slow && (passed || std::fabs(target_ - p) <= dvMaxDt_)) {
        p = target_;
        vNew = 0;
    }
    if (dir == 0.0 && std::fabs(vNew) < 1e-12)
        vNew = 0;
    pos_ = p;
    vel_ = vNew;
    noteAtTarget();
}

} // namespace k528::axis
