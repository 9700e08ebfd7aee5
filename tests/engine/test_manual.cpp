// РУЧНОЙ: jog from the machine's buttons (F ОБЫЧНАЯ / F УСКОРЕН.), handwheels
// with multiplier and sign, DRF, the manual cycles of Z1001, подналадка and
// компенсация правки.
#include "rig/engine_rig.h"

#include <QtTest>

using namespace k528;
using namespace k528::testrig;
namespace z = k528::engine::z;

class TestManual : public QObject {
    Q_OBJECT
private slots:
    void jogSpeeds() {
        EngineRig r("training-lathe", noHoming);
        r.m->setJog(Z, -1);
        r.advance(1000);
        QCOMPARE(r.z().feedDiscPerMin, 2000000); // F ОБЫЧНАЯ Z: 200000 ×10 disc/min
        r.m->setJog(Z, -1, true);
        r.advance(1000);
        QCOMPARE(r.z().feedDiscPerMin, 6000000); // F УСКОРЕН.
        QVERIFY(r.bit(z::rapidMotion(Z)));
        QVERIFY(r.ctl->pressOverrideKey(2).ok()); // C140 = 5: 20 %
        r.advance(1000);
        QCOMPARE(r.z().feedDiscPerMin, 1200000);
        r.m->setJog(Z, 0);
        r.advance(500);
        QVERIFY(!r.z().moving);
    }
    // One pulse = one discrete of motion, × МНОЖИТ. with the multiplier bit;
    // ЗНАК М1 inverts; the handwheel is wired to the channel of C105/C106.
    void handwheel() {
        EngineRig r("training-lathe", noHoming);
        r.m->setHandwheel(X, 1, true);
        r.m->turnHandwheel(1, 50);
        r.advance(300);
        QVERIFY(std::llabs(r.current(X) - 100) <=
                kRestTol);                   // 50 discretes of motion = 100 on the diameter
        r.m->setHandwheel(X, 1, true, true); // × МНОЖИТ.М1 = 10
        r.m->turnHandwheel(1, 50);
        r.advance(300);
        QVERIFY(std::llabs(r.current(X) - 1100) <= kRestTol);
        QVERIFY(r.ctl->io().pulse[1].count == 100); // C105 = 2: module 1, channel 2
        // Buttons have priority over the handwheel.
        r.m->setJog(X, 1);
        r.advance(100);
        r.m->turnHandwheel(1, -500);
        r.advance(100);
        QVERIFY(r.current(X) > 1100);
        r.m->setJog(X, 0);
        r.advance(300);
        const std::int64_t x = r.current(X);
        EngineRig q("training-lathe", [](auto& p) {
            noHoming(p);
            p.setC(11, 1); // ЗНАК М1
        });
        q.m->setHandwheel(X, 1, true);
        q.m->turnHandwheel(1, 50);
        q.advance(300);
        QVERIFY(std::llabs(q.current(X) + 100) <= kRestTol);
        QVERIFY(x > 1100);
    }
    // DRF: the handwheel moves the axis into the handwheel offset R230; the
    // current coordinate stays (unless G50 / Z1006.4 leave the offset out).
    void drf() {
        EngineRig r("training-lathe", noHoming);
        r.m->setHandwheel(X, 1, true, true, true);
        const std::int64_t c0 = r.current(X);
        r.m->turnHandwheel(1, 20); // 200 discretes of motion = 400 on the diameter
        r.advance(300);
        QCOMPARE(r.ctl->r(230), 400);
        QVERIFY(std::llabs(r.current(X) - c0) <= kRestTol);
        QVERIFY(std::llabs(r.machine(X) - 400) <= kRestTol);
        r.w().setBit(z::outOfCycleNoDrf(X), true);
        r.tick();
        QVERIFY(std::llabs(r.current(X) - 400) <= kRestTol);
        r.w().setBit(z::outOfCycleNoDrf(X), false);
        // In АВТОМАТ, during a move: the target moves with it.
        r.load("%L1\nN1 G1 X10 FX300\n");
        r.start(1);
        r.advance(500);
        r.m->turnHandwheel(1, 10);
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->r(230), 600);
        QVERIFY(std::llabs(r.current(X) - 10000) <= kRestTol);
        QVERIFY(std::llabs(r.machine(X) - 10600) <= kRestTol);
    }
    // Z1001.0 (cycle 1, C143 = L90) interrupts a running program; Z2001.8
    // while it runs. Cycles 2..8 only in РУЧНОЙ.
    void manualCycles() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L90\nN1 G1 Z-3 FZ1000\nN2 M2\n%L91\nN1 R7=1\n%L1\nN1 G1 Z-50 FZ500\n");
        r.start(1);
        r.advance(500);
        r.m->startCycle(1);
        r.advance(30);
        QCOMPARE(r.ctl->programView().mainProgram, 90);
        QCOMPARE(r.ctl->programView().cycle, 1);
        QCOMPARE(r.ctl->r(250), 90);
        QVERIFY(r.bit(z::cycleRunning(1)));
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->state(), ProgramState::Ended);
        QVERIFY(!r.bit(z::cycleRunning(1)));
        QVERIFY(std::llabs(r.current(Z) + 3000) <= kRestTol);
        // Cycle 6 (C148 = L91): not in АВТОМАТ, yes in РУЧНОЙ.
        r.m->startCycle(6);
        r.advance(50);
        QCOMPARE(r.ctl->r(7), 0);
        QVERIFY(r.ctl->selectMode(Mode::Manual).ok());
        r.advance(50);
        r.m->startCycle(6);
        r.advance(50);
        QCOMPARE(r.ctl->r(7), 1);
        // A cycle not defined (C144 = 0): nothing happens.
        r.m->startCycle(2);
        r.advance(50);
        QVERIFY(r.alarms().empty());
    }
    // ВКЛ.ПОДНАЛ. = 1: Z1006.1/.2 add ±R218 to the correction R226.
    void adjustment() {
        EngineRig r("training-lathe", [](auto& p) {
            noHoming(p);
            p.setC(13, 1);
        });
        QVERIFY(r.ctl->setR(218, 15).ok());
        const std::int64_t c0 = r.current(X);
        r.w().setBit(z::adjustPlus(X), true);
        r.tick();
        r.w().setBit(z::adjustPlus(X), false);
        r.tick();
        r.w().setBit(z::adjustPlus(X), true);
        r.tick();
        QCOMPARE(r.ctl->r(226), 30);
        r.w().setBit(z::adjustPlus(X), false);
        r.w().setBit(z::adjustMinus(X), true);
        r.tick();
        QCOMPARE(r.ctl->r(226), 15);
        QCOMPARE(r.current(X), c0 - 15);   // no motion, the coordinate shifts
        EngineRig q("training-lathe", noHoming); // C13 = 0: no effect
        q.w().setBit(z::adjustPlus(X), true);
        q.tick();
        QCOMPARE(q.ctl->r(226), 0);
    }
    // Z1007.0/.1: «выполнить компенсацию черновой/чистовой правки» (R210/R211) into R224.
    void dressingCompensation() {
        EngineRig r("grinder-205", noHoming);
        QCOMPARE(r.ctl->r(224), 0);
        r.w().setBit(z::roughDressComp(X), true);
        r.tick();
        QCOMPARE(r.ctl->r(224), 20);
        r.w().setBit(z::finishDressComp(X), true);
        r.tick();
        QCOMPARE(r.ctl->r(224), 25);
    }
};

QTEST_APPLESS_MAIN(TestManual)
#include "test_manual.moc"
