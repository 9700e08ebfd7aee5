#include <QtTest>

#include "units/units.h"

using namespace k528::units;

class TestUnits : public QObject {
    Q_OBJECT
private slots:
    void discretes() {
        const AxisScale um{Discrete::Mm0_001, false};
        QCOMPARE(mmToDisc(5.342, um), 5342);
        QCOMPARE(mmToDisc(-1234.678, um), -1234678);
        QCOMPARE(mmToDisc(0.0005, um), 1);   // half away from zero
        QCOMPARE(mmToDisc(-0.0005, um), -1);
        QCOMPARE(discToMm(190000, um), 190.0);
        const AxisScale cm{Discrete::Mm0_01, false};
        QCOMPARE(mmToDisc(5.342, cm), 534);
        QCOMPARE(cm.kd(), 10.0);
        const AxisScale tenth{Discrete::Mm0_0001, false};
        QCOMPARE(tenth.kd(), 0.1);
        QCOMPARE(tenth.decimals(), 4);
    }
    void internalUnitsAreHalfAMotionDiscrete() {
        const AxisScale z{Discrete::Mm0_001, false};
        const AxisScale x{Discrete::Mm0_001, true};
        QCOMPARE(discToInternal(1000, z), 2000);  // 1 mm of Z = 2000 internal units
        QCOMPARE(discToInternal(1000, x), 1000);  // 1 mm of diameter = 0.5 mm slide = 1000 units
        QCOMPARE(z.internalMotionMm(), 0.0005);
        QCOMPARE(x.internalMotionMm(), 0.0005);
        // Back to discretes by the exact reciprocal: the quotient bit for bit.
        for (const double v : {0.0, 1.0, -3.0, 2001.0, 12345.678901, -0.1, 1e300, 4.9e-324}) {
            QVERIFY(internalToDisc(v, z) == v / static_cast<double>(z.internalPerDisc()));
            QVERIFY(internalToDisc(v, x) == v / static_cast<double>(x.internalPerDisc()));
            QCOMPARE(z.internalPerDisc() * z.discPerInternal(), 1.0);
            QCOMPARE(x.internalPerDisc() * x.discPerInternal(), 1.0);
        }
        QCOMPARE(internalToDisc(2001.0, z), 1000.5);
    }
    void formats() {
        const AxisScale um{Discrete::Mm0_001, false};
        QCOMPARE(formatDisc(234567, um), std::string("234.567"));
        QCOMPARE(formatDisc(-20, um), std::string("-0.020"));
        QCOMPARE(formatDisc(0, um), std::string("0.000"));
        QCOMPARE(formatDisc(12051240, AxisScale{Discrete::Mm0_0001, false}), std::string("1205.1240"));
        QCOMPARE(formatDisc(-1006, AxisScale{Discrete::Mm0_01, false}), std::string("-10.06"));
        QCOMPARE(formatTrimmed(1.25, 3), std::string("1.25"));
        QCOMPARE(formatTrimmed(-3.0, 3), std::string("-3"));
        QCOMPARE(formatTrimmed(-0.0002, 3), std::string("0")); // never "-0"
        QCOMPARE(formatTrimmed(120.0, 0), std::string("120")); // no point: zeros of the whole part stay
        QCOMPARE(formatTrimmed(954.929658, 2), std::string("954.93"));
    }
    void speedConstants() {
        // Appendix Ж: F ОБЫЧНАЯ 500000 = 5000 mm/min at 0.001 mm.
        const AxisScale um{Discrete::Mm0_001, false};
        QCOMPARE(speedParamToMmPerMin(500000, um), 5000.0);
        QCOMPARE(mmPerMinToSpeedParam(50.0, um), 5000);
    }
    void accelerationConstants() {
        // Parameter 22, formula 3: value = 25600·A/Kd.
        const AxisScale um{Discrete::Mm0_001, false};
        QCOMPARE(mPerS2ToAccelParam(0.078125, um), 2000);
        QCOMPARE(accelParamToMmPerS2(2000, um), 78.125);
        // Appendix Ж, C74: braking from 10 m/min over 80 mm. The exact
        // acceleration gives 4444; the manual's 4445 comes from formula 2's
        // rounded coefficient 3.556 (exactly 3.5556).
        const double v = 10.0 / 60.0, s = 0.080;
        QCOMPARE(mPerS2ToAccelParam(v * v / (2 * s), um), 4444);
    }
    void overrideSteps() {
        QCOMPARE(overrideCodeToPercent(7), 50);
        QCOMPARE(overrideCodeToPercent(10), 100);
        QCOMPARE(overrideCodeToPercent(15), 100);
        QCOMPARE(overridePercentToCode(35), 6);
        QCOMPARE(overridePercentToCode(40), -1);
    }
};

QTEST_APPLESS_MAIN(TestUnits)
#include "test_units.moc"
