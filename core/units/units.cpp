#include "units/units.h"

#include <cinttypes>
#include <cstdio>

namespace k528::units {

std::string formatDisc(std::int64_t disc, const AxisScale& s) {
    const auto per = static_cast<std::uint64_t>(s.discretesPerMm());
    const std::uint64_t mag = disc < 0 ? 0 - static_cast<std::uint64_t>(disc) : static_cast<std::uint64_t>(disc);
    char buf[48];
    std::snprintf(buf, sizeof buf, "%s%" PRIu64 ".%0*" PRIu64, disc < 0 ? "-" : "", mag / per, s.decimals(),
                  mag % per);
    return buf;
}

std::string formatTrimmed(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    std::string s = buf;
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0')
            s.pop_back();
        if (s.back() == '.')
            s.pop_back();
    }
    if (s == "-0")
        s = "0";
    return s;
}

} // namespace k528::units
