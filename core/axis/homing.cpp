#include "axis/homing.h"

#include <cmath>

namespace k528::axis {

namespace {
int signOf(std::int64_t v, int fallback) { return v > 0 ? 1 : (v < 0 ? -1 : fallback); }
} // namespace

bool HomingCycle::start(Servo& servo, bool camPressed) {
    const Constants& k = servo.constants();
    alarm_ = 0;
    distanceDisc_ = 0;
    dir_ = k.homeNegative ? -1 : 1;
    camWas_ = camPressed;
    if (camPressed) {
        // Already on the cam: at F ОТКЛ.БТ in the cam's direction.
        dir_ = signOf(k.decelCamDisc, dir_);
        camStart_ = servo.actual();
        phase_ = Phase::OnCam;
        return servo.jog(dir_, k.speedParamToInternalPerMs(k.feedHomeSlow));
    }
    phase_ = Phase::Approach;
    return servo.jog(dir_, k.speedParamToInternalPerMs(k.feedHomeStart));
}

void HomingCycle::cancel(Servo& servo) {
    if (running())
        servo.stop();
    phase_ = Phase::Idle;
}

void HomingCycle::fail(Servo& servo, int alarm) {
    servo.stop();
    alarm_ = alarm;
    phase_ = Phase::Failed;
}

void HomingCycle::beginSearch(Servo& servo) {
    const Constants& k = servo.constants();
    searchStart_ = servo.actual();
    dir_ = signOf(k.zeroSearchDisc, dir_);
    const double slow = k.speedParamToInternalPerMs(k.feedHomeSlow);
    phase_ = Phase::Search;
    if (k.zeroSearchDisc != 0)
        servo.moveTo(searchStart_ + k.discToInternal(static_cast<double>(k.zeroSearchDisc)), slow);
    else
        servo.jog(dir_, slow);
}

void HomingCycle::tick(Servo& servo, bool cam) {
    const Constants& k = servo.constants();
    const bool rising = cam && !camWas_;
    const bool falling = !cam && camWas_;
    camWas_ = cam;
    if (!running())
        return;
    if (servo.fault() != Fault::None || !servo.loopClosed()) {
        phase_ = Phase::Idle; // the engine reports the fault itself
        return;
    }
    const double slow = k.speedParamToInternalPerMs(k.feedHomeSlow);
    switch (phase_) {
    case Phase::Approach:
        if (rising) {
            camStart_ = servo.actual();
            dir_ = signOf(k.decelCamDisc, dir_);
            phase_ = Phase::OnCam;
            servo.jog(dir_, slow);
        } else if (!servo.moving()) {
            fail(servo, 40); // stopped (e.g. at a limit) before reaching the cam
        }
        break;
    case Phase::OnCam:
        if (falling) {
            leftCam_ = servo.actual();
            if (k.beforeZeroSearchDisc != 0) {
                phase_ = Phase::BeforeSearch;
                dir_ = signOf(k.beforeZeroSearchDisc, dir_);
                servo.moveTo(leftCam_ + k.discToInternal(static_cast<double>(k.beforeZeroSearchDisc)), slow);
            } else {
                beginSearch(servo);
            }
        } else if (k.decelCamDisc != 0 &&
                   std::fabs(servo.actual() - camStart_) >=
                       std::fabs(k.discToInternal(static_cast<double>(k.decelCamDisc)))) {
            fail(servo, 40);
        } else if (!servo.moving()) {
            fail(servo, 40);
        }
        break;
    case Phase::BeforeSearch:
        if (servo.inPosition())
            beginSearch(servo);
        break;
    case Phase::Search:
        distanceDisc_ = std::llround(k.internalToDisc(std::fabs(servo.actual() - leftCam_)));
        if (servo.zeroMarkSeen()) {
            const double mark = servo.zeroMarkInternal();
            distanceDisc_ = std::llround(k.internalToDisc(std::fabs(mark - leftCam_)));
            reference_ = mark + k.discToInternal(static_cast<double>(k.homeOffsetDisc));
            phase_ = Phase::ToReference;
            servo.moveTo(reference_, slow);
        } else if (!servo.moving()) {
            fail(servo, 41);
        }
        break;
    case Phase::ToReference:
        if (servo.inPosition()) {
            // The reference point gets ЗНАЧЕНИЕ БТ; the axis may stand a few
            // units off it (inside ДОПУСК ПОЗ): keep that difference.
            const double value = k.discToInternal(static_cast<double>(k.homeValueDisc));
            servo.setActualValue(value + (servo.actual() - reference_));
            phase_ = Phase::Done;
        }
        break;
    default:
        break;
    }
}

} // namespace k528::axis
