#include "plc/description.h"

#include "plc/description_texts.h"

#include "resources/embedded.h"
#include "util/json.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <tuple>
#include <utility>

namespace k528::plc {

namespace {

using profile::problem;

struct SlotName {
    std::string_view key;
    int word; // X word for axis keys (Z adds 3)
    int bit;
};

// Z1000/Z1001 (appendix И, table И.1).
constexpr SlotName kGeneralSlots[] = {
    {"estop_ok", 1000, 0},  {"feed_enable", 1000, 1}, {"start_enable", 1000, 2},
    {"start", 1000, 3},     {"stop", 1000, 4},        {"reset", 1000, 5},
    {"data_hold", 1000, 6}, {"acknowledge", 1000, 7}, {"cycle1", 1001, 0},
    {"cycle2", 1001, 1},    {"cycle3", 1001, 2},      {"cycle4", 1001, 3},
    {"cycle5", 1001, 4},    {"cycle6", 1001, 5},      {"cycle7", 1001, 6},
    {"cycle8", 1001, 7},    {"r150", 1001, 8},
};

// Z1005..Z1007 for X; Z1008..Z1010 for Z.
constexpr SlotName kAxisSlots[] = {
    {"loop_off", 1005, 0},
    {"regulator", 1005, 1},
    {"feed_enable", 1005, 2},
    {"decel_cam", 1005, 3},
    {"accel2", 1005, 4},
    {"limit_plus", 1005, 5},
    {"limit_minus", 1005, 6},
    {"jog_plus", 1005, 7},
    {"jog_minus", 1005, 8},
    {"rapid", 1005, 9},
    {"wheel1", 1005, 10},
    {"wheel2", 1005, 11},
    {"wheel1_mult", 1005, 12},
    {"wheel2_mult", 1005, 13},
    {"wheel1_drf", 1005, 14},
    {"wheel2_drf", 1005, 15},
    {"adjust_plus", 1006, 1},
    {"adjust_minus", 1006, 2},
    {"encoder_on", 1006, 3},
    {"no_drf", 1006, 4},
    {"no_correction", 1006, 5},
    {"no_dressing", 1006, 6},
    {"no_zero_offset", 1006, 7},
    {"erase1", 1006, 12},
    {"erase2", 1006, 13},
    {"erase3", 1006, 14},
    {"erase4", 1006, 15},
    {"rough_dress_comp", 1007, 0},
    {"finish_dress_comp", 1007, 1},
};

bool validName(std::string_view n) {
    if (n.empty() || n.size() > 40)
        return false;
    if (!(std::isalpha(static_cast<unsigned char>(n[0])) || n[0] == '_'))
        return false;
    for (char c : n)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_'))
            return false;
    return true;
}

constexpr std::string_view kReserved[] = {"true",    "false",  "and",          "or",
                                          "not",     "rise",   "fall",         "first_scan",
                                          "link_ok", "m_busy", "acknowledged", "alarm_active"};

void checkName(const JsonNode& node, std::string_view key, const std::string& name) {
    if (!validName(name))
        node.failAt(key, problem("name.invalid", {name}));
    for (std::string_view r : kReserved)
        if (r == name)
            node.failAt(key, problem("name.reserved", {name}));
    if (name.size() >= 2 && (name[0] == 'K') &&
        std::all_of(name.begin() + 1, name.end(),
                    [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
        node.failAt(key, problem("name.key", {name}));
    if (name[0] == 'Z' && name.size() > 1 && std::isdigit(static_cast<unsigned char>(name[1])))
        node.failAt(key, problem("name.address", {name}));
}

Actions readActions(const JsonNode& n) {
    Actions a;
    a.path = n.path();
    a.set = n.strings("set");
    a.reset = n.strings("reset");
    a.toggle = n.strings("toggle");
    a.pulse = n.strings("pulse");
    return a;
}

// A text for people in both languages: {"ru": …, "en": …}, neither missing
// nor empty (a Russian window must not fall back to the English silently),
// or one string written in one language, shown as written in both.
std::pair<std::string, std::string> readBilingual(const JsonNode& owner, std::string_view key) {
    if (!owner.has(key))
        return {};
    const JsonNode t = owner.child(key);
    if (t.isString())
        return {t.asString(), t.asString()};
    t.expectObject({"ru", "en"});
    std::pair<std::string, std::string> out{t.string("ru"), t.string("en")};
    if (out.first.empty())
        t.failAt("ru", problem("empty"));
    if (out.second.empty())
        t.failAt("en", problem("empty"));
    return out;
}

int percentToCode(int pct) {
    constexpr int steps[] = {0, 1, 2, 5, 10, 20, 35, 50, 75, 90, 100};
    for (int c = 0; c <= 10; ++c)
        if (steps[c] == pct)
            return c;
    return -1;
}

} // namespace

std::optional<ZAddress> parseZ(std::string_view t) {
    if (t.size() < 4 || t[0] != 'Z')
        return std::nullopt;
    const auto dot = t.find('.');
    if (dot == std::string_view::npos || dot < 2 || dot + 1 >= t.size())
        return std::nullopt;
    int word = 0, bit = 0;
    for (std::size_t i = 1; i < dot; ++i) {
        if (!std::isdigit(static_cast<unsigned char>(t[i])) || word > 100000)
            return std::nullopt;
        word = word * 10 + (t[i] - '0');
    }
    for (std::size_t i = dot + 1; i < t.size(); ++i) {
        if (!std::isdigit(static_cast<unsigned char>(t[i])) || bit > 100)
            return std::nullopt;
        bit = bit * 10 + (t[i] - '0');
    }
    if (bit > 15)
        return std::nullopt;
    return ZAddress{word, bit};
}

std::optional<ZAddress> slotAddress(std::string_view key) {
    for (const SlotName& s : kGeneralSlots)
        if (s.key == key)
            return ZAddress{s.word, s.bit};
    for (int axis = 0; axis < 2; ++axis) {
        const std::string_view prefix = axis == 0 ? "x." : "z.";
        if (key.substr(0, 2) != prefix)
            continue;
        const std::string_view rest = key.substr(2);
        for (const SlotName& s : kAxisSlots)
            if (s.key == rest)
                return ZAddress{s.word + 3 * axis, s.bit};
    }
    return std::nullopt;
}

std::vector<std::string> slotKeys() {
    std::vector<std::string> k;
    for (const SlotName& s : kGeneralSlots)
        k.emplace_back(s.key);
    for (const char* a : {"x.", "z."})
        for (const SlotName& s : kAxisSlots)
            k.push_back(std::string(a) + std::string(s.key));
    return k;
}

const MFunctionDef* MachineDescription::mFunction(int m) const {
    for (const MFunctionDef& f : mFunctions)
        if (f.m == m)
            return &f;
    return nullptr;
}

MachineDescription readDescription(std::string_view text, const std::string& source) {
    MachineDescription d;
    d.source = source;
    d.document = std::make_shared<const Json>(parseDocument(text, source));
    const JsonNode root(*d.document, source, "");
    root.expectObject({"format", "name", "title", "plc", "modules", "inputs", "outputs", "flags",
                       "logic", "m_functions", "unknown_m", "interlocks", "keys", "leds", "alarms",
                       "work", "positioner", "equipment", "proveout"});
    if (root.integer("format", 1, 1000) != 1)
        root.failAt("format", problem("format"));
    d.name = root.string("name");
    if (d.name.empty())
        root.failAt("name", problem("empty"));
    d.title = root.string("title", "");

    if (root.has("plc")) {
        const JsonNode p = root.child("plc");
        p.expectObject({"debounce_ms", "pulse_ms", "m_timing_ms"});
        d.timing.debounceMs = static_cast<int>(p.integer("debounce_ms", 0, 100, 8));
        d.timing.pulseMs = static_cast<int>(p.integer("pulse_ms", 1, 10000, 20));
        if (p.has("m_timing_ms")) {
            const JsonNode t = p.child("m_timing_ms");
            t.expectObject({"t1", "t2", "t3", "t4"});
            d.timing.t1Ms = static_cast<int>(t.integer("t1", 0, 10000, 20));
            d.timing.t2Ms = static_cast<int>(t.integer("t2", 0, 10000, 20));
            d.timing.t3Ms = static_cast<int>(t.integer("t3", 0, 10000, 40));
            d.timing.t4Ms = static_cast<int>(t.integer("t4", 0, 10000, 80));
        }
    }

    for (const JsonNode& m : root.optionalArray("modules")) {
        m.expectObject({"place", "title"});
        ModuleDef md;
        md.place = static_cast<int>(m.integer("place", 0, 15));
        md.title = m.string("title", "");
        for (const ModuleDef& o : d.modules)
            if (o.place == md.place)
                m.failAt("place", problem("module.twice", {std::to_string(md.place)}));
        d.modules.push_back(md);
    }
    const auto moduleOf = [&](const JsonNode& n) {
        const int place = static_cast<int>(n.integer("module", 0, 15, 0));
        if (!d.modules.empty() &&
            std::none_of(d.modules.begin(), d.modules.end(),
                         [&](const ModuleDef& m) { return m.place == place; }))
            n.failAt("module", problem("module.none", {std::to_string(place)}));
        return place;
    };

    for (const JsonNode& n : root.optionalArray("inputs")) {
        n.expectObject({"name", "signal", "contact", "module", "debounce_ms", "text"});
        InputDef in;
        in.path = n.path();
        in.name = n.string("name");
        checkName(n, "name", in.name);
        in.signal = n.string("signal");
        const std::string contact = n.string("contact", "no");
        if (contact != "no" && contact != "nc")
            n.failAt("contact", problem("contact", {contact}));
        in.normallyClosed = contact == "nc";
        in.module = moduleOf(n);
        in.debounceMs = static_cast<int>(n.integer("debounce_ms", 0, 100, d.timing.debounceMs));
        in.text = n.string("text", "");
        d.inputs.push_back(std::move(in));
    }
    for (const JsonNode& n : root.optionalArray("outputs")) {
        n.expectObject({"name", "signal", "module", "text"});
        OutputDef out;
        out.path = n.path();
        out.name = n.string("name");
        checkName(n, "name", out.name);
        out.signal = n.string("signal");
        out.module = moduleOf(n);
        out.text = n.string("text", "");
        d.outputs.push_back(std::move(out));
    }
    for (const JsonNode& n : root.optionalArray("flags")) {
        FlagDef f;
        f.path = n.path();
        if (n.isString()) {
            f.name = n.asString();
            checkName(n, "", f.name);
        } else {
            n.expectObject({"name", "text"});
            f.name = n.string("name");
            checkName(n, "name", f.name);
            f.text = n.string("text", "");
        }
        d.flags.push_back(std::move(f));
    }

    for (const JsonNode& n : root.optionalArray("logic")) {
        n.expectObject({"out", "set", "reset", "timer", "on_delay_ms", "off_delay_ms", "pulse_ms",
                        "when", "comment"});
        RungDef r;
        r.path = n.path();
        int kinds = 0;
        if (n.has("out")) {
            r.kind = RungKind::Coil;
            r.target = n.string("out");
            ++kinds;
        }
        if (n.has("set")) {
            r.kind = RungKind::Set;
            r.target = n.string("set");
            ++kinds;
        }
        if (n.has("reset")) {
            r.kind = RungKind::Reset;
            r.target = n.string("reset");
            ++kinds;
        }
        if (n.has("timer")) {
            r.target = n.string("timer");
            checkName(n, "timer", r.target);
            int t = 0;
            if (n.has("on_delay_ms")) {
                r.kind = RungKind::OnDelay;
                r.ms = static_cast<int>(n.integer("on_delay_ms", 0, 86400000));
                ++t;
            }
            if (n.has("off_delay_ms")) {
                r.kind = RungKind::OffDelay;
                r.ms = static_cast<int>(n.integer("off_delay_ms", 0, 86400000));
                ++t;
            }
            if (n.has("pulse_ms")) {
                r.kind = RungKind::Pulse;
                r.ms = static_cast<int>(n.integer("pulse_ms", 1, 86400000));
                ++t;
            }
            if (t != 1)
                n.fail(problem("timer.one"));
            ++kinds;
        } else if (n.has("on_delay_ms") || n.has("off_delay_ms") || n.has("pulse_ms")) {
            n.fail(problem("timer.delay"));
        }
        if (kinds != 1)
            n.fail(problem("rung.one"));
        r.when = n.string("when");
        d.logic.push_back(std::move(r));
    }

    for (const JsonNode& n : root.optionalArray("m_functions")) {
        n.expectObject({"m", "text", "set", "reset", "toggle", "pulse", "done", "wait_work",
                        "timeout_ms", "timeout_alarm"});
        MFunctionDef f;
        f.path = n.path();
        f.m = static_cast<int>(n.integer("m", 0, 99));
        if (d.mFunction(f.m))
            n.failAt("m", problem("m.twice", {std::to_string(f.m)}));
        std::tie(f.textRu, f.textEn) = readBilingual(n, "text");
        f.actions = readActions(n);
        f.done = n.string("done", "");
        f.waitWork = static_cast<int>(n.integer("wait_work", 1, 32, 0));
        f.timeoutMs = static_cast<int>(n.integer("timeout_ms", 1, 86400000, 0));
        f.timeoutAlarm = static_cast<int>(n.integer("timeout_alarm", 1, 32, 0));
        if ((f.timeoutMs > 0) != (f.timeoutAlarm > 0))
            n.fail(problem("m.timeout"));
        d.mFunctions.push_back(std::move(f));
    }
    if (root.has("unknown_m")) {
        const JsonNode u = root.child("unknown_m");
        u.expectObject({"acknowledge", "alarm"});
        d.unknownM.acknowledge = u.boolean("acknowledge", !u.has("alarm"));
        d.unknownM.alarm = static_cast<int>(u.integer("alarm", 1, 32, 0));
        if (d.unknownM.acknowledge == (d.unknownM.alarm > 0))
            u.fail(problem("unknown-m"));
    }

    for (const JsonNode& n : root.optionalArray("interlocks")) {
        n.expectObject({"name", "when", "alarm", "work", "feed_hold", "data_hold", "start_inhibit",
                        "stop_program", "reset_program", "estop", "latch", "off", "override_max"});
        InterlockDef il;
        il.path = n.path();
        il.name = n.string("name");
        checkName(n, "name", il.name);
        il.when = n.string("when");
        il.alarm = static_cast<int>(n.integer("alarm", 1, 32, 0));
        il.work = static_cast<int>(n.integer("work", 1, 32, 0));
        il.feedHold = n.boolean("feed_hold", false);
        il.dataHold = n.boolean("data_hold", false);
        il.startInhibit = n.boolean("start_inhibit", false);
        il.stopProgram = n.boolean("stop_program", false);
        il.resetProgram = n.boolean("reset_program", false);
        il.estop = n.boolean("estop", false);
        il.latch = n.boolean("latch", false);
        il.off = n.strings("off");
        if (n.has("override_max")) {
            const int pct = static_cast<int>(n.integer("override_max", 0, 100));
            il.overrideMaxCode = percentToCode(pct);
            if (il.overrideMaxCode < 0)
                n.failAt("override_max", problem("override.step", {std::to_string(pct)}));
        }
        d.interlocks.push_back(std::move(il));
    }

    for (const JsonNode& n : root.optionalArray("keys")) {
        n.expectObject({"key", "text", "when", "set", "reset", "toggle", "pulse"});
        KeyDef k;
        k.path = n.path();
        k.key = static_cast<int>(n.integer("key", 1, 12));
        for (const KeyDef& o : d.keys)
            if (o.key == k.key)
                n.failAt("key", problem("key.twice", {std::to_string(k.key)}));
        k.text = n.string("text", "");
        k.when = n.string("when", "");
        k.actions = readActions(n);
        if (k.actions.empty())
            n.fail(problem("key.action"));
        d.keys.push_back(std::move(k));
    }
    for (const JsonNode& n : root.optionalArray("leds")) {
        n.expectObject({"key", "green", "red"});
        LedDef l;
        l.path = n.path();
        l.key = static_cast<int>(n.integer("key", 1, 12));
        for (const LedDef& o : d.leds)
            if (o.key == l.key)
                n.failAt("key", problem("led.twice", {std::to_string(l.key)}));
        l.green = n.string("green", "");
        l.red = n.string("red", "");
        d.leds.push_back(std::move(l));
    }
    for (const auto& [key, list] : {std::pair{"alarms", &d.alarms}, std::pair{"work", &d.work}}) {
        for (const JsonNode& n : root.optionalArray(key)) {
            n.expectObject({"k", "when"});
            MessageDef m;
            m.path = n.path();
            m.k = static_cast<int>(n.integer("k", 1, 32));
            for (const MessageDef& o : *list)
                if (o.k == m.k)
                    n.failAt("k", problem("message.twice", {std::to_string(m.k)}));
            m.when = n.string("when");
            list->push_back(std::move(m));
        }
    }

    if (root.has("positioner")) {
        const JsonNode p = root.child("positioner");
        p.expectObject();
        const auto addSlot = [&](const JsonNode& owner, const std::string& key,
                                 const std::string& fullKey) {
            const auto a = slotAddress(fullKey);
            if (!a)
                owner.failAt(key, problem("slot.unknown", {[] {
                                 std::string s;
                                 for (const std::string& k : slotKeys())
                                     s += (s.empty() ? "" : ", ") + k;
                                 return s;
                             }()}));
            SlotDef s;
            s.word = a->word;
            s.bit = a->bit;
            s.key = fullKey;
            s.when = owner.string(key);
            s.path = owner.child(key).path();
            d.slotDefs.push_back(std::move(s));
        };
        for (const std::string& key : p.keys()) {
            if (key == "x" || key == "z") {
                const JsonNode ax = p.child(key);
                ax.expectObject();
                for (const std::string& k : ax.keys())
                    addSlot(ax, k, key + "." + k);
            } else if (key == "mode") {
                for (const JsonNode& r : p.child("mode").elements()) {
                    r.expectObject({"code", "when"});
                    ModeRule m;
                    m.path = r.path();
                    m.code = static_cast<int>(r.integer("code", 0, 7));
                    m.when = r.string("when");
                    d.modeRules.push_back(std::move(m));
                }
            } else if (key == "override") {
                const JsonNode o = p.child("override");
                o.expectObject({"from_plc", "code"});
                d.override_.present = true;
                d.override_.path = o.path();
                d.override_.fromPlc = o.string("from_plc");
                const std::vector<std::string> bits = o.strings("code");
                if (bits.size() != 4)
                    o.failAt("code", problem("override.code"));
                for (std::size_t i = 0; i < 4; ++i)
                    d.override_.code[i] = bits[i];
            } else if (key == "bits") {
                const JsonNode b = p.child("bits");
                b.expectObject();
                for (const std::string& k : b.keys()) {
                    const auto a = parseZ(k);
                    if (!a || a->word < 1011 || a->word > 1013)
                        b.failAt(k, problem("bits.word"));
                    SlotDef s;
                    s.word = a->word;
                    s.bit = a->bit;
                    s.key = k;
                    s.when = b.string(k);
                    s.path = b.child(k).path();
                    d.slotDefs.push_back(std::move(s));
                }
            } else {
                addSlot(p, key, key);
            }
        }
        for (std::size_t i = 0; i < d.slotDefs.size(); ++i)
            for (std::size_t j = 0; j < i; ++j)
                if (d.slotDefs[i].word == d.slotDefs[j].word &&
                    d.slotDefs[i].bit == d.slotDefs[j].bit)
                    throw DescriptionError(source, d.slotDefs[i].path,
                                           problem("slot.same-bit", {d.slotDefs[j].path}));
    }

    if (root.has("equipment")) {
        root.child("equipment").expectObject();
        d.equipment = std::make_shared<const Json>(d.document->at("equipment"));
    } else {
        d.equipment = std::make_shared<const Json>(Json::object());
    }
    // What the prove-out of programs knows of the machine (its geometry, what
    // its M functions do): read by core/proveout from `document`.
    if (root.has("proveout"))
        root.child("proveout").expectObject();
    return d;
}

namespace {
std::string resourcePath(std::string_view name) {
    return "machines/" + std::string(name) + ".json";
}
} // namespace

bool descriptionExists(std::string_view name) {
    return resources::find(resourcePath(name)).has_value();
}

std::vector<std::string> descriptionNames() {
    std::vector<std::string> names;
    for (const resources::Resource& r : resources::under("machines/")) {
        std::string_view p = r.path.substr(9);
        if (p.size() > 5 && p.substr(p.size() - 5) == ".json")
            names.emplace_back(p.substr(0, p.size() - 5));
    }
    std::sort(names.begin(), names.end());
    return names;
}

MachineDescription loadDescription(std::string_view nameOrPath) {
    if (nameOrPath.size() > 5 && nameOrPath.substr(nameOrPath.size() - 5) == ".json") {
        std::ifstream f{std::string(nameOrPath), std::ios::binary};
        if (!f)
            throw DescriptionError(std::string(nameOrPath), "", problem("file.cannot-read"));
        std::ostringstream s;
        s << f.rdbuf();
        return readDescription(s.str(), std::string(nameOrPath));
    }
    const auto text = resources::find(resourcePath(nameOrPath));
    if (!text) {
        std::string known;
        for (const std::string& n : descriptionNames())
            known += (known.empty() ? "" : ", ") + n;
        throw DescriptionError(std::string(nameOrPath), "", problem("file.unknown-machine", {known}));
    }
    return readDescription(*text, resourcePath(nameOrPath));
}

} // namespace k528::plc
