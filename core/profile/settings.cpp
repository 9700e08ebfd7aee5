#include "profile/settings.h"
#include "profile/problem.h"

#include "profile/line.h"
#include "profile/english.h"

#include "util/utf8.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <system_error>

namespace k528::profile {

namespace {

std::string quoted(std::string_view s) {
    return "'" + std::string(s) + "'";
}

std::vector<std::pair<std::string, std::string>>::const_iterator
findEntry(const std::vector<std::pair<std::string, std::string>>& v, std::string_view key) {
    return std::find_if(v.begin(), v.end(), [&](const auto& e) { return e.first == key; });
}

bool isBlank(char c) {
    return c == ' ' || c == '\t';
}

} // namespace

std::optional<std::int64_t> parseInt(std::string_view t) {
    if (t.empty())
        return std::nullopt;
    std::size_t i = 0;
    bool neg = false;
    if (t[0] == '+' || t[0] == '-') {
        neg = t[0] == '-';
        i = 1;
    }
    if (i >= t.size())
        return std::nullopt;
    std::uint64_t v = 0;
    const auto [p, ec] = std::from_chars(t.data() + i, t.data() + t.size(), v);
    if (ec != std::errc() || p != t.data() + t.size())
        return std::nullopt;
    if (!neg && v > static_cast<std::uint64_t>(INT64_MAX))
        return std::nullopt;
    if (neg && v > static_cast<std::uint64_t>(INT64_MAX) + 1)
        return std::nullopt;
    return neg ? static_cast<std::int64_t>(0 - v) : static_cast<std::int64_t>(v);
}

std::optional<double> parseDouble(std::string_view t) {
    if (t.empty())
        return std::nullopt;
    std::size_t i = t[0] == '+' ? 1 : 0;
    if (i >= t.size())
        return std::nullopt;
    double v = 0;
    const auto [p, ec] = std::from_chars(t.data() + i, t.data() + t.size(), v);
    if (ec != std::errc() || p != t.data() + t.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::optional<bool> parseBool(std::string_view t) {
    if (t == "true" || t == "1" || t == "yes" || t == "on")
        return true;
    if (t == "false" || t == "0" || t == "no" || t == "off")
        return false;
    return std::nullopt;
}

std::string formatDouble(double v) {
    char buf[64];
    const auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
    (void)ec;
    return std::string(buf, p);
}

Problem settingKeyProblem(std::string_view key) {
    if (key.empty())
        return problem("key.empty");
    if (key.size() > 64)
        return problem("key.long");
    if (!(key[0] >= 'a' && key[0] <= 'z'))
        return problem("key.start", {std::string(key)});
    for (char ch : key)
        if (!((ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_' || ch == '.'))
            return problem("key.char", {std::string(key)});
    return {};
}

Problem settingValueProblem(std::string_view value) {
    if (!utf8::isValid(value))
        return problem("value.utf8");
    if (utf8::length(value) > 200)
        return problem("value.long");
    for (char ch : value) {
        if (ch == '\n' || ch == '\r')
            return problem("value.lines");
        if (static_cast<unsigned char>(ch) < 0x20 && ch != '\t')
            return problem("value.control");
        if (ch == ';')
            return problem("value.semicolon");
    }
    if (!value.empty() && (isBlank(value.front()) || isBlank(value.back())))
        return problem("value.blank");
    return {};
}

std::string Settings::keyError(std::string_view key) { return settingKeyProblem(key).text(); }

std::string Settings::valueError(std::string_view value) { return settingValueProblem(value).text(); }

void Settings::set(std::string_view key, std::string_view value) {
    if (auto e = keyError(key); !e.empty())
        throw SettingError("simulation setting: " + e);
    if (auto e = valueError(value); !e.empty())
        throw SettingError("simulation setting " + std::string(key) + ": " + e);
    for (auto& entry : entries_) {
        if (entry.first == key) {
            entry.second = std::string(value);
            return;
        }
    }
    entries_.emplace_back(std::string(key), std::string(value));
}

void Settings::setInt(std::string_view key, std::int64_t value) {
    set(key, std::to_string(value));
}
void Settings::setDouble(std::string_view key, double value) {
    if (!std::isfinite(value))
        throw SettingError("simulation setting " + std::string(key) + ": not a finite number");
    set(key, formatDouble(value));
}
void Settings::setBool(std::string_view key, bool value) {
    set(key, value ? "true" : "false");
}

bool Settings::erase(std::string_view key) {
    const auto it = findEntry(entries_, key);
    if (it == entries_.end())
        return false;
    entries_.erase(it);
    return true;
}

bool Settings::has(std::string_view key) const {
    return findEntry(entries_, key) != entries_.end();
}

std::optional<std::string> Settings::find(std::string_view key) const {
    const auto it = findEntry(entries_, key);
    if (it == entries_.end())
        return std::nullopt;
    return it->second;
}

std::string Settings::getString(std::string_view key, std::string_view fallback) const {
    auto v = find(key);
    return v ? *v : std::string(fallback);
}

std::int64_t Settings::getInt(std::string_view key, std::int64_t fallback) const {
    const auto v = find(key);
    if (!v)
        return fallback;
    const auto n = parseInt(*v);
    if (!n)
        throw SettingError("simulation setting " + std::string(key) + " = " + quoted(*v) +
                           ": not a whole number");
    return *n;
}

double Settings::getDouble(std::string_view key, double fallback) const {
    const auto v = find(key);
    if (!v)
        return fallback;
    const auto d = parseDouble(*v);
    if (!d)
        throw SettingError("simulation setting " + std::string(key) + " = " + quoted(*v) +
                           ": not a number");
    return *d;
}

bool Settings::getBool(std::string_view key, bool fallback) const {
    const auto v = find(key);
    if (!v)
        return fallback;
    const auto b = parseBool(*v);
    if (!b)
        throw SettingError("simulation setting " + std::string(key) + " = " + quoted(*v) +
                           ": not true/false");
    return *b;
}

std::int64_t Settings::requireInt(std::string_view key) const {
    if (!has(key))
        throw SettingError("simulation setting " + std::string(key) + " is missing");
    return getInt(key, 0);
}

double Settings::requireDouble(std::string_view key) const {
    if (!has(key))
        throw SettingError("simulation setting " + std::string(key) + " is missing");
    return getDouble(key, 0.0);
}

namespace {

using T = SettingType;

// clang-format off
constexpr SimulationKey kKeys[] = {
    {"tick_ms", T::Int, 1, 100, "1", "ms", "Simulation step: the controller, PLC and machine advance in ticks of this length.", "engine"},
    {"nesting_limit", T::Int, 1, 99, "8", "", "Deepest subprogram nesting; deeper calls stop the program with message 48.", "engine, program"},
    {"x.screw_lead_mm", T::Double, 0.01, 1000, "", "mm", "Slide travel per revolution of the ball screw.", "machine, profile calculator"},
    {"x.gear_ratio", T::Double, 0.001, 1000, "1", "", "Motor (encoder) revolutions per screw revolution.", "machine, profile calculator"},
    {"x.encoder_lines", T::Int, 1, 1000000, "", "lines/rev", "Encoder lines per motor revolution (the controller counts 4 pulses per line).", "machine, profile calculator"},
    {"x.drive_max_volts", T::Double, 0.1, 10, "", "V", "Umax: command voltage at which the drive runs at x.drive_max_speed_mm_per_min.", "machine, profile calculator"},
    {"x.drive_max_speed_mm_per_min", T::Double, 1, 200000, "", "mm/min", "Vmax: slide speed at x.drive_max_volts.", "machine, profile calculator"},
    {"x.kv", T::Double, 0.01, 100, "", "(m/min)/mm", "Servo gain Kv used to design K(ОШИБ) (manual: 0.75...1.5).", "profile calculator"},
    {"x.drive_time_constant_ms", T::Double, 0, 1000, "", "ms", "First-order lag of the drive's speed response.", "axis"},
    {"z.screw_lead_mm", T::Double, 0.01, 1000, "", "mm", "As x.screw_lead_mm, for Z.", "machine, profile calculator"},
    {"z.gear_ratio", T::Double, 0.001, 1000, "1", "", "As x.gear_ratio, for Z.", "machine, profile calculator"},
    {"z.encoder_lines", T::Int, 1, 1000000, "", "lines/rev", "As x.encoder_lines, for Z.", "machine, profile calculator"},
    {"z.drive_max_volts", T::Double, 0.1, 10, "", "V", "As x.drive_max_volts, for Z.", "machine, profile calculator"},
    {"z.drive_max_speed_mm_per_min", T::Double, 1, 200000, "", "mm/min", "As x.drive_max_speed_mm_per_min, for Z.", "machine, profile calculator"},
    {"z.kv", T::Double, 0.01, 100, "", "(m/min)/mm", "As x.kv, for Z.", "profile calculator"},
    {"z.drive_time_constant_ms", T::Double, 0, 1000, "", "ms", "As x.drive_time_constant_ms, for Z.", "axis"},
    {"handwheel1.lines", T::Int, 1, 10000, "100", "pulses/rev", "Pulses per revolution of handwheel 1.", "machine"},
    {"handwheel2.lines", T::Int, 1, 10000, "100", "pulses/rev", "Pulses per revolution of handwheel 2.", "machine"},
    {"m_code_lead_ms", T::Int, 0, 1000, "20", "ms", "M hand-over: time from the code on Z2001.0-6 to the strobe Z2001.7 (GOST 26642 T2).", "engine"},
    {"machine", T::String, 0, 0, "", "", "Machine description the simulated PLC and machine run: the name of an embedded resources/machines/<name>.json or a path to a .json file (default: the description named as the profile, else generic).", "machine"},
    {"plc.m_ack_delay_ms", T::Int, 0, 60000, "40", "ms", "Ideal PLC: time from the M strobe to its acknowledgement Z1000.11 (GOST T3).", "engine (ideal machine)"},
    {"plc.pulse_ms", T::Int, 1, 1000, "20", "ms", "Ideal PLC: length of the Start, Stop, Reset, acknowledgement and cycle pulses.", "engine (ideal machine)"},
    {"x.start_mm", T::Double, -100000, 100000, "", "mm", "Simulated machine (and the ideal test double): X at power-on, machine coordinates as displayed (default: 20 mm of slide before the deceleration cam, inside the soft limits).", "machine, engine (ideal machine)"},
    {"x.decel_cam_mm", T::Double, 0.1, 1000, "", "mm", "Simulated machine (and the ideal test double): length of the deceleration cam, mm of slide (default: 3/4 of S конечника БТ, 3 mm when it is 0).", "machine, engine (ideal machine)"},
    {"x.limit_minus_mm", T::Double, -100000, 100000, "", "mm", "Simulated machine (and the ideal test double): the - limit switch, machine coordinates (default: 2 mm of slide beyond -ОГРАНИЧЕН, the cam and the zero mark).", "machine, engine (ideal machine)"},
    {"x.limit_plus_mm", T::Double, -100000, 100000, "", "mm", "Simulated machine (and the ideal test double): the + limit switch, machine coordinates (default: 2 mm of slide beyond +ОГРАНИЧЕН, the cam and the zero mark).", "machine, engine (ideal machine)"},
    {"z.start_mm", T::Double, -100000, 100000, "", "mm", "As x.start_mm, for Z.", "machine, engine (ideal machine)"},
    {"z.decel_cam_mm", T::Double, 0.1, 1000, "", "mm", "As x.decel_cam_mm, for Z.", "machine, engine (ideal machine)"},
    {"z.limit_minus_mm", T::Double, -100000, 100000, "", "mm", "As x.limit_minus_mm, for Z.", "machine, engine (ideal machine)"},
    {"z.limit_plus_mm", T::Double, -100000, 100000, "", "mm", "As x.limit_plus_mm, for Z.", "machine, engine (ideal machine)"},
    {"constants.lock", T::String, 0, 0, "", "", "Training: the machine constants locked by the trainer for a class (the value names the class): the studio's constants dock and the K923's C-parameter editing refuse changes until the trainer unlocks them.", "training (studio)"},
    {"push.unreleased", T::Bool, 0, 0, "false", "", "Shop database: a push to the controller may take programs that are not released (a technologist's prove-out); otherwise released programs only.", "transfer (push)"},
    // The tools of the turret's stations n = 1..8 (profile/tools.h).
    {"tool.n.kind", T::String, 0, 0, "", "", "The tool at station n: turning, facing, grooving, boring, drill or threading (the other tool.n keys need it).", "profile tools, proveout, setup sheet, backplot"},
    {"tool.n.name", T::String, 0, 0, "", "", "The tool's name for people (the setup sheet).", "setup sheet"},
    {"tool.n.name.en", T::String, 0, 0, "", "", "The tool's name in English (tool.n.name is the Russian).", "setup sheet"},
    {"tool.n.tip_radius_mm", T::Double, 0, 50, "0", "mm", "The tool's nose radius.", "setup sheet, backplot"},
    {"tool.n.orientation", T::String, 0, 0, "+z+x", "", "Where the tool's body lies from its tip: +z+x (an outside tool held from above), -z+x, +z-x (a boring bar), -z-x.", "proveout, backplot"},
    {"tool.n.width_mm", T::Double, 0.001, 1000, "3", "mm", "The tool's body along Z from its tip (a drill's or boring bar's length: default 150).", "proveout, backplot"},
    {"tool.n.height_mm", T::Double, 0.001, 1000, "1000", "mm", "The tool's body along X (radially) from its tip; a drill's diameter (default 10 for drills and boring bars).", "proveout, backplot"},
    {"tool.n.max_depth_mm", T::Double, 0, 100, "0", "mm", "The deepest cut the tool takes (its cutting edge); 0: no limit.", "proveout"},
    {"tool.n.offset_r", T::Int, 0, 148, "", "", "The R-parameter of the tool's X offset (its Z offset is the next): the values the program copies into R226/R227 after the tool change.", "proveout, setup sheet, trial part"},
    // The English of a text for people (profile.h, englishKey): the title,
    // technological message #k (text.en.m<k>), PLC message A01 (text.en.a01), W, S.
    {"text.en.item", T::String, 0, 0, "", "", "The English of a text for people beside its Russian: title.en=, #k.en=, A01.en= in the machine file.", "the studio in English, the CLI's --lang en"},
    {"line", T::String, 0, 0, "", "", "Shop: where the machine's controller is, tcp://HOST:PORT/UNIT (Modbus TCP) or serial:DEVICE?baud=115200&parity=none&address=1 (RS485).", "shop (k528 shop, the studio's Connect)"},
};
// clang-format on

} // namespace

std::span<const SimulationKey> simulationKeys() {
    return kKeys;
}

const SimulationKey* findSimulationKey(std::string_view key) {
    // tool.<station>.<key>: the entry tool.n.<key> (station 1..8).
    std::string generic;
    if (key.substr(0, 5) == "tool." && key.size() > 7 && key[5] >= '1' && key[5] <= '8' &&
        key[6] == '.') {
        generic = "tool.n." + std::string(key.substr(7));
        key = generic;
    }
    if (!englishItem(key).empty())
        key = "text.en.item";
    for (const SimulationKey& k : kKeys)
        if (k.key == key)
            return &k;
    return nullptr;
}

Problem simulationValueProblem(std::string_view key, std::string_view value) {
    const SimulationKey* k = findSimulationKey(key);
    if (!k)
        return {};
    const auto range = [&](double v) -> Problem {
        if (v < k->min || v > k->max)
            return problem("value.range", {std::string(value), formatDouble(k->min), formatDouble(k->max)});
        return {};
    };
    switch (k->type) {
    case SettingType::Int: {
        const auto n = parseInt(value);
        if (!n)
            return problem("value.integer", {std::string(value)});
        return range(static_cast<double>(*n));
    }
    case SettingType::Double: {
        const auto d = parseDouble(value);
        if (!d)
            return problem("value.number", {std::string(value)});
        return range(*d);
    }
    case SettingType::Bool:
        if (!parseBool(value))
            return problem("value.bool", {std::string(value)});
        return {};
    case SettingType::String:
        if (const std::string item = englishItem(key); !item.empty())
            return englishTextProblem(item, value);
        if (key == "line")
            return lineProblem(value);
        return {};
    }
    return {};
}

std::string checkSimulationValue(std::string_view key, std::string_view value) {
    return simulationValueProblem(key, value).text();
}

} // namespace k528::profile
