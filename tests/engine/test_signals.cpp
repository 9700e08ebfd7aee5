// Gx36..Gx39: a move ends early on signal 1..4 (PLC bit or fast input) and
// the rest of the path is erased (R242/R243: the following error then);
// Gx10: the axis follows the handwheel up to the programmed point.
#include "rig/engine_rig.h"

#include <QtTest>

using namespace k528;
using namespace k528::testrig;
namespace z = k528::engine::z;

class TestSignals : public QObject {
    Q_OBJECT
private slots:
    // G236 on the training lathe: signal 1 of Z through the PLC (Z1009.12).
    void eraseOnPlcSignal() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G236 G1 Z-50 FZ1000\nN2 G1 X5 FX1000\n");
        r.start(1);
        r.advance(1500);
        QVERIFY(r.z().moving);
        r.m->setSignal(Z, 1, true);
        r.tick();
        QVERIFY(r.bit(z::eraseSignal(Z, 1)));
        r.tick();
        // R243: the following error when the signal came, display discretes.
        const std::int32_t err = r.ctl->r(243);
        QVERIFY2(err < 0 && err > -1000, qPrintable(QString::number(err)));
        QVERIFY(r.until([&] { return r.ctl->programView().frameNumber == 2; },
                        2000)); // the frame ended
        r.m->setSignal(Z, 1, false);
        const std::int64_t stopped = r.current(Z);
        QVERIFY(stopped < -20000 && stopped > -30000);
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->state(), ProgramState::Ended);
        QVERIFY(std::llabs(r.current(Z) - stopped) <= kRestTol); // the rest of the path is gone
        QVERIFY(std::llabs(r.current(X) - 5000) <= kRestTol);
    }
    // Without the signal the frame ends at its target; signal 2 does not end G236.
    void noSignalEndsNormally() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G236 G1 Z-10 FZ2000\n");
        r.start(1);
        r.advance(100);
        r.m->setSignal(Z, 2, true);
        QVERIFY(r.runToEnd());
        QVERIFY(std::llabs(r.current(Z) + 10000) <= kRestTol);
    }
    // A signal already present: the axis does not move at all.
    void signalAlreadyPresent() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G237 G1 Z-10 FZ2000\n");
        r.m->setSignal(Z, 2, true);
        r.start(1);
        QVERIFY(r.runToEnd());
        QVERIFY(std::llabs(r.current(Z)) <= kRestTol);
    }
    // The grinder's gauge on fast inputs X5..X8 (functions 7..10): G136 ends
    // on «касание» (function 7, active at 0), G138 on «чистовой припуск снят».
    void eraseOnFastInput() {
        EngineRig r("grinder-205");
        QVERIFY(r.home());
        r.load("%L1\nN1 G0 X20\nN2 G136 G1 X30 FX300\nN3 G138 G1 X35 FX300\n");
        r.start(1);
        QVERIFY(r.until([&] { return r.ctl->programView().frameNumber == 2; }, 5000));
        r.advance(1000);
        QCOMPARE(r.w().word(2006) & (1u << 4), 1u << 4); // X5 at 1: no touch
        r.m->setSignal(X, 1, true);
        r.tick();
        QCOMPARE(r.w().word(2006) & (1u << 4), 0u); // touch: 0
        QVERIFY(!r.bit(z::eraseSignal(X, 1)));      // not through the PLC
        QVERIFY(r.until([&] { return r.ctl->programView().frameNumber == 3; }, 2000));
        r.m->setSignal(X, 1, false);
        const std::int64_t touched = r.current(X);
        QVERIFY2(touched > 24000 && touched < 26000, qPrintable(QString::number(touched)));
        r.advance(1000);
        r.m->setSignal(X, 3, true);
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->state(), ProgramState::Ended);
        QVERIFY(r.current(X) < 32000);
    }
    // Gx10: the axis follows handwheel pulses and stops at the programmed
    // point however far the wheel turns; Z2007.9 while the frame is active.
    void handwheelFrame() {
        EngineRig r("training-lathe", noHoming);
        r.m->setHandwheel(Z, 2, true, true); // wheel 2 on Z, ×МНОЖИТ.М2 = 10
        r.load("%L1\nN1 G210 Z-5\nN2 R1=1\n");
        r.start(1);
        r.advance(50);
        QVERIFY(r.bit(z::handwheelFrameActive(Z)));
        QCOMPARE(r.ctl->state(), ProgramState::Running);
        r.m->turnHandwheel(2, -100); // 100 pulses × 10 discretes = 1 mm
        r.advance(500);
        QVERIFY(std::llabs(r.current(Z) + 1000) <= kRestTol);
        QCOMPARE(r.ctl->r(1), 0);
        r.m->turnHandwheel(2, 300); // the other way: not past the start
        r.advance(500);
        QVERIFY(std::llabs(r.current(Z)) <= kRestTol);
        r.m->turnHandwheel(2, -1000); // 10 mm: stops at Z-5
        QVERIFY(r.runToEnd());
        QVERIFY(std::llabs(r.current(Z) + 5000) <= kRestTol);
        QCOMPARE(r.ctl->r(1), 1);
        QVERIFY(!r.bit(z::handwheelFrameActive(Z)));
    }
};

QTEST_APPLESS_MAIN(TestSignals)
#include "test_signals.moc"
