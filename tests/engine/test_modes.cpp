// Modes of 2.6 chosen on the panel or by the PLC's code Z1000.8-10;
// «Если в предыдущем режиме выполнялось перемещение, оно прекращается»;
// the power-on test (2.6.1) and editing C-parameters.
#include "engine/self_test.h"
#include "rig/engine_rig.h"

#include <QtTest>

using namespace k528;
using namespace k528::testrig;
namespace z = k528::engine::z;
using k528::engine::Refusal;

class TestModes : public QObject {
    Q_OBJECT
private slots:
    // «После включения питания устанавливается ручной режим работы».
    void powerOnInManual() {
        EngineRig r;
        QCOMPARE(r.ctl->mode(), Mode::Manual);
        QCOMPARE(r.ctl->state(), ProgramState::Idle);
        QVERIFY(r.bit(z::Ready));
        QVERIFY(r.bit(z::ModeManual));
        QVERIFY(r.alarms().empty());
        QVERIFY(r.bit(z::loopClosed(X)) && r.bit(z::loopClosed(Z)));
    }
    // The PLC's mode code imposes a mode: F1..F7 are refused; code 0 gives it back.
    void plcModeCode() {
        EngineRig r;
        r.m->setModeCode(3);
        r.tick();
        QCOMPARE(r.ctl->mode(), Mode::Reference);
        QVERIFY(r.bit(z::ModeReference));
        QVERIFY(r.ctl->programView().modeFromPlc);
        const auto res = r.ctl->selectMode(Mode::Auto);
        QCOMPARE(res.refusal, Refusal::ModeFromPlc);
        QCOMPARE(r.ctl->mode(), Mode::Reference);
        r.m->setModeCode(1);
        r.tick();
        QCOMPARE(r.ctl->mode(), Mode::Auto);
        r.m->setModeCode(0);
        r.tick();
        QCOMPARE(r.ctl->mode(), Mode::Auto); // it stays
        QVERIFY(r.ctl->selectMode(Mode::SetActual).ok());
        r.tick();
        QCOMPARE(r.ctl->mode(), Mode::SetActual);
    }
    // Leaving РУЧНОЙ stops a jog; the buttons do nothing in АВТОМАТ.
    void leavingManualStopsJog() {
        EngineRig r("training-lathe", noHoming);
        r.m->setJog(Z, -1);
        r.advance(500);
        QVERIFY(r.z().moving);
        QVERIFY(r.ctl->selectMode(Mode::Auto).ok());
        r.advance(300);
        QVERIFY(!r.z().moving);
        const std::int64_t z0 = r.current(Z);
        r.advance(500);
        QCOMPARE(r.current(Z), z0);
        r.m->setJog(Z, 0);
    }
    // Leaving АВТОМАТ interrupts the program and stops its motion; back in
    // АВТОМАТ, «Пуск» continues to the same target.
    void leavingAutoInterrupts() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G1 Z-30 FZ1000\nN2 R1=1\n");
        r.start(1);
        r.advance(800);
        r.m->setModeCode(2); // the PLC switches to РУЧНОЙ
        r.advance(500);
        QCOMPARE(r.ctl->mode(), Mode::Manual);
        QCOMPARE(r.ctl->state(), ProgramState::Interrupted);
        QVERIFY(!r.z().moving);
        const std::int64_t stopped = r.current(Z);
        QVERIFY(stopped < -5000 && stopped > -25000);
        r.m->pressStart(); // «Пуск» in РУЧНОЙ does not continue a program of АВТОМАТ
        r.advance(300);
        QCOMPARE(r.ctl->state(), ProgramState::Interrupted);
        // Meanwhile the operator may jog the axis away.
        r.m->setJog(Z, 1);
        r.advance(300);
        r.m->setJog(Z, 0);
        r.advance(300);
        QVERIFY(r.current(Z) > stopped + 2000);
        r.m->setModeCode(1);
        r.advance(50);
        r.m->pressStart();
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->state(), ProgramState::Ended);
        QCOMPARE(r.ctl->r(1), 1);
        QVERIFY(std::llabs(r.current(Z) + 30000) <= kRestTol);
    }
    // Operator functions belong to their modes.
    void functionsOfModes() {
        EngineRig r;
        QCOMPARE(r.ctl->setC(22, 5000).refusal, Refusal::WrongMode);
        QCOMPARE(r.ctl->setCurrentValue(X, 0).refusal, Refusal::WrongMode);
        QCOMPARE(r.ctl->clearRParameters().refusal, Refusal::WrongMode);
        QCOMPARE(r.ctl->clearCParameters().refusal, Refusal::WrongMode);
        QCOMPARE(r.ctl->clearPrograms().refusal, Refusal::WrongMode);
        QVERIFY(r.ctl->selectMode(Mode::MachineData).ok());
        QVERIFY(r.ctl->setC(22, 5000).ok());
        QCOMPARE(r.ctl->c()[22], 5000);
        const auto bad = r.ctl->setC(29, 5000); // МАКС.ЦАП 0..2047
        QCOMPARE(bad.refusal, Refusal::ValueOutOfRange);
        QCOMPARE(bad.text(), std::string("C029 = 5000 is outside the range 0...2047 of «МАКС.ЦАП»"));
        QCOMPARE(r.ctl->setC(153, 0).refusal, Refusal::NoSuchParameter);
        QVERIFY(r.ctl->selectMode(Mode::DataControl).ok());
        QVERIFY(r.ctl->setR(5, 7).ok());
        QVERIFY(r.ctl->clearRParameters().ok());
        QCOMPARE(r.ctl->r(5), 0);
        QCOMPARE(r.ctl->selectProgram(100).refusal, Refusal::NoSuchProgram);
        QVERIFY(r.ctl->selectProgram(1).ok());
        QCOMPARE(r.ctl->r(252), 1);
    }
    // A new C-parameter acts at once: F УСК.АВТ. of Z halved doubles a rapid's time.
    void constantsRefreshServo() {
        EngineRig r("training-lathe", noHoming);
        QVERIFY(r.ctl->selectMode(Mode::MachineData).ok());
        QVERIFY(r.ctl->setC(94, 300000).ok()); // 3000 mm/min
        r.load("%L1\nN1 G0 Z-30\n");
        r.start(1);
        const double t = r.setpointArrivalS(Z, 10000);
        QVERIFY2(t > 0.6 + 0.125 - 0.003 && t < 0.6 + 0.125 + 0.003,
                 qPrintable(QString::number(t)));
    }
    // The power-on test: the machine constants (15, 13/29, 37, 38, 39) and the
    // program store (31); a fixed constant clears its message once acknowledged.
    void selfTest() {
        {
            EngineRig r("training-lathe", [](auto& p) { p.c[19] = 0; }); // L ИМП.ДОС out of 1..32767
            QVERIFY(r.hasAlarm(13));
            QVERIFY(!r.hasAlarm(29));
            QVERIFY(r.bit(z::Ready)); // a machine fault, not a system one
            QVERIFY(r.ctl->selectMode(Mode::MachineData).ok());
            QVERIFY(r.ctl->setC(19, 1).ok());
            r.ctl->escape();
            QVERIFY(!r.hasAlarm(13));
        }
        {
            EngineRig r("training-lathe", [](auto& p) { p.c[69] = 1; }); // both encoders on one channel
            QVERIFY(r.hasAlarm(37));
        }
        {
            EngineRig r("training-lathe", [](auto& p) { p.c[70] = 1; });
            QVERIFY(r.hasAlarm(38));
        }
        {
            EngineRig r("training-lathe", [](auto& p) { p.c[106] = 2; });
            QVERIFY(r.hasAlarm(39));
        }
        {
            EngineRig r("training-lathe", [](auto& p) { p.c[4] = 1; }); // two discretes on X
            QVERIFY(r.hasAlarm(15));
            QVERIFY(!r.bit(z::Ready));
        }
        {
            EngineRig r("training-lathe", [](auto& p) { p.programs[5] = "%L5\nN1 G1 X=\n"; });
            QVERIFY(r.hasAlarm(31));
            QVERIFY(!r.bit(z::Ready));
        }
        const auto m = k528::engine::configurationMessages(profile::builtin("grinder-205").c);
        for (bool b : m)
            QVERIFY(!b);
    }
    // System messages from the machine side's module health.
    void moduleFaults() {
        EngineRig r;
        r.ctl->io().dacModuleOk = false;
        r.tick();
        QVERIFY(r.hasAlarm(3));
        QVERIFY(!r.bit(z::Ready));
        r.ctl->io().dacModuleOk = true;
        r.tick();
        QVERIFY(r.hasAlarm(3));
        QVERIFY(r.bit(z::Ready));
        r.m->pressAcknowledge(); // Z1000.7 is for machine faults
        r.advance(30);
        QVERIFY(r.hasAlarm(3));
        r.ctl->escape(); // C125 = 1
        QVERIFY(!r.hasAlarm(3));
    }
};

QTEST_APPLESS_MAIN(TestModes)
#include "test_modes.moc"
