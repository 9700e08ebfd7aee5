#include "cli_texts.h"
#include "machine_buttons.h"

#include "args.h"

#include <algorithm>
#include <cmath>

namespace k528::cli {

namespace {

constexpr std::string_view kButtonList =
    "DRIVES_ON START STOP RESET X+ X- Z+ Z- RAPID CHUCK ESTOP";

} // namespace

std::string upperToken(std::string_view s) {
    std::string u(s);
    for (char& c : u)
        if (c >= 'a' && c <= 'z')
            c = static_cast<char>(c - 'a' + 'A');
    return u;
}

// PUSH:NAME, HOLD:NAME:S, PULL:ESTOP.
std::optional<ButtonStep> parseButton(const std::string& token, std::string& error) {
    const std::string t = upperToken(token);
    const auto colon = t.find(':');
    const std::string verb = t.substr(0, colon);
    std::string rest = t.substr(colon + 1);
    ButtonStep b;
    b.holdMs = kPushMs;
    if (verb == "HOLD") {
        const auto c2 = rest.rfind(':');
        const auto s = c2 == std::string::npos ? std::nullopt
                                               : parseNumber(std::string_view(rest).substr(c2 + 1));
        if (!s || *s <= 0 || !std::isfinite(*s) || *s > 1e5) {
            error = cliText("keys.hold", {token});
            return std::nullopt;
        }
        b.holdMs = std::max<std::int64_t>(1, std::llround(*s * 1000.0));
        rest = rest.substr(0, c2);
    }
    if (rest == "ESTOP") {
        if (verb == "HOLD") {
            error = cliText("keys.estop-hold", {token});
            return std::nullopt;
        }
        b.pull = verb == "PULL";
        return b;
    }
    if (verb == "PULL") {
        error = cliText("keys.pull", {token});
        return std::nullopt;
    }
    if (const auto button = machine::buttonFromName(rest)) {
        b.button = *button;
        return b;
    }
    error = cliText("keys.button", {token, std::string(kButtonList)});
    return std::nullopt;
}

void pressButton(machine::Simulation& sim, const ButtonStep& b) {
    if (!b.button) {
        b.pull ? sim.releaseEmergencyStop() : sim.pressEmergencyStop();
        sim.advance(kSeenMs);
        return;
    }
    sim.press(*b.button);
    sim.advance(b.holdMs);
    sim.release(*b.button);
    sim.advance(kSeenMs);
}

} // namespace k528::cli
