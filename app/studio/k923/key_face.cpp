#include "k923/key_face.h"

#include "k923/key_map.h"

#include <QCoreApplication>

namespace k528::studio {

using panel::Key;

namespace {

// The translation context of the key texts.
class K923Keys {
    Q_DECLARE_TR_FUNCTIONS(k528::studio::K923Keys)
};

// The mode names of the screens (2.6): АВТ, РУЧ, ПБТ, УСТ are printed on the
// screens; ПАР, УП, ДАН are ours for C-parameters, programs and data. The
// manual gives F8 no mode: its key carries only its name.
const char* const kModeLegends[8] = {"АВТ", "РУЧ", "ПБТ", "УСТ", "ПАР", "УП", "ДАН", ""};

// Table 4: K1..K6 use bits 0..5 of Z1300/Z1906/Z1907, K7..K12 bits 8..13.
int machineKeyBit(int k) {
    return k <= 6 ? k - 1 : k + 1;
}

} // namespace

KeyFace keyFace(Key key) {
    KeyFace f;
    const int n = panel::functionNumber(key);
    if (panel::isFunctionKey(key)) {
        f.style = KeyStyle::Mode;
        const QString mode = QString::fromUtf8(kModeLegends[n - 1]);
        f.legend = mode.isEmpty() ? QStringLiteral("F%1").arg(n) : mode;
        f.corner = mode.isEmpty() ? QString() : QStringLiteral("F%1").arg(n);
        return f;
    }
    if (panel::isKKey(key)) {
        f.style = KeyStyle::Machine;
        f.legend = QStringLiteral("K%1").arg(n);
        f.led = LedKind::TwoColour;
        return f;
    }
    if (panel::isLKey(key)) {
        f.style = KeyStyle::Machine;
        f.legend = QStringLiteral("L%1").arg(n);
        f.led = LedKind::Green;
        return f;
    }
    if (const int d = panel::digitOf(key); d >= 0) {
        f.style = KeyStyle::Digit;
        f.legend = QString::number(d);
        return f;
    }
    switch (key) {
    case Key::Up:
        f.icon = KeyIcon::Up;
        f.shiftedLegend = true;
        break;
    case Key::Down:
        f.icon = KeyIcon::Down;
        f.shiftedLegend = true;
        break;
    case Key::Left:
        f.icon = KeyIcon::Left;
        break;
    case Key::Right:
        f.icon = KeyIcon::Right;
        break;
    case Key::Mode:
        f.legend = "MODE";
        break;
    case Key::Help:
        f.legend = "HELP";
        break;
    case Key::Esc:
        f.legend = "ESC";
        f.style = KeyStyle::Escape;
        break;
    case Key::Shift:
        f.legend = "SHIFT";
        f.led = LedKind::Yellow;
        break;
    case Key::Par:
        f.legend = "PAR";
        break;
    case Key::Ack:
        f.legend = "ACK";
        break;
    case Key::Ins:
        f.legend = "INS";
        break;
    case Key::Del:
        f.legend = "DEL";
        break;
    case Key::Enter:
        f.legend = "ENTER";
        f.icon = KeyIcon::Enter;
        f.style = KeyStyle::Enter;
        break;
    case Key::Point:
        f.legend = ".";
        f.style = KeyStyle::Digit;
        break;
    case Key::Plus:
        f.legend = "+";
        f.style = KeyStyle::Operator;
        break;
    case Key::Minus:
        f.legend = QStringLiteral("\u2212");
        f.style = KeyStyle::Operator;
        break;
    case Key::Multiply:
        f.legend = "*";
        f.style = KeyStyle::Operator;
        break;
    case Key::Divide:
        f.legend = "/";
        f.style = KeyStyle::Operator;
        break;
    case Key::Equals:
        f.legend = "=";
        f.style = KeyStyle::Operator;
        break;
    case Key::Percent:
        f.legend = "%";
        f.sub = "R";
        f.style = KeyStyle::Operator;
        break;
    case Key::Exclamation:
        f.legend = "!";
        f.style = KeyStyle::Operator;
        break;
    default:
        break;
    }
    return f;
}

QString keyTitle(Key key) {
    switch (key) {
    case Key::Up:
        return QStringLiteral("▲");
    case Key::Down:
        return QStringLiteral("▼");
    case Key::Left:
        return QStringLiteral("◀");
    case Key::Right:
        return QStringLiteral("►");
    case Key::Percent:
        return QStringLiteral("% R");
    case Key::Minus:
        return QStringLiteral("\u2212");
    default:
        break;
    }
    const KeyFace f = keyFace(key);
    return f.corner.isEmpty() ? f.legend : f.corner + ' ' + f.legend;
}

QString keyDescription(Key key) {
    const int n = panel::functionNumber(key);
    if (panel::isFunctionKey(key)) {
        static const char* const modes[8] = {
            QT_TRANSLATE_NOOP("k528::studio::K923Keys",
                              "Mode AUTOMATIC: the machine works by the control program."),
            QT_TRANSLATE_NOOP(
                "k528::studio::K923Keys",
                "Mode MANUAL: the machine's push-buttons and handwheels move the axes; "
                "R-parameters can be edited."),
            QT_TRANSLATE_NOOP(
                "k528::studio::K923Keys",
                "Mode REFERENCE POINT: the homing cycle ties the axes to the machine."),
            QT_TRANSLATE_NOOP("k528::studio::K923Keys",
                              "Mode PRESETS: technological parameters of the machine in groups."),
            QT_TRANSLATE_NOOP("k528::studio::K923Keys",
                              "Mode MACHINE CONSTANTS: editing the C-parameters (password)."),
            QT_TRANSLATE_NOOP("k528::studio::K923Keys",
                              "Mode PROGRAM EDITING: editing the control programs (password)."),
            QT_TRANSLATE_NOOP(
                "k528::studio::K923Keys",
                "Mode DATA MANAGEMENT: clearing memory and working with the PC (password)."),
            QT_TRANSLATE_NOOP("k528::studio::K923Keys",
                              "Mode key F8: the K528-05 has no eighth mode."),
        };
        return K923Keys::tr(modes[n - 1]) + ' ' +
               K923Keys::tr("The key opens the main screen of the mode.");
    }
    if (panel::isKKey(key))
        return K923Keys::
            tr("Machine function key K%1. The PLC program of the machine gives it its function: "
               "pressing sets Z1300.%2. Its LED is green by Z1906.%2, red by Z1907.%2, amber by "
               "both.")
                .arg(n)
                .arg(machineKeyBit(n));
    if (panel::isLKey(key))
        return K923Keys::
            tr("Feed override key L%1: selects the override whose code machine constant C%2 holds "
               "(codes 0–10 = 0…100 %). Its LED shows the override key in effect.")
                .arg(n)
                .arg(138 + n);
    if (const int d = panel::digitOf(key); d >= 0)
        return K923Keys::tr("Digit %1.").arg(d);
    switch (key) {
    case Key::Up:
        return K923Keys::tr("Moves the marker up to the previous parameter or line.");
    case Key::Down:
        return K923Keys::tr("Moves the marker down to the next parameter or line.");
    case Key::Left:
        return K923Keys::tr("Moves the marker left; in the axis screens, to the other axis.");
    case Key::Right:
        return K923Keys::tr("Moves the marker right; in the axis screens, to the other axis.");
    case Key::Mode:
        return K923Keys::tr("Pages through the screens of the current mode.");
    case Key::Help:
        return K923Keys::tr("Enters the service screens (messages, faults, system, diagnostics) "
                            "and returns from them.");
    case Key::Esc:
        return K923Keys::tr(
            "As the machine constants set it: cancels editing a parameter, resets the system, "
            "acknowledges error and fault messages.");
    case Key::Shift:
        return K923Keys::tr(
            "Switches keys with two functions to their second one: press SHIFT, then the key. "
            "The LED shows SHIFT engaged; pressing SHIFT again releases it.");
    case Key::Par:
        return K923Keys::tr("Goes to choosing a parameter by its number, and back.");
    case Key::Ack:
        return K923Keys::tr(
            "Enters the number of the program for automatic mode; in the program editor, "
            "inserts a computing or jump frame.");
    case Key::Ins:
        return K923Keys::tr("Inserts a new standard frame after the current one (program editor).");
    case Key::Del:
        return K923Keys::tr("Deletes a program, a frame or the value of a parameter.");
    case Key::Enter:
        return K923Keys::tr("Enters the typed value.");
    case Key::Point:
        return K923Keys::tr("Decimal point.");
    case Key::Plus:
        return K923Keys::tr("Addition.");
    case Key::Minus:
        return K923Keys::tr("Subtraction; the minus sign.");
    case Key::Multiply:
        return K923Keys::tr("Multiplication.");
    case Key::Divide:
        return K923Keys::tr("Division.");
    case Key::Equals:
        return K923Keys::tr("Assigns the result.");
    case Key::Percent:
        return K923Keys::tr("Types the letter R (R-parameters).");
    case Key::Exclamation:
        return K923Keys::tr("Sets or clears the skip mark «/» of a frame (program editor).");
    default:
        return {};
    }
}

QString shiftedDescription(Key key) {
    switch (key) {
    case Key::Up:
        return K923Keys::tr("SHIFT+▲: three lines up; in the program editor, the previous frame.");
    case Key::Down:
        return K923Keys::tr("SHIFT+▼: three lines down; in the program editor, the next frame.");
    default:
        return {};
    }
}

QString keyToolTip(Key key) {
    QString html = QStringLiteral("<p style='white-space:pre'><b>%1</b></p><p>%2</p>")
                       .arg(keyTitle(key).toHtmlEscaped(), keyDescription(key).toHtmlEscaped());
    const QString shifted = shiftedDescription(key);
    if (!shifted.isEmpty())
        html += QStringLiteral("<p>%1</p>").arg(shifted.toHtmlEscaped());
    QStringList pc = pcKeysFor({key, false});
    QString pcText = pc.join(QStringLiteral(", "));
    if (key == Key::Shift)
        pcText =
            K923Keys::tr("%1 (latches like a click); or hold Shift with the other key").arg(pcText);
    html += QStringLiteral("<p>%1 <b>%2</b>")
                .arg(K923Keys::tr("PC keyboard:").toHtmlEscaped(), pcText.toHtmlEscaped());
    const QStringList pcShifted = pcKeysFor({key, true});
    if (!pcShifted.isEmpty())
        html += QStringLiteral("<br>SHIFT+%1: <b>%2</b>")
                    .arg(keyTitle(key).toHtmlEscaped(),
                         pcShifted.join(QStringLiteral(", ")).toHtmlEscaped());
    html += QStringLiteral("</p>");
    return html;
}

} // namespace k528::studio
