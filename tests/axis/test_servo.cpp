#include <QtTest>

#include <cmath>

#include "rig/axis_loop.h"

using namespace k528::axis;
namespace testrig = k528::testrig;
using testrig::AxisLoop;

namespace {
Constants with(const std::function<void(Constants&)>& f) {
    Constants k = testrig::grinderZ();
    f(k);
    return k;
}
} // namespace

class TestServo : public QObject {
    Q_OBJECT
private slots:
    void faultNumbersAreTheManuals() {
        QCOMPARE(faultMessage(Fault::FollowingError, AxisId::X), 7);
        QCOMPARE(faultMessage(Fault::FollowingError, AxisId::Z), 23);
        QCOMPARE(faultMessage(Fault::Standstill, AxisId::Z), 24);
        QCOMPARE(faultMessage(Fault::EncoderStall, AxisId::X), 56);
        QCOMPARE(faultMessage(Fault::EncoderStall, AxisId::Z), 57);
        QCOMPARE(faultMessage(Fault::DriveNotReady, AxisId::Z), 32);
        QCOMPARE(faultMessage(Fault::None, AxisId::Z), 0);
    }

    // Mechanics::quiet(): the encoder's outputs are those before the last
    // tick, which found the plant at rest (a reader copies them only when not
    // quiet). A push or a broken channel changes them at once: not quiet
    // until a tick at rest again; a tick that moves the motor is not quiet.
    // The drive's speed of a DAC code is computed once and kept: a code set
    // again gives the motor the same speed as a code set the first time, in
    // the DAC's range and beyond it (drift and a reversed wiring included).
    void mechanicsSpeedOfACodeKept() {
        MechanicsSettings set = testrig::grinderZMechanics();
        set.driftVolts = 0.013;
        for (bool inverted : {false, true}) {
            set.dacWiredInverted = inverted;
            for (int code : {0, 1, -1, 777, -2048, 2047, 3000, -5000}) {
                Mechanics fresh(set), again(set);
                fresh.setDriveEnabled(true);
                again.setDriveEnabled(true);
                fresh.setDacCode(code);
                again.setDacCode(code);
                again.setDacCode(code == 5 ? 6 : 5);
                again.setDacCode(code); // from what was kept
                fresh.tick(1.0);
                again.tick(1.0);
                QCOMPARE(again.motorSpeedMmPerMin(), fresh.motorSpeedMmPerMin());
                QVERIFY(code == 0 || fresh.motorSpeedMmPerMin() != 0.0);
                QCOMPARE(again.driveVolts(), fresh.driveVolts());
            }
        }
    }
    void mechanicsQuietUntilTheEncoderChanges() {
        Mechanics m(testrig::grinderZMechanics());
        const auto rest = [&] {
            for (int t = 0; t < 3; ++t)
                m.tick(1.0);
        };
        rest();
        QVERIFY(m.quiet());
        const std::int64_t count = m.encoderCount();
        m.pushSlide(0.01);
        QCOMPARE(m.encoderCount(), count + 20);
        QVERIFY(!m.quiet());
        m.tick(1.0);
        QVERIFY(!m.quiet()); // the push unsettled it
        m.tick(1.0);
        QVERIFY(m.quiet());

        m.setChannelBroken(2, true);
        QVERIFY(!m.channelOk(2));
        QVERIFY(!m.quiet());
        rest();
        QVERIFY(m.quiet());
        m.setChannelBroken(2, false);
        QVERIFY(!m.quiet());
        rest();
        QVERIFY(m.quiet());

        // Frozen, the counter stops; thawed, it catches up in the next tick.
        m.setEncoderFrozen(true);
        m.tick(1.0);
        QVERIFY(!m.quiet());
        m.pushSlide(0.01);
        QCOMPARE(m.encoderCount(), count + 20);
        rest();
        m.setEncoderFrozen(false);
        m.tick(1.0);
        QVERIFY(!m.quiet());
        QCOMPARE(m.encoderCount(), count + 40);

        // Driven, it moves: not quiet until it stands again.
        m.setDriveEnabled(true);
        m.setDacCode(200);
        m.tick(1.0);
        QVERIFY(!m.quiet());
        m.setDacCode(0);
        int ticks = 0;
        while (!m.quiet() && ticks < 5000) {
            m.tick(1.0);
            ++ticks;
        }
        QVERIFY(m.quiet());
        QVERIFY(m.encoderCount() > count + 40);
    }

    void actualFollowsTheEncoderThroughLN() {
        // At power-on an incremental encoder gives no absolute position: 0.
        Servo s(AxisId::Z, testrig::grinderZ());
        Mechanics m(testrig::grinderZMechanics());
        ServoInputs in;
        in.encoderCount = m.encoderCount();
        s.tick(in, 1.0);
        QCOMPARE(s.actual(), 0.0);
        AxisLoop r;
        QCOMPARE(r.servo.actual(), AxisLoop::mm(100));
        r.servo.setActualValue(0);
        QCOMPARE(r.servo.actual(), 0.0);
        r.mech.pushSlide(1.0);
        r.in.regulatorEnable = false;
        r.step();
        QCOMPARE(r.servo.actual(), AxisLoop::mm(1.0));
        QCOMPARE(r.servo.pulsesLastTick(), std::int64_t(2000));
    }

    // The manual's loop: DAC = V·Ks·3/128 + E·Ke/256 gives 2.5 V at 5 m/min
    // on the grinder's Z (Ks = 131 for 5 V at 10 m/min).
    void feedForwardGivesUmaxAtVmax() {
        AxisLoop r;
        const double v = r.servo.constants().mmPerMinToInternalPerMs(5000);
        QVERIFY(r.servo.moveTo(AxisLoop::mm(300), v));
        r.runUntil([&] { return r.servo.commandVelocity() == v; }, 10000);
        r.run(200);
        const double volts = r.servo.dac() / 204.8;
        QVERIFY2(std::fabs(volts - 2.5) < 0.03, qPrintable(QString::number(volts)));
        // The drive then runs at 5000 mm/min and the lag is small.
        QVERIFY(std::fabs(r.mech.motorSpeedMmPerMin() - 5000) < 20);
        QVERIFY(std::fabs(r.servo.followingError()) < 20);
    }

    void moveEndsInsideToleranceWithoutFault() {
        AxisLoop r;
        const double v = r.servo.constants().mmPerMinToInternalPerMs(1000);
        QVERIFY(r.servo.moveTo(AxisLoop::mm(200), v));
        const auto ms = r.runUntil([&] { return r.servo.inPosition(); }, 20000);
        // 100 mm at 1000 mm/min with УСКОРЕНИЕ 1 = 4445: the setpoint takes
        // 6 s + v/a = 6.096 s; the loop (Ke = 13, i.e. Kv = 1 (m/min)/mm, a
        // time constant of 60 ms) then settles into ДОПУСК ПОЗ = 10 units.
        QVERIFY2(ms >= 6096 && ms < 6400, qPrintable(QString::number(ms)));
        QCOMPARE(r.servo.fault(), Fault::None);
        QVERIFY(std::fabs(r.servo.followingError()) <= 10);
        QVERIFY(r.maxAbsError < 200); // well inside МАКС.ОШИБКА = 1000
        r.run(2000);                  // past ЗАДЕРЖКА КП: still fine
        QCOMPARE(r.servo.fault(), Fault::None);
        QVERIFY(std::fabs(r.mech.slideMm() - 200.0) < 0.005);
    }

    void followingErrorOnMiswiredDrive() {
        auto m = testrig::grinderZMechanics();
        m.dacWiredInverted = true; // the axis runs away from the setpoint
        AxisLoop r(testrig::grinderZ(), m);
        QVERIFY(r.servo.moveTo(AxisLoop::mm(150), r.servo.constants().mmPerMinToInternalPerMs(1000)));
        const auto ms = r.runUntil([&] { return r.servo.fault() != Fault::None; }, 5000);
        QVERIFY(ms > 0);
        QCOMPARE(r.servo.fault(), Fault::FollowingError);
        QCOMPARE(faultMessage(r.servo.fault(), AxisId::Z), 23);
        QVERIFY(!r.servo.loopClosed());
        QCOMPARE(r.servo.dac(), 0);
        // ЗНАК ЦАП corrects the wiring.
        AxisLoop fixed(with([](Constants& k) { k.dacInvert = true; }), m);
        QVERIFY(fixed.servo.moveTo(AxisLoop::mm(150), fixed.servo.constants().mmPerMinToInternalPerMs(1000)));
        QVERIFY(fixed.runUntil([&] { return fixed.servo.inPosition(); }, 10000) > 0);
        QCOMPARE(fixed.servo.fault(), Fault::None);
    }

    void dacLimitAlarm() {
        AxisLoop r(with([](Constants& k) { k.dacLimit = 300; }));
        QVERIFY(r.servo.moveTo(AxisLoop::mm(300), r.servo.constants().mmPerMinToInternalPerMs(5000)));
        QVERIFY(r.runUntil([&] { return r.servo.fault() != Fault::None; }, 10000) > 0);
        QCOMPARE(r.servo.fault(), Fault::DacLimit);
        QCOMPARE(faultMessage(Fault::DacLimit, AxisId::Z), 22);
    }

    void dacIsClampedToMaxDac() {
        AxisLoop r(with([](Constants& k) {
            k.dacMax = 400;
            k.dacLimit = 0;
            k.maxErrorInternal = 0;
        }));
        QVERIFY(r.servo.moveTo(AxisLoop::mm(300), r.servo.constants().mmPerMinToInternalPerMs(5000)));
        int maxDac = 0;
        for (int i = 0; i < 3000; ++i) {
            r.step();
            maxDac = std::max(maxDac, std::abs(r.servo.dac()));
        }
        QCOMPARE(maxDac, 400);
        QVERIFY(std::abs(r.servo.dacUnclamped()) > 400);
    }

    void standstillCheckAfterDelay() {
        AxisLoop r;
        r.run(1000); // past ЗАДЕРЖКА КП = 800 ms
        QVERIFY(r.servo.inPosition());
        // A push the loop cannot correct at once: 0.1 mm = 200 units > ДОПУСК КП 20.
        r.mech.setJammed(true);
        r.mech.pushSlide(0.1);
        r.step();
        QCOMPARE(r.servo.fault(), Fault::Standstill);
        QCOMPARE(faultMessage(r.servo.fault(), AxisId::Z), 24);
    }

    void standstillCheckWaitsForDelayAfterMove() {
        // ЗАДЕРЖКА КП = 800 ms: a residual error right after a move is tolerated.
        AxisLoop r(with([](Constants& k) { k.clampToleranceInternal = 1; }));
        QVERIFY(r.servo.moveTo(AxisLoop::mm(110), r.servo.constants().mmPerMinToInternalPerMs(3000)));
        r.runUntil([&] { return r.servo.target() == r.servo.setpoint(); }, 10000);
        r.run(700);
        QCOMPARE(r.servo.fault(), Fault::None);
    }

    void encoderStallWhileMoving() {
        // T контроля ДОС = 2500 ms; МАКС.ОШИБКА off so that the stall check speaks.
        AxisLoop r(with([](Constants& k) {
            k.maxErrorInternal = 0;
            k.dacLimit = 0;
        }));
        r.mech.setEncoderFrozen(true);
        QVERIFY(r.servo.moveTo(AxisLoop::mm(300), r.servo.constants().mmPerMinToInternalPerMs(500)));
        const auto ms = r.runUntil([&] { return r.servo.fault() != Fault::None; }, 10000);
        QCOMPARE(r.servo.fault(), Fault::EncoderStall);
        QVERIFY2(ms >= 2500 && ms <= 2510, qPrintable(QString::number(ms)));
    }

    void noStallAlarmWhenEncoderCounts() {
        AxisLoop r(with([](Constants& k) { k.maxErrorInternal = 0; }));
        QVERIFY(r.servo.moveTo(AxisLoop::mm(110), r.servo.constants().mmPerMinToInternalPerMs(500)));
        r.run(4000);
        QCOMPARE(r.servo.fault(), Fault::None);
    }

    void channelBreak() {
        AxisLoop r;
        r.mech.setChannelBroken(2, true);
        r.step();
        QCOMPARE(r.servo.fault(), Fault::Channel2Break);
        QCOMPARE(faultMessage(r.servo.fault(), AxisId::Z), 21);
    }

    void moveWithoutRegulatorEnable() {
        AxisLoop r;
        r.in.regulatorEnable = false;
        r.run(500); // past ЗАДЕРЖКА БР = 400 ms
        QVERIFY(!r.servo.regulatorOn());
        QVERIFY(!r.servo.moveTo(AxisLoop::mm(110), 10));
        QCOMPARE(r.servo.fault(), Fault::RegulatorNotEnabled);
        QCOMPARE(faultMessage(r.servo.fault(), AxisId::Z), 17);
    }

    void regulatorBlocksAfterDelayAndWatchesClamp() {
        AxisLoop r;
        r.run(10);
        r.in.regulatorEnable = false;
        r.run(399);
        QVERIFY(r.servo.regulatorOn()); // ЗАДЕРЖКА БР = 400 ms
        r.run(2);
        QVERIFY(!r.servo.regulatorOn());
        QCOMPARE(r.servo.fault(), Fault::None);
        r.mech.pushSlide(0.005); // 10 units: inside ДОПУСК КП = 20
        r.step();
        QCOMPARE(r.servo.fault(), Fault::None);
        r.mech.pushSlide(0.01); // now 30 units off the clamped position
        r.step();
        QCOMPARE(r.servo.fault(), Fault::Standstill);
    }

    void emergencyStopOpensTheLoopAndFollows() {
        AxisLoop r;
        QVERIFY(r.servo.moveTo(AxisLoop::mm(300), r.servo.constants().mmPerMinToInternalPerMs(5000)));
        r.run(1500);
        r.in.emergencyStop = true;
        r.step();
        QVERIFY(!r.servo.loopClosed());
        QCOMPARE(r.servo.dac(), 0);
        r.run(1000);
        QCOMPARE(r.mech.motorSpeedMmPerMin(), 0.0);
        QCOMPARE(r.servo.setpoint(), r.servo.actual()); // follow-up (индикация)
        QVERIFY(!r.servo.regulatorOn());
        QCOMPARE(r.servo.fault(), Fault::None);
        r.in.emergencyStop = false;
        r.step();
        QVERIFY(r.servo.loopClosed());
    }

    void driveNotReady() {
        AxisLoop r;
        r.in.driveReady = false;
        r.step();
        QCOMPARE(r.servo.fault(), Fault::DriveNotReady);
        QCOMPARE(faultMessage(r.servo.fault(), AxisId::Z), 32);
    }

    void faultResetClosesTheLoopAgain() {
        AxisLoop r;
        r.mech.setChannelBroken(1, true);
        r.step();
        QCOMPARE(r.servo.fault(), Fault::Channel1Break);
        r.mech.setChannelBroken(1, false);
        r.run(500);
        r.servo.resetFault();
        r.step();
        QCOMPARE(r.servo.fault(), Fault::None);
        QVERIFY(r.servo.loopClosed());
        QVERIFY(r.servo.moveTo(AxisLoop::mm(101), r.servo.constants().mmPerMinToInternalPerMs(1000)));
        QVERIFY(r.runUntil([&] { return r.servo.inPosition(); }, 5000) > 0);
    }

    void backlashCompensation() {
        // 20 µm of play between screw and slide; КОМП.ЛЮФТА = 20 discretes.
        auto m = testrig::grinderZMechanics();
        m.backlashMm = 0.020;
        const auto approach = [&](bool compensate, double via) {
            AxisLoop r(with([&](Constants& k) { k.backlashDisc = compensate ? 20 : 0; }), m);
            const double v = r.servo.constants().mmPerMinToInternalPerMs(20);
            r.servo.moveTo(AxisLoop::mm(via), v);
            r.runUntil([&] { return r.servo.inPosition(); }, 120000);
            r.run(1000);
            r.servo.moveTo(AxisLoop::mm(100.5), v);
            r.runUntil([&] { return r.servo.inPosition(); }, 120000);
            r.run(1000);
            return std::pair(r.mech.slideMm() - 100.5, r.servo.actual() - AxisLoop::mm(100.5));
        };
        const auto [fromBelowPlain, a1] = approach(false, 100.2);
        const auto [fromAbovePlain, a2] = approach(false, 100.8);
        // Without compensation the slide stops half the play short on either
        // side (plus up to ДОПУСК ПОЗ = 5 µm: the loop's DAC resolution).
        QVERIFY2(fromBelowPlain < -0.008 && fromBelowPlain > -0.016 && fromAbovePlain > 0.008 &&
                     fromAbovePlain < 0.016,
                 qPrintable(QString("%1 %2").arg(fromBelowPlain).arg(fromAbovePlain)));
        const auto [fromBelow, a3] = approach(true, 100.2);
        const auto [fromAbove, a4] = approach(true, 100.8);
        QVERIFY2(std::fabs(fromBelow) <= 0.005 && std::fabs(fromAbove) <= 0.005,
                 qPrintable(QString("%1 %2").arg(fromBelow).arg(fromAbove)));
        QVERIFY(std::fabs(a3) <= 10 && std::fabs(a4) <= 10); // the display reads the target
    }

    void driftCompensation() {
        auto m = testrig::grinderZMechanics();
        m.driftVolts = 10 / 204.8; // exactly 10 DAC units of offset
        AxisLoop plain(testrig::grinderZ(), m);
        plain.run(3000);
        AxisLoop comp(with([](Constants& k) { k.driftCompDac = -10; }), m);
        comp.run(3000);
        // Without compensation the loop holds the axis with a standing error
        // of drift/(Ke/256) = 10·256/13 ≈ 197 units: the standstill check trips.
        QCOMPARE(plain.servo.fault(), Fault::Standstill);
        QCOMPARE(comp.servo.fault(), Fault::None);
        QVERIFY(std::fabs(comp.servo.followingError()) <= 1);
    }

    void overrideZeroHoldsTheAxis() {
        AxisLoop r;
        r.servo.moveTo(AxisLoop::mm(200), r.servo.constants().mmPerMinToInternalPerMs(2000));
        r.run(1000);
        r.servo.setOverride(0);
        r.run(1000);
        const double held = r.servo.actual();
        r.run(1000);
        QVERIFY(std::fabs(r.servo.actual() - held) < 2);
        QVERIFY(!r.servo.inPosition());
        r.servo.setOverride(1);
        QVERIFY(r.runUntil([&] { return r.servo.inPosition(); }, 10000) > 0);
    }

    void feedHoldInputHoldsTheAxis() {
        AxisLoop r;
        r.servo.moveTo(AxisLoop::mm(200), r.servo.constants().mmPerMinToInternalPerMs(2000));
        r.run(1000);
        r.in.feedEnable = false;
        r.run(1000);
        QCOMPARE(r.servo.commandVelocity(), 0.0);
        r.in.feedEnable = true;
        QVERIFY(r.runUntil([&] { return r.servo.inPosition(); }, 10000) > 0);
        QVERIFY(std::fabs(r.servo.actual() - AxisLoop::mm(200)) <= 10);
    }

    void jogStopsAtTheGivenLimit() {
        AxisLoop r;
        const double limit = AxisLoop::mm(120);
        QVERIFY(r.servo.jog(+1, r.servo.constants().mmPerMinToInternalPerMs(3000), &limit));
        QVERIFY(r.runUntil([&] { return r.servo.inPosition(); }, 20000) > 0);
        QVERIFY(std::fabs(r.servo.actual() - limit) <= 10);
        QVERIFY(!r.servo.jogging());
    }

    void remainingPathOfAJog() {
        AxisLoop r;
        QVERIFY(r.servo.jog(+1, r.servo.constants().mmPerMinToInternalPerMs(1000)));
        r.run(100);
        QCOMPARE(r.servo.remaining(), 0.0); // an open-ended jog has no rest of path
        const double limit = AxisLoop::mm(150);
        QVERIFY(r.servo.jog(+1, r.servo.constants().mmPerMinToInternalPerMs(1000), &limit));
        r.run(100);
        QVERIFY(r.servo.remaining() > AxisLoop::mm(40));
        QCOMPARE(r.servo.remaining(), r.servo.target() - r.servo.setpoint());
    }

    void invalidRatioIsAFault() {
        AxisLoop r(with([](Constants& k) { k.encoderN = 0; }));
        QCOMPARE(r.servo.fault(), Fault::RatioError);
        QCOMPARE(faultMessage(r.servo.fault(), AxisId::Z), 29);
        r.servo.resetFault();
        QCOMPARE(r.servo.fault(), Fault::RatioError); // until the constants are fixed
        r.servo.setConstants(testrig::grinderZ());
        QCOMPARE(r.servo.fault(), Fault::None);
    }

    void deterministic() {
        const auto run = [] {
            AxisLoop r;
            r.servo.moveTo(AxisLoop::mm(187.25), r.servo.constants().mmPerMinToInternalPerMs(4321));
            double sum = 0;
            for (int i = 0; i < 8000; ++i) {
                r.step();
                sum += r.servo.actual() + r.servo.dac();
            }
            return sum;
        };
        QCOMPARE(run(), run());
    }
};

QTEST_APPLESS_MAIN(TestServo)
#include "test_servo.moc"
