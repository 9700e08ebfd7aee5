// The PC keyboard on the K923 panel: which PC key presses which panel key.
//
//   F1..F8              F1..F8 (mode keys)
//   Ctrl+1..9, 0, -, =  K1..K12 (the twelve keys of the digit row, in order)
//   Alt+1..4            L1..L4
//   arrows              ▲ ▼ ◀ ►;  Shift+arrow = SHIFT+arrow
//   PgUp / PgDn         SHIFT+▲ / SHIFT+▼ (three lines / previous, next frame)
//   M, H, P, A          MODE, HELP, PAR, ACK
//   S                   SHIFT (latches the panel's SHIFT, as a click on it)
//   Insert (or I)       INS;  Delete or Backspace: DEL
//   Enter, Return       ENTER;  Esc: ESC
//   digits (both)       0..9;  '.' or ',': '.'
//   + - * / = ! %       the same keys;  R: '%' (the panel types R with it)
//
// Letters work in the Russian layout as well (the same physical key: Ь Р З Ф
// Ы Ш К). Shift held on a PC key that is not a character makes a SHIFT press
// (Shift+F4 = SHIFT+F4). Tab is left alone, so the keyboard can leave the panel.
#pragma once

#include "panel/keys.h"

#include <QKeyCombination>
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

class QKeyEvent;

namespace k528::studio {

// The panel key a PC key press means, or nullopt (the key is not the panel's).
std::optional<panel::KeyPress> mapPcKey(int qtKey, Qt::KeyboardModifiers modifiers,
                                        const QString& text);
std::optional<panel::KeyPress> mapPcKey(const QKeyEvent& event);

// Keys that repeat while held (mouse or PC keyboard): the cursor keys.
bool repeatsWhenHeld(panel::Key key);

// The documented PC keys, one row per PC key: what the tooltips, the keyboard
// map and docs/panel-widget.md list (and what the tests press).
struct PcKeyBinding {
    panel::KeyPress press;
    QKeyCombination combination;
};
const std::vector<PcKeyBinding>& pcKeyBindings();

// The PC keys for `press` as the user reads them ("Ctrl+1", "PgUp").
QStringList pcKeysFor(const panel::KeyPress& press);

} // namespace k528::studio
