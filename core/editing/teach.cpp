#include "editing/teach.h"

#include "catalog/rparams.h"
#include "units/units.h"

#include <cmath>
#include <cstdio>

namespace k528::editing {

namespace {

std::string mm(double v) {
    return units::formatTrimmed(std::round(v * 1000) / 1000, 3);
}

bool contains(std::string_view s, std::string_view part) { return s.find(part) != std::string_view::npos; }

} // namespace

std::string teachFrame(int n, std::optional<double> xMm, std::optional<double> zMm) {
    if (!xMm && !zMm)
        return {};
    std::string f;
    if (n > 0) {
        f += 'N';
        f += std::to_string(n);
    }
    const auto word = [&f](char address, double v) {
        if (!f.empty())
            f += ' ';
        f += address;
        f += mm(v);
    };
    if (xMm)
        word('X', *xMm);
    if (zMm)
        word('Z', *zMm);
    return f;
}

std::vector<TeachTarget> teachTargets() {
    std::vector<TeachTarget> out;
    for (int n = 0; n < catalog::kRParamCount; ++n) {
        const catalog::RParamDef* d = catalog::findRParam(n);
        if (!d || d->readOnly() || d->user())
            continue;
        const bool x = contains(d->panelHint, "координата X") && d->unit == catalog::RUnit::DiscX;
        const bool z = contains(d->panelHint, "координата Z") && d->unit == catalog::RUnit::DiscZ;
        if (!x && !z)
            continue;
        out.push_back({n, x ? catalog::Axis::X : catalog::Axis::Z, contains(d->meaningRu, "в системе станка"),
                       d->panelHint, d->meaningRu, d->meaningEn});
    }
    return out;
}

std::string teachRFrame(int n, int r, std::int64_t disc) {
    std::string f;
    if (n > 0) {
        f += 'N';
        f += std::to_string(n);
        f += ' ';
    }
    f += 'R';
    f += std::to_string(r);
    f += '=';
    f += std::to_string(disc);
    return f;
}

int nextFrameNumber(int previous) { return previous > 0 ? previous + 1 : 0; }

} // namespace k528::editing
