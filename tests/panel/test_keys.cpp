#include <QtTest>

#include "panel/keys.h"

using namespace k528::panel;

class TestKeys : public QObject {
    Q_OBJECT
private slots:
    void everyCliNameRoundTrips() {
        // shared/spec/cli.md lists these names.
        const char* names[] = {"F1", "F8", "K1", "K12", "L1", "L4", "UP", "DOWN", "LEFT", "RIGHT", "MODE",
                               "HELP", "ESC", "SHIFT", "PAR", "ACK", "INS", "DEL", "ENTER", "0", "9", ".",
                               "+", "-", "*", "/", "=", "%", "!"};
        for (const char* n : names) {
            const auto k = keyFromName(n);
            QVERIFY2(k.has_value(), n);
            QCOMPARE(std::string(keyName(*k)), std::string(n));
        }
        QCOMPARE(kKeyCount, 8 + 12 + 4 + 4 + 9 + 10 + 8);
    }
    void shiftCombos() {
        QCOMPARE(parseKey("SHIFT+UP"), std::optional<KeyPress>(KeyPress{Key::Up, true}));
        QCOMPARE(parseKey("shift+down"), std::optional<KeyPress>(KeyPress{Key::Down, true}));
        QCOMPARE(parseKey("enter"), std::optional<KeyPress>(KeyPress{Key::Enter, false}));
        QVERIFY(!parseKey("SHIFT+").has_value());
        QVERIFY(!parseKey("F9").has_value());
        QVERIFY(!parseKey("K13").has_value());
        QCOMPARE(formatKey(KeyPress{Key::Down, true}), std::string("SHIFT+DOWN"));
    }
    void splitsKeyStrings() {
        const auto t = splitKeys("  F2 SHIFT+UP\t1  2 ENTER WAIT:2.5 ");
        QCOMPARE(t.size(), std::size_t(6));
        QCOMPARE(t[1], std::string("SHIFT+UP"));
        QCOMPARE(t[5], std::string("WAIT:2.5"));
    }
    void classifies() {
        QCOMPARE(digitOf(Key::D7), 7);
        QCOMPARE(digitOf(Key::Point), -1);
        QCOMPARE(functionNumber(Key::F7), 7);
        QCOMPARE(functionNumber(Key::K12), 12);
        QCOMPARE(functionNumber(Key::L3), 3);
        QCOMPARE(functionNumber(Key::Enter), 0);
        QVERIFY(isKKey(Key::K10) && !isKKey(Key::L1));
    }
};

QTEST_APPLESS_MAIN(TestKeys)
#include "test_keys.moc"
