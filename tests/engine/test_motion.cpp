// Motion frames: G00/G01 with per-axis feeds, trapezoid times, G91, feed
// limits, override, Gx56, dwell, «Стоп»/«Пуск», data hold.
#include "rig/engine_rig.h"

#include <QtTest>

using namespace k528;
using namespace k528::testrig;
namespace z = k528::engine::z;

namespace {
double seconds(const EngineRig& r) {
    return static_cast<double>(r.ctl->programEndMs() - r.ctl->programStartMs()) / 1000.0;
}
} // namespace

class TestMotion : public QObject {
    Q_OBJECT
private slots:
    // 100 mm at 1000 mm/min with УСКОРЕНИЕ 1 = 2000 takes 6 s + v/a = 6.213 s.
    void trapezoidTime() {
        EngineRig r("training-lathe", [](auto& p) {
            noHoming(p);
            p.setC(74, 2000);
        });
        r.load("%L1\nN1 G90 G1 Z-100 FZ1000\n");
        r.start(1);
        // The setpoint: 6.213 s (the move starts one tick after «Пуск» is seen).
        const double ts = r.setpointArrivalS(Z, 10000);
        QVERIFY2(ts >= 6.212 && ts <= 6.216, qPrintable(QString::number(ts)));
        // The frame ends once the axis is inside ДОПУСК ПОЗ (the drive's lag settles).
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->state(), ProgramState::Ended);
        const double t = seconds(r);
        QVERIFY2(t >= ts && t <= ts + 0.2, qPrintable(QString::number(t)));
        QVERIFY(std::llabs(r.current(Z) + 100000) <= kRestTol);
    }
    // G00 moves each axis at its F УСК.АВТ. (C94 = 6000 mm/min, C74 = 10240):
    // 60 mm take 0.6 s + v/a = 0.6 + 100/400 = 0.85 s.
    void rapidUsesAutoMaxFeed() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G0 Z-60\n");
        r.start(1);
        const double t = r.setpointArrivalS(Z, 10000);
        QVERIFY2(t >= 0.849 && t <= 0.853, qPrintable(QString::number(t)));
        QVERIFY(r.runToEnd());
        QVERIFY(r.bit(z::referenced(Z)));
    }
    // Feeds above F УСК.АВТ. are limited to it.
    void feedLimitedToAutoMax() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G1 Z-60 FZ9000\n");
        r.start(1);
        const double t = r.setpointArrivalS(Z, 10000);
        QVERIFY2(t >= 0.849 && t <= 0.853, qPrintable(QString::number(t)));
    }
    // A positioner, not an interpolator: each axis at its own feed; the
    // frame ends when both are in position.
    void axesIndependent() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G1 X10 FX100 Z-5 FZ1000\nN2 G1 Z-10\n");
        r.start(1);
        r.advance(1000);
        QVERIFY(r.z().inPosition && !r.z().moving); // Z: 0.3 s
        QVERIFY(r.x().moving);                      // X: 10 mm at 100 mm/min = 6 s
        QCOMPARE(r.ctl->programView().frameNumber, 1);
        QVERIFY(r.runToEnd());
        QVERIFY(std::llabs(r.current(X) - 10000) <= kRestTol);
        QVERIFY(std::llabs(r.current(Z) + 10000) <= kRestTol); // FZ stayed modal
        const double t = seconds(r);
        QVERIFY2(t > 6.0 && t < 6.9, qPrintable(QString::number(t)));
    }
    // G01 on an axis whose feed was never set: 33 (X) / 49 (Z) with the line.
    void feedNeverSet() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L3\nN1 G90\nN2 G1 X10\n");
        r.start(3);
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->state(), ProgramState::Alarm);
        const auto* a = r.alarm(33);
        QVERIFY(a);
        QCOMPARE(a->program, 3);
        QCOMPARE(a->line, 3);
        EngineRig q("training-lathe", noHoming);
        q.load("%L3\nG1 Z10\n");
        q.start(3);
        QVERIFY(q.runToEnd());
        QVERIFY(q.hasAlarm(49));
    }
    void incremental() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G91 G1 Z-10 FZ2000\nN2 Z-10\nN3 G90 Z-5\n");
        r.start(1);
        r.until([&] { return r.ctl->programView().frameNumber == 3; }, 10000);
        QVERIFY(std::llabs(r.current(Z) + 20000) <= kRestTol);
        QVERIFY(r.runToEnd());
        QVERIFY(std::llabs(r.current(Z) + 5000) <= kRestTol);
    }
    // Override 0 %: the axes stop (Z2000.14) and the frame waits.
    void overrideZero() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G1 Z-20 FZ1000\n");
        r.m->setOverrideCode(0);
        r.start(1);
        r.advance(2000);
        QVERIFY(r.bit(z::OverrideZero));
        QCOMPARE(r.ctl->r(249), 0);
        QCOMPARE(r.ctl->state(), ProgramState::Running);
        QVERIFY(std::llabs(r.current(Z)) <= kRestTol);
        r.m->setOverrideCode(10);
        QVERIFY(r.runToEnd());
        QVERIFY(!r.bit(z::OverrideZero));
        QVERIFY(std::llabs(r.current(Z) + 20000) <= kRestTol);
    }
    // The override scales the feed; Gx56 takes it off one axis (G55 back).
    void overrideAndG56() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G1 Z-10 FZ600\n%L2\nN1 G256 G1 Z-20 FZ600\n");
        r.m->setOverrideCode(7); // 50 %
        r.start(1);
        const double half = r.setpointArrivalS(Z, 10000); // 10 mm at 300 mm/min: 2 s + 5/400 s
        QVERIFY2(half > 2.011 && half < 2.016, qPrintable(QString::number(half)));
        QVERIFY(r.runToEnd());
        r.start(2);
        const double full = r.setpointArrivalS(Z, 10000); // G256: 600 mm/min, 1 s + 10/400 s
        QVERIFY2(full > 1.023 && full < 1.028, qPrintable(QString::number(full)));
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->modal().noOverrideAxis, 1);
    }
    // G04 X1.5: 1.5 s, «Идет выдержка времени» (Z2000.11).
    void dwell() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G4 X1.5\n");
        r.start(1);
        r.advance(500);
        QCOMPARE(r.ctl->state(), ProgramState::Dwell);
        QVERIFY(r.bit(z::DwellRunning));
        QVERIFY(r.runToEnd());
        QVERIFY(!r.bit(z::DwellRunning));
        const double t = seconds(r);
        QVERIFY2(t >= 1.5 && t <= 1.503, qPrintable(QString::number(t)));
    }
    // «Стоп»: feed and data hold (Z2000.9); «Пуск» continues from there.
    void stopAndContinue() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G1 Z-30 FZ1000\nN2 G1 Z-31\n");
        r.start(1);
        r.advance(600);
        r.m->pressStop();
        r.advance(500);
        QCOMPARE(r.ctl->state(), ProgramState::Interrupted);
        QVERIFY(r.bit(z::ProgramInterrupted));
        QVERIFY(!r.bit(z::ProgramRunning));
        QVERIFY(!r.z().moving);
        const std::int64_t held = r.current(Z);
        QVERIFY(held < -5000 && held > -25000);
        r.advance(500);
        QVERIFY(std::llabs(r.current(Z) - held) <= kRestTol);
        r.m->pressStart();
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->state(), ProgramState::Ended);
        QVERIFY(std::llabs(r.current(Z) + 31000) <= kRestTol);
    }
    // «Блокировка ввода данных»: the motion goes on, the next frame waits.
    void dataHold() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G1 Z-10 FZ2000\nN2 Z-20\n");
        r.start(1);
        r.m->setDataHold(true);
        r.advance(2000);
        QVERIFY(std::llabs(r.current(Z) + 10000) <= kRestTol);
        QCOMPARE(r.ctl->state(), ProgramState::Running);
        r.m->setDataHold(false);
        QVERIFY(r.runToEnd());
        QVERIFY(std::llabs(r.current(Z) + 20000) <= kRestTol);
    }
    // A diameter axis: X is programmed and shown as the diameter; the slide
    // moves half of it, at half the programmed feed.
    void diameterAxis() {
        EngineRig r("training-lathe");
        QVERIFY(r.home());
        const double slide0 = r.m->slideMm(X);
        r.load("%L1\nN1 G1 X200 FX1000\n");
        r.start(1);
        // 70 mm of diameter at 1000 mm/min (a = 10666 -> 416.7 mm/s²): 4.2 s + 0.04 s.
        const double ts = r.setpointArrivalS(X, 10000);
        QVERIFY2(ts > 4.238 && ts < 4.245, qPrintable(QString::number(ts)));
        QVERIFY(r.runToEnd());
        QVERIFY2(r.ctl->state() == ProgramState::Ended, qPrintable(alarmList(r)));
        QVERIFY(std::llabs(r.current(X) - 200000) <= kRestTol);
        QVERIFY(std::fabs(r.m->slideMm(X) - 100.0) < 0.006);
        QVERIFY(slide0 > 100.0);
    }
};

QTEST_APPLESS_MAIN(TestMotion)
#include "test_motion.moc"
