// The K923 panel widget: LCD dots, blinking, mouse and PC keyboard, SHIFT
// latch, LEDs, scaling, focus. Runs on the offscreen platform.
//
// Mouse events go through the window system as a real click does, so a click
// at a point of the panel reaches the key under it.
#define QTEST_QPA_MOUSE_HANDLING
#include "k923/k923_widget.h"
#include "rig/widgets.h"
#include "k923/key_face.h"
#include "k923/key_map.h"
#include "k923/keyboard_map_dialog.h"
#include "k923/lcd_widget.h"
#include "k923/panel_key.h"
#include "main_window.h"
#include "session/simulation_session.h"
#include "panel/lcd_font.h"

#include <QAction>
#include <QDockWidget>
#include <QLineEdit>
#include <QMainWindow>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtTest>

using PanelDisplay = k528::panel::Display;
using k528::panel::Key;
using k528::panel::KeyPress;
using k528::studio::K923Widget;
using k528::studio::LcdWidget;

namespace {

std::string line(const QString& text) {
    return text.leftJustified(20, ' ', true).toStdString();
}

PanelDisplay screen(const QStringList& lines) {
    PanelDisplay d = K923Widget::blankDisplay();
    for (int i = 0; i < 4 && i < lines.size(); ++i)
        d.lcd.lines[static_cast<std::size_t>(i)] = line(lines[i]);
    return d;
}

// Colour distance.
int dist(QColor a, QColor b) {
    return std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) +
           std::abs(a.blue() - b.blue());
}

// Whether the dot (x, y) of cell (row, col) is drawn lit in `img` (an image
// of the LCD widget), judged by the colour at the dot's centre.
bool litInImage(const QImage& img, const LcdWidget& lcd, int row, int col, int x, int y) {
    const QPointF c = lcd.layout().dotRect(row, col, x, y).center();
    const QColor px = img.pixelColor(static_cast<int>(c.x()), static_cast<int>(c.y()));
    const auto colours = lcd.colors();
    return dist(px, colours.lit) < dist(px, colours.unlit);
}

// Checks all 40 dots of a cell against `glyph`.
void expectCell(const QImage& img, const LcdWidget& lcd, int row, int col,
                const k528::panel::Glyph& glyph, const char* what) {
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 5; ++x)
            QVERIFY2(litInImage(img, lcd, row, col, x, y) == glyph.dot(x, y),
                     qPrintable(QStringLiteral("%1: cell %2,%3 dot %4,%5")
                                    .arg(what)
                                    .arg(row)
                                    .arg(col)
                                    .arg(x)
                                    .arg(y)));
}

QImage grabLcd(K923Widget& w) {
    return w.lcd()->grab().toImage();
}

enum class Led { Off, Green, Red, Amber, Yellow };

Led classify(QColor c) {
    const int r = c.red(), g = c.green(), b = c.blue();
    if (std::max({r, g, b}) < 140)
        return Led::Off;
    if (g > r + 60 && g > b + 60)
        return Led::Green;
    if (r > 200 && g < 120)
        return Led::Red;
    if (r > 200 && g >= 120 && g < 200 && b < 120)
        return Led::Amber;
    if (r > 200 && g >= 200 && b < 160)
        return Led::Yellow;
    return Led::Off;
}

Led ledAt(K923Widget& w, Key k) {
    const QImage img = w.grab().toImage();
    const QPointF c = *w.ledCentre(k);
    return classify(img.pixelColor(static_cast<int>(c.x()), static_cast<int>(c.y())));
}

Key keyAt(int i) {
    return static_cast<Key>(i);
}

struct Shown {
    K923Widget w;
    explicit Shown(QSize size = {455, 640}) {
        w.resize(size);
        w.show();
    }
};

} // namespace

class TestK923Widget : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("K528StudioTest");
        QSettings().clear();
    }

    void rendersTheDotsOfACharacter() {
        Shown s;
        QVERIFY(QTest::qWaitForWindowExposed(&s.w));
        s.w.lcd()->setBlinkFrozen(true);
        s.w.setDisplay(screen({"АВТ      1    100%", "   Ж", "Щ", "                   %"}));
        const QImage img = grabLcd(s.w);
        expectCell(img, *s.w.lcd(), 1, 3, *k528::panel::lcdGlyph(U'Ж'), "Ж");
        expectCell(img, *s.w.lcd(), 0, 0, *k528::panel::lcdGlyph(U'А'), "А");
        expectCell(img, *s.w.lcd(), 2, 0, *k528::panel::lcdGlyph(U'Щ'), "Щ");
        expectCell(img, *s.w.lcd(), 3, 19, *k528::panel::lcdGlyph(U'%'), "%");
        expectCell(img, *s.w.lcd(), 1, 4, k528::panel::Glyph{}, "space");
        QCOMPARE(s.w.lcd()->character(1, 3), U'Ж');
        QCOMPARE(s.w.lcd()->text().split('\n').at(0), QStringLiteral("АВТ      1    100%  "));
    }

    void unknownCharacterShowsThePlaceholder() {
        Shown s;
        s.w.setDisplay(screen({"€"}));
        expectCell(grabLcd(s.w), *s.w.lcd(), 0, 0, k528::panel::lcdPlaceholderGlyph(),
                   "placeholder");
    }

    void blueThemeDrawsTheSameDots() {
        Shown s;
        s.w.setLcdTheme(k528::studio::LcdTheme::Blue);
        s.w.setDisplay(screen({"", "", "  Я"}));
        const QImage img = grabLcd(s.w);
        expectCell(img, *s.w.lcd(), 2, 2, *k528::panel::lcdGlyph(U'Я'), "Я on blue");
        QVERIFY(s.w.lcd()->colors().lit.lightness() > s.w.lcd()->colors().unlit.lightness());
        s.w.setLcdTheme(k528::studio::LcdTheme::YellowGreen);
        QCOMPARE(QSettings().value("k923/lcdTheme").toString(), QStringLiteral("yellow-green"));
    }

    void blinkingAlternatesTheField() {
        Shown s;
        LcdWidget& lcd = *s.w.lcd();
        lcd.setBlinkFrozen(true);
        PanelDisplay d = screen({"", "R224= -12.356"});
        d.lcd.blinkRow = 1;
        d.lcd.blinkColumn = 0;
        d.lcd.blinkLength = 4;
        s.w.setDisplay(d);
        lcd.setBlinkPhase(false);
        QImage img = grabLcd(s.w);
        expectCell(img, lcd, 1, 0, *k528::panel::lcdGlyph(U'R'), "phase 0");
        expectCell(img, lcd, 1, 3, *k528::panel::lcdGlyph(U'4'), "phase 0");
        lcd.setBlinkPhase(true);
        img = grabLcd(s.w);
        for (int c = 0; c < 4; ++c)
            expectCell(img, lcd, 1, c, k528::panel::lcdBlockGlyph(), "phase 1: block");
        expectCell(img, lcd, 1, 4, *k528::panel::lcdGlyph(U'='), "outside the field");
        lcd.setBlinkStyle(LcdWidget::BlinkStyle::Blank);
        img = grabLcd(s.w);
        expectCell(img, lcd, 1, 2, k528::panel::Glyph{}, "phase 1: blank");
        lcd.setBlinkStyle(LcdWidget::BlinkStyle::Block);
        QVERIFY(lcd.isBlinking(1, 3));
        QVERIFY(!lcd.isBlinking(1, 4));
        QVERIFY(lcd.isDotLit(1, 2, 0, 7)); // the block lights the cursor line too

        // Running, the field alternates about twice a second.
        QSignalSpy spy(&lcd, &LcdWidget::blinkPhaseChanged);
        lcd.setBlinkFrozen(false);
        QTRY_VERIFY_WITH_TIMEOUT(spy.count() >= 3, 3000);
        // No blinking field: the timer stops and nothing changes.
        s.w.setDisplay(screen({"", "R224= -12.356"}));
        const int n = spy.count();
        QTest::qWait(3 * LcdWidget::kBlinkHalfPeriodMs);
        QVERIFY(spy.count() <= n + 1);
        QVERIFY(!lcd.isBlinking(1, 0));
    }

    void repaintsOnlyWhatChanged() {
        Shown s;
        QVERIFY(QTest::qWaitForWindowExposed(&s.w));
        s.w.lcd()->setBlinkFrozen(true);
        const PanelDisplay d = screen({"РУЧ 1         100%", "R98=-12345", ">R99=5034", "R100=0"});
        s.w.setDisplay(d);
        QCoreApplication::processEvents();

        struct PaintSpy : QObject {
            QRegion painted;
            int count = 0;
            bool eventFilter(QObject*, QEvent* e) override {
                if (e->type() == QEvent::Paint) {
                    ++count;
                    painted += static_cast<QPaintEvent*>(e)->region();
                }
                return false;
            }
        } spy;
        s.w.lcd()->installEventFilter(&spy);
        s.w.setDisplay(d); // the same: nothing to paint
        QTest::qWait(50);
        QCOMPARE(spy.count, 0);

        PanelDisplay d2 = d;
        d2.lcd.lines[2] = line(">R99=5035");
        s.w.setDisplay(d2);
        QTRY_VERIFY(spy.count > 0);
        const QRect cell =
            s.w.lcd()->layout().cellRect(2, 8).toAlignedRect().adjusted(-2, -2, 2, 2);
        QVERIFY2(cell.contains(spy.painted.boundingRect()), "only the changed cell is repainted");
        s.w.lcd()->removeEventFilter(&spy);
    }

    void mouseClickOnEveryKeyEmitsIt() {
        Shown s;
        QVERIFY(QTest::qWaitForWindowExposed(&s.w));
        QSignalSpy spy(&s.w, &K923Widget::keyPressed);
        for (int i = 0; i < k528::panel::kKeyCount; ++i) {
            const Key k = keyAt(i);
            if (k == Key::Shift)
                continue;
            spy.clear();
            QTest::mouseClick(&s.w, Qt::LeftButton, {}, s.w.keyRect(k).center());
            QVERIFY2(spy.count() == 1, k528::panel::keyName(k).data());
            QCOMPARE(spy.at(0).at(0).value<KeyPress>(), (KeyPress{k, false}));
        }
        // A Shift-click is SHIFT+key.
        spy.clear();
        QTest::mouseClick(s.w.key(Key::F4), Qt::LeftButton, Qt::ShiftModifier);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).value<KeyPress>(), (KeyPress{Key::F4, true}));
    }

    void shiftLatchesForTheNextKey() {
        Shown s;
        QVERIFY(QTest::qWaitForWindowExposed(&s.w));
        QSignalSpy spy(&s.w, &K923Widget::keyPressed);
        QCOMPARE(ledAt(s.w, Key::Shift), Led::Off);
        QTest::mouseClick(&s.w, Qt::LeftButton, {}, s.w.keyRect(Key::Shift).center());
        QVERIFY(s.w.shiftLatched());
        QCOMPARE(spy.count(), 0); // a lone SHIFT is not a key press
        QCOMPARE(ledAt(s.w, Key::Shift), Led::Yellow);
        QTest::mouseClick(&s.w, Qt::LeftButton, {}, s.w.keyRect(Key::Up).center());
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).value<KeyPress>(), (KeyPress{Key::Up, true}));
        QVERIFY(!s.w.shiftLatched());
        QCOMPARE(ledAt(s.w, Key::Shift), Led::Off);
        QTest::mouseClick(&s.w, Qt::LeftButton, {}, s.w.keyRect(Key::Up).center());
        QCOMPARE(spy.at(1).at(0).value<KeyPress>(), (KeyPress{Key::Up, false}));
        // SHIFT twice releases the latch.
        QTest::mouseClick(&s.w, Qt::LeftButton, {}, s.w.keyRect(Key::Shift).center());
        QTest::mouseClick(&s.w, Qt::LeftButton, {}, s.w.keyRect(Key::Shift).center());
        QVERIFY(!s.w.shiftLatched());
        // From the PC keyboard: S latches, then Down.
        s.w.setFocus();
        QTest::keyClick(&s.w, Qt::Key_S);
        QVERIFY(s.w.shiftLatched());
        QTest::keyClick(&s.w, Qt::Key_Down);
        QCOMPARE(spy.last().at(0).value<KeyPress>(), (KeyPress{Key::Down, true}));
        // The model's SHIFT LED is shown as well.
        PanelDisplay d = K923Widget::blankDisplay();
        d.leds.shift = true;
        s.w.setDisplay(d);
        QCOMPARE(ledAt(s.w, Key::Shift), Led::Yellow);
    }

    void pcKeyboardMapsToPanelKeys() {
        Shown s;
        s.w.setFocus();
        QSignalSpy spy(&s.w, &K923Widget::keyPressed);
        const auto expect = [&](auto&& sendKey, KeyPress want, const char* what) {
            spy.clear();
            sendKey();
            QVERIFY2(spy.count() == 1, what);
            QVERIFY2(spy.at(0).at(0).value<KeyPress>() == want,
                     qPrintable(QString(what) + " gave " +
                                QString::fromStdString(
                                    k528::panel::formatKey(spy.at(0).at(0).value<KeyPress>()))));
        };
        const auto key = [&](Qt::Key k, Qt::KeyboardModifiers m = {}) {
            return [&s, k, m] { QTest::keyClick(&s.w, k, m); };
        };
        const auto typed = [&](Qt::Key k, const QString& text, Qt::KeyboardModifiers m = {}) {
            return [&s, k, text, m] { QTest::sendKeyEvent(QTest::Click, &s.w, k, text, m); };
        };
        // Written out independently of key_map.cpp.
        for (int i = 0; i < 8; ++i)
            expect(key(Qt::Key(Qt::Key_F1 + i)), {keyAt(static_cast<int>(Key::F1) + i), false},
                   "F-key");
        expect(key(Qt::Key_F3, Qt::ShiftModifier), {Key::F3, true}, "Shift+F3");
        expect(key(Qt::Key_1, Qt::ControlModifier), {Key::K1, false}, "Ctrl+1");
        expect(key(Qt::Key_9, Qt::ControlModifier), {Key::K9, false}, "Ctrl+9");
        expect(key(Qt::Key_0, Qt::ControlModifier), {Key::K10, false}, "Ctrl+0");
        expect(key(Qt::Key_Minus, Qt::ControlModifier), {Key::K11, false}, "Ctrl+-");
        expect(key(Qt::Key_Equal, Qt::ControlModifier), {Key::K12, false}, "Ctrl+=");
        expect(key(Qt::Key_1, Qt::AltModifier), {Key::L1, false}, "Alt+1");
        expect(key(Qt::Key_4, Qt::AltModifier), {Key::L4, false}, "Alt+4");
        expect(key(Qt::Key_Up), {Key::Up, false}, "Up");
        expect(key(Qt::Key_Down), {Key::Down, false}, "Down");
        expect(key(Qt::Key_Left), {Key::Left, false}, "Left");
        expect(key(Qt::Key_Right), {Key::Right, false}, "Right");
        expect(key(Qt::Key_Up, Qt::ShiftModifier), {Key::Up, true}, "Shift+Up");
        expect(key(Qt::Key_PageUp), {Key::Up, true}, "PgUp");
        expect(key(Qt::Key_PageDown), {Key::Down, true}, "PgDn");
        expect(key(Qt::Key_Return), {Key::Enter, false}, "Return");
        expect(key(Qt::Key_Enter, Qt::KeypadModifier), {Key::Enter, false}, "keypad Enter");
        expect(key(Qt::Key_Escape), {Key::Esc, false}, "Esc");
        expect(key(Qt::Key_Insert), {Key::Ins, false}, "Insert");
        expect(key(Qt::Key_Delete), {Key::Del, false}, "Delete");
        expect(key(Qt::Key_Backspace), {Key::Del, false}, "Backspace");
        expect(key(Qt::Key_M), {Key::Mode, false}, "M");
        expect(key(Qt::Key_H), {Key::Help, false}, "H");
        expect(key(Qt::Key_P), {Key::Par, false}, "P");
        expect(key(Qt::Key_A), {Key::Ack, false}, "A");
        expect(key(Qt::Key_I), {Key::Ins, false}, "I");
        expect(key(Qt::Key_R), {Key::Percent, false}, "R");
        for (int d = 0; d <= 9; ++d) {
            expect(key(Qt::Key(Qt::Key_0 + d)), {keyAt(static_cast<int>(Key::D0) + d), false},
                   "digit");
            expect(key(Qt::Key(Qt::Key_0 + d), Qt::KeypadModifier),
                   {keyAt(static_cast<int>(Key::D0) + d), false}, "keypad digit");
        }
        expect(key(Qt::Key_Period), {Key::Point, false}, ".");
        expect(key(Qt::Key_Comma), {Key::Point, false}, ",");
        expect(key(Qt::Key_Plus), {Key::Plus, false}, "+");
        expect(key(Qt::Key_Minus), {Key::Minus, false}, "-");
        expect(key(Qt::Key_Asterisk), {Key::Multiply, false}, "*");
        expect(key(Qt::Key_Slash), {Key::Divide, false}, "/");
        expect(key(Qt::Key_Equal), {Key::Equals, false}, "=");
        expect(key(Qt::Key_Percent), {Key::Percent, false}, "%");
        expect(key(Qt::Key_Exclam), {Key::Exclamation, false}, "!");
        // Characters typed with Shift are the character, not SHIFT+key.
        expect(typed(Qt::Key_Exclam, "!", Qt::ShiftModifier), {Key::Exclamation, false},
               "Shift+1 = !");
        expect(typed(Qt::Key_Percent, "%", Qt::ShiftModifier), {Key::Percent, false},
               "Shift+5 = %");
        expect(typed(Qt::Key_Asterisk, "*", Qt::ShiftModifier), {Key::Multiply, false},
               "Shift+8 = *");
        // The Russian layout: the letters on the same keys.
        expect(typed(Qt::Key(0x42C), QStringLiteral("ь")), {Key::Mode, false}, "Ь = M");
        expect(typed(Qt::Key(0x420), QStringLiteral("р")), {Key::Help, false}, "Р = H");
        expect(typed(Qt::Key(0x417), QStringLiteral("з")), {Key::Par, false}, "З = P");
        expect(typed(Qt::Key(0x424), QStringLiteral("ф")), {Key::Ack, false}, "Ф = A");
        expect(typed(Qt::Key(0x41A), QStringLiteral("к")), {Key::Percent, false}, "К = R");

        // Keys that are not the panel's: nothing.
        spy.clear();
        QTest::keyClick(&s.w, Qt::Key_F9);
        QTest::keyClick(&s.w, Qt::Key_Q, Qt::ControlModifier);
        QTest::keyClick(&s.w, Qt::Key_5, Qt::AltModifier);
        QTest::keyClick(&s.w, Qt::Key_X);
        QTest::keyClick(&s.w, Qt::Key_Space);
        QCOMPARE(spy.count(), 0);
    }

    void everyDocumentedBindingWorks() {
        Shown s;
        s.w.setFocus();
        QSignalSpy spy(&s.w, &K923Widget::keyPressed);
        QSignalSpy latch(&s.w, &K923Widget::shiftLatchChanged);
        int covered = 0;
        for (const auto& b : k528::studio::pcKeyBindings()) {
            spy.clear();
            latch.clear();
            QTest::keyClick(&s.w, b.combination.key(), b.combination.keyboardModifiers());
            const QString what = QKeySequence(b.combination).toString();
            if (b.press.key == Key::Shift) {
                QVERIFY2(latch.count() == 1 && s.w.shiftLatched(), qPrintable(what));
                s.w.setShiftLatched(false);
                continue;
            }
            QVERIFY2(spy.count() == 1, qPrintable(what));
            QVERIFY2(spy.at(0).at(0).value<KeyPress>() == b.press, qPrintable(what));
            ++covered;
        }
        QVERIFY(covered > 60);
        // Every panel key has a PC key, shown in its tooltip.
        for (int i = 0; i < k528::panel::kKeyCount; ++i) {
            const Key k = keyAt(i);
            const QStringList pc = k528::studio::pcKeysFor({k, false});
            QVERIFY2(!pc.isEmpty(), k528::panel::keyName(k).data());
            const QString tip = s.w.key(k)->toolTip();
            QVERIFY2(tip.contains(pc.first().toHtmlEscaped()), qPrintable(tip));
            QVERIFY(tip.contains(k528::studio::keyTitle(k).toHtmlEscaped()));
        }
        QVERIFY(s.w.key(Key::Up)->toolTip().contains("PgUp"));
    }

    void heldArrowRepeatsButOtherKeysDoNot() {
        Shown s;
        s.w.setFocus();
        QSignalSpy spy(&s.w, &K923Widget::keyPressed);
        QTest::keyPress(&s.w, Qt::Key_PageDown);
        QVERIFY(s.w.key(Key::Down)->isDown()); // the key is shown pressed
        for (int i = 0; i < 3; ++i) {
            QKeyEvent repeat(QEvent::KeyPress, Qt::Key_PageDown, Qt::NoModifier, QString(), true);
            QApplication::sendEvent(&s.w, &repeat);
        }
        QTest::keyRelease(&s.w, Qt::Key_PageDown);
        QVERIFY(!s.w.key(Key::Down)->isDown());
        QCOMPARE(spy.count(), 4);
        for (const auto& args : spy)
            QCOMPARE(args.at(0).value<KeyPress>(), (KeyPress{Key::Down, true}));
        spy.clear();
        QTest::keyPress(&s.w, Qt::Key_Return);
        QKeyEvent repeat(QEvent::KeyPress, Qt::Key_Return, Qt::NoModifier, QString(), true);
        QApplication::sendEvent(&s.w, &repeat);
        QTest::keyRelease(&s.w, Qt::Key_Return);
        QCOMPARE(spy.count(), 1);
    }

    void doesNotStealKeysFromOtherWidgets() {
        QMainWindow window;
        auto* central = new QWidget(&window);
        auto* layout = new QVBoxLayout(central);
        auto* editor = new QLineEdit(central);
        auto* panel = new K923Widget(central);
        layout->addWidget(editor);
        layout->addWidget(panel);
        window.setCentralWidget(central);
        auto* refresh = window.addAction("refresh");
        refresh->setShortcut(Qt::Key_F5);
        auto* quit = window.addAction("quit");
        quit->setShortcut(Qt::CTRL | Qt::Key_Q);
        QSignalSpy refreshed(refresh, &QAction::triggered);
        QSignalSpy quitted(quit, &QAction::triggered);
        window.resize(500, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        QSignalSpy spy(panel, &K923Widget::keyPressed);

        editor->setFocus();
        QTest::keyClicks(editor, "R12=5");
        QTest::keyClick(editor, Qt::Key_Up);
        QTest::keyClick(editor, Qt::Key_F5);
        QCOMPARE(editor->text(), QStringLiteral("R12=5"));
        QCOMPARE(spy.count(), 0);
        QCOMPARE(refreshed.count(), 1);

        // Clicking the panel gives it the keyboard; then its keys win over the
        // window's shortcut F5, and shortcuts it does not use still work.
        QTest::mouseClick(panel, Qt::LeftButton, {}, panel->keyRect(Key::D7).center());
        QVERIFY(panel->hasFocus());
        QCOMPARE(spy.count(), 1);
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_F5);
        QCOMPARE(spy.count(), 2);
        QCOMPARE(spy.last().at(0).value<KeyPress>(), (KeyPress{Key::F5, false}));
        QCOMPARE(refreshed.count(), 1);
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Q, Qt::ControlModifier);
        QCOMPARE(quitted.count(), 1);
        QCOMPARE(spy.count(), 2);
        // Tab leaves the panel.
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Tab);
        QVERIFY(!panel->hasFocus());
    }

    void ledsShowTheDisplaysBits() {
        Shown s;
        QVERIFY(QTest::qWaitForWindowExposed(&s.w));
        PanelDisplay d = K923Widget::blankDisplay();
        // K<k>: off, green, red, amber in turn.
        for (int k = 1; k <= 12; ++k) {
            if (k % 4 == 1 || k % 4 == 3)
                d.leds.green |= static_cast<std::uint16_t>(1u << (k - 1));
            if (k % 4 == 2 || k % 4 == 3)
                d.leds.red |= static_cast<std::uint16_t>(1u << (k - 1));
        }
        d.leds.override = 0b0100; // L3
        s.w.setDisplay(d);
        for (int k = 1; k <= 12; ++k) {
            const Key key = keyAt(static_cast<int>(Key::K1) + k - 1);
            const Led want = k % 4 == 0   ? Led::Off
                             : k % 4 == 1 ? Led::Green
                             : k % 4 == 2 ? Led::Red
                                          : Led::Amber;
            QVERIFY2(ledAt(s.w, key) == want, qPrintable(QStringLiteral("K%1").arg(k)));
        }
        for (int n = 1; n <= 4; ++n)
            QCOMPARE(ledAt(s.w, keyAt(static_cast<int>(Key::L1) + n - 1)),
                     n == 3 ? Led::Green : Led::Off);
        QCOMPARE(ledAt(s.w, Key::Shift), Led::Off);
        // 17 LEDs and no more.
        int leds = 0;
        for (int i = 0; i < k528::panel::kKeyCount; ++i)
            leds += s.w.ledCentre(keyAt(i)) ? 1 : 0;
        QCOMPARE(leds, 17);
        s.w.setDisplay(K923Widget::blankDisplay());
        QCOMPARE(ledAt(s.w, Key::K1), Led::Off);
        QCOMPARE(ledAt(s.w, Key::L3), Led::Off);
    }

    void scalesWithoutGapsOrOverlaps_data() {
        QTest::addColumn<QSize>("size");
        QTest::newRow("small") << QSize(300, 422);
        QTest::newRow("large") << QSize(910, 1280);
        QTest::newRow("wide dock") << QSize(900, 500);
        QTest::newRow("default dock") << QSize(400, 560);
    }
    void scalesWithoutGapsOrOverlaps() {
        QFETCH(QSize, size);
        Shown s(size);
        QVERIFY(QTest::qWaitForWindowExposed(&s.w));
        s.w.lcd()->setBlinkFrozen(true);
        const QRectF plate = s.w.panelLayout().plate();
        QVERIFY(QRectF(s.w.rect()).adjusted(-1, -1, 1, 1).contains(plate));
        QVERIFY(plate.width() >= 0.95 * size.width() || plate.height() >= 0.95 * size.height());
        std::vector<QRect> rects{s.w.lcdRect()};
        for (int i = 0; i < k528::panel::kKeyCount; ++i)
            rects.push_back(s.w.keyRect(keyAt(i)));
        for (std::size_t i = 0; i < rects.size(); ++i) {
            QVERIFY(!rects[i].isEmpty());
            QVERIFY(plate.contains(QRectF(rects[i])));
            for (std::size_t j = i + 1; j < rects.size(); ++j)
                QVERIFY2(!rects[i].intersects(rects[j]),
                         qPrintable(QStringLiteral("%1 and %2 overlap").arg(i).arg(j)));
        }
        // The digit keys are all the same size.
        for (int d = 1; d <= 9; ++d)
            QCOMPARE(s.w.keyRect(keyAt(static_cast<int>(Key::D0) + d)).size(),
                     s.w.keyRect(Key::D1).size());

        // The LCD: same-sized dots on whole pixels, dots apart, cells further apart.
        const auto l = s.w.lcd()->layout();
        QVERIFY(l.pixelAligned());
        QVERIFY(l.dotSize() < l.pitch());
        QCOMPARE(l.pitch(), std::round(l.pitch()));
        QVERIFY(l.glass().contains(l.dotArea()));
        QVERIFY(QRectF(s.w.lcd()->rect()).contains(l.glass()));
        // Whole-pixel dots cost little of the characters' size.
        QVERIFY2(l.dotArea().width() >= 0.7 * s.w.lcdRect().width(),
                 qPrintable(QString::number(l.pitch())));
        const QRectF a = l.dotRect(0, 0, 0, 0);
        const QRectF b = l.dotRect(0, 0, 1, 0);
        const double dotGap = b.left() - a.right();
        QVERIFY(dotGap > 0);
        QCOMPARE(b.left() - a.left(), l.pitch());
        QCOMPARE(l.cellPitchX(), std::round(l.cellPitchX()));
        QCOMPARE(l.cellPitchY(), std::round(l.cellPitchY()));
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 20; ++c) {
                const QRectF cell = l.cellRect(r, c);
                QVERIFY(l.dotArea().contains(cell));
                QCOMPARE(cell.size(), l.cellRect(0, 0).size());
                if (c + 1 < 20)
                    QVERIFY(l.cellRect(r, c + 1).left() - cell.right() > dotGap); // cells apart
                if (r + 1 < 4)
                    QVERIFY(l.cellRect(r + 1, c).top() - cell.bottom() > dotGap);
            }

        s.w.setDisplay(screen({"", "", "", "                   Ю"}));
        expectCell(grabLcd(s.w), *s.w.lcd(), 3, 19, *k528::panel::lcdGlyph(U'Ю'), "Ю, last cell");
        // A click hits the key at this size too.
        QSignalSpy spy(&s.w, &K923Widget::keyPressed);
        QTest::mouseClick(&s.w, Qt::LeftButton, {}, s.w.keyRect(Key::Enter).center());
        QCOMPARE(spy.count(), 1);
    }

    void keyboardMapListsEveryKey() {
        Shown s;
        s.w.showKeyboardMap();
        auto* dialog = s.w.findChild<k528::studio::KeyboardMapDialog*>();
        QVERIFY(dialog);
        QVERIFY(dialog->isVisible());
        QTableWidget* t = dialog->table();
        QCOMPARE(t->rowCount(), k528::panel::kKeyCount + 2); // + SHIFT+▲, SHIFT+▼
        QStringList titles;
        for (int r = 0; r < t->rowCount(); ++r) {
            titles << t->item(r, 0)->text();
            QVERIFY(!t->item(r, 1)->text().isEmpty());
            QVERIFY(!t->item(r, 2)->text().isEmpty());
        }
        for (const char* title :
             {"F1 АВТ", "F8", "K12", "L4", "▲", "SHIFT+▲", "SHIFT+▼", "ENTER", "% R", "!"})
            QVERIFY2(titles.contains(QString::fromUtf8(title)), title);
        dialog->close();
    }

    void keyFacesFollowTheManual() {
        using k528::studio::keyFace;
        QCOMPARE(keyFace(Key::F1).legend, QStringLiteral("АВТ"));
        QCOMPARE(keyFace(Key::F2).legend, QStringLiteral("РУЧ"));
        QCOMPARE(keyFace(Key::F3).legend, QStringLiteral("ПБТ"));
        QCOMPARE(keyFace(Key::F4).legend, QStringLiteral("УСТ"));
        QCOMPARE(keyFace(Key::F8).legend, QStringLiteral("F8"));
        QCOMPARE(keyFace(Key::F1).corner, QStringLiteral("F1"));
        QCOMPARE(keyFace(Key::Percent).legend + ' ' + keyFace(Key::Percent).sub,
                 QStringLiteral("% R"));
        QVERIFY(keyFace(Key::Up).shiftedLegend);
        QVERIFY(keyFace(Key::Down).shiftedLegend);
        QVERIFY(!keyFace(Key::Left).shiftedLegend);
        // K7 is bit 8 of Z1300/Z1906/Z1907 (table 4).
        QVERIFY(k528::studio::keyDescription(Key::K7).contains("Z1906.8"));
        QVERIFY(k528::studio::keyDescription(Key::K6).contains("Z1300.5"));
        QVERIFY(k528::studio::keyDescription(Key::L2).contains("C140"));
    }

    void mainWindowCarriesTheSessionsPanel() {
        k528::studio::MainWindow w;
        auto* panel = w.k923();
        QVERIFY(panel);
        QCOMPARE(w.k923Dock()->widget(), panel);
        QCOMPARE(w.findChild<K923Widget*>(), panel);
        // The powered-on controller's РУЧНОЙ screen, drawn by the panel model.
        QCOMPARE(panel->display(), w.session()->panel().display());
        QVERIFY(panel->lcd()->backlight());
        QVERIFY(panel->lcd()->text().startsWith(QStringLiteral("РУЧ")));
    }

    void writesSampleImages() {
        // Pictures for a human to look at (build/…/test-output/); also a check
        // that the rendering is not empty.
        QDir().mkpath(K528_BINARY_DIR "/test-output");
        const QList<QStringList> screens = {
            {"УСТ ПРЕДУСТАНОВКИ", "> 1 - КООРД.И СМЕЩ.", "  2 - ИСХОДНОЕ", "  3 - ПОДНАЛАДКА"},
            {"АВТ      1    100%", "Шлифование торца", "*X  234.567 -110.000",
             " Z -1065.124   0.000"},
            {"Укажите тип кадра", "1-вычислит.кадр", "2-кадр усл.перехода", "3-кадр безусл.перех"},
            {"ABCDEFGHIJKLMNOPQRST", "abcdefghijklmnopqrst", "UVWXYZuvwxyz01234567",
             "89!\"#$%&'()*+,-./:;<"},
            {"=>?@[\\]^_`{|}~ ▲▼◀►№°", "АБВГДЕЁЖЗИЙКЛМНОПРС", "ТУФХЦЧШЩЪЫЬЭЮЯ «»±█",
             "абвгдеёжзийклмнопрст"},
            {"уфхцчшщъыьэюя ←→↑↓", "РЕДАКТИРОВАНИЕ УП", "N202 IF R1>0", "     GOTO 301"},
        };
        int n = 0;
        for (const QStringList& lines : screens) {
            Shown s({600, 844});
            s.w.lcd()->setBlinkFrozen(true);
            PanelDisplay d = screen(lines);
            d.leds.green = 0b0000'0001'0000'0101;
            d.leds.red = 0b0000'0000'0000'0110;
            d.leds.override = 0b0001;
            s.w.setDisplay(d);
            const QImage img = s.w.grab().toImage();
            K528_VERIFY_SHOT(img, QStringLiteral("k923-sample-%1.png").arg(++n));
            K528_VERIFY_SHOT(s.w.lcd()->grab(), QStringLiteral("k923-lcd-%1.png").arg(n));
        }
    }
};

QTEST_MAIN(TestK923Widget)
#include "test_k923_widget.moc"
