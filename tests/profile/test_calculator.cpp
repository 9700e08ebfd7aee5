// The C-constant calculator reproduces appendix Ж's worked values.
#include "profile/builtin.h"
#include "profile/calculator.h"

#include <QtTest>

using namespace k528;
using namespace k528::profile;
using namespace k528::profile::calc;

namespace {
const units::AxisScale um{units::Discrete::Mm0_001, false};
const units::AxisScale umDiameter{units::Discrete::Mm0_001, true};
} // namespace

class TestCalculator : public QObject {
    Q_OBJECT
private slots:
    // Ж, parameter 22: Vmax = 5000 mm/min, Tразг = 2 s -> 2133; 23: 1 s -> 4266.
    void formula1() {
        const AccelResult a = accelByRunUp(5000000, 2000, umDiameter);
        QCOMPARE(a.formula, 1);
        QCOMPARE(a.printedValue, std::int64_t(2133));
        QCOMPARE(accelByRunUp(5000000, 1000, umDiameter).printedValue, std::int64_t(4266));
        // The run-up described is 0.0833 m/s / 2 s = 0.04167 m/s²; in the unit
        // of formulas 2 and 3 that is 1066, and 2133 means twice the acceleration.
        QVERIFY(qAbs(a.describedMPerS2 - 5.0 / 60.0 / 2.0) < 1e-12);
        QCOMPARE(a.consistentValue, std::int64_t(1066));
        QVERIFY(qAbs(a.printedFactor() - 2.0) < 0.001);
    }

    // Ж, parameters 74/75: Vmax = 10 m/min, Сторм = 80 / 20 mm -> 4445 / 17780.
    void formula2() {
        const AccelResult a = accelByBraking(10000000, 80000, um);
        QCOMPARE(a.formula, 2);
        QCOMPARE(a.printedValue, std::int64_t(4445));
        QCOMPARE(a.consistentValue, std::int64_t(4444)); // 3.556 is 3.5556 rounded
        QVERIFY(qAbs(a.printedFactor() - 1.0) < 0.001);
        const AccelResult b = accelByBraking(10000000, 20000, um);
        QCOMPARE(b.printedValue, std::int64_t(17780));
        QCOMPARE(b.consistentValue, std::int64_t(17777));
    }

    void formula3() {
        QCOMPARE(accelByValue(0.078125, um).printedValue, std::int64_t(2000));
        QCOMPARE(accelByValue(0.078125, um).consistentValue, std::int64_t(2000));
        QCOMPARE(accelByValue(1.0, units::AxisScale{units::Discrete::Mm0_01, false}).printedValue,
                 std::int64_t(2560));
        QCOMPARE(accelByValue(0.1, units::AxisScale{units::Discrete::Mm0_0001, false}).printedValue,
                 std::int64_t(25600));
        // Formulas 2 and 3 agree: braking 6 m/min in 5 mm is 1 m/s².
        QCOMPARE(accelByBraking(6000000, 5000, um).consistentValue,
                 accelByValue(1.0, um).printedValue);
    }

    // Ж, parameters 26/27 and 78/79.
    void gains() {
        QCOMPARE(speedGain(10, 10, um), std::int64_t(262));
        QCOMPARE(errorGain(1, 10, 10, um), std::int64_t(26));
        QCOMPARE(speedGain(5, 10, um), std::int64_t(131));
        QCOMPARE(errorGain(1, 5, 10, um), std::int64_t(13));
        QCOMPARE(speedGain(10, 10, units::AxisScale{units::Discrete::Mm0_01, false}),
                 std::int64_t(2620));
        QCOMPARE(errorGain(1.5, 10, 15, um), std::int64_t(26));
    }

    // Ж: 5 mm per motor revolution, 2500 lines, 0.001 mm -> 1/2 (X on the diameter too).
    void encoderRatios() {
        const EncoderRatio r = encoderRatio(5, 1, 2500, um);
        QCOMPARE(r.l, std::int64_t(1));
        QCOMPARE(r.n, std::int64_t(2));
        QVERIFY(r.exact);
        QCOMPARE(r.discPerPulse, 0.5);
        const EncoderRatio d = encoderRatio(5, 1, 2500, umDiameter);
        QCOMPARE(d.l, std::int64_t(1));
        QCOMPARE(d.n, std::int64_t(2));
        QCOMPARE(encoderRatio(10, 2, 2000, um).l, std::int64_t(5));
        QCOMPARE(encoderRatio(10, 2, 2000, um).n, std::int64_t(8));
        QCOMPARE(encoderRatio(6, 1, 1024, um).l, std::int64_t(375));
        QCOMPARE(encoderRatio(6, 1, 1024, um).n, std::int64_t(256));
        QCOMPARE(encoderRatio(5, 1, 2500, units::AxisScale{units::Discrete::Mm0_0001, false}).l,
                 std::int64_t(5));
        // Does not fit 1..32767: the closest fraction that does.
        const EncoderRatio big = encoderRatio(5, 7.0 / 3.0, 32768, um);
        QVERIFY(!big.exact);
        QVERIFY(big.l >= 1 && big.l <= 32767 && big.n >= 1 && big.n <= 32767);
        QVERIFY(qAbs(big.errorPpm) < 1.0);
        QVERIFY_THROWS_EXCEPTION(CalcError, encoderRatio(5.0004, 1, 2500, um));
        QVERIFY_THROWS_EXCEPTION(CalcError, encoderRatio(5, 1, 0, um));
    }

    void speedsAndDacLimit() {
        QCOMPARE(speedParam(5000, um), std::int64_t(500000));
        QCOMPARE(speedParam(50, um), std::int64_t(5000));
        QCOMPARE(speedParam(5, um), std::int64_t(500));
        QCOMPARE(dacLimit(2047), std::int64_t(2395)); // Ж: 2395
        QCOMPARE(dacLimit(2047, 15), std::int64_t(2354));
        QVERIFY_THROWS_EXCEPTION(CalcError, speedParam(-1, um));
    }

    void wholeAxis() {
        AxisDesign d;
        d.scale = umDiameter;
        d.feedNormalMmPerMin = 5000;
        d.feedRapidMmPerMin = 8000;
        d.feedAutoRapidMmPerMin = 5000;
        d.feedHomeStartMmPerMin = 50;
        d.feedHomeCreepMmPerMin = 5;
        d.accel1 = {AccelSpec::By::RunUp, 5000, 2000, 0, 0, true};
        const AxisConstants k = designAxis(d);
        // Ж's axis X, with УСКОРЕНИЕ 1 by formula 1 as printed.
        QCOMPARE(k.values.at(22), std::int64_t(2133));
        QCOMPARE(k.values.at(19), std::int64_t(1));
        QCOMPARE(k.values.at(20), std::int64_t(2));
        QCOMPARE(k.values.at(26), std::int64_t(262));
        QCOMPARE(k.values.at(27), std::int64_t(26));
        QCOMPARE(k.values.at(28), std::int64_t(2395));
        QCOMPARE(k.values.at(40), std::int64_t(500000));
        QCOMPARE(k.values.at(41), std::int64_t(800000));
        QCOMPARE(k.values.at(44), std::int64_t(500));
        QCOMPARE(k.values.at(7), std::int64_t(1));
        QCOMPARE(k.values.at(23), std::int64_t(0));
        QVERIFY(!k.steps.empty());
        // Consistent unit: half of it.
        d.accel1.asPrinted = false;
        QCOMPARE(designAxis(d).values.at(22), std::int64_t(1066));
        // Faster than the drive can go.
        d.feedRapidMmPerMin = 30000;
        QVERIFY_THROWS_EXCEPTION(CalcError, designAxis(d));
        d.feedRapidMmPerMin = 8000;
        // An acceleration beyond the parameter's range.
        d.accel1 = {AccelSpec::By::Value, 0, 0, 0, 2.0, false};
        QVERIFY_THROWS_EXCEPTION(CalcError, designAxis(d));
    }

    void summary() {
        const AxisSummary s = summarizeAxis(builtin("grinder-205"), catalog::Axis::X);
        QCOMPARE(s.feedAutoRapidMmPerMin, 5000.0);
        QCOMPARE(s.accel1MPerS2, 2000.0 / 25600.0);
        QCOMPARE(s.accel2MPerS2, 4000.0 / 25600.0);
        QCOMPARE(s.motionMmPerPulse, 0.0005);
        QCOMPARE(s.limitPlusMm, 40.0);
        QVERIFY(qAbs(s.runUpToAutoRapidMs - (5.0 / 60.0) / (2000.0 / 25600.0) * 1000.0) < 1e-9);
    }
};

QTEST_APPLESS_MAIN(TestCalculator)
#include "test_calculator.moc"
