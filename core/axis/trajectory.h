// The setpoint generator of one axis: time-optimal trapezoidal profiles
// (constant acceleration, cruise at the speed limit, constant deceleration)
// towards a target that may change on the fly (handwheel, jog release), with
// a speed scale for the feed override and feed hold.
//
// Units: positions in internal units, time in ms, speeds in internal/ms,
// accelerations in internal/ms². Deterministic: plain double arithmetic in a
// fixed order.
#pragma once

namespace k528::axis {

class Trajectory {
public:
    // At rest at `pos`, no motion pending.
    void reset(double pos);

    // Move to `target` with speed limit `vmax` (> 0) and acceleration `accel` (> 0).
    void moveTo(double target, double vmax, double accel);
    // Change the target of the current motion (keeps speed limit and acceleration).
    void setTarget(double target) {
        target_ = target;
        stopping_ = false;
        noteAtTarget();
    }
    void setSpeedLimit(double vmax) {
        vmax_ = vmax;
        stepDt_ = kNoStep;
    }
    void setAccel(double accel) {
        accel_ = accel;
        stepDt_ = kNoStep;
    }
    // Scale of the speed limit: feed override × feed enable, 0..1. At 0 the
    // axis decelerates to rest and waits with the target kept.
    void setScale(double scale) {
        if (scale != scale_) {
            scale_ = scale;
            stepDt_ = kNoStep;
        }
    }

    // Decelerate to rest with `accel`; the point where it stops becomes the
    // target (the rest of the path is dropped).
    void stop(double accel);

    // Advance by dtMs.
    void tick(double dtMs);

    double position() const { return pos_; }
    double velocity() const { return vel_; }
    double target() const { return target_; }
    double remaining() const { return target_ - pos_; }
    bool stopping() const { return stopping_; }
    // Exactly at the target and at rest.
    bool atTarget() const { return atTarget_; }
    // At rest (may be short of the target while the scale is 0).
    bool atRest() const { return vel_ == 0.0; }
    // Distance needed to stop from the current speed with acceleration a.
    double brakingDistance(double a) const { return a > 0 ? vel_ * vel_ / (2.0 * a) : 0.0; }

private:
    // atTarget() kept with every change of position, speed or target (the
    // servo and the engine ask several times a tick).
    void noteAtTarget() { atTarget_ = pos_ == target_ && vel_ == 0.0; }
    // The values of a step that depend only on the acceleration, the scaled
    // speed limit and the step length, computed with the same operations in
    // the same order as the step itself would (so bit for bit the same), once
    // for as long as these stay: a move's every step reads them.
    void prepareStep(double dt);
    static constexpr double kNoStep = -1.0; // stepDt_: nothing prepared

    double pos_ = 0, vel_ = 0, target_ = 0;
    bool atTarget_ = true;
    double vmax_ = 0, accel_ = 1, scale_ = 1;
    double stopAccel_ = 1;
    bool stopping_ = false;
    double stepDt_ = kNoStep;  // the step length the values below are for
    double a_ = 1;             // the acceleration in use (a tiny one for none)
    double limit_ = 0;         // the scaled speed limit, >= 0
    double aadtdt_ = 0;        // a·a·dt·dt
    double eightA_ = 0;        // 8·a
    double dvMax_ = 0;         // a·dt: the speed change of one step
    double dvMaxDt_ = 0;       // a·dt·dt: the arrival window
    double cruiseSq_ = 0;      // (2·limit + a·dt)²·(1 + 1e-9): see tick()
};

} // namespace k528::axis
