// The character generator of the K923's LCD: 5×8-dot cells in the style of
// the HD44780 / KS0066 controllers with a Cyrillic ROM. Glyphs are 5×7 (the
// eighth row is the cursor line) and cover printable ASCII 0x20..0x7E,
// Cyrillic А..Я, а..я, Ё, ё and the symbols of the manual's screens
// (▲ ▼ ◀ ► ← → ↑ ↓ № ° « » ± ½ and the block █ used for blinking).
//
// Pure data and lookup, no Qt: the desktop widget draws these dots, and
// `k528 panel` or a profile check can ask whether the LCD can show a text.
// The glyph table (lcd_font.cpp) is written as readable rows of '#' and '.'.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <utility>

namespace k528::panel {

inline constexpr int kGlyphColumns = 5; // dots across a cell
inline constexpr int kGlyphRows = 8;    // dots down a cell (row 7: cursor line)

// One character cell: rows[y] holds the dots of row y (0 = top); bit 4 is the
// leftmost dot (x = 0), bit 0 the rightmost (x = 4).
struct Glyph {
    std::array<std::uint8_t, kGlyphRows> rows{};

    bool dot(int x, int y) const {
        return x >= 0 && x < kGlyphColumns && y >= 0 && y < kGlyphRows &&
               ((rows[static_cast<std::size_t>(y)] >> (kGlyphColumns - 1 - x)) & 1u) != 0;
    }
    int litDots() const;
    friend bool operator==(const Glyph&, const Glyph&) = default;
};

// The code point the LCD draws for `cp`: typographic variants become the
// character the ROM has (◄ -> ◀, ▶ -> ►, – — − -> '-', “ ” „ -> '"',
// ‘ ’ -> '\'', no-break space -> ' '); every other code point is itself.
char32_t lcdCanonical(char32_t cp);

// The glyph of `cp` (after lcdCanonical), or nullopt if the LCD has none.
std::optional<Glyph> lcdGlyph(char32_t cp);
// The glyph of `cp`, or the placeholder box for a character the LCD lacks.
Glyph lcdGlyphOrPlaceholder(char32_t cp);
bool lcdCanShow(char32_t cp);

// A hollow 5×7 box: what the LCD shows for a character it has no glyph for.
Glyph lcdPlaceholderGlyph();
// All 5×8 dots lit (█): the blinking field's other phase.
Glyph lcdBlockGlyph();

// Every code point with a glyph of its own or a declared look-alike, in
// table order (ASCII, Cyrillic capitals, small letters, symbols).
std::span<const char32_t> lcdCharacters();

// The declared look-alikes: (character, the character whose glyph it uses),
// e.g. (U'А', U'A') – Cyrillic А is drawn as Latin A, as in the real ROMs.
// Any two other characters have different glyphs.
std::span<const std::pair<char32_t, char32_t>> lcdLookAlikes();

// The first character of the UTF-8 text `text` the LCD cannot show, or
// nullopt if it can show all of them (malformed bytes count as U+FFFD).
std::optional<char32_t> lcdFirstUnsupported(std::string_view text);

} // namespace k528::panel
