#include <QtTest>

#include "program/decimal.h"

using k528::program::Decimal;

class TestDecimal : public QObject {
    Q_OBJECT
private slots:
    void parsesAndPrintsShortestExact_data() {
        QTest::addColumn<QString>("in");
        QTest::addColumn<QString>("out");
        QTest::newRow("point") << "5.342" << "5.342";
        QTest::newRow("no point") << "5" << "5";
        QTest::newRow("trailing zeros") << "20.500" << "20.5";
        QTest::newRow("all zeros after point") << "5.000" << "5";
        QTest::newRow("negative") << "-1234.678" << "-1234.678";
        QTest::newRow("plus") << "+12.10" << "12.1";
        QTest::newRow("leading point") << ".5" << "0.5";
        QTest::newRow("negative leading point") << "-.05" << "-0.05";
        QTest::newRow("trailing point") << "7." << "7";
        QTest::newRow("leading zeros") << "007.0100" << "7.01";
        QTest::newRow("negative zero") << "-0.000" << "0";
        QTest::newRow("zero") << "0" << "0";
        QTest::newRow("small") << "0.0001" << "0.0001";
        QTest::newRow("18 digits") << "123456789.123456789" << "123456789.123456789";
        QTest::newRow("zeros inside") << "100.001" << "100.001";
    }
    void parsesAndPrintsShortestExact() {
        QFETCH(QString, in);
        QFETCH(QString, out);
        const auto d = Decimal::parse(in.toStdString());
        QVERIFY(d.has_value());
        QCOMPARE(QString::fromStdString(d->toString()), out);
        // Normalised: equal values are equal members.
        QCOMPARE(*Decimal::parse(out.toStdString()), *d);
    }
    void rejectsMalformed_data() {
        QTest::addColumn<QString>("in");
        for (const char* s : {"", ".", "-", "+", "5..3", "5.3.2", "1e5", "5,3", "--5", " 5", "0x10", "1234567890.123456789"})
            QTest::newRow(s) << s;
    }
    void rejectsMalformed() {
        QFETCH(QString, in);
        QVERIFY(!Decimal::parse(in.toStdString()).has_value());
    }
    void compares() {
        const auto a = *Decimal::parse("9999.999");
        const auto b = *Decimal::parse("9999.9991");
        const auto c = *Decimal::parse("10000");
        QVERIFY(a < b);
        QVERIFY(b < c);
        QVERIFY(*Decimal::parse("-0.5") < *Decimal::parse("0"));
        QVERIFY(*Decimal::parse("2.50") == *Decimal::parse("2.5"));
        QVERIFY(*Decimal::parse("-9999.999") < *Decimal::parse("-9999.998"));
    }
    void roundsHalfAwayFromZero() {
        QCOMPARE(Decimal::parse("5.3425")->toUnits(3), 5343LL);
        QCOMPARE(Decimal::parse("5.3424")->toUnits(3), 5342LL);
        QCOMPARE(Decimal::parse("-5.3425")->toUnits(3), -5343LL);
        QCOMPARE(Decimal::parse("-5.3424")->toUnits(3), -5342LL);
        QCOMPARE(Decimal::parse("5")->toUnits(4), 50000LL);
        QCOMPARE(Decimal::parse("0.005")->toUnits(2), 1LL);
        QCOMPARE(Decimal::parse("12.324")->toUnits(3), 12324LL);
        QCOMPARE(QString::fromStdString(Decimal::parse("5.3425")->rounded(3).toString()), QString("5.343"));
        QCOMPARE(QString::fromStdString(Decimal::parse("2.996")->rounded(2).toString()), QString("3"));
    }
    void toDoubleIsNearest() {
        QCOMPARE(Decimal::parse("100.001")->toDouble(), 100.001);
        QCOMPARE(Decimal::parse("-30.5")->toDouble(), -30.5);
    }
    void fromScaledNormalises() {
        const Decimal d = Decimal::fromScaled(12300, 3);
        QCOMPARE(d.mantissa, 123LL);
        QCOMPARE(d.scale, 1);
        QCOMPARE(Decimal::fromScaled(0, 5).scale, 0);
    }
};

QTEST_APPLESS_MAIN(TestDecimal)
#include "test_decimal.moc"
