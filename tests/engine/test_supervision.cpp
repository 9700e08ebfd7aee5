// Supervision of the axes and the machine: soft limits (12/28), limit
// switches (10/11/26/27), following error (7/23), standstill (8/24),
// encoder stall (56/57), emergency stop (9), regulator (1/17), and how
// messages are acknowledged.
#include "rig/engine_rig.h"

#include <QtTest>
#include <map>

using namespace k528;
using namespace k528::testrig;
namespace z = k528::engine::z;

class TestSupervision : public QObject {
    Q_OBJECT
private slots:
    // A programmed target beyond a soft limit is refused before the move.
    void softLimitProgram() {
        EngineRig r;
        QVERIFY(r.home());
        const std::int64_t x0 = r.machine(X);
        r.load("%L1\nN1 G1 X200 FX3000\nN2 X280\n%L2\nN1 G0 Z300\n");
        r.start(1);
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->state(), ProgramState::Alarm);
        const auto* a = r.alarm(12);
        QVERIFY(a);
        QCOMPARE(a->line, 3);
        QVERIFY(std::llabs(r.machine(X) - 200000) <= kRestTol);
        QVERIFY(x0 > 200000);
        r.m->pressReset();
        r.m->pressAcknowledge();
        r.advance(50);
        r.start(2);
        QVERIFY(r.runToEnd());
        QVERIFY(r.hasAlarm(28));
        QVERIFY(std::llabs(r.machine(Z) - 290000) <= kRestTol); // did not move
    }
    // Jog stops at the soft limit (only when referenced and C10 = 1).
    void softLimitJog() {
        EngineRig r;
        QVERIFY(r.home());
        QVERIFY(r.ctl->selectMode(Mode::Manual).ok());
        r.m->setJog(X, 1);
        QVERIFY(r.until([&] { return r.hasAlarm(12); }, 10000));
        r.advance(200);
        QVERIFY(std::llabs(r.machine(X) - 272000) <= kRestTol); // +ОГРАНИЧЕН
        QVERIFY(!r.m->limitPlusPressed(X));
        r.m->setJog(X, -1); // away from it: allowed
        r.advance(500);
        QVERIFY(r.machine(X) < 271000);
        r.m->setJog(X, 0);
    }
    // Limit switch: braking with УСКОРЕНИЕ 2, the direction locked, message 27.
    void limitSwitch() {
        EngineRig r("training-lathe", noHoming); // not referenced: no soft limits
        QVERIFY(r.ctl->selectMode(Mode::Manual).ok());
        r.m->setJog(Z, 1); // F ОБЫЧНАЯ 2000 mm/min
        QVERIFY(r.until([&] { return r.m->limitPlusPressed(Z); }, 120000));
        const double hit = r.m->slideMm(Z);
        r.advance(500);
        QVERIFY(r.hasAlarm(27));
        QVERIFY(r.ctl->alarmRegistry().active(27));
        // v²/2a: 33.3 mm/s with 1 m/s² (C75 = 25600) is 0.56 mm (УСКОРЕНИЕ 1 would need 1.39 mm).
        const double over = r.m->slideMm(Z) - hit;
        QVERIFY2(over > 0.4 && over < 0.8, qPrintable(QString::number(over)));
        const double stood = r.m->slideMm(Z);
        r.advance(500);
        QVERIFY(std::fabs(r.m->slideMm(Z) - stood) < 0.01); // + stays locked while held
        r.m->setJog(Z, 0);
        r.advance(100);
        r.m->setJog(Z, 1);
        r.advance(500);
        QVERIFY(std::fabs(r.m->slideMm(Z) - stood) < 0.01);
        r.m->setJog(Z, -1);
        QVERIFY(r.until([&] { return !r.m->limitPlusPressed(Z); }, 5000));
        r.m->setJog(Z, 0);
        r.advance(200);
        QVERIFY(!r.ctl->alarmRegistry().active(27));
        QVERIFY(r.hasAlarm(27)); // latched until acknowledged
        r.m->pressAcknowledge();
        r.advance(50);
        QVERIFY(!r.hasAlarm(27));
    }
    // МАКС.ОШИБКА exceeded while moving: 23; both axes stop; the program ends.
    void followingError() {
        EngineRig r("training-lathe", [](auto& p) {
            noHoming(p);
            p.setC(82, 100); // Z: 100 internal units = 0.05 mm
        });
        r.load("%L1\nN1 G1 X40 FX3000\nN2 G0 Z-50\n");
        r.start(1);
        QVERIFY(r.until([&] { return r.hasAlarm(23); }, 20000));
        QCOMPARE(r.ctl->state(), ProgramState::Alarm);
        QVERIFY(r.bit(z::loopError(Z)));
        r.advance(1000);
        QVERIFY(!r.x().moving);
        QVERIFY(!r.z().moving);
        QVERIFY(!r.bit(z::loopClosed(Z)));
        r.ctl->escape(); // C124 = 1: acknowledges the machine fault
        r.advance(20);
        QVERIFY(!r.hasAlarm(23));
        QVERIFY(r.bit(z::loopClosed(Z)));
    }
    // At rest, ЗАДЕРЖКА КП after the move, |E| > ДОПУСК КП: 24.
    void standstill() {
        EngineRig r("training-lathe", noHoming);
        r.advance(1000);
        r.m->mechanics(Z)->pushSlide(0.05); // 100 internal units, ДОПУСК КП 20
        r.advance(5);
        QVERIFY(r.hasAlarm(24));
        QVERIFY(r.bit(z::loopError(Z)));
        QVERIFY(!r.hasAlarm(8));
    }
    // T контроля ДОС: the encoder does not change while a move is commanded: 57.
    void encoderStall() {
        EngineRig r("training-lathe", [](auto& p) {
            noHoming(p);
            p.setC(82, 0); // no following-error check: the stall check must find it
        });
        r.m->mechanics(Z)->setEncoderFrozen(true);
        r.load("%L1\nN1 G1 Z-50 FZ500\n");
        r.start(1);
        r.advance(900);
        QVERIFY(!r.hasAlarm(57));
        QVERIFY(r.until([&] { return r.hasAlarm(57); }, 500));
        QCOMPARE(r.ctl->state(), ProgramState::Alarm);
    }
    // The same checks on X give X's messages: 7 (МАКС.ОШИБКА, C30),
    // 8 (standstill), 56 (encoder stall).
    void xAxisMessages() {
        {
            EngineRig r("training-lathe", [](auto& p) {
                noHoming(p);
                p.setC(30, 100);
            });
            r.load("%L1\nN1 G0 X100\n");
            r.start(1);
            QVERIFY(r.until([&] { return r.hasAlarm(7); }, 20000));
            QVERIFY(r.bit(z::loopError(X)));
            QVERIFY(!r.hasAlarm(23));
        }
        {
            EngineRig r("training-lathe", noHoming);
            r.advance(1000);
            r.m->mechanics(X)->pushSlide(0.05);
            r.advance(5);
            QVERIFY2(r.hasAlarm(8), "standstill X");
            QVERIFY(!r.hasAlarm(24));
        }
        {
            EngineRig r("training-lathe", [](auto& p) {
                noHoming(p);
                p.setC(30, 0);
            });
            r.m->mechanics(X)->setEncoderFrozen(true);
            r.load("%L1\nN1 G1 X50 FX500\n");
            r.start(1);
            QVERIFY(r.until([&] { return r.hasAlarm(56); }, 2000));
            QVERIFY(!r.hasAlarm(57));
        }
    }
    // Z1000.0 = 0: emergency stop, 9; loop open at once, regulator blocked after ЗАДЕРЖКА БР.
    void emergencyStop() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G1 Z-50 FZ1000\n");
        r.start(1);
        r.advance(500);
        r.m->setEmergencyStop(true);
        r.tick();
        QVERIFY(r.hasAlarm(9));
        QCOMPARE(r.ctl->state(), ProgramState::Alarm);
        QVERIFY(!r.bit(z::loopClosed(Z)));
        QCOMPARE(r.ctl->io().dac[1], 0);
        QVERIFY(r.bit(z::regulatorEnabled(Z)));
        r.advance(300); // ЗАДЕРЖКА БР
        QVERIFY(!r.bit(z::regulatorEnabled(Z)));
        QVERIFY(!r.ctl->io().regulatorEnable[1]);
        r.m->pressAcknowledge();
        r.advance(50);
        QVERIFY(r.hasAlarm(9)); // still there: the cause lasts
        r.m->setEmergencyStop(false);
        r.advance(50);
        QVERIFY(r.hasAlarm(9));
        r.m->pressAcknowledge();
        r.advance(50);
        QVERIFY(!r.hasAlarm(9));
        QVERIFY(r.bit(z::loopClosed(Z)));
    }
    // A motion without «Деблокировка регулятора»: 1 (X).
    void regulatorNotEnabled() {
        EngineRig r("training-lathe", noHoming);
        r.m->setRegulatorEnable(X, false);
        r.advance(400);
        QVERIFY(!r.bit(z::regulatorEnabled(X)));
        QVERIFY(r.ctl->selectMode(Mode::Manual).ok());
        r.m->setJog(X, 1);
        r.advance(10);
        QVERIFY(r.hasAlarm(1));
    }
    // «Обрыв канала 1/2 ДОС»: 4/5 (X), 20/21 (Z).
    void encoderChannelBreak() {
        EngineRig r("training-lathe", noHoming);
        r.m->mechanics(X)->setChannelBroken(2, true);
        r.m->mechanics(Z)->setChannelBroken(1, true);
        r.advance(5);
        QVERIFY(r.hasAlarm(5));
        QVERIFY(r.hasAlarm(20));
        QVERIFY(r.bit(z::loopError(X)));
        r.m->mechanics(X)->setChannelBroken(2, false);
        r.ctl->escape();
        r.advance(5);
        QVERIFY(!r.hasAlarm(5));
        QVERIFY(r.hasAlarm(20)); // still broken
    }
    // A message with its number is one line everywhere it is shown (panel,
    // `k528 run`, the desktop): table М.1's «37. Ошибка N ДОС», «38. Ошибка N
    // ЦАП», «56. Контроль ДОС оси X» with a blank after the dot, «39.Ошибка N
    // маховика» without; English always with one.
    void alarmTextAsTableM1PrintsIt() {
        // Both encoders, and both DACs, on one channel: 37 and 38 at power-on.
        EngineRig r("training-lathe", [](profile::MachineProfile& p) {
            p.c[69] = p.c[17];
            p.c[70] = p.c[18];
        });
        std::map<int, engine::AlarmView> shown;
        for (const engine::AlarmView& a : r.ctl->alarms())
            shown[a.number] = a;
        QVERIFY(shown.count(37) && shown.count(38));
        QCOMPARE(engine::alarmText(shown[37], true), std::string("37. Ошибка N ДОС"));
        QCOMPARE(engine::alarmText(shown[38], true), std::string("38. Ошибка N ЦАП"));
        QCOMPARE(engine::alarmText(shown[37], false), "37. " + shown[37].textEn);
        QVERIFY(!shown[37].textEn.empty());
        for (const auto& [n, text] :
             {std::pair{56, "56. Контроль ДОС оси X"}, std::pair{39, "39.Ошибка N маховика"},
              std::pair{33, "33.Задание координаты X"}, std::pair{64, "64. G04/L"}}) {
            engine::AlarmView a;
            a.number = n;
            QCOMPARE(engine::alarmText(a, true), std::string(text));
        }
    }
    // «Пуск» is refused while a message is shown.
    void startRefusedWithAlarm() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 R1=1\n");
        r.advance(1000);
        r.m->mechanics(Z)->pushSlide(0.05);
        r.advance(10);
        QVERIFY(r.hasAlarm(24));
        r.start(1);
        QCOMPARE(r.ctl->state(), ProgramState::Idle);
        QCOMPARE(r.ctl->r(1), 0);
    }
};

QTEST_APPLESS_MAIN(TestSupervision)
#include "test_supervision.moc"
