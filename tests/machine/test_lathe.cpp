// training-lathe as a trainee runs it: power on (drives), home, start the
// shaft program L1, feed hold, resume, E-stop, acknowledge, restart — the
// signals, messages and positions at each step. Then the lathe's own
// equipment: turret, chuck, door, setting-up mode, K keys and LEDs.
#include "engine/interface_words.h"
#include "engine/rparams.h"
#include "rig/machine_rig.h"

using namespace k528;
using namespace k528::testrig;
namespace z = engine::z;

namespace {
bool greenLed(MachineRig& r, int k) {
    return (r.c().words().word(z::GreenLedsWord) >> z::keyBit(k)) & 1u;
}
bool redLed(MachineRig& r, int k) {
    return (r.c().words().word(z::RedLedsWord) >> z::keyBit(k)) & 1u;
}
void pressKey(MachineRig& r, int k) {
    r.c().words().setBit(engine::ZBit{1300, z::keyBit(k)}, true);
    r.advance(30);
}
} // namespace

class TestLathe : public QObject {
    Q_OBJECT
private slots:
    void scriptedOperator() {
        MachineRig r;
        // --- power on: the controller is ready, the drives are off -------------
        QVERIFY(r.bit(z::Ready));
        QVERIFY(r.bit(z::EmergencyStopOk)); // GOST 26642 E-stop: high = working
        QVERIFY(!r.bit(z::regulatorEnable(X)));
        QVERIFY(r.work(10)); // «Включите приводы»
        QVERIFY(!r.lamp("drives"));
        QVERIFY(r.alarms().empty());
        QVERIFY(r.drivesOn());
        QVERIFY(r.lamp("drives"));
        QVERIFY(r.bit(z::regulatorEnable(X)) && r.bit(z::regulatorEnable(Z)));
        QVERIFY(r.bit(z::FeedEnable) && r.bit(z::StartEnable));
        QVERIFY(!r.work(10));
        QVERIFY(r.work(12)); // «Выполните привязку к базовой точке»
        QVERIFY(r.work(8));  // the way lubrication runs at drives-on

        // --- home ---------------------------------------------------------------
        QVERIFY(!r.lamp("reference"));
        QVERIFY(r.home());
        r.advance(20);
        QVERIFY(r.lamp("reference"));
        QVERIFY(!r.work(12));
        // At ЗНАЧЕНИЕ БТ, within ДОПУСК ПОЗ; the slide where the machine system says.
        QVERIFY(std::llabs(r.c().axisView(X).machineDisc - 270000) <= 10);
        QVERIFY(std::llabs(r.c().axisView(Z).machineDisc - 290000) <= 10);
        QVERIFY(std::fabs(r.s().machineMm(X) - 270.0) < 0.012);
        QVERIFY(std::fabs(r.s().machineMm(Z) - 290.0) < 0.012);

        // --- start L1 -------------------------------------------------------------
        QVERIFY(r.start(1));
        QVERIFY(r.bit(z::ProgramRunning)); // GOST «программа в работе»
        r.advance(40);
        QVERIFY(r.lamp("cycle_start"));
        // M3: the frame waits for the spindle.
        QVERIFY(r.until([&] { return r.c().programView().mCode == 3; }, 2000));
        QVERIFY(r.until([&] { return r.work(7); }, 1000)); // «Разгон шпинделя»
        QCOMPARE(r.c().state(), ProgramState::WaitingM);
        QVERIFY(r.rpm("spindle") > 0 && r.rpm("spindle") < 760);
        QVERIFY(!r.s().openDoor()); // locked while the spindle turns
        QVERIFY(r.until([&] { return r.c().programView().mCode == 8; }, 3000));
        QVERIFY(r.rpm("spindle") >= 760);
        QVERIFY(r.until([&] { return r.c().programView().frameNumber >= 3; }, 10000));
        QVERIFY(r.lamp("spindle") && r.lamp("coolant"));
        QVERIFY(r.sim->view().pumps[0].pressure);

        // --- feed hold: «Стоп» (a normally closed button) during a cut ---------
        QVERIFY(r.until(
            [&] { return r.c().axisView(X).moving && r.c().programView().frameNumber == 3; },
            10000));
        r.sim->pressFor(Button::CycleStop, 100);
        QVERIFY(r.untilState(ProgramState::Interrupted, 200));
        QVERIFY(r.bit(z::ProgramInterrupted));
        QVERIFY(!r.bit(z::ProgramRunning));
        r.advance(500);
        QVERIFY(!r.c().axisView(X).moving);
        const std::int64_t held = r.c().axisView(X).currentDisc;
        r.advance(500);
        QCOMPARE(r.c().axisView(X).currentDisc, held);
        QVERIFY(r.lamp("cycle_stop"));
        QVERIFY(r.work(13)); // «Программа прервана: нажмите ПУСК»
        QVERIFY(r.rpm("spindle") >= 760); // the spindle keeps turning

        // --- resume ---------------------------------------------------------------
        r.sim->pressFor(Button::CycleStart, 100);
        QVERIFY(r.until([&] { return r.c().state() == ProgramState::Running; }, 200));
        r.advance(300);
        QVERIFY(r.c().axisView(X).currentDisc != held);
        QVERIFY(!r.work(13));

        // --- E-stop ---------------------------------------------------------------
        r.sim->pressEmergencyStop();
        r.advance(20);
        QVERIFY(!r.bit(z::EmergencyStopOk));
        QVERIFY(r.hasAlarm(9));
        QVERIFY(r.plcAlarm(23)); // «Нажата кнопка аварийного останова»
        QVERIFY(r.lamp("alarm"));
        QVERIFY(r.untilState(ProgramState::Alarm, 200) || !engine::programActive(r.c().state()));
        QVERIFY(r.until([&] { return r.rpm("spindle") == 0; }, 5000));
        QVERIFY(!r.sim->view().pumps[0].on);
        QVERIFY(r.until([&] { return !r.sim->view().drivesPower; }, 1000)); // after ЗАДЕРЖКА БР
        QVERIFY(!r.lamp("drives"));
        QVERIFY(r.c().axisView(X).referenced); // the encoders kept counting

        // --- release, acknowledge -------------------------------------------------
        r.sim->releaseEmergencyStop();
        r.advance(30);
        QVERIFY(r.bit(z::EmergencyStopOk));
        QVERIFY(r.hasAlarm(9));                    // latched until acknowledged
        QVERIFY(!r.c().alarmRegistry().active(9)); // the cause is gone
        r.push(Button::Reset);
        QVERIFY2(r.alarms().empty(), r.alarmList().c_str());
        QVERIFY(!r.plcAlarm(23));
        QVERIFY(!r.lamp("alarm"));

        // --- restart --------------------------------------------------------------
        QVERIFY(r.drivesOn());
        QVERIFY(r.start(1));
        QVERIFY(r.runToEnd(600000));
        QVERIFY2(r.c().state() == ProgramState::Ended, r.alarmList().c_str());
        QVERIFY(r.alarms().empty());
        QCOMPARE(r.rpm("spindle"), 0.0); // M5 waited until it stood
        QVERIFY(!r.lamp("coolant"));
        QVERIFY(std::fabs(r.mm(X) - 42.0) < 0.006);
        QVERIFY(std::fabs(r.mm(Z) - 2.0) < 0.006);
        QCOMPARE(r.c().r(11), 36000);
        const auto codes = r.sim->mCodes();
        QCOMPARE(std::vector<int>(codes.begin(), codes.begin() + 2), (std::vector<int>{3, 8}));
        QCOMPARE(std::vector<int>(codes.end() - 5, codes.end()),
                 (std::vector<int>{3, 8, 5, 9, 30}));
    }

    // T numbers are not in the K528 language: M61..M64 index the turret.
    // The equipment ticks only while it is awake (machine/equipment.h): the
    // same units ticked every tick with the same contactors and valves go
    // through the same states — each transition on its own (the pump's
    // rise and fall, the spindle's ramp up and down, the turret's indexing
    // and locking, the chuck's strokes), the rest of the machine at rest.
    void equipmentAsIfTickedEveryTick() {
        MachineRig r;
        QVERIFY(r.drivesOn());
        QVERIFY(r.home());
        r.advance(8000); // the lubrication cycle after switching on is over
        r.load("%L5\nN1 M8\nN2 G4 X1\nN3 M3\nN4 G4 X1\nN5 M62\nN6 G4 X1\nN7 M5\n"
               "N8 G4 X1\nN9 M9\nN10 G4 X1\nN11 M11\nN12 G4 X1\nN13 M10\nN14 G4 X1\nN15 M30\n");
        machine::Equipment& eq = r.s().equipment();
        // The reference: the same units on their own signals, ticked every tick.
        machine::Signals ref;
        machine::Spindle spindle(ref, eq.spindle("spindle")->settings());
        machine::Pump coolant(ref, eq.pump("coolant")->settings());
        machine::Pump lube(ref, eq.pump("lube")->settings());
        machine::Chuck chuck(ref, eq.chuck->settings());
        machine::Turret turret(ref, eq.turret->settings());
        QCOMPARE(eq.chuck->position(), chuck.position());
        QCOMPARE(eq.turret->angle(), turret.angle());
        QVERIFY(!eq.pump("lube")->pressure() && !eq.pump("coolant")->pressure());
        const machine::Signals& sig = r.s().machineSignals();
        std::vector<std::pair<int, int>> wires; // the simulation's actuator, the reference's
        for (const char* a : {"spindle.fwd", "spindle.rev", "coolant.on", "lube.on", "chuck.clamp",
                              "chuck.unclamp", "turret.cw", "turret.ccw"})
            wires.emplace_back(*sig.findActuator(a), *ref.findActuator(a));
        QVERIFY(r.start(5));
        int ticks = 0;
        bool indexed = false, opened = false;
        while (r.c().state() != ProgramState::Ended && ticks < 60000) {
            r.tick();
            ++ticks;
            for (const auto& [from, to] : wires)
                ref.setActuator(to, sig.actuator(from));
            spindle.tick(1.0);
            coolant.tick(1.0);
            lube.tick(1.0);
            chuck.tick(1.0);
            turret.tick(1.0);
            const QString at = QString("tick %1").arg(ticks);
            QVERIFY2(eq.spindle("spindle")->rpm() == spindle.rpm(), qPrintable(at));
            QVERIFY2(eq.pump("coolant")->pressure() == coolant.pressure(), qPrintable(at));
            QVERIFY2(eq.pump("lube")->pressure() == lube.pressure(), qPrintable(at));
            QVERIFY2(eq.chuck->position() == chuck.position(), qPrintable(at));
            QVERIFY2(eq.turret->angle() == turret.angle(), qPrintable(at));
            QVERIFY2(eq.turret->locked() == turret.locked(), qPrintable(at));
            indexed = indexed || turret.station() == 2;
            opened = opened || chuck.unclamped();
        }
        QCOMPARE(r.c().state(), ProgramState::Ended);
        QVERIFY(indexed && opened);
        QVERIFY(turret.locked() && chuck.clamped() && spindle.rpm() == 0 && !coolant.pressure());
    }

    void turretByMCodes() {
        MachineRig r;
        QVERIFY(r.drivesOn());
        QVERIFY(r.home());
        QCOMPARE(r.sim->view().turretStation, 1);
        r.load("%L5\nN1 M63\nN2 M62\nN3 M30\n");
        QVERIFY(r.start(5));
        QVERIFY(r.until(
            [&] { return r.sim->view().turretStation == 2 && !r.sim->view().turretLocked; }, 3000));
        QVERIFY(r.work(5)); // «Поворот резцедержателя»
        QCOMPARE(r.c().state(), ProgramState::WaitingM);
        QVERIFY(r.until([&] { return r.c().programView().frameNumber == 2; }, 5000));
        QCOMPARE(r.sim->view().turretStation, 3);
        QVERIFY(r.sim->view().turretLocked);
        QVERIFY(r.runToEnd(10000));
        QCOMPARE(r.c().state(), ProgramState::Ended);
        // M62 from 3: forward through 4 and 1 to 2.
        QCOMPARE(r.sim->view().turretStation, 2);
        QVERIFY(greenLed(r, 8) && !greenLed(r, 9));
        // K9 (tool 3) in РУЧНОЙ.
        r.c().selectMode(Mode::Manual);
        pressKey(r, 9);
        QVERIFY(redLed(r, 9));
        QVERIFY(r.until(
            [&] { return r.sim->view().turretStation == 3 && r.sim->view().turretLocked; }, 5000));
        r.advance(30);
        QVERIFY(greenLed(r, 9) && !redLed(r, 9));
    }

    // A jammed turret: the M function is not acknowledged; after its time
    // the PLC raises A10 «Резцедержатель не повернулся»; «Сброс» ends it.
    void turretTimeout() {
        MachineRig r;
        QVERIFY(r.drivesOn());
        QVERIFY(r.home());
        r.s().inject({Fault::TurretJam});
        r.load("%L5\nN1 M62\nN2 M30\n");
        QVERIFY(r.start(5));
        r.advance(7000);
        QCOMPARE(r.c().state(), ProgramState::WaitingM);
        QVERIFY(!r.plcAlarm(10));
        r.advance(1500);
        QVERIFY(r.plcAlarm(10));
        r.push(Button::Reset);
        QCOMPARE(r.c().state(), ProgramState::Idle);
        QVERIFY(!r.bit(z::MStrobe));
    }

    // An M function the description does not know holds the frame and shows A16.
    void unknownMFunction() {
        MachineRig r;
        QVERIFY(r.drivesOn());
        QVERIFY(r.home());
        r.load("%L5\nN1 M77\nN2 M30\n");
        QVERIFY(r.start(5));
        r.advance(500);
        QCOMPARE(r.c().state(), ProgramState::WaitingM);
        QVERIFY(r.plcAlarm(16));
        QVERIFY(!r.bit(z::MAcknowledge));
    }

    // The chuck pedal opens and closes the chuck only with the spindle
    // stopped; with the chuck open a start is inhibited.
    void chuckAndStartInhibit() {
        MachineRig r;
        QVERIFY(r.drivesOn());
        QVERIFY(r.home());
        QVERIFY(r.lamp("chuck"));
        r.push(Button::ChuckPedal);
        QVERIFY(r.until([&] { return r.sim->view().chuckOpen; }, 1000));
        r.advance(20);
        QVERIFY(r.work(2) && r.work(16));
        QVERIFY(!r.bit(z::StartEnable));
        r.sim->pressFor(Button::CycleStart, 100);
        r.advance(200);
        QVERIFY(r.plcAlarm(18)); // «Пуск запрещён: патрон разжат»
        QVERIFY(!engine::programActive(r.c().state()));
        // K1 (spindle) refused with the chuck open.
        r.c().selectMode(Mode::Manual);
        pressKey(r, 1);
        r.advance(500);
        QCOMPARE(r.rpm("spindle"), 0.0);
        QVERIFY(r.plcAlarm(28));
        r.push(Button::ChuckPedal);
        QVERIFY(r.until([&] { return r.sim->view().chuckClamped; }, 1000));
        r.advance(20);
        QVERIFY(r.bit(z::StartEnable));
        r.push(Button::Reset);
        QVERIFY(!r.plcAlarm(18));
        // Spindle by K1, then the pedal is refused while it turns.
        pressKey(r, 1);
        QVERIFY(r.until([&] { return r.rpm("spindle") > 700; }, 3000));
        QVERIFY(greenLed(r, 1));
        r.push(Button::ChuckPedal);
        r.advance(500);
        QVERIFY(r.sim->view().chuckClamped);
        QVERIFY(r.plcAlarm(20));
        pressKey(r, 2);
        QVERIFY(r.until([&] { return r.rpm("spindle") == 0; }, 5000));
    }

    // The door: locked while the spindle turns; open, it inhibits a start
    // and holds the feed; in setting-up mode (K12) the axes move at 10 %.
    void doorAndSetupMode() {
        MachineRig r;
        QVERIFY(r.drivesOn());
        QVERIFY(r.home());
        QVERIFY(r.s().openDoor());
        r.advance(20);
        QVERIFY(r.work(1));
        QVERIFY(r.lamp("door"));
        QVERIFY(!r.bit(z::FeedEnable));
        QVERIFY(!r.bit(z::StartEnable));
        // Jog refused (feed hold).
        r.c().selectMode(Mode::Manual);
        r.sim->press(Button::JogZMinus);
        r.advance(300);
        QVERIFY(!r.c().axisView(Z).moving);
        r.sim->release(Button::JogZMinus);
        // Setting-up mode: the feed is back at 10 % (override code 4).
        pressKey(r, 12);
        QVERIFY(r.work(9) && r.work(15));
        QVERIFY(r.bit(z::FeedEnable));
        QCOMPARE(r.c().programView().overridePercent, 10);
        const double z0 = r.mm(Z);
        r.sim->press(Button::JogZMinus);
        r.advance(1000);
        r.sim->release(Button::JogZMinus);
        r.advance(300);
        const double moved = z0 - r.mm(Z);
        // F ОБЫЧНАЯ 2000 mm/min at 10 %: about 3.3 mm in a second.
        QVERIFY2(moved > 2.5 && moved < 3.6, qPrintable(QString::number(moved)));
        // The spindle is refused with the door open.
        pressKey(r, 1);
        r.advance(300);
        QCOMPARE(r.rpm("spindle"), 0.0);
        QVERIFY(r.plcAlarm(21));
        r.s().closeDoor();
        pressKey(r, 12);
        r.advance(20);
        QCOMPARE(r.c().programView().overridePercent, 100);
    }

    // The override selector (Z1001.11, Z1001.12-15) and its position «K923».
    void overrideSelector() {
        MachineRig r;
        QVERIFY(r.s().hasOverrideSwitch());
        r.advance(20);
        QVERIFY(!r.bit(z::OverrideFromPlc));     // «K923»: the L keys decide
        QVERIFY(r.c().pressOverrideKey(3).ok()); // L3 = 50 %
        r.advance(5);
        QCOMPARE(r.c().programView().overridePercent, 50);
        r.s().setOverrideSwitch(5); // 20 %
        r.advance(20);
        QVERIFY(r.bit(z::OverrideFromPlc));
        QCOMPARE(r.c().programView().overridePercent, 20);
        r.s().setOverrideSwitch(0);
        r.advance(20);
        QVERIFY(r.bit(z::OverrideZero));
        QVERIFY(r.work(19));
        r.s().setOverrideSwitch(-1);
        r.advance(20);
        QCOMPARE(r.c().programView().overridePercent, 50);
    }

    // The handwheel: selector X, multiplier positions x1 / x10 / x100.
    void handwheel() {
        MachineRig r;
        QVERIFY(r.drivesOn());
        QVERIFY(r.home());
        r.c().selectMode(Mode::Manual);
        r.s().selectHandwheel(machine::HandwheelAxis::X);
        QCOMPARE(r.s().handwheelDiscretesPerDetent(0), 2);  // diameter: 1 µm slide = 2 µm
        QCOMPARE(r.s().handwheelDiscretesPerDetent(1), 20); // МНОЖИТ.М1 = 10
        QCOMPARE(r.s().handwheelDiscretesPerDetent(2), 200);
        for (int step = 0; step < 3; ++step) {
            r.s().selectHandwheelMultiplier(step);
            r.advance(30);
            // The target moves by exactly the pulses (one internal unit = one
            // displayed discrete on the diameter); the slide follows within ДОПУСК ПОЗ.
            const double t0 = r.c().servo(X).target();
            const std::int64_t x0 = r.c().axisView(X).currentDisc;
            r.s().turnHandwheel(-25);
            r.advance(2000);
            const std::int64_t want = -25 * r.s().handwheelDiscretesPerDetent(step);
            QCOMPARE(r.c().servo(X).target() - t0, static_cast<double>(want));
            QVERIFY(std::llabs(r.c().axisView(X).currentDisc - x0 - want) <= 10);
        }
        QVERIFY(r.work(27));
        // Off: the handwheel does nothing.
        r.s().selectHandwheel(machine::HandwheelAxis::Off);
        r.advance(30);
        const double x0 = r.c().servo(X).target();
        r.s().turnHandwheel(50);
        r.advance(1000);
        QCOMPARE(r.c().servo(X).target(), x0);
        // Z with its own wheel channel (M2).
        r.s().selectHandwheel(machine::HandwheelAxis::Z);
        r.s().selectHandwheelMultiplier(1);
        r.advance(30);
        const double z0 = r.c().servo(Z).target();
        r.s().turnHandwheel(10);
        r.advance(1000);
        QCOMPARE(r.c().servo(Z).target() - z0,
                 200.0); // 10 x МНОЖИТ.М2 10 discretes, 2 internal each
    }

    // Manual cycles from the K keys: K11 cycle 1 (C143 = 90), K5 cycle 6 (C148 = 91).
    void manualCyclesFromKeys() {
        MachineRig r;
        QVERIFY(r.drivesOn());
        QVERIFY(r.home());
        r.c().selectMode(Mode::Manual);
        r.advance(20);
        pressKey(r, 11);
        QVERIFY(r.bit(z::cycleRunning(1)));
        QVERIFY(greenLed(r, 11));
        QVERIFY(r.work(21));
        QVERIFY(r.until([&] { return !r.bit(z::cycleRunning(1)); }, 60000));
        QVERIFY(std::llabs(r.c().axisView(X).machineDisc - 200000) <=
                10); // R220, within ДОПУСК ПОЗ
        pressKey(r, 5);
        QVERIFY(r.bit(z::cycleRunning(6)));
        QVERIFY(r.work(20));
        QVERIFY(r.until([&] { return !r.bit(z::cycleRunning(6)); }, 600000));
        QVERIFY2(r.alarms().empty(), r.alarmList().c_str());
    }
};

QTEST_APPLESS_MAIN(TestLathe)
#include "test_lathe.moc"
