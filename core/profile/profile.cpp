#include "profile/profile.h"
#include "profile/english.h"

#include <cctype>
#include <optional>
#include <stdexcept>
#include <string>

namespace k528::profile {

namespace {

void checkNumber(int number) {
    if (number < 1 || number > catalog::kCParamCount)
        throw std::out_of_range("no C-parameter " + std::to_string(number) + " (1..152)");
}

} // namespace

std::int64_t MachineProfile::cValue(int number) const {
    checkNumber(number);
    return c[static_cast<std::size_t>(number)];
}

void MachineProfile::setC(int number, std::int64_t value) {
    checkNumber(number);
    c[static_cast<std::size_t>(number)] = value;
}

std::map<int, std::string>& MachineProfile::plcTexts(catalog::PlcGroup g) {
    switch (g) {
    case catalog::PlcGroup::Alarm:
        return plcAlarm;
    case catalog::PlcGroup::Work:
        return plcWork;
    case catalog::PlcGroup::System:
        return plcSystem;
    }
    return plcAlarm;
}

const std::map<int, std::string>& MachineProfile::plcTexts(catalog::PlcGroup g) const {
    return const_cast<MachineProfile*>(this)->plcTexts(g);
}

std::int64_t axisValue(const MachineProfile& p, catalog::Axis axis, int xNumber) {
    if (xNumber < 1 || xNumber > catalog::kAxisBlock || axis == catalog::Axis::Common)
        throw std::out_of_range("no axis parameter " + std::to_string(xNumber));
    return p.cValue(catalog::axisParam(xNumber, axis));
}

bool axisPresent(const MachineProfile& p, catalog::Axis axis) {
    return axisValue(p, axis, catalog::c::kAxisPresent) == 1;
}

units::AxisScale axisScale(const MachineProfile& p, catalog::Axis axis) {
    units::AxisScale s;
    if (axisValue(p, axis, catalog::c::kDiscrete0001) == 1)
        s.discrete = units::Discrete::Mm0_0001;
    else if (axisValue(p, axis, catalog::c::kDiscrete001) == 1)
        s.discrete = units::Discrete::Mm0_001;
    else if (axisValue(p, axis, catalog::c::kDiscrete01) == 1)
        s.discrete = units::Discrete::Mm0_01;
    else
        s.discrete = units::Discrete::Mm0_001;
    s.diameter = axisValue(p, axis, catalog::c::kDiameter) == 1;
    return s;
}

namespace {

constexpr std::string_view kEnglishPrefix = "text.en.";

// A whole number of at most 2 digits, nullopt otherwise.
std::optional<int> smallNumber(std::string_view s) {
    if (s.empty() || s.size() > 2)
        return std::nullopt;
    int n = 0;
    for (char c : s) {
        if (c < '0' || c > '9')
            return std::nullopt;
        n = n * 10 + (c - '0');
    }
    return n;
}

std::string two(int k) { return (k < 10 ? "0" : "") + std::to_string(k); }

std::string englishOf(const MachineProfile& p, std::string_view item) {
    const std::string key = englishKey(item);
    return key.empty() ? std::string() : p.simulation.getString(key, "");
}

} // namespace

std::string englishKey(std::string_view item) {
    if (item == "title")
        return std::string(kEnglishPrefix) + "title";
    if (item.size() >= 2 && item[0] == '#') {
        const auto n = smallNumber(item.substr(1));
        if (n && *n >= 1 && *n <= catalog::kTechMessageCount && item.substr(1) == std::to_string(*n))
            return std::string(kEnglishPrefix) + "m" + std::to_string(*n);
        return {};
    }
    if (item.size() == 3) {
        const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(item[0])));
        const auto k = smallNumber(item.substr(1));
        for (catalog::PlcGroup g : catalog::kPlcGroups)
            if (catalog::plcGroupLetter(g) == letter && k && *k >= 1 && *k <= catalog::plcMessageCount(g))
                return std::string(kEnglishPrefix) + static_cast<char>(std::tolower(letter)) + two(*k);
    }
    return {};
}

std::string englishItem(std::string_view key) {
    if (!key.starts_with(kEnglishPrefix))
        return {};
    const std::string_view rest = key.substr(kEnglishPrefix.size());
    std::string item;
    if (rest == "title")
        item = "title";
    else if (rest.size() >= 2 && rest[0] == 'm')
        item = "#" + std::string(rest.substr(1));
    else if (rest.size() == 3 && (rest[0] == 'a' || rest[0] == 'w' || rest[0] == 's'))
        item = std::string(1, static_cast<char>(std::toupper(static_cast<unsigned char>(rest[0])))) +
               std::string(rest.substr(1));
    return !item.empty() && englishKey(item) == key ? item : std::string();
}

std::string titleText(const MachineProfile& p, bool english) {
    if (english)
        if (std::string en = englishOf(p, "title"); !en.empty())
            return en;
    return p.title;
}

std::string messageText(const MachineProfile& p, int number, bool english) {
    if (english)
        if (std::string en = englishOf(p, "#" + std::to_string(number)); !en.empty())
            return en;
    const auto it = p.messages.find(number);
    return it == p.messages.end() ? std::string() : it->second;
}

std::string toolName(const MachineProfile& p, const Tool& t, bool english) {
    if (english)
        if (std::string en = p.simulation.getString("tool." + std::to_string(t.station) + ".name.en", "");
            !en.empty())
            return en;
    return t.name;
}

std::string plcText(const MachineProfile& p, catalog::PlcGroup g, int k, bool english) {
    if (english)
        if (std::string en = englishOf(p, std::string(1, catalog::plcGroupLetter(g)) + two(k)); !en.empty())
            return en;
    const auto& texts = p.plcTexts(g);
    const auto it = texts.find(k);
    return it == texts.end() ? std::string() : it->second;
}

} // namespace k528::profile
