// What the K923 shows: the 4×20 LCD with an optional blinking position, and
// its 17 LEDs. The panel model (panel/panel.h) produces it; the desktop
// widget and `k528 panel` render it.
//
// LEDs (the manual names 17 and maps K1..K12 in table 4; the rest is our
// decision, docs/panel.md): K1..K12 each have a two-colour LED driven by
// Z1906 (green) and Z1907 (red); L1..L4 each have a LED showing the override
// key in effect; one LED shows SHIFT engaged. 12 + 4 + 1 = 17.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace k528::panel {

inline constexpr int kLcdRows = 4;
inline constexpr int kLcdColumns = 20;

struct Lcd {
    // Exactly 20 characters (Unicode code points, UTF-8 encoded) per line.
    std::array<std::string, kLcdRows> lines;
    // The blinking field: row 0..3, columns [blinkColumn, blinkColumn+blinkLength);
    // blinkLength 0 = nothing blinks.
    int blinkRow = 0;
    int blinkColumn = 0;
    int blinkLength = 0;

    friend bool operator==(const Lcd&, const Lcd&) = default;
};

struct Leds {
    std::uint16_t green = 0; // bit k-1: K<k> green (k = 1..12)
    std::uint16_t red = 0;   // bit k-1: K<k> red
    std::uint8_t override = 0; // bit n-1: L<n> in effect
    bool shift = false;

    bool greenOn(int k) const { return (green >> (k - 1)) & 1u; }
    bool redOn(int k) const { return (red >> (k - 1)) & 1u; }
    bool overrideOn(int n) const { return (override >> (n - 1)) & 1u; }
    friend bool operator==(const Leds&, const Leds&) = default;
};

struct Display {
    Lcd lcd;
    Leds leds;
    friend bool operator==(const Display&, const Display&) = default;
};

} // namespace k528::panel
