// k528 panel [--profile NAME|PATH] [--db PATH] [--machine] [--keys "KEY KEY …"] [--json] [--lang ru|en]
// (shared/spec/cli.md; the screens in docs/panel.md).
//
// A freshly powered-on controller on the engine's ideal machine
// (engine/ideal_machine.h) — or, with --machine, on the simulated machine of
// the profile (machine/simulation.h: its PLC, drives and pendant, whose
// buttons PUSH:/HOLD:/PULL: tokens press, whose K923 and PLC FAULT:/CLEAR:
// tokens break and mend) — the K923 model over it (panel/panel.h), the keys
// pressed in order; WAIT:S lets S seconds of machine time pass; PLCMODE:N
// makes the PLC impose mode N. Prints the four LCD lines, or JSON with the LEDs.
#include "args.h"
#include "cli.h"
#include "cli_texts.h"
#include "machine_buttons.h"
#include "machine_profile.h"
#include "engine/positioner.h"
#include "engine/ideal_machine.h"
#include "machine/simulation.h"
#include "plc/description.h"
#include "program_cli.h"
#include "panel/keys.h"
#include "panel/panel.h"
#include "profile/builtin.h"
#include "profile/text_format.h"
#include "util/json.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace k528::cli {

namespace {


// A fault of the K923's health or the PLC (--machine): FAULT:NAME injects it,
// CLEAR:NAME mends it (docs/panel.md, table М.1 of appendix М).
struct FaultStep {
    machine::FaultSpec fault;
    bool clear = false;
};
struct HealthFaultName {
    std::string_view name;
    machine::Fault kind;
    int detail;
};
constexpr HealthFaultName kHealthFaults[] = {
    {"PLC_LINK", machine::Fault::K923, static_cast<int>(machine::K923Part::PlcLink)},
    {"BP_LINK", machine::Fault::K923, static_cast<int>(machine::K923Part::PositionerLink)},
    {"RAM", machine::Fault::K923, static_cast<int>(machine::K923Part::Ram)},
    {"RESIDENT", machine::Fault::K923, static_cast<int>(machine::K923Part::Resident)},
    {"PLC_STOP", machine::Fault::PlcStopped, 0},
};
constexpr std::string_view kHealthFaultList = "PLC_LINK BP_LINK RAM RESIDENT PLC_STOP";

// PLCMODE:N: the PLC imposes mode N (1..7) on Z1000.8-10; PLCMODE:0 lets go.
struct PlcModeStep {
    int code = 0;
};

// One token of --keys: a key press, a wait in milliseconds, a machine button,
// a fault, a mode the PLC imposes.
using Step = std::variant<panel::KeyPress, std::int64_t, ButtonStep, FaultStep, PlcModeStep>;

// FAULT:NAME, CLEAR:NAME.
std::optional<Step> parseFault(const std::string& token, std::string& error) {
    const std::string t = upperToken(token);
    const auto colon = t.find(':');
    const std::string name = t.substr(colon + 1);
    for (const HealthFaultName& f : kHealthFaults)
        if (f.name == name)
            return FaultStep{machine::FaultSpec(f.kind, engine::AxisId::X, f.detail),
                             t.compare(0, colon, "CLEAR") == 0};
    error = cliText("keys.fault", {token, std::string(kHealthFaultList)});
    return std::nullopt;
}

// PLCMODE:N, N = 0..7.
std::optional<Step> parsePlcMode(const std::string& token, std::string& error) {
    const std::string n = token.substr(8);
    if (n.size() == 1 && n[0] >= '0' && n[0] <= '7')
        return PlcModeStep{n[0] - '0'};
    error = cliText("keys.plc-mode", {token});
    return std::nullopt;
}

std::optional<Step> parseStep(const std::string& token, std::string& error) {
    {
        const std::string t = upperToken(token);
        if (t.rfind("FAULT:", 0) == 0 || t.rfind("CLEAR:", 0) == 0)
            return parseFault(token, error);
        if (t.rfind("PLCMODE:", 0) == 0)
            return parsePlcMode(token, error);
    }
    {
        const std::string t = upperToken(token.substr(0, 5));
        if (t.rfind("PUSH:", 0) == 0 || t.rfind("HOLD:", 0) == 0 || t.rfind("PULL:", 0) == 0) {
            const auto b = parseButton(token, error);
            return b ? std::optional<Step>(Step{*b}) : std::nullopt;
        }
    }
    if (token.size() > 5 &&
        (token.compare(0, 5, "WAIT:") == 0 || token.compare(0, 5, "wait:") == 0)) {
        const auto s = parseNumber(std::string_view(token).substr(5));
        if (!s || *s < 0 || !std::isfinite(*s) || *s > 1e6) {
            error = cliText("keys.wait", {token});
            return std::nullopt;
        }
        return Step{static_cast<std::int64_t>(std::llround(*s * 1000.0))};
    }
    if (const auto k = panel::parseKey(token))
        return Step{*k};
    error = cliText("keys.unknown", {token});
    return std::nullopt;
}

// What the keys act on: the ideal machine, or the simulated one (--machine).
class Bench {
public:
    virtual ~Bench() = default;
    virtual engine::Positioner& controller() = 0;
    virtual void advance(std::int64_t ms) = 0;
    // PLCMODE:N — the PLC's mode code, 0 = the K923 chooses.
    virtual void imposeMode(int code) = 0;
};

class IdealBench final : public Bench {
public:
    explicit IdealBench(const profile::MachineProfile& p) : ctl_(p), m_(ctl_) {
        ctl_.powerOn();
        m_.advance(10); // the PLC's first scans, as `k528 run` does
    }
    engine::Positioner& controller() override { return ctl_; }
    void advance(std::int64_t ms) override { m_.advance(ms); }
    void imposeMode(int code) override {
        m_.setModeCode(code);
        m_.advance(kSeenMs);
    }

private:
    engine::Positioner ctl_;
    engine::IdealMachine m_;
};

class MachineBench final : public Bench {
public:
    explicit MachineBench(const profile::MachineProfile& p) : sim_(p) {
        sim_.powerOn();
        sim_.advance(10);
    }
    engine::Positioner& controller() override { return sim_.controller(); }
    void advance(std::int64_t ms) override { sim_.advance(ms); }
    void imposeMode(int code) override {
        sim_.plc().imposeMode(code == 0 ? -1 : code); // 0: the description's rules again
        sim_.advance(kSeenMs);
    }
    void fault(const FaultStep& f) {
        f.clear ? sim_.clear(f.fault) : sim_.inject(f.fault);
        sim_.advance(kSeenMs);
    }
    panel::Health health() const { return sim_.k923Health(); }
    // Button steps exist only with --machine (checked before anything runs).
    void button(const ButtonStep& b) { pressButton(sim_, b); }

private:
    machine::Simulation sim_;
};

Json ledList(std::uint32_t bits, int count) {
    Json a = Json::array();
    for (int k = 1; k <= count; ++k)
        if ((bits >> (k - 1)) & 1u)
            a.emplace_back(k);
    return a;
}

} // namespace

int runPanel(std::span<const std::string> argv) {
    const Args args(argv, {"--json", "--machine"}, {"--profile", "--db", "--keys", "--lang"});
    if (!args.ok())
        return usageError(args.error());
    if (!args.positional().empty())
        return usageError(cliText("panel.no-file"));
    // The LCD is the panel's own (Russian); --lang is the language of the messages on stderr.
    Lang lang = Lang::Ru;
    if (const auto l = args.value("--lang"); l && !parseLang(*l, lang))
        return usageError(cliText("opt.lang", {*l}));
    const bool ru = lang == Lang::Ru;

    const bool onMachine = args.has("--machine");
    std::vector<Step> steps;
    for (const std::string& token : panel::splitKeys(args.value("--keys").value_or(""))) {
        std::string error;
        const auto step = parseStep(token, error);
        if (!step)
            return usageError(error);
        if (std::holds_alternative<ButtonStep>(*step) && !onMachine)
            return usageError(cliText("panel.button", {token}));
        if (std::holds_alternative<FaultStep>(*step) && !onMachine)
            return usageError(cliText("panel.fault", {token}));
        steps.push_back(*step);
    }

    const std::optional<profile::MachineProfile> loaded = machineProfile(args);
    if (!loaded)
        return ExitUsage;
    const profile::MachineProfile& profile = *loaded;

    std::unique_ptr<Bench> bench;
    MachineBench* machineBench = nullptr;
    try {
        if (onMachine) {
            auto m = std::make_unique<MachineBench>(profile);
            machineBench = m.get();
            bench = std::move(m);
        } else {
            bench = std::make_unique<IdealBench>(profile);
        }
    } catch (const plc::DescriptionError& e) {
        printDescriptionError(e, lang);
        return ExitUsage;
    }
    panel::Panel k923(bench->controller());
    // The trainer's lock of the constants (setting constants.lock): as the
    // studio's K923, F5 (РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ) and ENTER on its screen
    // are refused, said on stderr, and the keys after them go on.
    const std::string lockedFor = profile.simulation.getString("constants.lock", "");
    const auto refusedByLock = [&](const panel::KeyPress& k) {
        if (lockedFor.empty())
            return false;
        const bool inC = bench->controller().mode() == engine::Mode::MachineData;
        return (k.key == panel::Key::F5 && !k.shift && !inC) || (k.key == panel::Key::Enter && inC);
    };
    try {
        for (const Step& s : steps) {
            if (const auto* k = std::get_if<panel::KeyPress>(&s)) {
                if (refusedByLock(*k))
                    std::fprintf(stderr, "%s\n",
                                 cliText("panel.locked", {k->key == panel::Key::F5 ? "F5" : "ENTER", lockedFor}, ru)
                                     .c_str());
                else
                    k923.press(*k);
            }
            else if (const auto* b = std::get_if<ButtonStep>(&s))
                machineBench->button(*b);
            else if (const auto* f = std::get_if<FaultStep>(&s))
                machineBench->fault(*f);
            else if (const auto* m = std::get_if<PlcModeStep>(&s))
                bench->imposeMode(m->code);
            else
                bench->advance(std::get<std::int64_t>(s));
            if (machineBench)
                k923.setHealth(machineBench->health()); // a fault may have changed the K923
        }
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "k528: %s\n", e.what()); // a fault this machine cannot have
        return ExitUsage;
    }

    const panel::Display d = k923.display();
    if (!args.has("--json")) {
        for (const std::string& line : d.lcd.lines)
            std::printf("%s\n", line.c_str());
        return ExitOk;
    }
    Json out;
    Json lines = Json::array();
    for (const std::string& line : d.lcd.lines)
        lines.emplace_back(line);
    out["lines"] = std::move(lines);
    Json leds;
    leds["green"] = ledList(d.leds.green, 12);
    leds["red"] = ledList(d.leds.red, 12);
    // Extensions (docs/panel.md): the L keys lit and the SHIFT LED.
    leds["override"] = ledList(d.leds.override, 4);
    leds["shift"] = d.leds.shift;
    out["leds"] = std::move(leds);
    // Extension: the blinking field, 0-based row and column, or null.
    if (d.lcd.blinkLength > 0) {
        Json blink;
        blink["row"] = d.lcd.blinkRow;
        blink["column"] = d.lcd.blinkColumn;
        blink["length"] = d.lcd.blinkLength;
        out["blink"] = std::move(blink);
    } else {
        out["blink"] = nullptr;
    }
    std::printf("%s\n", json::dump(out).c_str());
    return ExitOk;
}

} // namespace k528::cli
