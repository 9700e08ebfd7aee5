// The push-buttons of the simulated machine's pendant as --keys tokens
// (PUSH:NAME, HOLD:NAME:S, PULL:ESTOP), shared by `k528 panel --machine`
// and `k528 serve` (a served controller can be driven to run a program).
#pragma once

#include "machine/simulation.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace k528::cli {

// A push-button of the simulated machine's pendant (--machine): pressed for
// holdMs, then released; the E-stop mushroom latches (PUSH:ESTOP) until it is
// pulled (PULL:ESTOP).
struct ButtonStep {
    std::optional<machine::Button> button; // nullopt: the E-stop mushroom
    std::int64_t holdMs = 0;
    bool pull = false;
};
constexpr std::int64_t kPushMs = 100; // an operator's push
constexpr std::int64_t kSeenMs = 30;  // time for the PLC's debounce to see the release

// PUSH:NAME, HOLD:NAME:S, PULL:ESTOP; nullopt and `error` for a bad token.
std::optional<ButtonStep> parseButton(const std::string& token, std::string& error);
// Presses (and releases) the button on `sim`, advancing it meanwhile.
void pressButton(machine::Simulation& sim, const ButtonStep& b);
std::string upperToken(std::string_view s);

} // namespace k528::cli
