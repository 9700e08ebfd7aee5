#include "axis/constants.h"

#include <stdexcept>

namespace k528::axis {

Constants Constants::fromC(std::span<const std::int64_t> c, AxisId axis) {
    if (c.size() < 105)
        throw std::invalid_argument("C-parameter table too short");
    const int b = cBase(axis);
    const auto at = [&](int n) { return c[static_cast<std::size_t>(b + n - 1)]; };
    Constants k;
    k.present = at(1) != 0;
    k.encoderInvert = at(2) != 0;
    k.dacInvert = at(3) != 0;
    // C4..6: exactly one is set on a valid set; the finest set flag wins
    // otherwise (the profile validator reports the conflict).
    if (at(4) != 0)
        k.scale.discrete = units::Discrete::Mm0_0001;
    else if (at(5) != 0)
        k.scale.discrete = units::Discrete::Mm0_001;
    else if (at(6) != 0)
        k.scale.discrete = units::Discrete::Mm0_01;
    k.scale.diameter = at(7) != 0;
    k.autoWithoutHoming = at(8) != 0;
    k.homeNegative = at(9) != 0;
    k.softLimitsOn = at(10) != 0;
    k.handwheel1Invert = at(11) != 0;
    k.handwheel2Invert = at(12) != 0;
    k.adjustEnabled = at(13) != 0;
    k.encoderCheckAtRest = at(14) != 0;
    k.encoderChannel = static_cast<int>(at(17));
    k.dacChannel = static_cast<int>(at(18));
    k.encoderL = at(19);
    k.encoderN = at(20);
    k.encoderCheckMs = at(21);
    k.accel1 = at(22);
    k.accel2 = at(23);
    k.handwheel1Mult = at(24);
    k.handwheel2Mult = at(25);
    k.ks = at(26);
    k.ke = at(27);
    k.dacLimit = at(28);
    k.dacMax = at(29);
    k.maxErrorInternal = at(30);
    k.posToleranceInternal = at(31);
    k.clampCheckDelayMs = at(32);
    k.clampToleranceInternal = at(33);
    k.driftCompDac = at(34);
    k.backlashDisc = at(35);
    k.regulatorOffDelayMs = at(36);
    k.beforeZeroSearchDisc = at(37);
    k.zeroSearchDisc = at(38);
    k.homeOffsetDisc = at(39);
    k.feedNormal = at(40);
    k.feedRapid = at(41);
    k.feedAutoMax = at(42);
    k.feedHomeStart = at(43);
    k.feedHomeSlow = at(44);
    k.homeValueDisc = at(45);
    k.softMinusDisc = at(46);
    k.softPlusDisc = at(47);
    k.decelCamDisc = at(48);
    return k;
}

double Constants::speedParamToInternalPerMs(std::int64_t param10DiscPerMin) const {
    // 10·disc/min -> disc/min -> internal/min -> internal/ms
    return static_cast<double>(param10DiscPerMin) * 10.0 * static_cast<double>(scale.internalPerDisc()) / 60000.0;
}

double Constants::mmPerMinToInternalPerMs(double mmPerMin) const {
    return mmPerMin * static_cast<double>(scale.discretesPerMm()) * static_cast<double>(scale.internalPerDisc()) /
           60000.0;
}

double Constants::internalPerMsToMmPerMin(double v) const {
    return v * 60000.0 / static_cast<double>(scale.internalPerDisc()) / static_cast<double>(scale.discretesPerMm());
}

double Constants::accelToInternalPerMs2(std::int64_t accelParam) const {
    // value = 25600·A/Kd, A in m/s² of the axis' displayed quantity:
    // A [disc/s²] = value·1e6/25600 (Kd cancels), then to internal/ms².
    return static_cast<double>(accelParam) * static_cast<double>(scale.internalPerDisc()) / 25600.0;
}

} // namespace k528::axis
