// The keys of the K923 panel (manual 2.3, table 3) and their names on the
// command line (`k528 panel --keys`, shared/spec/cli.md).
//
// The function keyboard has 26 keys: F1..F8, K1..K12, L1..L4, MODE and HELP;
// the system keyboard has the cursor keys, ESC, SHIFT, PAR, ACK, INS, DEL,
// ENTER, the digits, '.', the arithmetic keys, '=', '%' (types "R") and '!'.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace k528::panel {

enum class Key {
    F1, F2, F3, F4, F5, F6, F7, F8,
    K1, K2, K3, K4, K5, K6, K7, K8, K9, K10, K11, K12,
    L1, L2, L3, L4,
    Up, Down, Left, Right,
    Mode, Help, Esc, Shift, Par, Ack, Ins, Del, Enter,
    D0, D1, D2, D3, D4, D5, D6, D7, D8, D9,
    Point, Plus, Minus, Multiply, Divide, Equals, Percent, Exclamation,
};

inline constexpr int kKeyCount = static_cast<int>(Key::Exclamation) + 1;

// A key press, possibly held with SHIFT ("SHIFT+UP").
struct KeyPress {
    Key key;
    bool shift = false;
    friend bool operator==(const KeyPress&, const KeyPress&) = default;
};

// The command-line name of a key: "F1", "K12", "UP", "ENTER", "0", ".", "%" ...
std::string_view keyName(Key k);
// A key by its command-line name (case-insensitive for letters); nullopt if unknown.
std::optional<Key> keyFromName(std::string_view name);
// "UP" or "SHIFT+UP"; parses what formatKey writes.
std::string formatKey(const KeyPress& k);
std::optional<KeyPress> parseKey(std::string_view text);

// Splits a --keys string ("F2 SHIFT+UP 1 2 ENTER WAIT:2.5") into tokens at
// blanks; WAIT:S tokens are kept as they are for the caller.
std::vector<std::string> splitKeys(std::string_view keys);

// The digit 0..9 of a digit key, or -1.
int digitOf(Key k);
// 1..8 for F1..F8, 1..12 for K1..K12, 1..4 for L1..L4; 0 otherwise.
int functionNumber(Key k);
bool isFunctionKey(Key k); // F1..F8
bool isKKey(Key k);        // K1..K12
bool isLKey(Key k);        // L1..L4

} // namespace k528::panel
