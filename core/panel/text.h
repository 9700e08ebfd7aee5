// Text helpers of the K923 screens: the 4×20 canvas the screens draw on, the
// number formats of the panel (coordinates in the axis discrete, feeds in
// mm/min, seconds), word wrap for the two-line messages, and the entry of a
// value from the keyboard (digits, point, sign, the arithmetic keys and «=»
// of table 3). Pure text: no engine here. Layouts: docs/panel.md.
#pragma once

#include "panel/display.h"
#include "panel/keys.h"
#include "units/units.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace k528::panel {

// The LCD as the screens draw it: 4 rows of 20 cells, 1-based columns.
class Canvas {
public:
    Canvas();
    // Writes `text` (UTF-8) from column `col` (1..20) of `row` (0..3); what
    // passes column 20 is cut.
    void put(int row, int col, std::string_view text);
    // Writes `text` so that its last character lands on `lastCol`.
    void putRight(int row, int lastCol, std::string_view text);
    void clearRow(int row);
    // The blinking field (2.6.7 «мерцание»): `len` cells from `col`.
    void blink(int row, int col, int len);
    void noBlink() { blinkLen_ = 0; }
    int blinkRow() const { return blinkRow_; }
    int blinkLength() const { return blinkLen_; }
    char32_t at(int row, int col) const;
    std::string line(int row) const; // exactly 20 code points
    Lcd lcd() const;

private:
    std::array<std::array<char32_t, kLcdColumns>, kLcdRows> cells_{};
    int blinkRow_ = 0, blinkCol_ = 1, blinkLen_ = 0;
};

// Number of code points.
int textWidth(std::string_view s);
// `s` right-aligned in `width` cells (longer text is returned whole).
std::string padLeft(std::string_view s, int width);
// Splits `text` into lines of at most `width` code points: breaks after a
// blank (dropped), or after '/', '.', ',', '-' when that keeps more on the
// line; a word longer than a line is cut.
std::vector<std::string> wrapText(std::string_view text, int width);

// Display discretes with the axis' decimals: "234.567", "-1065.124".
std::string formatCoordinate(std::int64_t disc, const units::AxisScale& s);
// A feed in display discretes per minute as mm/min with 2 decimals
// ("10.00", "1000.00"); with `maxWidth` > 0, fewer decimals when the text
// would be wider ("1000.0", "12000").
std::string formatFeed(std::int64_t discPerMin, const units::AxisScale& s, int maxWidth = 0);
// Milliseconds as seconds with 3 decimals: 1000 -> "1.000".
std::string formatSeconds(std::int64_t ms);

// The value of a typed text: numbers with an optional decimal point and the
// operations + - * / evaluated from left to right (table 3: «+ - * /
// Арифметические операции», «= Присвоение результата»), a leading '-' or
// one after an operation being a sign. The result is scaled by
// 10^decimals (decimals 0..6) and rounded half away from zero; nullopt for
// a malformed text, a number with more decimals than `decimals`, a
// division by zero or a result beyond ±9.2·10^18.
std::optional<std::int64_t> evaluateEntry(std::string_view text, int decimals);
// The scaled value as text with `decimals` digits after the point ("12.300").
std::string formatScaled(std::int64_t scaled, int decimals);

// What a key types into an entry: '0'..'9', '.', '+', '-', '*', '/', '=',
// 'R' (the % key), or 0 for a key that types nothing.
char typedChar(Key k);

// A value being typed on the panel.
class Entry {
public:
    enum class Kind {
        Digits,     // 0..9 only (numbers of programs, parameters, the password)
        Calculator, // digits, '.', + - * /; '=' replaces the text by its value
        Frame,      // a frame word's value: R first, or [-]digits[.digits]
        Operand,    // an operand of a computational frame: R…, or [-]digits
        OpOperand,  // an operation then an operand: "+12", "*R99"
    };

    bool active() const { return active_; }
    const std::string& text() const { return text_; }
    // Starts typing (an empty text).
    void start(Kind kind, int maxChars, int decimals = 0);
    void stop() { active_ = false, text_.clear(); }
    // Types the key; false if the key types nothing in this kind of entry
    // (the caller may give it another meaning). Characters beyond maxChars
    // are ignored (consumed).
    bool type(Key k);
    // Starts typing with `k` when nothing is typed yet: true if `k` typed
    // something (the entry stays inactive for a key that types nothing).
    bool begin(Key k, Kind kind, int maxChars, int decimals = 0);
    // DEL while typing: the last character.
    void backspace();
    // «=» (Присвоение результата): a Calculator text becomes its value, with
    // the entry's decimals; false (text kept) if it has none.
    bool assignResult();
    Kind kind() const { return kind_; }

    // A key at a prompt for a number: ВВОД answers it (`given` gets the text
    // typed, the entry stops), ПАР withdraws it (the entry stops), DEL takes
    // back the last character, any other key is typed. The screen closes its
    // prompt unless the answer is still being typed.
    enum class Answer { Typing, Given, Withdrawn };
    Answer answer(Key k, std::string& given);

private:
    Kind kind_ = Kind::Digits;
    int max_ = 20;
    int decimals_ = 0;
    bool active_ = false;
    std::string text_;
};

} // namespace k528::panel
