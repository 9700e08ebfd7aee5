// The text helpers of the screens: the canvas, the panel's number formats,
// the message wrap and the typed entry with the arithmetic of table 3.
#include "panel/text.h"

#include <QtTest>

using namespace k528;
using namespace k528::panel;

namespace {
units::AxisScale scale(units::Discrete d) {
    units::AxisScale s;
    s.discrete = d;
    return s;
}
QStringList q(const std::vector<std::string>& v) {
    QStringList l;
    for (const auto& s : v)
        l << QString::fromStdString(s);
    return l;
}
} // namespace

class TestText : public QObject {
    Q_OBJECT
private slots:
    void canvas() {
        Canvas c;
        c.put(0, 1, "АВТ");
        c.putRight(0, 19, "100%");
        c.put(1, 18, "ОШИБКА"); // cut at column 20
        c.blink(3, 19, 5);
        QCOMPARE(QString::fromStdString(c.line(0)), QString("АВТ            100% "));
        QCOMPARE(QString::fromStdString(c.line(1)), QString("                 ОШИ"));
        const Lcd l = c.lcd();
        QCOMPARE(l.blinkRow, 3);
        QCOMPARE(l.blinkColumn, 18);
        QCOMPARE(l.blinkLength, 2);
        c.noBlink();
        QCOMPARE(c.lcd().blinkLength, 0);
    }

    void wrap_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QStringList>("lines");
        // Appendix М prints these two broken after 20 characters.
        QTest::newRow("8") << "8.Контроль полож/зажима оси X"
                           << QStringList{"8.Контроль полож/", "зажима оси X"};
        QTest::newRow("13") << "13.Ошибка коэфф.преобразования ДОС (X)"
                            << QStringList{"13.Ошибка коэфф.", "преобразования ДОС", "(X)"};
        QTest::newRow("short") << "19.Нет связи с ПЛК" << QStringList{"19.Нет связи с ПЛК"};
        QTest::newRow("exactly 20")
            << "12345678901234567890" << QStringList{"12345678901234567890"};
        QTest::newRow("long word")
            << "АБВГДЕЖЗИЙКЛМНОПРСТУФХ" << QStringList{"АБВГДЕЖЗИЙКЛМНОПРСТУ", "ФХ"};
        QTest::newRow("blanks") << "  один   два  " << QStringList{"один   два"};
    }
    void wrap() {
        QFETCH(QString, text);
        QFETCH(QStringList, lines);
        QCOMPARE(q(wrapText(text.toStdString(), 20)), lines);
    }

    void formats() {
        const auto s3 = scale(units::Discrete::Mm0_001);
        const auto s2 = scale(units::Discrete::Mm0_01);
        const auto s4 = scale(units::Discrete::Mm0_0001);
        QCOMPARE(formatCoordinate(-1065124, s3), std::string("-1065.124"));
        QCOMPARE(formatCoordinate(-24, s3), std::string("-0.024"));
        QCOMPARE(formatFeed(10000, s3), std::string("10.00"));
        QCOMPARE(formatFeed(1000000, s3), std::string("1000.00"));
        QCOMPARE(formatFeed(1000000, s3, 6), std::string("1000.0"));
        QCOMPARE(formatFeed(12000000, s3, 6), std::string("12000"));
        QCOMPARE(formatFeed(100005, s3), std::string("100.01")); // rounded half away
        QCOMPARE(formatFeed(150, s2), std::string("1.50"));
        QCOMPARE(formatFeed(15, s4), std::string("0.00"));
        QCOMPARE(formatSeconds(1000), std::string("1.000"));
        QCOMPARE(formatSeconds(250), std::string("0.250"));
        QCOMPARE(formatScaled(-5, 3), std::string("-0.005"));
        QCOMPARE(padLeft("АБ", 4), std::string("  АБ"));
        QCOMPARE(padLeft("АБВГД", 4), std::string("АБВГД"));
    }

    void evaluate_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("decimals");
        QTest::addColumn<qlonglong>("value"); // -999 = no value
        QTest::newRow("integer") << "12" << 0 << 12LL;
        QTest::newRow("mm") << "-12.356" << 3 << -12356LL;
        QTest::newRow("fewer decimals") << "1.5" << 3 << 1500LL;
        QTest::newRow("trailing point") << "7." << 2 << 700LL;
        QTest::newRow("too many decimals") << "1.2345" << 3 << -999LL;
        QTest::newRow("left to right") << "2+3*4" << 0 << 20LL;
        QTest::newRow("decimal product") << "1.5*1.5" << 3 << 2250LL;
        QTest::newRow("quotient") << "10/3" << 3 << 3333LL;
        QTest::newRow("quotient half up") << "5/2" << 0 << 3LL;
        QTest::newRow("negative quotient") << "-5/2" << 0 << -3LL;
        QTest::newRow("sign after op") << "5*-2" << 0 << -10LL;
        QTest::newRow("subtraction") << "5-7" << 0 << -2LL;
        QTest::newRow("division by zero") << "5/0" << 0 << -999LL;
        QTest::newRow("dangling op") << "5+" << 0 << -999LL;
        QTest::newRow("empty") << "" << 0 << -999LL;
        QTest::newRow("two points") << "1.2.3" << 3 << -999LL;
    }
    void evaluate() {
        QFETCH(QString, text);
        QFETCH(int, decimals);
        QFETCH(qlonglong, value);
        const auto v = evaluateEntry(text.toStdString(), decimals);
        if (value == -999)
            QVERIFY(!v.has_value());
        else
            QCOMPARE(v.value_or(-999), std::int64_t(value));
    }

    void entryKinds() {
        Entry e;
        e.start(Entry::Kind::Digits, 2);
        QVERIFY(e.type(Key::D1));
        QVERIFY(!e.type(Key::Point));
        QVERIFY(e.type(Key::D2));
        QVERIFY(e.type(Key::D3)); // consumed, not typed: two characters
        QCOMPARE(e.text(), std::string("12"));
        e.start(Entry::Kind::Frame, 10);
        QVERIFY(e.type(Key::Percent));
        QVERIFY(!e.type(Key::Point));
        QVERIFY(e.type(Key::D7));
        QCOMPARE(e.text(), std::string("R7"));
        e.start(Entry::Kind::Frame, 10);
        for (Key k : {Key::Minus, Key::D5, Key::Point, Key::D3})
            QVERIFY(e.type(k));
        QVERIFY(!e.type(Key::Minus));
        QVERIFY(!e.type(Key::Point));
        QCOMPARE(e.text(), std::string("-5.3"));
        e.start(Entry::Kind::OpOperand, 13);
        QVERIFY(!e.type(Key::D1)); // an operation first
        QVERIFY(e.type(Key::Multiply));
        QVERIFY(e.type(Key::Percent));
        QVERIFY(e.type(Key::D9));
        QCOMPARE(e.text(), std::string("*R9"));
        e.start(Entry::Kind::Calculator, 12, 3);
        for (Key k : {Key::D1, Key::D0, Key::Plus, Key::D2, Key::Point, Key::D5})
            QVERIFY(e.type(k));
        QVERIFY(!e.type(Key::Equals)); // «=» is the caller's: assignResult
        QVERIFY(e.assignResult());
        QCOMPARE(e.text(), std::string("12.500"));
        e.backspace();
        QCOMPARE(e.text(), std::string("12.50"));
    }
};

QTEST_APPLESS_MAIN(TestText)
#include "test_text.moc"
