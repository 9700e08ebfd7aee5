// k528 db calc — the C-constant calculator (profile::calc) from physical
// quantities: constants of one axis, how each was obtained, and the remark on
// formula 1 of parameter 22 (docs/machine-constants.md).
#include "args.h"
#include "catalog/cparams.h"
#include "cli.h"
#include "cli_texts.h"
#include "db/database.h"
#include "db/location.h"
#include "db_cli.h"
#include "profile/calculator.h"
#include "profile/error_text.h"
#include "profile/settings.h"
#include "profile/text_format.h"
#include "util/json.h"
#include "util/utf8.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

namespace k528::cli {

namespace cat = k528::catalog;
namespace cc = k528::catalog::c;
namespace calc = k528::profile::calc;

namespace {

int calcFail(const std::string& message, int code = ExitUsage) {
    std::fprintf(stderr, "k528: %s\n", message.c_str());
    return code;
}

std::string pad(const std::string& s, std::size_t width) {
    const std::size_t len = utf8::length(s);
    return len >= width ? s : s + std::string(width - len, ' ');
}

std::string fmt(double v) {
    return profile::formatDouble(v);
}

std::string fixed(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

// "runup:5000:2000", "braking:5000:10", "value:0.5"
bool parseAccel(const std::string& option, const std::string& text, calc::AccelSpec& a,
                std::string& error) {
    std::vector<std::string> parts;
    std::size_t pos = 0;
    while (true) {
        const auto c = text.find(':', pos);
        parts.push_back(text.substr(pos, c == std::string::npos ? std::string::npos : c - pos));
        if (c == std::string::npos)
            break;
        pos = c + 1;
    }
    std::vector<double> nums;
    for (std::size_t i = 1; i < parts.size(); ++i) {
        const auto v = parseNumber(parts[i]);
        if (!v) {
            error = cliText("calc.accel-number", {option, text, parts[i]});
            return false;
        }
        nums.push_back(*v);
    }
    if (parts[0] == "runup" && nums.size() == 2) {
        a.by = calc::AccelSpec::By::RunUp;
        a.vmaxMmPerMin = nums[0];
        a.runUpMs = nums[1];
    } else if (parts[0] == "braking" && nums.size() == 2) {
        a.by = calc::AccelSpec::By::Braking;
        a.vmaxMmPerMin = nums[0];
        a.brakingMm = nums[1];
    } else if (parts[0] == "value" && nums.size() == 1) {
        a.by = calc::AccelSpec::By::Value;
        a.aMPerS2 = nums[0];
    } else {
        error = cliText("calc.accel-form", {option, text});
        return false;
    }
    return true;
}

// The remark on an acceleration's formula; `param` names it (C022 or C023).
std::string remark(const calc::AccelResult& r, int param, bool asPrinted, bool russian) {
    const cat::CParamDef& def = cat::cParam(param);
    const std::string which(russian ? def.name : def.nameEn);
    std::string s;
    if (r.formula == 1)
        s = cliText("calc.remark.1",
                    {which, std::to_string(r.printedValue), fixed(r.printedMPerS2, 4), fixed(r.describedMPerS2, 4),
                     std::to_string(r.consistentValue)},
                    russian);
    else if (r.formula == 2)
        s = cliText("calc.remark.2", {which, std::to_string(r.printedValue), std::to_string(r.consistentValue)},
                    russian);
    else
        s = cliText("calc.remark.3", {which, std::to_string(r.consistentValue)}, russian);
    if (r.formula != 3)
        s += cliText(asPrinted ? "calc.remark.printed" : "calc.remark.consistent", {}, russian);
    return s;
}

Json accelJson(const calc::AccelResult& r) {
    Json j;
    j["formula"] = r.formula;
    j["printed_value"] = r.printedValue;
    j["consistent_value"] = r.consistentValue;
    j["described_m_per_s2"] = r.describedMPerS2;
    j["printed_m_per_s2"] = r.printedMPerS2;
    j["printed_factor"] = r.printedFactor();
    return j;
}

// The range each number option accepts: the simulation key it becomes when a
// machine keeps it (profile-format.md), so a value given here could be stored;
// speeds up to the fastest drive the registry knows.
struct OptionRange {
    std::string_view option;
    std::string_view key; // "" when `min`..`max` below
    double min = 0, max = 0;
    std::string_view unit;
};
constexpr OptionRange kOptionRanges[] = {
    {"--screw-lead", "x.screw_lead_mm", 0, 0, "unit.mm"},
    {"--gear", "x.gear_ratio", 0, 0, ""},
    {"--encoder-lines", "x.encoder_lines", 0, 0, "unit.lines"},
    {"--drive-volts", "x.drive_max_volts", 0, 0, "unit.volts"},
    {"--drive-speed", "x.drive_max_speed_mm_per_min", 0, 0, "unit.mm-per-min"},
    {"--kv", "x.kv", 0, 0, "unit.kv"},
    {"--feed", "", 0, 200000, "unit.mm-per-min"},
    {"--rapid", "", 0, 200000, "unit.mm-per-min"},
    {"--auto-rapid", "", 0, 200000, "unit.mm-per-min"},
    {"--home-start", "", 0, 200000, "unit.mm-per-min"},
    {"--home-creep", "", 0, 200000, "unit.mm-per-min"},
    {"--dac-max", "", 0, 2047, ""},
    {"--dac-limit-percent", "", 0, 100, "%"},
};

// Reads `text` of `option` into `target`; "" or the message: not a number, or a
// number outside the option's range (naming the range).
std::string calcNumber(std::string_view option, const std::string& text, double& target) {
    const OptionRange* range = nullptr;
    for (const auto& r : kOptionRanges)
        if (r.option == option)
            range = &r;
    double lo = -1e300, hi = 1e300;
    std::string unit;
    if (range) {
        lo = range->min;
        hi = range->max;
        // A unit's id of the catalog (a per cent sign is said as it is).
        unit = range->unit.starts_with("unit.") ? cliText(range->unit) : std::string(range->unit);
        if (const profile::SimulationKey* k =
                range->key.empty() ? nullptr : profile::findSimulationKey(range->key)) {
            lo = k->min;
            hi = k->max;
        }
    }
    const auto bound = [](double x) { // 1000000, not 1e+06
        return x == std::floor(x) && std::fabs(x) < 1e15 ? std::to_string(static_cast<long long>(x))
                                                          : fmt(x);
    };
    const std::string rangeText = bound(lo) + ".." + bound(hi) + (unit.empty() ? "" : " " + unit);
    const char* b = text.data();
    const char* e = text.data() + text.size();
    if (b != e && *b == '+')
        ++b;
    double v = 0;
    // Exponent form ("1e-3") is a number too; "nan" and "inf" are not.
    const auto [ptr, ec] = std::from_chars(b, e, v, std::chars_format::general);
    const bool whole = b != e && ptr == e;
    if (whole && ec == std::errc::result_out_of_range)
        return cliText("calc.out-of-range", {std::string(option), text, rangeText});
    if (!whole || ec != std::errc() || !std::isfinite(v))
        return cliText("calc.not-number", {std::string(option), text});
    if (v < lo || v > hi)
        return cliText("calc.out-of-range", {std::string(option), text, rangeText});
    target = v;
    return {};
}

} // namespace

int runDbCalc(std::span<const std::string> argv) {
    const Args a(argv, {"--diameter", "--as-printed", "--json"},
                 {"--db", "--machine", "--axis", "--discrete", "--screw-lead", "--gear",
                  "--encoder-lines", "--drive-volts", "--drive-speed", "--kv", "--feed", "--rapid",
                  "--auto-rapid", "--home-start", "--home-creep", "--accel", "--accel2",
                  "--dac-max", "--dac-limit-percent", "--lang"});
    // --lang: the language of the messages, as every db subcommand's.
    if (const auto l = a.value("--lang"); l && *l != "ru" && *l != "en")
        return usageError(cliText("opt.lang", {*l}));
    if (!a.ok())
        return usageError(a.error());
    if (!a.positional().empty())
        return usageError(cliText("calc.usage"));

    cat::Axis axis = cat::Axis::X;
    if (const auto v = a.value("--axis")) {
        if (*v == "X" || *v == "x")
            axis = cat::Axis::X;
        else if (*v == "Z" || *v == "z")
            axis = cat::Axis::Z;
        else
            return usageError(cliText("calc.axis", {*v}));
    }
    const auto number = [&](const char* option, double& target) -> bool {
        if (const auto v = a.value(option)) {
            const std::string error = calcNumber(option, *v, target);
            if (!error.empty()) {
                usageError(error);
                return false;
            }
        }
        return true;
    };

    calc::AxisDesign d;
    std::optional<profile::MachineProfile> machine;
    bool haveAccel1 = false;
    if (const auto m = a.value("--machine")) {
        try {
            machine = db::loadProfile(*m, a.value("--db").value_or(""));
            d = calc::designFromSettings(*machine, axis);
            const calc::AxisSummary s = calc::summarizeAxis(*machine, axis);
            d.feedNormalMmPerMin = s.feedNormalMmPerMin;
            d.feedRapidMmPerMin = s.feedRapidMmPerMin;
            d.feedAutoRapidMmPerMin = s.feedAutoRapidMmPerMin;
            d.feedHomeStartMmPerMin = s.feedHomeStartMmPerMin;
            d.feedHomeCreepMmPerMin = s.feedHomeCreepMmPerMin;
            d.accel1 = calc::AccelSpec{};
            d.accel1.aMPerS2 = s.accel1MPerS2;
            haveAccel1 = true;
            if (profile::axisValue(*machine, axis, cc::kAccel2) != 0) {
                calc::AccelSpec a2;
                a2.aMPerS2 = s.accel2MPerS2;
                d.accel2 = a2;
            }
        } catch (const profile::SettingError& e) {
            return calcFail(cliText("calc.machine-data", {*m, profile::errorText(e, russianCommandLine())}));
        } catch (const profile::FileError& e) {
            return calcFail(profile::errorText(e, russianCommandLine()));
        } catch (const db::Error& e) {
            return calcFail(e.text(russianCommandLine() ? db::Lang::Ru : db::Lang::En));
        }
    } else {
        for (const char* required : {"--screw-lead", "--encoder-lines", "--drive-speed", "--accel"})
            if (!a.value(required))
                return usageError(cliText("calc.needs", {required}));
    }
    if (const auto v = a.value("--discrete")) {
        if (*v == "0.01")
            d.scale.discrete = units::Discrete::Mm0_01;
        else if (*v == "0.001")
            d.scale.discrete = units::Discrete::Mm0_001;
        else if (*v == "0.0001")
            d.scale.discrete = units::Discrete::Mm0_0001;
        else
            return usageError(cliText("calc.discrete", {*v}));
    }
    if (a.has("--diameter"))
        d.scale.diameter = true;
    double lines = static_cast<double>(d.encoderLines), dacMax = static_cast<double>(d.dacMax);
    if (!number("--screw-lead", d.screwLeadMm) || !number("--gear", d.gearRatio) ||
        !number("--encoder-lines", lines) || !number("--drive-volts", d.driveMaxVolts) ||
        !number("--drive-speed", d.driveMaxSpeedMmPerMin) || !number("--kv", d.kv) ||
        !number("--feed", d.feedNormalMmPerMin) || !number("--rapid", d.feedRapidMmPerMin) ||
        !number("--auto-rapid", d.feedAutoRapidMmPerMin) ||
        !number("--home-start", d.feedHomeStartMmPerMin) ||
        !number("--home-creep", d.feedHomeCreepMmPerMin) || !number("--dac-max", dacMax) ||
        !number("--dac-limit-percent", d.dacLimitPercent))
        return ExitUsage;
    if (lines != std::floor(lines) || lines < 1 || lines > 1e9)
        return usageError(cliText("calc.encoder"));
    if (dacMax != std::floor(dacMax) || dacMax < 0 || dacMax > 2047)
        return usageError(cliText("calc.dac"));
    d.encoderLines = static_cast<std::int64_t>(lines);
    d.dacMax = static_cast<std::int64_t>(dacMax);
    std::string error;
    const bool asPrinted = a.has("--as-printed");
    if (const auto v = a.value("--accel")) {
        if (!parseAccel("--accel", *v, d.accel1, error))
            return usageError(error);
        haveAccel1 = true;
    }
    if (const auto v = a.value("--accel2")) {
        calc::AccelSpec a2;
        if (!parseAccel("--accel2", *v, a2, error))
            return usageError(error);
        d.accel2 = a2;
    }
    (void)haveAccel1;
    d.accel1.asPrinted = asPrinted;
    if (d.accel2)
        d.accel2->asPrinted = asPrinted;

    calc::AxisConstants r;
    try {
        r = calc::designAxis(d);
    } catch (const calc::CalcError& e) {
        return calcFail("calc: " + profile::errorText(e, russianCommandLine()), ExitInputErrors);
    }

    // The report is read by a technologist: in --lang; --json keeps English
    // (the same in both languages, as every --json).
    const bool russian = russianCommandLine() && !a.has("--json");
    std::vector<std::string> remarks;
    remarks.push_back(remark(r.accel1, cc::kAccel1, asPrinted, russian));
    if (r.accel2)
        remarks.push_back(remark(*r.accel2, cc::kAccel2, asPrinted, russian));
    // The remark on formula 1 is printed always: it is what a technologist
    // checking appendix Ж's figures needs to know.
    remarks.push_back(cliText("calc.remark.formula1", {}, russian));

    if (a.has("--json")) {
        Json root;
        root["axis"] = cat::axisName(axis);
        if (machine)
            root["machine"] = machine->name;
        Json cs = Json::array();
        for (const auto& [x, v] : r.values) {
            const int n = cat::axisParam(x, axis);
            Json j;
            j["number"] = n;
            j["key"] = cat::cParam(n).key();
            j["name"] = cat::cParam(n).name;
            j["value"] = v;
            if (machine)
                j["current"] = machine->cValue(n);
            cs.push_back(std::move(j));
        }
        root["constants"] = std::move(cs);
        Json ratio;
        ratio["l"] = r.ratio.l;
        ratio["n"] = r.ratio.n;
        ratio["exact"] = r.ratio.exact;
        ratio["error_ppm"] = r.ratio.errorPpm;
        root["encoder_ratio"] = std::move(ratio);
        root["accel1"] = accelJson(r.accel1);
        if (r.accel2)
            root["accel2"] = accelJson(*r.accel2);
        Json steps = Json::array();
        for (const auto& s : r.steps)
            steps.push_back(calc::stepText(s, axis, false));
        root["steps"] = std::move(steps);
        Json rem = Json::array();
        for (const auto& s : remarks)
            rem.push_back(s);
        root["remarks"] = std::move(rem);
        std::string text = json::dump(root) + "\n";
        std::fwrite(text.data(), 1, text.size(), stdout);
        return ExitOk;
    }

    std::string s = cliText("calc.head", {std::string(cat::axisName(axis)), fmt(d.scale.discreteMm())}) +
                    (d.scale.diameter ? cliText("calc.head.diameter") : "") +
                    (machine ? cliText("calc.head.machine", {machine->name}) : "") + "\n\n";
    for (const auto& [x, v] : r.values) {
        const int n = cat::axisParam(x, axis);
        const auto& def = cat::cParam(n);
        s += def.key() + "  " + pad(std::string(def.name), 20) + " " + pad(std::to_string(v), 8);
        if (machine) {
            const auto cur = machine->cValue(n);
            s += cur == v ? cliText("calc.as-now") : cliText("calc.now", {std::to_string(cur)});
        }
        s += "\n";
    }
    s += "\n" + cliText("calc.how") + "\n";
    for (const auto& step : r.steps)
        s += "  " + calc::stepText(step, axis, russian) + "\n";
    s += "\n";
    for (const auto& rm : remarks)
        s += rm + "\n";
    std::fwrite(s.data(), 1, s.size(), stdout);
    return ExitOk;
}

} // namespace k528::cli
