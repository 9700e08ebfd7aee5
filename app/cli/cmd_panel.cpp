// k528 panel [--profile NAME|PATH] [--keys "KEY KEY …"] [--json]
// (shared/spec/cli.md; the screens in docs/panel.md).
//
// A freshly powered-on controller on the ideal machine of `k528 run`
// (engine/ideal_machine.h), the K923 model over it (panel/panel.h), the keys
// pressed in order; WAIT:S lets S seconds of machine time pass. Prints the
// four LCD lines, or JSON with the LEDs.
#include "args.h"
#include "cli.h"
#include "machine_profile.h"
#include "engine/controller.h"
#include "engine/ideal_machine.h"
#include "panel/keys.h"
#include "panel/panel.h"
#include "profile/builtin.h"
#include "profile/text_format.h"
#include "util/json.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace k528::cli {

namespace {

// One token of --keys: a key press or a wait in milliseconds.
using Step = std::variant<panel::KeyPress, std::int64_t>;

std::optional<Step> parseStep(const std::string& token, std::string& error) {
    if (token.size() > 5 &&
        (token.compare(0, 5, "WAIT:") == 0 || token.compare(0, 5, "wait:") == 0)) {
        const auto s = parseNumber(std::string_view(token).substr(5));
        if (!s || *s < 0 || !std::isfinite(*s) || *s > 1e6) {
            error = "bad time in --keys token '" + token + "': WAIT:S takes seconds, 0..1000000";
            return std::nullopt;
        }
        return Step{static_cast<std::int64_t>(std::llround(*s * 1000.0))};
    }
    if (const auto k = panel::parseKey(token))
        return Step{*k};
    error = "unknown key '" + token +
            "' in --keys (keys: F1..F8 K1..K12 L1..L4 UP DOWN LEFT RIGHT MODE HELP ESC SHIFT PAR "
            "ACK INS DEL "
            "ENTER 0..9 . + - * / = % !, SHIFT+KEY, WAIT:S)";
    return std::nullopt;
}

json::Array ledList(std::uint32_t bits, int count) {
    json::Array a;
    for (int k = 1; k <= count; ++k)
        if ((bits >> (k - 1)) & 1u)
            a.emplace_back(k);
    return a;
}

} // namespace

int runPanel(std::span<const std::string> argv) {
    const Args args(argv, {"--json"}, {"--profile", "--db", "--keys"});
    if (!args.ok())
        return usageError(args.error());
    if (!args.positional().empty())
        return usageError("panel takes no file: give the keys with --keys \"KEY KEY ...\"");

    std::vector<Step> steps;
    for (const std::string& token : panel::splitKeys(args.value("--keys").value_or(""))) {
        std::string error;
        const auto step = parseStep(token, error);
        if (!step)
            return usageError(error);
        steps.push_back(*step);
    }

    const std::optional<profile::MachineProfile> loaded = machineProfile(args);
    if (!loaded)
        return ExitUsage;
    const profile::MachineProfile& profile = *loaded;

    engine::Controller controller(profile);
    engine::IdealMachine machine(controller);
    controller.powerOn();
    machine.advance(10); // the PLC's first scans, as `k528 run` does
    panel::Panel k923(controller);
    for (const Step& s : steps) {
        if (const auto* k = std::get_if<panel::KeyPress>(&s))
            k923.press(*k);
        else
            machine.advance(std::get<std::int64_t>(s));
    }

    const panel::Display d = k923.display();
    if (!args.has("--json")) {
        for (const std::string& line : d.lcd.lines)
            std::printf("%s\n", line.c_str());
        return ExitOk;
    }
    json::Value out;
    json::Array lines;
    for (const std::string& line : d.lcd.lines)
        lines.emplace_back(line);
    out.set("lines", std::move(lines));
    json::Value leds;
    leds.set("green", ledList(d.leds.green, 12));
    leds.set("red", ledList(d.leds.red, 12));
    // Extensions (docs/panel.md): the L keys lit and the SHIFT LED.
    leds.set("override", ledList(d.leds.override, 4));
    leds.set("shift", d.leds.shift);
    out.set("leds", std::move(leds));
    // Extension: the blinking field, 0-based row and column, or null.
    if (d.lcd.blinkLength > 0) {
        json::Value blink;
        blink.set("row", d.lcd.blinkRow);
        blink.set("column", d.lcd.blinkColumn);
        blink.set("length", d.lcd.blinkLength);
        out.set("blink", std::move(blink));
    } else {
        out.set("blink", nullptr);
    }
    std::printf("%s\n", out.dump().c_str());
    return ExitOk;
}

} // namespace k528::cli
