// The reference-point cycle as manual 2.6.4 prints it, run in ПБТ from the
// PLC's direction signals; the «X»/«Z» flags; alarms 40, 41, 42.
#include "rig/engine_rig.h"

#include <QtTest>

using namespace k528;
using namespace k528::testrig;
namespace z = k528::engine::z;

class TestHoming : public QObject {
    Q_OBJECT
private slots:
    // 1) «ПБТ В "-"» = 0: «ПЕРЕМЕЩЕНИЕ В +» starts it; 2) off the cam at
    // F СТАРТ БТ; 3) on the cam F ОТКЛ.БТ; 4) off the cam to the zero mark;
    // 5) СМЕЩЕНИЕ БТ, the point gets ЗНАЧЕНИЕ БТ; 6) the «X» flag.
    void sequence() {
        EngineRig r;
        QVERIFY(!r.x().referenced);
        QVERIFY(!r.bit(z::referenced(X)));
        QVERIFY(r.ctl->selectMode(Mode::Reference).ok());
        r.tick();
        QVERIFY(r.bit(z::ModeReference));
        // «ПЕРЕМЕЩЕНИЕ В -» does not start it (C9 = 0).
        r.m->setJog(X, -1);
        r.advance(100);
        r.m->setJog(X, 0);
        QVERIFY(!r.x().homing);
        QVERIFY(std::fabs(r.m->slideMm(X) - r.m->placement(X).startMm) < 1e-9);
        r.m->setJog(X, 1);
        r.tick();
        r.m->setJog(X, 0);
        r.advance(300);
        QVERIFY(r.x().homing);
        QCOMPARE(r.x().feedDiscPerMin, 1500000); // F СТАРТ БТ = 150000 (10·disc/min)
        QVERIFY(r.until([&] { return r.m->camPressed(X); }, 60000));
        QVERIFY(r.until([&] { return r.x().feedDiscPerMin == 100000; }, 2000)); // F ОТКЛ.БТ
        QVERIFY(r.m->camPressed(X));
        QVERIFY(r.until([&] { return !r.m->camPressed(X); }, 60000));
        QVERIFY(r.until([&] { return r.x().referenced; }, 60000));
        QVERIFY(r.bit(z::referenced(X)));
        QVERIFY(!r.z().referenced);
        r.advance(500);
        // ЗНАЧЕНИЕ БТ = 270.000 at the reference point: the machine system
        // now equals the slide position (× 2, diameter).
        QVERIFY(std::llabs(r.machine(X) - 270000) <= kRestTol);
        QVERIFY(std::fabs(r.m->machineMm(X) - 270.0) < 0.011);
        // R246: from leaving the cam to the zero mark (1.5 mm of slide = 3 mm).
        QVERIFY2(std::llabs(r.ctl->r(246) - 3000) <= 2, qPrintable(QString::number(r.ctl->r(246))));
        QCOMPARE(r.x().homeDistanceDisc, std::int64_t(r.ctl->r(246)));
        QVERIFY(r.home()); // Z as well
        QVERIFY(std::llabs(r.machine(Z) - 290000) <= kRestTol);
        QVERIFY(std::fabs(r.m->machineMm(Z) - 290.0) < 0.011);
    }
    // «ПБТ В "-"» = 1: «ПЕРЕМЕЩЕНИЕ В -» starts it (grinder 205, axis X).
    void negativeDirection() {
        EngineRig r("grinder-205");
        QVERIFY(r.ctl->selectMode(Mode::Reference).ok());
        r.m->setJog(X, 1);
        r.advance(100);
        r.m->setJog(X, 0);
        QVERIFY(!r.x().homing);
        r.m->setJog(X, -1);
        r.tick();
        r.m->setJog(X, 0);
        r.advance(100);
        QVERIFY(r.x().homing);
        QVERIFY(r.ctl->servo(X).commandVelocity() < 0);
        QVERIFY(r.until([&] { return r.x().referenced; }, 600000));
        r.advance(2000);
        QVERIFY(std::llabs(r.machine(X)) <= kRestTol); // ЗНАЧЕНИЕ БТ = 0
    }
    // 40 «Нет съезда с конечника "0"»: the cam is longer than S конечника БТ.
    void alarm40() {
        EngineRig r("training-lathe", [](auto& p) { p.simulation.set("x.decel_cam_mm", "25"); });
        QVERIFY(!r.home());
        QVERIFY(r.hasAlarm(40));
        QVERIFY(!r.x().referenced);
        QVERIFY(!r.x().homing);
        QVERIFY(r.m->camPressed(X));
    }
    // 41 «Нет "0"-метки»: the search ends before the mark.
    void alarm41() {
        EngineRig r;
        QVERIFY(r.ctl->selectMode(Mode::MachineData).ok());
        QVERIFY(r.ctl->setC(38, 1000).ok()); // S поиска 0-метки: 1 mm of diameter = 0.5 mm of slide
        QVERIFY(!r.home());
        QVERIFY(r.hasAlarm(41));
        QVERIFY(!r.x().referenced);
    }
    // 42: «Попытка запустить УП без привязки к базовой точке».
    void alarm42() {
        EngineRig r;
        r.load("%L1\nN1 G1 Z-1 FZ100\n");
        r.start(1);
        QCOMPARE(r.ctl->state(), ProgramState::Alarm);
        QVERIFY(r.hasAlarm(42));
        r.m->pressReset();
        r.advance(50);
        QVERIFY(!r.hasAlarm(42));
        QVERIFY(r.home());
        r.start(1);
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->state(), ProgramState::Ended);
        QVERIFY(!r.hasAlarm(42));
    }
    // АВТ.БЕЗ ПБТ = 1: the program starts without homing; the cycle is blocked.
    void autoWithoutHoming() {
        EngineRig r("training-lathe", noHoming);
        QVERIFY(r.bit(z::referenced(X)));
        QVERIFY(!r.x().referenced);
        QVERIFY(r.ctl->selectMode(Mode::Reference).ok());
        r.m->setJog(X, 1);
        r.advance(200);
        r.m->setJog(X, 0);
        QVERIFY(!r.x().homing);
        r.load("%L1\nN1 G1 Z-1 FZ100\n");
        r.start(1);
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->state(), ProgramState::Ended);
    }
    // Leaving ПБТ (or an emergency stop) ends the cycle; the axis is not referenced.
    void interrupted() {
        EngineRig r;
        QVERIFY(r.ctl->selectMode(Mode::Reference).ok());
        r.m->setJog(X, 1);
        r.tick();
        r.m->setJog(X, 0);
        r.advance(500);
        QVERIFY(r.x().homing);
        QVERIFY(r.ctl->selectMode(Mode::Manual).ok());
        r.advance(500);
        QVERIFY(!r.x().homing);
        QVERIFY(!r.x().referenced);
        QVERIFY(!r.ctl->servo(X).moving());
        QVERIFY(r.ctl->selectMode(Mode::Reference).ok());
        r.m->setJog(X, 1);
        r.tick();
        r.m->setJog(X, 0);
        r.advance(500);
        r.m->setEmergencyStop(true);
        r.advance(100);
        QVERIFY(!r.x().homing);
        QVERIFY(r.hasAlarm(9));
    }
};

QTEST_APPLESS_MAIN(TestHoming)
#include "test_homing.moc"
