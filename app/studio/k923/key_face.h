// What is printed on each key of the K923 and what the key does: the legends
// (as the manual names the keys; the mode keys carry their mode's short name
// from the screens), the key's colour group, its LED, and the translated
// description for the tooltip (manual table 3).
#pragma once

#include "panel/keys.h"

#include <QString>

namespace k528::studio {

enum class KeyStyle {
    Mode,     // F1..F8
    Machine,  // K1..K12, L1..L4
    Control,  // MODE HELP SHIFT PAR ACK INS DEL and the cursor keys
    Escape,   // ESC
    Enter,    // ENTER
    Digit,    // 0..9 and '.'
    Operator, // + - * / = % !
};

enum class LedKind {
    None,
    TwoColour, // K1..K12: green (Z1906), red (Z1907), both = amber
    Green,     // L1..L4: the override key in effect
    Yellow,    // SHIFT engaged
};

enum class KeyIcon { None, Up, Down, Left, Right, Enter };

struct KeyFace {
    QString legend; // the main print: "АВТ", "ESC", "7", "%"
    QString corner; // small print in the top-left corner: "F1", or ""
    QString sub;    // small print after the legend: "R" on the % key
    KeyIcon icon = KeyIcon::None;
    bool shiftedLegend = false; // SHIFT+▲/▼: the amber double arrow
    KeyStyle style = KeyStyle::Control;
    LedKind led = LedKind::None;
};

KeyFace keyFace(panel::Key key);

// The key as a reader names it: "F1 АВТ", "▲", "% R", "K7".
QString keyTitle(panel::Key key);

// What the key does, translated (tooltip, keyboard map).
QString keyDescription(panel::Key key);
// What SHIFT+key does, translated, or "" if the manual gives it no SHIFT function.
QString shiftedDescription(panel::Key key);

// The rich-text tooltip of a key: title, description, the PC keys.
QString keyToolTip(panel::Key key);

} // namespace k528::studio
