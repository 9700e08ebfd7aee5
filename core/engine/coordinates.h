// Coordinate systems of manual 2.4:
//
//   current = absolute − zero offset − dressing sum − correction − handwheel offset
//
// All in display discretes of the axis (on a diameter axis, of the
// diameter). The components live in the R-parameters of appendix Л:
// R224/R225 dressing sum, R226/R227 correction, R228/R229 zero offset,
// R230/R231 handwheel offset (DRF). In a program G50..G53 leave one of them
// out (G54 takes all of them back); outside a program the PLC's out-of-cycle
// bits Z1006.4..7 / Z1009.4..7 do the same.
#pragma once

#include "engine/rparams.h"

#include <cstdint>

namespace k528::engine {

// Components left out of the current coordinate (bit set = left out).
enum Exclusion : std::uint8_t {
    ExcludeNone = 0,
    ExcludeDrf = 1,        // G50 / Z1006.4  «отмена СМА»
    ExcludeCorrection = 2, // G51 / Z1006.5
    ExcludeDressing = 4,   // G52 / Z1006.6
    ExcludeZeroOffset = 8, // G53 / Z1006.7
};

// The exclusion of G-function g of group 6 (G50..G54); G54 -> ExcludeNone.
constexpr std::uint8_t exclusionOfG(int g) {
    switch (g) {
    case 50:
        return ExcludeDrf;
    case 51:
        return ExcludeCorrection;
    case 52:
        return ExcludeDressing;
    case 53:
        return ExcludeZeroOffset;
    default:
        return ExcludeNone;
    }
}

struct Components {
    std::int64_t dressing = 0, correction = 0, zeroOffset = 0, drf = 0;
};

// The components of axis `axis` (0 = X, 1 = Z) from the R store.
inline Components components(const RStore& r, int axis) {
    Components c;
    c.dressing = r[r::DressingSumX + axis];
    c.correction = r[r::CorrectionX + axis];
    c.zeroOffset = r[r::ZeroOffsetX + axis];
    c.drf = r[r::DrfX + axis];
    return c;
}

// The sum of the components not left out by `exclude`.
constexpr std::int64_t activeOffset(const Components& c, std::uint8_t exclude) {
    std::int64_t s = 0;
    if (!(exclude & ExcludeZeroOffset))
        s += c.zeroOffset;
    if (!(exclude & ExcludeDressing))
        s += c.dressing;
    if (!(exclude & ExcludeCorrection))
        s += c.correction;
    if (!(exclude & ExcludeDrf))
        s += c.drf;
    return s;
}

// current = absolute − active components; absolute = current + active components.
inline std::int64_t currentFromMachine(std::int64_t machineDisc, const RStore& r, int axis,
                                       std::uint8_t exclude) {
    return machineDisc - activeOffset(components(r, axis), exclude);
}
inline std::int64_t machineFromCurrent(std::int64_t currentDisc, const RStore& r, int axis,
                                       std::uint8_t exclude) {
    return currentDisc + activeOffset(components(r, axis), exclude);
}

// «Установка фактического значения» and Gx92: the zero offset that makes the
// current coordinate of an axis standing at `machineDisc` read `valueDisc`
// (2.4: the zero offset is recomputed). The other components count as they
// are in effect (`exclude`); the zero offset itself always counts, so under
// G53 the new value shows once the zero offset is taken back.
inline std::int64_t zeroOffsetFor(std::int64_t machineDisc, std::int64_t valueDisc, const RStore& r,
                                  int axis, std::uint8_t exclude) {
    Components c = components(r, axis);
    c.zeroOffset = 0;
    return machineDisc - valueDisc -
           activeOffset(c, static_cast<std::uint8_t>(exclude & ~ExcludeZeroOffset));
}

} // namespace k528::engine
