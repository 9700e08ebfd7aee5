#include "k923/key_map.h"

#include <QKeyEvent>
#include <QKeySequence>

namespace k528::studio {

using panel::Key;
using panel::KeyPress;

namespace {

std::optional<Key> digitKey(int n) {
    if (n < 0 || n > 9)
        return std::nullopt;
    return static_cast<Key>(static_cast<int>(Key::D0) + n);
}

// Ctrl + the digit row: K1..K12.
std::optional<Key> machineKey(int qtKey) {
    if (qtKey >= Qt::Key_1 && qtKey <= Qt::Key_9)
        return static_cast<Key>(static_cast<int>(Key::K1) + (qtKey - Qt::Key_1));
    switch (qtKey) {
    case Qt::Key_0:
        return Key::K10;
    case Qt::Key_Minus:
        return Key::K11;
    case Qt::Key_Equal:
        return Key::K12;
    default:
        return std::nullopt;
    }
}

// A typed character that is a key of the panel.
std::optional<Key> characterKey(QChar c) {
    if (c.isDigit() && c.unicode() < 128)
        return digitKey(c.unicode() - '0');
    switch (c.unicode()) {
    case '.':
    case ',':
        return Key::Point;
    case '+':
        return Key::Plus;
    case '-':
        return Key::Minus;
    case '*':
        return Key::Multiply;
    case '/':
        return Key::Divide;
    case '=':
        return Key::Equals;
    case '%':
        return Key::Percent;
    case '!':
        return Key::Exclamation;
    default:
        return std::nullopt;
    }
}

// Letter mnemonics; the Cyrillic letter on the same key of the ЙЦУКЕН layout.
std::optional<Key> letterKey(QChar c) {
    switch (c.toUpper().unicode()) {
    case 'M':
    case u'Ь':
        return Key::Mode;
    case 'H':
    case u'Р':
        return Key::Help;
    case 'P':
    case u'З':
        return Key::Par;
    case 'A':
    case u'Ф':
        return Key::Ack;
    case 'S':
    case u'Ы':
        return Key::Shift;
    case 'I':
    case u'Ш':
        return Key::Ins;
    case 'R':
    case u'К':
        return Key::Percent;
    default:
        return std::nullopt;
    }
}

// Character keys by their Qt key code, for events without text.
std::optional<Key> characterKeyByCode(int qtKey) {
    if (qtKey >= Qt::Key_0 && qtKey <= Qt::Key_9)
        return digitKey(qtKey - Qt::Key_0);
    switch (qtKey) {
    case Qt::Key_Period:
    case Qt::Key_Comma:
        return Key::Point;
    case Qt::Key_Plus:
        return Key::Plus;
    case Qt::Key_Minus:
        return Key::Minus;
    case Qt::Key_Asterisk:
        return Key::Multiply;
    case Qt::Key_Slash:
        return Key::Divide;
    case Qt::Key_Equal:
        return Key::Equals;
    case Qt::Key_Percent:
        return Key::Percent;
    case Qt::Key_Exclam:
        return Key::Exclamation;
    default:
        return std::nullopt;
    }
}

} // namespace

std::optional<KeyPress> mapPcKey(int qtKey, Qt::KeyboardModifiers modifiers, const QString& text) {
    const Qt::KeyboardModifiers mods = modifiers & ~(Qt::KeypadModifier | Qt::GroupSwitchModifier);
    const bool shift = mods.testFlag(Qt::ShiftModifier);
    const bool ctrl = mods.testFlag(Qt::ControlModifier);
    const bool alt = mods.testFlag(Qt::AltModifier);
    if (mods.testFlag(Qt::MetaModifier))
        return std::nullopt;
    if (ctrl && !alt) {
        if (const auto k = machineKey(qtKey))
            return KeyPress{*k, shift};
        return std::nullopt; // leave Ctrl+Q and the other shortcuts alone
    }
    if (alt && !ctrl) {
        if (qtKey >= Qt::Key_1 && qtKey <= Qt::Key_4)
            return KeyPress{static_cast<Key>(static_cast<int>(Key::L1) + (qtKey - Qt::Key_1)),
                            shift};
        return std::nullopt; // menus' Alt+letter
    }
    if (ctrl || alt)
        return std::nullopt;

    if (qtKey >= Qt::Key_F1 && qtKey <= Qt::Key_F8)
        return KeyPress{static_cast<Key>(static_cast<int>(Key::F1) + (qtKey - Qt::Key_F1)), shift};
    switch (qtKey) {
    case Qt::Key_Up:
        return KeyPress{Key::Up, shift};
    case Qt::Key_Down:
        return KeyPress{Key::Down, shift};
    case Qt::Key_Left:
        return KeyPress{Key::Left, shift};
    case Qt::Key_Right:
        return KeyPress{Key::Right, shift};
    case Qt::Key_PageUp:
        return KeyPress{Key::Up, true};
    case Qt::Key_PageDown:
        return KeyPress{Key::Down, true};
    case Qt::Key_Return:
    case Qt::Key_Enter:
        return KeyPress{Key::Enter, shift};
    case Qt::Key_Escape:
        return KeyPress{Key::Esc, shift};
    case Qt::Key_Insert:
        return KeyPress{Key::Ins, shift};
    case Qt::Key_Delete:
    case Qt::Key_Backspace:
        return KeyPress{Key::Del, shift};
    default:
        break;
    }

    // Characters: by what was typed, so that the keyboard layout does not
    // matter ('!' is Shift+1 on one keyboard and a key of its own on another);
    // the Shift that typed them is not a panel SHIFT.
    const QChar c = text.size() == 1 ? text.front() : QChar();
    if (!c.isNull()) {
        if (const auto k = characterKey(c))
            return KeyPress{*k, false};
        if (const auto k = letterKey(c))
            return KeyPress{*k, shift};
        return std::nullopt;
    }
    if (const auto k = characterKeyByCode(qtKey))
        return KeyPress{*k, false};
    if (qtKey >= Qt::Key_A && qtKey <= Qt::Key_Z)
        if (const auto k = letterKey(QChar(qtKey)))
            return KeyPress{*k, shift};
    return std::nullopt;
}

std::optional<KeyPress> mapPcKey(const QKeyEvent& event) {
    return mapPcKey(event.key(), event.modifiers(), event.text());
}

bool repeatsWhenHeld(Key key) {
    return key == Key::Up || key == Key::Down || key == Key::Left || key == Key::Right;
}

const std::vector<PcKeyBinding>& pcKeyBindings() {
    static const std::vector<PcKeyBinding> bindings = [] {
        std::vector<PcKeyBinding> b;
        const auto add = [&b](Key k, bool shift, QKeyCombination c) {
            b.push_back({KeyPress{k, shift}, c});
        };
        for (int i = 0; i < 8; ++i)
            add(static_cast<Key>(static_cast<int>(Key::F1) + i), false, Qt::Key(Qt::Key_F1 + i));
        for (int i = 0; i < 9; ++i)
            add(static_cast<Key>(static_cast<int>(Key::K1) + i), false,
                Qt::ControlModifier | Qt::Key(Qt::Key_1 + i));
        add(Key::K10, false, Qt::ControlModifier | Qt::Key_0);
        add(Key::K11, false, Qt::ControlModifier | Qt::Key_Minus);
        add(Key::K12, false, Qt::ControlModifier | Qt::Key_Equal);
        for (int i = 0; i < 4; ++i)
            add(static_cast<Key>(static_cast<int>(Key::L1) + i), false,
                Qt::AltModifier | Qt::Key(Qt::Key_1 + i));
        add(Key::Up, false, Qt::Key_Up);
        add(Key::Down, false, Qt::Key_Down);
        add(Key::Left, false, Qt::Key_Left);
        add(Key::Right, false, Qt::Key_Right);
        add(Key::Up, true, Qt::ShiftModifier | Qt::Key_Up);
        add(Key::Up, true, Qt::Key_PageUp);
        add(Key::Down, true, Qt::ShiftModifier | Qt::Key_Down);
        add(Key::Down, true, Qt::Key_PageDown);
        add(Key::Mode, false, Qt::Key_M);
        add(Key::Help, false, Qt::Key_H);
        add(Key::Esc, false, Qt::Key_Escape);
        add(Key::Shift, false, Qt::Key_S);
        add(Key::Par, false, Qt::Key_P);
        add(Key::Ack, false, Qt::Key_A);
        add(Key::Ins, false, Qt::Key_Insert);
        add(Key::Ins, false, Qt::Key_I);
        add(Key::Del, false, Qt::Key_Delete);
        add(Key::Del, false, Qt::Key_Backspace);
        add(Key::Enter, false, Qt::Key_Return);
        add(Key::Enter, false, Qt::KeypadModifier | Qt::Key_Enter);
        for (int i = 0; i < 10; ++i)
            add(static_cast<Key>(static_cast<int>(Key::D0) + i), false, Qt::Key(Qt::Key_0 + i));
        add(Key::Point, false, Qt::Key_Period);
        add(Key::Point, false, Qt::Key_Comma);
        add(Key::Plus, false, Qt::Key_Plus);
        add(Key::Minus, false, Qt::Key_Minus);
        add(Key::Multiply, false, Qt::Key_Asterisk);
        add(Key::Divide, false, Qt::Key_Slash);
        add(Key::Equals, false, Qt::Key_Equal);
        add(Key::Percent, false, Qt::Key_Percent);
        add(Key::Percent, false, Qt::Key_R);
        add(Key::Exclamation, false, Qt::Key_Exclam);
        return b;
    }();
    return bindings;
}

QStringList pcKeysFor(const KeyPress& press) {
    QStringList out;
    for (const PcKeyBinding& b : pcKeyBindings())
        if (b.press == press)
            out << QKeySequence(b.combination).toString(QKeySequence::NativeText);
    return out;
}

} // namespace k528::studio
