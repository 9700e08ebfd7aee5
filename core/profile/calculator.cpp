#include "profile/calculator.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace k528::profile::calc {

namespace cat = k528::catalog;
namespace cc = k528::catalog::c;

namespace {

// Integer part, as appendix Ж writes results; float noise below 1e-9 of the
// value does not turn 4445 into 4444.
std::int64_t integerPart(double v) {
    const double eps = 1e-9 * std::max(1.0, std::fabs(v));
    return static_cast<std::int64_t>(v < 0 ? std::ceil(v - eps) : std::floor(v + eps));
}

void positive(double v, const char* id) {
    if (!(v > 0) || !std::isfinite(v))
        throw CalcError(problem(id));
}

// m/s² of a parameter value in K528 Studio's unit.
double unitMPerS2(double value, const units::AxisScale& s) {
    return value * s.kd() / 25600.0;
}

AccelResult finish(AccelResult r, const units::AxisScale& s) {
    r.printedValue = integerPart(r.printedRaw);
    r.consistentRaw = 25600.0 * r.describedMPerS2 / s.kd();
    r.consistentValue = integerPart(r.consistentRaw);
    r.printedMPerS2 = unitMPerS2(static_cast<double>(r.printedValue), s);
    return r;
}

// Motion discretes per minute -> m/s.
double discPerMinToMPerS(double v, const units::AxisScale& s) {
    return v * s.discreteMm() / 1000.0 / 60.0;
}

// Best fraction p/q of x with p, q <= limit (Stern–Brocot / continued fractions).
std::pair<std::int64_t, std::int64_t> bestFraction(double x, std::int64_t limit) {
    std::int64_t p0 = 0, q0 = 1, p1 = 1, q1 = 0;
    double f = x;
    std::pair<std::int64_t, std::int64_t> best{1, 1};
    double bestErr = std::fabs(1.0 - x);
    for (int iter = 0; iter < 64; ++iter) {
        const auto a = static_cast<std::int64_t>(std::floor(f));
        const std::int64_t p2 = a * p1 + p0, q2 = a * q1 + q0;
        if (p2 > limit || q2 > limit) {
            // Semiconvergents between the last convergent and the next one.
            for (std::int64_t k = a - 1; k >= 1; --k) {
                const std::int64_t p = k * p1 + p0, q = k * q1 + q0;
                if (p <= limit && q <= limit && p > 0) {
                    const double err =
                        std::fabs(static_cast<double>(p) / static_cast<double>(q) - x);
                    if (err < bestErr) {
                        best = {p, q};
                        bestErr = err;
                    }
                    break;
                }
            }
            break;
        }
        if (p2 > 0) {
            const double err = std::fabs(static_cast<double>(p2) / static_cast<double>(q2) - x);
            if (err < bestErr) {
                best = {p2, q2};
                bestErr = err;
            }
        }
        p0 = p1;
        q0 = q1;
        p1 = p2;
        q1 = q2;
        const double frac = f - static_cast<double>(a);
        if (frac < 1e-12)
            break;
        f = 1.0 / frac;
    }
    return best;
}

// x as p/q with q <= 100000 exactly (within 1e-9), or nullopt.
std::optional<std::pair<std::int64_t, std::int64_t>> exactFraction(double x) {
    for (std::int64_t q = 1; q <= 100000; ++q) {
        const double p = x * static_cast<double>(q);
        const double r = std::round(p);
        if (std::fabs(p - r) < 1e-9 * std::max(1.0, p))
            return std::pair{static_cast<std::int64_t>(r), q};
    }
    return std::nullopt;
}

std::string fmt(double v) {
    std::ostringstream o;
    o.precision(6);
    o << v;
    return o.str();
}

} // namespace

AccelResult accelByRunUp(double vmaxDiscPerMin, double runUpMs, const units::AxisScale& s) {
    positive(vmaxDiscPerMin, "calc.vmax");
    positive(runUpMs, "calc.run-up");
    AccelResult r;
    r.formula = 1;
    r.printedRaw = kFormula1Printed * vmaxDiscPerMin / runUpMs;
    r.describedMPerS2 = discPerMinToMPerS(vmaxDiscPerMin, s) / (runUpMs / 1000.0);
    return finish(r, s);
}

AccelResult accelByBraking(double vmaxDiscPerMin, double brakingDisc, const units::AxisScale& s) {
    positive(vmaxDiscPerMin, "calc.vmax");
    positive(brakingDisc, "calc.braking");
    AccelResult r;
    r.formula = 2;
    r.printedRaw = kFormula2Printed * vmaxDiscPerMin * vmaxDiscPerMin / brakingDisc;
    const double v = discPerMinToMPerS(vmaxDiscPerMin, s);
    const double dist = brakingDisc * s.discreteMm() / 1000.0;
    r.describedMPerS2 = v * v / (2.0 * dist);
    return finish(r, s);
}

AccelResult accelByValue(double aMPerS2, const units::AxisScale& s) {
    positive(aMPerS2, "calc.acceleration");
    AccelResult r;
    r.formula = 3;
    r.printedRaw = 25600.0 * aMPerS2 / s.kd();
    r.describedMPerS2 = aMPerS2;
    return finish(r, s);
}

std::int64_t speedGain(double umaxVolts, double vmaxMPerMin, const units::AxisScale& s) {
    positive(umaxVolts, "calc.umax");
    positive(vmaxMPerMin, "calc.vmax");
    return integerPart(kKsCoefficient * s.kd() * umaxVolts / vmaxMPerMin);
}

std::int64_t errorGain(double kv, double umaxVolts, double vmaxMPerMin, const units::AxisScale& s) {
    positive(kv, "calc.kv");
    positive(umaxVolts, "calc.umax");
    positive(vmaxMPerMin, "calc.vmax");
    return integerPart(kKeCoefficient * s.kd() * kv * umaxVolts / vmaxMPerMin);
}

EncoderRatio encoderRatio(double screwLeadMm, double gearRatio, std::int64_t encoderLines,
                          const units::AxisScale& s) {
    positive(screwLeadMm, "calc.screw-lead");
    positive(gearRatio, "calc.gear-ratio");
    if (encoderLines < 1)
        throw CalcError(problem("calc.encoder-lines"));
    // Discretes of motion per screw revolution: a whole number.
    const double perRev = screwLeadMm * static_cast<double>(s.discretesPerMm());
    const double perRevRounded = std::round(perRev);
    if (std::fabs(perRev - perRevRounded) > 1e-6)
        throw CalcError(problem("calc.lead-discretes", {fmt(screwLeadMm), fmt(s.discreteMm())}));
    const auto g = exactFraction(gearRatio);
    if (!g)
        throw CalcError(problem("calc.gear-fraction", {fmt(gearRatio)}));
    // L/N = discPerScrewRev / (4·lines·g), g = gp/gq.
    std::int64_t l = static_cast<std::int64_t>(perRevRounded) * g->second;
    std::int64_t n = 4 * encoderLines * g->first;
    const std::int64_t d = std::gcd(l, n);
    l /= d;
    n /= d;
    EncoderRatio r;
    r.discPerPulse = static_cast<double>(l) / static_cast<double>(n);
    if (l <= 32767 && n <= 32767) {
        r.l = l;
        r.n = n;
        return r;
    }
    const auto [bl, bn] = bestFraction(r.discPerPulse, 32767);
    r.l = bl;
    r.n = bn;
    r.exact = false;
    r.errorPpm =
        (static_cast<double>(bl) / static_cast<double>(bn) - r.discPerPulse) / r.discPerPulse * 1e6;
    return r;
}

std::int64_t speedParam(double mmPerMin, const units::AxisScale& s) {
    if (!(mmPerMin >= 0) || !std::isfinite(mmPerMin))
        throw CalcError(problem("calc.speed"));
    return units::mmPerMinToSpeedParam(mmPerMin, s);
}

std::int64_t dacLimit(std::int64_t dacMax, double percent) {
    return units::roundHalfAway(static_cast<double>(dacMax) * (1.0 + percent / 100.0));
}

namespace {

AccelResult accel(const AccelSpec& a, const units::AxisScale& s) {
    switch (a.by) {
    case AccelSpec::By::RunUp:
        return accelByRunUp(a.vmaxMmPerMin * static_cast<double>(s.discretesPerMm()), a.runUpMs, s);
    case AccelSpec::By::Braking:
        return accelByBraking(a.vmaxMmPerMin * static_cast<double>(s.discretesPerMm()),
                              a.brakingMm * static_cast<double>(s.discretesPerMm()), s);
    case AccelSpec::By::Value:
        return accelByValue(a.aMPerS2, s);
    }
    return {};
}

// An acceleration's step: how it was given, A, the formula as printed and
// the consistent value, and the value entered.
Step accelStep(int param, const AccelSpec& a, const AccelResult& r, std::int64_t entered) {
    Step s;
    s.param = param;
    switch (a.by) {
    case AccelSpec::By::RunUp:
        s.id = "accel.run-up";
        s.args = {fmt(a.vmaxMmPerMin), fmt(a.runUpMs)};
        break;
    case AccelSpec::By::Braking:
        s.id = "accel.braking";
        s.args = {fmt(a.vmaxMmPerMin), fmt(a.brakingMm)};
        break;
    case AccelSpec::By::Value:
        s.id = "accel.value";
        s.args = {fmt(a.aMPerS2)};
        break;
    }
    for (std::string v : {fmt(r.describedMPerS2), std::to_string(r.formula), fmt(r.printedRaw),
                          fmt(r.consistentRaw), std::to_string(entered)})
        s.args.push_back(std::move(v));
    return s;
}

// The steps as the technologist reads them (`k528 db calc`); %1 is the
// constant's panel name, the rest the step's arguments.
constexpr util::CatalogText kStepTexts[] = {
    {"ratio", "L/N: %2 мм на оборот винта = %3 дискрет; %4 об. двигателя x %5 штрихов x 4 = %6 импульсов -> %7/%8",
     "L/N: %2 mm per screw rev = %3 discretes; %4 motor rev x %5 lines x 4 = %6 pulses -> %7/%8"},
    {"ratio.nearest",
     "L/N: %2 мм на оборот винта = %3 дискрет; %4 об. двигателя x %5 штрихов x 4 = %6 импульсов -> %7/%8 "
     "(ближайшее, %9 ppm)",
     "L/N: %2 mm per screw rev = %3 discretes; %4 motor rev x %5 lines x 4 = %6 pulses -> %7/%8 (nearest, %9 ppm)"},
    {"accel.run-up", "%1: разгон 0 -> %2 мм/мин за %3 мс: A = %4 м/с², формула %5 по напечатанному %6, 25600·A/Kd = %7 -> %8",
     "%1: run-up 0 -> %2 mm/min in %3 ms: A = %4 m/s², formula %5 as printed %6, 25600·A/Kd = %7 -> %8"},
    {"accel.braking",
     "%1: торможение %2 мм/мин -> 0 на %3 мм: A = %4 м/с², формула %5 по напечатанному %6, 25600·A/Kd = %7 -> %8",
     "%1: braking %2 mm/min -> 0 in %3 mm: A = %4 m/s², formula %5 as printed %6, 25600·A/Kd = %7 -> %8"},
    {"accel.value", "%1: A = %2 м/с²: A = %3 м/с², формула %4 по напечатанному %5, 25600·A/Kd = %6 -> %7",
     "%1: A = %2 m/s²: A = %3 m/s², formula %4 as printed %5, 25600·A/Kd = %6 -> %7"},
    {"speed-gain", "%1 = 262 x Kd %2 x %3 В / %4 м/мин = %5", "%1 = 262 x Kd %2 x %3 V / %4 m/min = %5"},
    {"error-gain", "%1 = 26.2 x Kd %2 x Kv %3 x %4 В / %5 м/мин = %6",
     "%1 = 26.2 x Kd %2 x Kv %3 x %4 V / %5 m/min = %6"},
    {"dac-limit", "%1 = %2 x (1 + %3 %) = %4", "%1 = %2 x (1 + %3 %) = %4"},
    {"feed", "%1: %2 мм/мин = %3 x 10 дискрет/мин", "%1: %2 mm/min = %3 x 10 discretes/min"},
};

} // namespace

AxisConstants designAxis(const AxisDesign& d) {
    AxisConstants out;
    const units::AxisScale& s = d.scale;
    out.values[cc::kDiscrete0001] = s.discrete == units::Discrete::Mm0_0001;
    out.values[cc::kDiscrete001] = s.discrete == units::Discrete::Mm0_001;
    out.values[cc::kDiscrete01] = s.discrete == units::Discrete::Mm0_01;
    out.values[cc::kDiameter] = s.diameter;

    out.ratio = encoderRatio(d.screwLeadMm, d.gearRatio, d.encoderLines, s);
    out.values[cc::kEncoderL] = out.ratio.l;
    out.values[cc::kEncoderN] = out.ratio.n;
    Step ratio{out.ratio.exact ? "ratio" : "ratio.nearest", 0,
               {fmt(d.screwLeadMm), fmt(d.screwLeadMm * static_cast<double>(s.discretesPerMm())),
                fmt(d.gearRatio), std::to_string(d.encoderLines),
                fmt(d.gearRatio * 4.0 * static_cast<double>(d.encoderLines)), std::to_string(out.ratio.l),
                std::to_string(out.ratio.n)}};
    if (!out.ratio.exact)
        ratio.args.push_back(fmt(out.ratio.errorPpm));
    out.steps.push_back(std::move(ratio));

    out.accel1 = accel(d.accel1, s);
    out.values[cc::kAccel1] =
        d.accel1.asPrinted ? out.accel1.printedValue : out.accel1.consistentValue;
    out.steps.push_back(accelStep(cc::kAccel1, d.accel1, out.accel1, out.values[cc::kAccel1]));
    if (d.accel2) {
        out.accel2 = accel(*d.accel2, s);
        out.values[cc::kAccel2] =
            d.accel2->asPrinted ? out.accel2->printedValue : out.accel2->consistentValue;
        out.steps.push_back(accelStep(cc::kAccel2, *d.accel2, *out.accel2, out.values[cc::kAccel2]));
    } else {
        out.values[cc::kAccel2] = 0;
    }

    const double vmaxMPerMin = d.driveMaxSpeedMmPerMin / 1000.0;
    out.values[cc::kKs] = speedGain(d.driveMaxVolts, vmaxMPerMin, s);
    out.values[cc::kKe] = errorGain(d.kv, d.driveMaxVolts, vmaxMPerMin, s);
    out.steps.push_back({"speed-gain", cc::kKs,
                         {fmt(s.kd()), fmt(d.driveMaxVolts), fmt(vmaxMPerMin), std::to_string(out.values[cc::kKs])}});
    out.steps.push_back({"error-gain", cc::kKe,
                         {fmt(s.kd()), fmt(d.kv), fmt(d.driveMaxVolts), fmt(vmaxMPerMin),
                          std::to_string(out.values[cc::kKe])}});

    out.values[cc::kDacMax] = d.dacMax;
    out.values[cc::kDacLimit] = dacLimit(d.dacMax, d.dacLimitPercent);
    out.steps.push_back({"dac-limit", cc::kDacLimit,
                         {std::to_string(d.dacMax), fmt(d.dacLimitPercent), std::to_string(out.values[cc::kDacLimit])}});

    const std::pair<int, double> feeds[] = {{cc::kFeedNormal, d.feedNormalMmPerMin},
                                            {cc::kFeedRapid, d.feedRapidMmPerMin},
                                            {cc::kFeedAutoRapid, d.feedAutoRapidMmPerMin},
                                            {cc::kFeedHomeStart, d.feedHomeStartMmPerMin},
                                            {cc::kFeedHomeCreep, d.feedHomeCreepMmPerMin}};
    for (const auto& [n, mm] : feeds) {
        out.values[n] = speedParam(mm, s);
        out.steps.push_back({"feed", n, {fmt(mm), std::to_string(out.values[n])}});
    }
    // The drive reaches driveMaxSpeed at driveMaxVolts; МАКС.ЦАП caps the
    // command at dacMax/2047 of 10 V.
    const double topFeed =
        std::max({d.feedNormalMmPerMin, d.feedRapidMmPerMin, d.feedAutoRapidMmPerMin});
    const double reachable =
        d.driveMaxSpeedMmPerMin * (10.0 * static_cast<double>(d.dacMax) / 2047.0) / d.driveMaxVolts;
    if (topFeed > reachable * (1.0 + 1e-9))
        throw CalcError(problem("calc.feed-reach", {fmt(topFeed), fmt(reachable)}));

    for (const auto& [n, v] : out.values)
        if (!cat::cParam(n).inRange(v))
            throw CalcError(cValueProblem(n, v));
    return out;
}

util::TextCatalog stepTexts() { return util::TextCatalog(kStepTexts); }

std::string stepText(const Step& s, cat::Axis axis, bool russian) {
    std::vector<std::string> args;
    if (s.param > 0) {
        const cat::CParamDef& def = cat::cParam(cat::axisParam(s.param, axis));
        args.emplace_back(russian ? def.name : def.nameEn);
    } else {
        args.emplace_back();
    }
    args.insert(args.end(), s.args.begin(), s.args.end());
    return stepTexts().render(s.id, args, russian);
}

AxisDesign designFromSettings(const MachineProfile& p, cat::Axis axis) {
    const std::string pre = axis == cat::Axis::X ? "x." : "z.";
    const Settings& st = p.simulation;
    AxisDesign d;
    d.scale = axisScale(p, axis);
    d.screwLeadMm = st.requireDouble(pre + "screw_lead_mm");
    d.gearRatio = st.getDouble(pre + "gear_ratio", 1.0);
    d.encoderLines = st.requireInt(pre + "encoder_lines");
    d.driveMaxVolts = st.requireDouble(pre + "drive_max_volts");
    d.driveMaxSpeedMmPerMin = st.requireDouble(pre + "drive_max_speed_mm_per_min");
    d.kv = st.requireDouble(pre + "kv");
    d.dacMax = axisValue(p, axis, cc::kDacMax);
    return d;
}

AxisSummary summarizeAxis(const MachineProfile& p, cat::Axis axis) {
    AxisSummary s;
    s.scale = axisScale(p, axis);
    const auto V = [&](int x) { return axisValue(p, axis, x); };
    const auto mmMin = [&](int x) { return units::speedParamToMmPerMin(V(x), s.scale); };
    s.feedNormalMmPerMin = mmMin(cc::kFeedNormal);
    s.feedRapidMmPerMin = mmMin(cc::kFeedRapid);
    s.feedAutoRapidMmPerMin = mmMin(cc::kFeedAutoRapid);
    s.feedHomeStartMmPerMin = mmMin(cc::kFeedHomeStart);
    s.feedHomeCreepMmPerMin = mmMin(cc::kFeedHomeCreep);
    s.accel1MPerS2 = units::accelParamToMPerS2(V(cc::kAccel1), s.scale);
    s.accel2MPerS2 =
        units::accelParamToMPerS2(V(cc::kAccel2) != 0 ? V(cc::kAccel2) : V(cc::kAccel1), s.scale);
    const double vAuto = s.feedAutoRapidMmPerMin / 60000.0; // m/s
    const double vRapid = s.feedRapidMmPerMin / 60000.0;
    if (s.accel1MPerS2 > 0) {
        s.runUpToAutoRapidMs = vAuto / s.accel1MPerS2 * 1000.0;
        s.brakingFromAutoRapidMm = vAuto * vAuto / (2.0 * s.accel1MPerS2) * 1000.0;
    }
    if (s.accel2MPerS2 > 0)
        s.emergencyBrakingFromRapidMm = vRapid * vRapid / (2.0 * s.accel2MPerS2) * 1000.0;
    if (V(cc::kEncoderN) != 0)
        s.motionMmPerPulse = static_cast<double>(V(cc::kEncoderL)) /
                             static_cast<double>(V(cc::kEncoderN)) * s.scale.discreteMm();
    s.limitMinusMm = units::discToMm(V(cc::kLimitMinus), s.scale);
    s.limitPlusMm = units::discToMm(V(cc::kLimitPlus), s.scale);
    s.homeValueMm = units::discToMm(V(cc::kHomeValue), s.scale);
    return s;
}

} // namespace k528::profile::calc
