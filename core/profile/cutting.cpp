#include "profile/cutting.h"

#include "catalog/rparams.h"
#include "units/units.h"

#include <cmath>
#include <numbers>
#include <string>

namespace k528::profile::cutting {

namespace {

// `id`: the problem "… must be a positive number" of the quantity.
void positive(double v, const char* id) {
    if (!std::isfinite(v) || v <= 0)
        throw CuttingError(problem(id));
}

} // namespace

double spindleSpeedRpm(double v, double d) {
    positive(v, "cutting.cutting-speed");
    positive(d, "cutting.diameter");
    return 1000.0 * v / (std::numbers::pi * d);
}

double cuttingSpeedMPerMin(double n, double d) {
    positive(n, "cutting.spindle-speed");
    positive(d, "cutting.diameter");
    return std::numbers::pi * d * n / 1000.0;
}

double feedPerMinute(double f, double n) {
    positive(f, "cutting.feed");
    positive(n, "cutting.spindle-speed");
    return f * n;
}

double wheelSurfaceSpeedMPerS(double d, double n) {
    positive(d, "cutting.wheel-diameter");
    positive(n, "cutting.wheel-speed");
    return std::numbers::pi * d * n / 60000.0;
}

double wheelDiameterMm(const MachineProfile& p, std::int64_t r207) {
    // R207 is a diameter in discretes of X whatever X shows (appendix Л).
    return static_cast<double>(r207) * axisScale(p, catalog::Axis::X).discreteMm();
}

std::int64_t presetR207(const MachineProfile& p) {
    const auto it = p.r.find(207);
    if (it == p.r.end())
        throw CuttingError(problem("cutting.no-r207"));
    return it->second;
}

TrialCorrection trialCorrection(const MachineProfile& p, const Tool& tool, catalog::Axis axis, double measuredMm,
                                double drawingMm) {
    if (tool.offsetR < 0)
        throw CuttingError(problem("cutting.no-offset", {std::to_string(tool.station)}));
    if (!std::isfinite(measuredMm) || !std::isfinite(drawingMm))
        throw CuttingError(problem("cutting.not-numbers"));
    TrialCorrection c;
    c.rNumber = axis == catalog::Axis::X ? tool.offsetR : tool.offsetR + 1;
    if (const auto it = p.r.find(c.rNumber); it != p.r.end())
        c.oldValue = it->second;
    c.errorMm = measuredMm - drawingMm;
    const units::AxisScale scale = axisScale(p, axis);
    // X is measured across the part (a diameter); a radius axis moves half of it.
    c.changeMm = -(axis == catalog::Axis::X && !scale.diameter ? c.errorMm / 2 : c.errorMm);
    c.newValue = c.oldValue + units::mmToDisc(c.changeMm, scale);
    if (c.newValue < catalog::kRMin || c.newValue > catalog::kRMax)
        throw CuttingError(problem("cutting.r-range", {std::to_string(c.rNumber)}));
    return c;
}

} // namespace k528::profile::cutting
