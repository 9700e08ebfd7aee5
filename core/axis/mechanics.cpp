#include "axis/mechanics.h"

#include <algorithm>
#include <cmath>

namespace k528::axis {

namespace {
constexpr double kDacCodesPerVolt = 204.8; // 12-bit ±10 V: code 2048 = 10 V
constexpr double kMaxVolts = 10.0;

// std::floor, exactly, without the library call it is on baseline x86-64
// (no SSE4.1): a slide is far inside ±2^52 counts or revolutions.
inline double floorExact(double x) {
    if (!(std::fabs(x) < 4503599627370496.0)) // 2^52: already an integer (or not finite)
        return std::floor(x);
    const double t = static_cast<double>(static_cast<std::int64_t>(x)); // toward zero
    return t > x ? t - 1.0 : (t == 0.0 ? std::copysign(0.0, x) : t);
}
} // namespace

Mechanics::Mechanics(const MechanicsSettings& s)
    : s_(s), halfBacklashMm_(s.backlashMm * 0.5), perCountMm_(s.mmPerCount()),
      perCountInverse_(1.0 / perCountMm_) {
    motorMm_ = slideMm_ = s.startSlideMm;
    updateEncoder(motorMm_);
    markCrossed_ = false;
    refreshTarget();
}

void Mechanics::refreshTarget() {
    // The speed of a code in the DAC's range is computed once and kept: the
    // two divisions lie on the path from the positioner's code to the motor
    // in every tick the code changes (the same operations, the same bits).
    const int slot = dacCode_ + kCodeOffset;
    if (slot >= 0 && slot < kCodeSlots) {
        double& kept = speedOfCode_[static_cast<std::size_t>(slot)];
        if (!(kept == kept)) // NaN: not computed yet
            kept = driveVolts() * s_.speedPerVoltMmPerMin / 60000.0;
        targetSpeed_ = kept;
        return;
    }
    targetSpeed_ = driveVolts() * s_.speedPerVoltMmPerMin / 60000.0;
}

double Mechanics::driveVolts() const {
    double u = static_cast<double>(dacCode_) / kDacCodesPerVolt;
    if (s_.dacWiredInverted)
        u = -u;
    return std::clamp(u + s_.driftVolts, -kMaxVolts, kMaxVolts);
}

void Mechanics::setChannelBroken(int channel, bool broken) {
    settled_ = quiet_ = false;
    if (channel == 1)
        channel1Broken_ = broken;
    else
        channel2Broken_ = broken;
    encoderBlocked_ = encoderFrozen_ || channel1Broken_ || channel2Broken_;
}

void Mechanics::pushSlide(double deltaMm) {
    const double before = motorMm_;
    settled_ = quiet_ = false;
    slideMm_ += deltaMm;
    motorMm_ += deltaMm; // a free screw turns with the slide
    updateEncoder(before);
}

void Mechanics::setTickLength(double dt) {
    alpha_ = s_.timeConstantMs > 0 ? 1.0 - std::exp(-dt / s_.timeConstantMs) : 1.0;
    brakeStep_ = s_.brakeAccelMmPerS2 * 1e-6 * dt; // mm/ms per tick
    accelStep_ = s_.maxAccelMmPerS2 * 1e-6 * dt;
    alphaDt_ = dt;
}

void Mechanics::updateEncoder(double previousMotorMm) {
    markCrossed_ = false;
    if (previousMotorMm == motorMm_ && countFresh_)
        return; // the motor stood still: same count, no mark
    const double perCount = perCountMm_;
    // Zero marks at motor positions phase + k·lead (k of the previous
    // position as the last call computed it).
    const double lead = s_.screwLeadMm;
    const bool k0Known = markRevFresh_ && previousMotorMm == markRevMotorMm_;
    const double k0 = k0Known ? markRev_ : floorExact((previousMotorMm - s_.zeroMarkPhaseMm) / lead);
    // Well inside the revolution of k0 (a millionth of a lead from either
    // mark, far above any rounding), the division gives k0 again.
    const double k1 = k0Known && motorMm_ >= markRevLoMm_ && motorMm_ <= markRevHiMm_
                          ? k0
                          : floorExact((motorMm_ - s_.zeroMarkPhaseMm) / lead);
    if (!k0Known || k1 != k0 || !(markRevHiMm_ > markRevLoMm_)) {
        markRevLoMm_ = s_.zeroMarkPhaseMm + (k1 + 1e-6) * lead;
        markRevHiMm_ = s_.zeroMarkPhaseMm + (k1 + 1.0 - 1e-6) * lead;
    }
    markRevMotorMm_ = motorMm_;
    markRev_ = k1;
    markRevFresh_ = true;
    if (k0 != k1 && !encoderBlocked_) {
        const double markMm = s_.zeroMarkPhaseMm + std::max(k0, k1) * lead;
        std::int64_t c = static_cast<std::int64_t>(std::llround(markMm / perCount));
        markCount_ = s_.encoderWiredInverted ? -c : c;
        markCrossed_ = true;
    }
    countFresh_ = !encoderBlocked_;
    if (!countFresh_)
        return; // the counter no longer follows the motor
    // floor(motor / perCount) from the reciprocal: the product is within
    // 2^-51 of the quotient, so away from an integer (a millionth of a
    // count, up to 2^28 counts) both floors agree; near one, the division.
    const double approx = motorMm_ * perCountInverse_;
    double whole = floorExact(approx);
    const double frac = approx - whole;
    if (!(std::fabs(approx) < 268435456.0 && frac > 1e-6 && frac < 1.0 - 1e-6))
        whole = floorExact(motorMm_ / perCount);
    std::int64_t c = static_cast<std::int64_t>(whole);
    count_ = s_.encoderWiredInverted ? -c : c;
}

} // namespace k528::axis
