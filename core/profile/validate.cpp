#include "profile/validate.h"
#include "profile/english.h"

#include "profile/problem.h"

#include "catalog/rparams.h"
#include "util/utf8.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace k528::profile {

namespace cat = k528::catalog;
namespace cc = k528::catalog::c;

namespace {

std::string num(std::int64_t v) {
    return std::to_string(v);
}

std::string cKey(int n) {
    return cat::cParam(n).key();
}

std::string keys(std::vector<int> ns) {
    std::sort(ns.begin(), ns.end());
    std::string s;
    for (int n : ns) {
        if (!s.empty())
            s += ",";
        s += cKey(n);
    }
    return s;
}

// «N ДОС» (C017)
std::string named(int n) {
    return "«" + std::string(cat::cParam(n).name) + "» (" + cKey(n) + ")";
}

std::string range(const cat::CParamDef& d) {
    return num(d.min) + "..." + num(d.max);
}

// Text checks shared by messages, PLC texts and titles: none or the problem.
Problem lineTextProblem(std::string_view text, std::size_t maxChars, bool allowLeadingBlank) {
    if (text.empty())
        return problem("text.empty");
    if (!utf8::isValid(text))
        return problem("text.utf8");
    for (char ch : text)
        if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f)
            return problem("text.control");
    const std::size_t len = utf8::length(text);
    if (len > maxChars)
        return problem("text.long", {std::to_string(len), std::to_string(maxChars)});
    if (text.back() == ' ')
        return problem("text.trailing-blank");
    if (!allowLeadingBlank && text.front() == ' ')
        return problem("text.leading-blank");
    return {};
}

// `outer` naming the part whose problem is `inner` (none when it has none).
Problem within(Problem outer, Problem inner) {
    if (inner.empty())
        return {};
    outer.within.push_back(std::move(inner));
    return outer;
}

// The findings, each said by core's catalog of problems (its "check.*" ids).
struct Collector {
    std::vector<Finding> out;
    void add(Severity s, std::vector<int> cs, std::optional<int> msg, std::string subject, Problem p) {
        std::sort(cs.begin(), cs.end());
        std::string ru = problemText(p, true), en = problemText(p, false);
        out.push_back(Finding{s, std::move(cs), msg, std::move(subject), std::move(p), std::move(ru), std::move(en)});
    }
    void addC(Severity s, std::vector<int> cs, std::optional<int> msg, std::string id,
              std::vector<std::string> args = {}) {
        std::string subject = keys(cs);
        add(s, std::move(cs), msg, std::move(subject), problem(std::move(id), std::move(args)));
    }
};

// The manual message that reports a bad value of parameter n (15 unless a
// dedicated one exists).
int rangeMessage(int n) {
    switch (n) {
    case cc::kEncoderL:
    case cc::kEncoderN:
        return 13;
    case cc::kEncoderL + cat::kAxisBlock:
    case cc::kEncoderN + cat::kAxisBlock:
        return 29;
    case cc::kEncoderChannel:
    case cc::kEncoderChannel + cat::kAxisBlock:
        return 37;
    case cc::kDacChannel:
    case cc::kDacChannel + cat::kAxisBlock:
        return 38;
    case cc::kWheel1Channel:
    case cc::kWheel2Channel:
        return 39;
    default:
        return 15;
    }
}

void checkAxis(Collector& col, std::span<const std::int64_t> c, cat::Axis axis) {
    const auto P = [&](int x) { return cat::axisParam(x, axis); };
    const auto V = [&](int x) { return c[static_cast<std::size_t>(P(x))]; };
    const std::string ax(cat::axisName(axis));

    // One display discrete (message 15: the manual has no message of its own).
    const int flags = static_cast<int>((V(cc::kDiscrete0001) == 1) + (V(cc::kDiscrete001) == 1) +
                                       (V(cc::kDiscrete01) == 1));
    if (flags != 1)
        col.addC(Severity::Error, {P(4), P(5), P(6)}, 15, "check.axis-discrete",
                 {ax, keys({P(4), P(5), P(6)}), std::to_string(flags)});

    // L/N: the range check reports 0 or > 32767 with 13/29; a ratio above 1
    // means one encoder pulse is more than one discrete.
    const std::int64_t L = V(cc::kEncoderL), N = V(cc::kEncoderN);
    if (L >= 1 && N >= 1 && L <= 32767 && N <= 32767 && L > N)
        col.addC(Severity::Warning, {P(19), P(20)}, std::nullopt, "check.axis-ratio", {ax, num(L), num(N)});

    // ПРЕДЕЛ ЦАП against МАКС.ЦАП: 15-20 % above (table Е.1, parameter 28).
    const std::int64_t limit = V(cc::kDacLimit), dmax = V(cc::kDacMax);
    const int alarm = axis == cat::Axis::X ? 6 : 22;
    if (dmax == 0) {
        col.addC(Severity::Warning, {P(29)}, std::nullopt, "check.dac-max-zero", {ax});
    } else if (limit < dmax) {
        col.addC(Severity::Error, {P(28), P(29)}, alarm, "check.dac-limit-below",
                 {ax, num(limit), num(dmax), std::to_string(alarm)});
    } else {
        const auto lo = units::roundHalfAway(1.15 * static_cast<double>(dmax));
        const auto hi = units::roundHalfAway(1.20 * static_cast<double>(dmax));
        if (limit < lo || limit > hi)
            col.addC(Severity::Warning, {P(28), P(29)}, std::nullopt, "check.dac-limit-margin",
                     {ax, num(limit), num(dmax), num(lo), num(hi)});
    }

    // Motion constants a working axis needs.
    if (V(cc::kAccel1) == 0)
        col.addC(Severity::Warning, {P(22)}, std::nullopt, "check.accel-zero", {ax});
    for (int x : {cc::kFeedNormal, cc::kFeedAutoRapid})
        if (V(x) == 0)
            col.addC(Severity::Warning, {P(x)}, std::nullopt, "check.feed-zero",
                     {ax, std::string(cat::cParam(P(x)).name), std::string(cat::cParam(P(x)).nameEn)});
    if (V(cc::kAutoWithoutHoming) == 0) {
        if (V(cc::kFeedHomeStart) == 0 || V(cc::kFeedHomeCreep) == 0)
            col.addC(Severity::Warning, {P(43), P(44)}, std::nullopt, "check.homing-speed-zero", {ax});
        else if (V(cc::kFeedHomeCreep) > V(cc::kFeedHomeStart))
            col.addC(Severity::Warning, {P(43), P(44)}, std::nullopt, "check.homing-creep", {ax});
    }

    // Software limits.
    if (V(cc::kSoftLimitsOn) == 1) {
        const std::int64_t lo = V(cc::kLimitMinus), hi = V(cc::kLimitPlus),
                           home = V(cc::kHomeValue);
        if (lo >= hi)
            col.addC(Severity::Error, {P(46), P(47)}, std::nullopt, "check.limits-order", {ax, num(lo), num(hi)});
        else if (home < lo || home > hi)
            col.addC(Severity::Warning, {P(45), P(46), P(47)}, std::nullopt, "check.home-outside",
                     {ax, num(home), num(lo), num(hi)});
    }

    // Fast inputs of the axis' module: one function per input.
    const int first = axis == cat::Axis::X ? cc::kFastInputX1 : cc::kFastInputZ1;
    for (int i = 0; i < 8; ++i) {
        const auto fi = c[static_cast<std::size_t>(first + i)];
        if (fi == 0)
            continue;
        for (int j = i + 1; j < 8; ++j)
            if (c[static_cast<std::size_t>(first + j)] == fi)
                col.addC(Severity::Warning, {first + i, first + j}, std::nullopt, "check.fast-input-twice",
                         {ax, num(fi)});
    }
}

} // namespace

std::vector<Finding> checkCParams(std::span<const std::int64_t> c,
                                  const std::map<int, std::string>* programs) {
    Collector col;
    if (c.size() < static_cast<std::size_t>(cat::kCParamCount + 1)) {
        col.add(Severity::Error, {}, 15, "C", problem("check.incomplete"));
        return col.out;
    }
    const auto V = [&](int n) { return c[static_cast<std::size_t>(n)]; };

    // Every value against its definition.
    for (const cat::CParamDef& d : cat::cParams()) {
        const std::int64_t v = V(d.number);
        if (d.inRange(v))
            continue;
        col.addC(Severity::Error, {d.number}, rangeMessage(d.number), "check.range",
                 {d.key(), std::string(d.name), num(v), range(d), std::string(d.nameEn)});
    }

    const bool px = V(cc::kAxisPresent) == 1;
    const bool pz = V(cat::axisParam(cc::kAxisPresent, cat::Axis::Z)) == 1;
    if (px)
        checkAxis(col, c, cat::Axis::X);
    if (pz)
        checkAxis(col, c, cat::Axis::Z);
    if (!px && !pz)
        col.addC(Severity::Warning, {1, 53}, std::nullopt, "check.no-axis");

    // Channels of the two СР34.23 modules: encoders of present axes each need
    // their own channel (37); DACs of present axes their own DAC channel
    // (38); the handwheels two channels of their own (39: a handwheel on an
    // encoder's channel is the handwheel's number set wrong, «Неверно задан
    // номер маховика» — the encoders are wired to their axes).
    const int encX = cc::kEncoderChannel, encZ = cat::axisParam(cc::kEncoderChannel, cat::Axis::Z);
    const int dacX = cc::kDacChannel, dacZ = cat::axisParam(cc::kDacChannel, cat::Axis::Z);
    const auto valid14 = [&](int n) { return V(n) >= 1 && V(n) <= 4; };
    if (px && pz && valid14(encX) && V(encX) == V(encZ))
        col.addC(Severity::Error, {encX, encZ}, 37, "check.encoders-channel",
                 {num(V(encX)), named(encX), named(encZ), keys({encX, encZ})});
    for (int wheel : {cc::kWheel1Channel, cc::kWheel2Channel}) {
        if (!valid14(wheel))
            continue;
        for (auto [present, enc] : {std::pair{px, encX}, std::pair{pz, encZ}})
            if (present && V(enc) == V(wheel))
                col.addC(Severity::Error, {enc, wheel}, 39, "check.wheel-encoder-channel",
                         {num(V(wheel)), named(wheel), named(enc), keys({wheel, enc})});
    }
    if (px && pz && valid14(dacX) && V(dacX) == V(dacZ))
        col.addC(Severity::Error, {dacX, dacZ}, 38, "check.drives-channel",
                 {num(V(dacX)), named(dacX), named(dacZ), keys({dacX, dacZ})});
    if (valid14(cc::kWheel1Channel) && V(cc::kWheel1Channel) == V(cc::kWheel2Channel))
        col.addC(Severity::Error, {cc::kWheel1Channel, cc::kWheel2Channel}, 39, "check.wheels-channel",
                 {num(V(cc::kWheel1Channel))});

    // Manual cycles started by the PLC run programs of the profile (45).
    if (programs) {
        for (int k = 0; k < 8; ++k) {
            const int n = cc::kManualCycle1 + k;
            const auto prog = V(n);
            if (prog >= 1 && prog <= 99 && !programs->contains(static_cast<int>(prog)))
                col.addC(Severity::Warning, {n}, 45, "check.manual-cycle", {std::to_string(k + 1), num(prog)});
        }
    }
    return col.out;
}

std::optional<int> programHeaderNumber(std::string_view line) {
    std::size_t i = 0;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
        ++i;
    if (i + 2 > line.size() || line[i] != '%' || (line[i + 1] != 'L' && line[i + 1] != 'l'))
        return std::nullopt;
    i += 2;
    const std::size_t start = i;
    int n = 0;
    while (i < line.size() && line[i] >= '0' && line[i] <= '9' && i - start < 6)
        n = n * 10 + (line[i++] - '0');
    if (i == start)
        return std::nullopt;
    if (i < line.size() && line[i] >= '0' && line[i] <= '9')
        return std::nullopt;
    return n;
}

Problem nameProblem(std::string_view name) {
    if (name.empty())
        return problem("name.empty");
    if (name.size() > 64)
        return problem("name.long");
    const auto alnum = [](char ch) { return (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9'); };
    if (!alnum(name[0]))
        return problem("name.start", {std::string(name)});
    for (char ch : name)
        if (!alnum(ch) && ch != '-' && ch != '_' && ch != '.')
            return problem("name.char", {std::string(name)});
    return {};
}

Problem titleProblem(std::string_view title) {
    if (title.empty())
        return {};
    return within(problem("title"), lineTextProblem(title, 120, false));
}

Problem cValueProblem(int number, std::int64_t value) {
    const cat::CParamDef* d = cat::findCParam(number);
    if (!d)
        return problem("c.none", {std::to_string(number)});
    if (!d->inRange(value))
        return problem("c.range", {d->key(), num(value), range(*d), std::string(d->name)});
    return {};
}

Problem rPresetProblem(int number, std::int64_t value) {
    const cat::RParamDef* d = cat::findRParam(number);
    if (!d)
        return problem("r.none", {std::to_string(number)});
    if (d->readOnly())
        return problem("r.read-only", {std::to_string(number)});
    if (value < cat::kRMin || value > cat::kRMax)
        return problem("r.range", {std::to_string(number), num(value)});
    return {};
}

Problem programProblem(int number, std::string_view text) {
    if (number < 1 || number > 99)
        return problem("program.number", {std::to_string(number)});
    const std::string l = std::to_string(number);
    if (text.empty())
        return problem("program.empty", {l});
    if (!utf8::isValid(text))
        return problem("program.utf8", {l});
    if (text.back() != '\n')
        return problem("program.no-line-break", {l});
    if (text.find('\r') != std::string_view::npos)
        return problem("program.carriage-return", {l});
    std::size_t pos = 0;
    int lineNo = 0;
    bool nonBlank = false;
    while (pos < text.size()) {
        const std::size_t end = text.find('\n', pos);
        const std::string_view line = text.substr(pos, end - pos);
        ++lineNo;
        pos = end + 1;
        const auto firstChar = line.find_first_not_of(" \t");
        if (firstChar != std::string_view::npos && line[firstChar] == '[')
            return problem("program.bracket", {l, std::to_string(lineNo)});
        if (line.find_first_not_of(" \t") != std::string_view::npos)
            nonBlank = true;
        if (auto h = programHeaderNumber(line); h && *h != number)
            return problem("program.header", {l, std::to_string(lineNo), std::to_string(*h)});
        std::string up = utf8::toUpper(line);
        const auto first = up.find_first_not_of(" \t");
        if (first != std::string::npos && up.compare(first, 9, "%MESSAGES") == 0)
            return problem("program.messages", {l, std::to_string(lineNo)});
    }
    if (!nonBlank)
        return problem("program.blank", {l});
    return {};
}

Problem messageProblem(int number, std::string_view text) {
    if (number < 1 || number > cat::kTechMessageCount)
        return problem("message.number", {std::to_string(number)});
    return within(problem("message.text", {std::to_string(number)}),
                  lineTextProblem(text, cat::kTechMessageMaxChars, true));
}

Problem plcTextProblem(cat::PlcGroup group, int k, std::string_view text) {
    const int count = cat::plcMessageCount(group);
    const std::string key =
        std::string(1, cat::plcGroupLetter(group)) + (k < 10 ? "0" : "") + std::to_string(k);
    if (k < 1 || k > count)
        return problem("plc.number", {key, std::to_string(count)});
    return within(problem("plc.text", {key}), lineTextProblem(text, cat::kPlcMessageMaxChars, true));
}

Problem englishTextProblem(std::string_view item, std::string_view text) {
    if (item == "title")
        return titleProblem(text);
    if (item.starts_with('#'))
        return messageProblem(std::stoi(std::string(item.substr(1))), text);
    for (cat::PlcGroup g : cat::kPlcGroups)
        if (!item.empty() && cat::plcGroupLetter(g) == item[0])
            return plcTextProblem(g, std::stoi(std::string(item.substr(1))), text);
    return {};
}

Problem settingProblem(std::string_view key, std::string_view value) {
    if (Problem e = settingKeyProblem(key); !e.empty())
        return within(problem("setting.key"), std::move(e));
    if (Problem e = settingValueProblem(value); !e.empty())
        return within(problem("setting.value", {std::string(key)}), std::move(e));
    return within(problem("setting.value", {std::string(key)}), simulationValueProblem(key, value));
}

std::string checkName(std::string_view name) { return nameProblem(name).text(); }
std::string checkTitle(std::string_view title) { return titleProblem(title).text(); }
std::string checkCValue(int number, std::int64_t value) { return cValueProblem(number, value).text(); }
std::string checkRPreset(int number, std::int64_t value) { return rPresetProblem(number, value).text(); }
std::string checkProgram(int number, std::string_view text) { return programProblem(number, text).text(); }
std::string checkMessage(int number, std::string_view text) { return messageProblem(number, text).text(); }
std::string checkPlcText(cat::PlcGroup group, int k, std::string_view text) {
    return plcTextProblem(group, k, text).text();
}
std::string checkSetting(std::string_view key, std::string_view value) { return settingProblem(key, value).text(); }

std::vector<Finding> validate(const MachineProfile& p) {
    std::vector<Finding> out = checkCParams(p.cValues(), &p.programs);
    Collector col;
    // An item's problem (core's catalog of problems).
    const auto item = [&](Problem problem, std::string subject) {
        if (!problem.empty())
            col.add(Severity::Error, {}, std::nullopt, std::move(subject), std::move(problem));
    };
    for (const auto& [n, v] : p.r)
        item(rPresetProblem(n, v), "R" + std::to_string(n));
    for (const auto& [n, text] : p.programs)
        item(programProblem(n, text), "L" + std::to_string(n));
    for (const auto& [n, text] : p.messages)
        item(messageProblem(n, text), "#" + std::to_string(n));
    for (cat::PlcGroup g : cat::kPlcGroups)
        for (const auto& [k, text] : p.plcTexts(g))
            item(plcTextProblem(g, k, text),
                 std::string(1, cat::plcGroupLetter(g)) + (k < 10 ? "0" : "") + std::to_string(k));
    for (const auto& [key, value] : p.simulation.entries()) {
        item(settingProblem(key, value), "simulation " + key);
        if (Settings::keyError(key).empty() && !findSimulationKey(key))
            col.add(Severity::Warning, {}, std::nullopt, "simulation " + key,
                    problem("check.setting-unknown", {key}));
    }
    item(nameProblem(p.name), "name");
    item(titleProblem(p.title), "title");
    out.insert(out.end(), col.out.begin(), col.out.end());
    return out;
}

bool hasErrors(const std::vector<Finding>& findings) {
    return std::any_of(findings.begin(), findings.end(),
                       [](const Finding& f) { return f.severity == Severity::Error; });
}

std::string formatFinding(const Finding& f, bool russian) {
    std::string s = f.severity == Severity::Error ? "error" : "warning";
    if (f.message)
        s += " [M" + std::to_string(*f.message) + "]";
    if (!f.subject.empty())
        s += " " + f.subject;
    return s + ": " + (russian ? f.textRu : f.textEn);
}

} // namespace k528::profile
