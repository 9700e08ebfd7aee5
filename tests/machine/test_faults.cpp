// Fault injection for training: each fault shows the manual's message (or
// the machine's PLC message) and its behaviour; clearing the cause and
// acknowledging brings the machine back.
#include "engine/interface_words.h"
#include "rig/machine_rig.h"

#include <set>

using namespace k528;
using namespace k528::testrig;
using k528::machine::PositionerPart;
using k528::machine::K923Part;
namespace z = engine::z;

namespace {
// A lathe with its drives on and homed.
std::unique_ptr<MachineRig> ready(std::string_view name = "training-lathe") {
    auto r = std::make_unique<MachineRig>(name);
    if (!r->drivesOn() || !r->home())
        return nullptr;
    r->advance(50);
    return r;
}
} // namespace

class TestFaults : public QObject {
    Q_OBJECT
private slots:
    void encoderChannelBreak_data() {
        QTest::addColumn<int>("axis");
        QTest::addColumn<int>("channel");
        QTest::addColumn<int>("message");
        QTest::newRow("X ch1") << 0 << 1 << 4;
        QTest::newRow("X ch2") << 0 << 2 << 5;
        QTest::newRow("Z ch1") << 1 << 1 << 20;
        QTest::newRow("Z ch2") << 1 << 2 << 21;
    }
    void encoderChannelBreak() {
        QFETCH(int, axis);
        QFETCH(int, channel);
        QFETCH(int, message);
        auto r = ready();
        QVERIFY(r);
        const FaultSpec f{Fault::EncoderChannelBreak, axis == 0 ? X : Z, channel};
        r->s().inject(f);
        r->advance(20);
        QVERIFY2(r->hasAlarm(message), r->alarmList().c_str());
        QVERIFY(r->bit(z::loopError(axis == 0 ? X : Z)));
        // Acknowledged only when the cause is gone.
        r->push(Button::Reset);
        QVERIFY(r->hasAlarm(message));
        r->s().clear(f);
        r->advance(20);
        r->push(Button::Reset);
        QVERIFY2(r->alarms().empty(), r->alarmList().c_str());
    }

    void driveNotReady() {
        for (const AxisId a : {X, Z}) {
            auto r = ready();
            QVERIFY(r);
            r->s().inject({Fault::DriveNotReady, a});
            r->advance(30);
            const int msg = a == X ? 16 : 32;
            QVERIFY2(r->hasAlarm(msg), r->alarmList().c_str());
            QVERIFY(r->plcAlarm(a == X ? 25 : 26)); // the PLC sees the drive's relay too
            r->s().clearFaults();
            r->advance(30);
            r->push(Button::Reset);
            QVERIFY2(r->alarms().empty(), r->alarmList().c_str());
            QVERIFY(!r->plcAlarm(a == X ? 25 : 26));
        }
    }

    void limitSwitch_data() {
        QTest::addColumn<int>("axis");
        QTest::addColumn<int>("dir");
        QTest::addColumn<int>("message");
        QTest::newRow("X+") << 0 << 1 << 11;
        QTest::newRow("X-") << 0 << -1 << 10;
        QTest::newRow("Z+") << 1 << 1 << 27;
        QTest::newRow("Z-") << 1 << -1 << 26;
    }
    void limitSwitch() {
        QFETCH(int, axis);
        QFETCH(int, dir);
        QFETCH(int, message);
        auto r = ready();
        QVERIFY(r);
        const AxisId a = axis == 0 ? X : Z;
        r->s().inject({Fault::LimitSwitch, a, dir});
        r->advance(30);
        QVERIFY2(r->hasAlarm(message), r->alarmList().c_str());
        QVERIFY(r->lamp("limit"));
        QVERIFY(r->plcAlarm(27));
        // The direction towards the switch is locked, the other is free.
        r->c().selectMode(Mode::Manual);
        const Button towards = a == X ? (dir > 0 ? Button::JogXPlus : Button::JogXMinus)
                                      : (dir > 0 ? Button::JogZPlus : Button::JogZMinus);
        const Button away = a == X ? (dir > 0 ? Button::JogXMinus : Button::JogXPlus)
                                   : (dir > 0 ? Button::JogZMinus : Button::JogZPlus);
        const double p0 = r->mm(a);
        r->s().press(towards);
        r->advance(300);
        r->s().release(towards);
        r->advance(100);
        QVERIFY(std::fabs(r->mm(a) - p0) < 0.02);
        r->s().press(away);
        r->advance(300);
        r->s().release(away);
        r->advance(300);
        QVERIFY(std::fabs(r->mm(a) - p0) > 1.0);
        r->s().clearFaults();
        r->advance(30);
        r->push(Button::Reset);
        QVERIFY2(r->alarms().empty(), r->alarmList().c_str());
        QVERIFY(!r->lamp("limit"));
    }

    // The E-stop circuit opens (not the mushroom): 9, and the PLC tells a
    // broken circuit from a pressed button.
    void emergencyStopCircuit() {
        auto r = ready();
        QVERIFY(r);
        r->s().inject({Fault::EmergencyStop});
        r->advance(20);
        QVERIFY(r->hasAlarm(9));
        QVERIFY(!r->bit(z::EmergencyStopOk));
        QVERIFY(r->plcAlarm(24));
        QVERIFY(!r->plcAlarm(23));
        QVERIFY(r->until([&] { return !r->s().view().drivesPower; }, 1000));
        r->s().clearFaults();
        r->advance(20);
        r->push(Button::Reset);
        QVERIFY(r->alarms().empty());
        QVERIFY(r->drivesOn());
    }

    // Interference on the encoder lines: the loop demands more than
    // ПРЕДЕЛ ЦАП at once: 6 (X), 22 (Z); the loop opens.
    void dacLimit() {
        for (const AxisId a : {X, Z}) {
            auto r = ready();
            QVERIFY(r);
            r->s().inject({Fault::DacLimit, a});
            r->advance(10);
            const int msg = a == X ? 6 : 22;
            QVERIFY2(r->hasAlarm(msg), r->alarmList().c_str());
            QVERIFY(!r->c().axisView(a).loopClosed);
            r->s().clearFaults();
            r->advance(20);
            r->push(Button::Reset);
            QVERIFY2(r->alarms().empty(), r->alarmList().c_str());
            // After the interference the count is right again: the position holds.
            QVERIFY(r->until([&] { return r->c().axisView(a).loopClosed; }, 2000));
            r->advance(1000);
            QVERIFY2(r->alarms().empty(), r->alarmList().c_str());
        }
    }

    // A PLC I/O module fails: 55 and the PLC's system message S(place+1);
    // the module's outputs drop (place 2: the contactors — the spindle stops).
    void plcModuleFailure() {
        auto r = ready();
        QVERIFY(r);
        r->c().selectMode(Mode::Manual);
        r->advance(20);
        r->c().words().setBit(engine::ZBit{1300, z::keyBit(1)}, true); // K1: spindle
        QVERIFY(r->until([&] { return r->rpm("spindle") > 700; }, 3000));
        r->s().inject({Fault::PlcModuleFailure, X, 2});
        r->advance(20);
        QVERIFY2(r->hasAlarm(55), r->alarmList().c_str());
        QVERIFY(r->system(3));
        QVERIFY(r->plcAlarm(32));
        QVERIFY(!r->bit(z::Ready)); // a system message: the positioner is not ready
        QVERIFY(r->until([&] { return r->rpm("spindle") == 0; }, 5000));
        QVERIFY(r->until([&] { return !r->s().view().drivesPower; }, 2000));
        r->s().clearFaults();
        r->advance(20);
        // System messages are acknowledged with ESC (C125 = 1).
        r->c().escape();
        r->advance(20);
        r->push(Button::Reset);
        QVERIFY2(r->alarms().empty(), r->alarmList().c_str());
        QVERIFY(!r->system(3));
        QVERIFY(r->bit(z::Ready));
    }

    // The input module fails: its inputs read 0 — the E-stop circuit among them.
    void inputModuleFailure() {
        auto r = ready();
        QVERIFY(r);
        r->s().inject({Fault::PlcModuleFailure, X, 0});
        r->advance(20);
        QVERIFY(r->hasAlarm(55));
        QVERIFY(r->system(1));
        QVERIFY(r->hasAlarm(9));
    }

    void lostLink() {
        auto r = ready();
        QVERIFY(r);
        r->s().inject({Fault::LostLink});
        r->advance(20);
        QVERIFY2(r->hasAlarm(19), r->alarmList().c_str());
        QVERIFY(!r->c().axisView(X).loopClosed);
        QCOMPARE(r->s().plc().signal("link_ok"), std::optional<bool>(false));
        QVERIFY(r->until([&] { return !r->s().view().drivesPower; }, 2000));
        r->s().clearFaults();
        r->advance(20);
        QVERIFY(r->plcAlarm(13)); // remembered until acknowledged
        r->c().escape();
        r->push(Button::Reset);
        QVERIFY2(r->alarms().empty(), r->alarmList().c_str());
        QVERIFY(!r->plcAlarm(13));
        QVERIFY(r->drivesOn());
    }

    // The positioner's own parts: each gives its message of appendix М; a
    // failed encoder module counts no more, a failed DAC module gives 0 V.
    void positionerParts_data() {
        QTest::addColumn<int>("part");
        QTest::addColumn<int>("message");
        QTest::newRow("CP34.23 place 0") << int(PositionerPart::PulseModule1) << 2;
        QTest::newRow("CP34.23 place 1") << int(PositionerPart::PulseModule2) << 18;
        QTest::newRow("CM32.03") << int(PositionerPart::DacModule) << 3;
        QTest::newRow("CP52.05") << int(PositionerPart::CommModule) << 14;
        QTest::newRow("K923 link") << int(PositionerPart::PanelLink) << 25;
        QTest::newRow("RAM/ROM") << int(PositionerPart::Memory) << 30;
    }
    void positionerParts() {
        QFETCH(int, part);
        QFETCH(int, message);
        auto r = ready();
        QVERIFY(r);
        const FaultSpec f{Fault::PositionerModule, X, part};
        QVERIFY(std::find(r->s().availableFaults().begin(), r->s().availableFaults().end(), f) !=
                r->s().availableFaults().end());
        const std::int64_t zCount = r->c().io().pulse[2].count;
        r->s().inject(f);
        r->advance(20);
        QVERIFY2(r->hasAlarm(message), r->alarmList().c_str());
        if (part == int(PositionerPart::PulseModule2)) {
            // Counts arriving on the encoder lines (the DacLimit fault adds a
            // burst): the counter of the dead module does not take them.
            r->s().inject({Fault::DacLimit, Z});
            r->advance(5);
            QCOMPARE(r->c().io().pulse[2].count, zCount);
            r->s().clear({Fault::DacLimit, Z});
        }
        r->s().clearFaults();
        r->advance(20);
        r->c().escape();
        r->push(Button::Reset);
        QVERIFY2(!r->hasAlarm(message), r->alarmList().c_str());
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 r->s().inject({Fault::PositionerModule, X, 7}));
    }

    // The PLC in «ОТЛАДКА СТОП»: its outputs drop (drives, spindle), its
    // words to the positioner are 0 — the E-stop input among them: 9 —, the
    // K923 says «Режим ПЛК СТОП !»; running again, the machine comes back.
    void plcStopped() {
        auto r = ready();
        QVERIFY(r);
        QVERIFY(!r->s().k923Health().plcStopped);
        r->s().inject({Fault::PlcStopped});
        r->advance(20);
        QVERIFY(r->s().k923Health().plcStopped);
        QVERIFY(r->s().plc().stopped());
        QVERIFY2(r->hasAlarm(9), r->alarmList().c_str());
        QVERIFY(!r->s().view().drivesPower);
        const std::int64_t scans = r->s().plc().scans();
        r->advance(200);
        QCOMPARE(r->s().plc().scans(), scans); // nothing runs
        r->s().clear({Fault::PlcStopped});
        r->advance(50);
        QVERIFY(r->s().plc().scans() > scans);
        QVERIFY(!r->s().k923Health().plcStopped);
        // A warm restart: the drives stay off until the operator switches them on.
        r->advance(1000);
        QVERIFY(!r->s().view().drivesPower);
        r->c().escape();
        r->push(Button::Reset);
        QVERIFY(r->drivesOn());
        QVERIFY2(!r->hasAlarm(9), r->alarmList().c_str());
    }

    // K923 faults change only the panel's state (k923Health), each its own flag.
    void k923Parts() {
        auto r = ready();
        QVERIFY(r);
        QCOMPARE(r->s().k923Health(), panel::Health{});
        r->s().inject({Fault::K923, X, int(K923Part::PlcLink)});
        QCOMPARE(r->s().k923Health(), (panel::Health{.plcLink = false}));
        r->s().inject({Fault::K923, X, int(K923Part::Ram)});
        QCOMPARE(r->s().k923Health(), (panel::Health{.ramOk = false, .plcLink = false}));
        r->advance(50);
        QVERIFY2(r->alarms().empty(), r->alarmList().c_str()); // the machine runs on
        r->s().clearFaults();
        QCOMPARE(r->s().k923Health(), panel::Health{});
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, r->s().inject({Fault::K923, X, 5}));
    }

    void equipment_data() {
        QTest::addColumn<QString>("machine");
        QTest::addColumn<int>("kind");
        QTest::addColumn<QString>("equipment");
        QTest::addColumn<int>("alarm");
        QTest::newRow("lathe spindle drive")
            << "training-lathe" << int(Fault::SpindleDrive) << "spindle" << 8;
        QTest::newRow("lathe spindle overheat")
            << "training-lathe" << int(Fault::SpindleOverheat) << "spindle" << 2;
        QTest::newRow("lathe coolant pump")
            << "training-lathe" << int(Fault::PumpOverload) << "coolant" << 5;
        QTest::newRow("lathe lube pump")
            << "training-lathe" << int(Fault::PumpOverload) << "lube" << 11;
        QTest::newRow("lathe chuck pressure")
            << "training-lathe" << int(Fault::ChuckPressure) << "" << 19;
        QTest::newRow("grinder wheel drive")
            << "grinder-205" << int(Fault::SpindleDrive) << "wheel" << 2;
        QTest::newRow("grinder work drive")
            << "grinder-205" << int(Fault::SpindleDrive) << "work" << 3;
        QTest::newRow("grinder wheel overheat")
            << "grinder-205" << int(Fault::SpindleOverheat) << "wheel" << 8;
        QTest::newRow("grinder hydraulics")
            << "grinder-205" << int(Fault::PumpOverload) << "hydraulics" << 1;
        QTest::newRow("grinder coolant")
            << "grinder-205" << int(Fault::PumpOverload) << "coolant" << 4;
        QTest::newRow("grinder gauge") << "grinder-205" << int(Fault::GaugeFault) << "" << 9;
        QTest::newRow("grinder chuck") << "grinder-205" << int(Fault::ChuckPressure) << "" << 6;
    }
    // Machine equipment faults show the machine's PLC alarm (the texts of the profile).
    void equipment() {
        QFETCH(QString, machine);
        QFETCH(int, kind);
        QFETCH(QString, equipment);
        QFETCH(int, alarm);
        auto r = ready(machine.toStdString());
        QVERIFY(r);
        const FaultSpec f{static_cast<Fault>(kind), X, 0, equipment.toStdString()};
        r->s().inject(f);
        r->advance(4000);
        QVERIFY2(r->plcAlarm(alarm), r->alarmList().c_str());
        const auto& texts = r->c().profile().plcAlarm;
        QVERIFY(texts.count(alarm));
        r->s().clear(f);
        r->advance(5000);
        r->push(Button::Reset);
        QVERIFY2(!r->plcAlarm(alarm), r->alarmList().c_str());
    }

    // The plant looks only where something can change (machine/simulation.h):
    // on a machine at rest (drives on, homed, nothing moving) each fault
    // still acts in the very next tick — on the axis switches, the ready
    // contacts and the positioner's inputs.
    void faultsActInTheNextTick_data() {
        QTest::addColumn<int>("kind");
        QTest::addColumn<int>("axis");
        QTest::addColumn<int>("detail");
        QTest::newRow("limit switch X+") << int(Fault::LimitSwitch) << 0 << 1;
        QTest::newRow("limit switch Z-") << int(Fault::LimitSwitch) << 1 << -1;
        QTest::newRow("drive not ready Z") << int(Fault::DriveNotReady) << 1 << 0;
        QTest::newRow("encoder channel Z 1") << int(Fault::EncoderChannelBreak) << 1 << 1;
        QTest::newRow("encoder channel X 2") << int(Fault::EncoderChannelBreak) << 0 << 2;
        QTest::newRow("dac limit X") << int(Fault::DacLimit) << 0 << 0;
        QTest::newRow("pulse module 2")
            << int(Fault::PositionerModule) << 0 << int(PositionerPart::PulseModule2);
        QTest::newRow("dac module")
            << int(Fault::PositionerModule) << 0 << int(PositionerPart::DacModule);
        QTest::newRow("memory") << int(Fault::PositionerModule) << 0 << int(PositionerPart::Memory);
        QTest::newRow("lost link") << int(Fault::LostLink) << 0 << 0;
    }
    void faultsActInTheNextTick() {
        QFETCH(int, kind);
        QFETCH(int, axis);
        QFETCH(int, detail);
        auto r = ready();
        QVERIFY(r);
        r->advance(500); // at rest
        const AxisId a = axis == 0 ? X : Z;
        const FaultSpec f{static_cast<Fault>(kind), a, detail};
        const machine::Signals& sig = r->s().machineSignals();
        const auto sensor = [&](const std::string& name) { return sig.sensor(*sig.findSensor(name)); };
        const std::string ax = axis == 0 ? "x" : "z";
        const engine::MachineIo& io = r->c().io();
        const auto ch = static_cast<std::size_t>(r->c().c()[axis == 0 ? 17 : 69] - 1); // C17 / C69
        const engine::MachineIo before = io;
        for (int t = 0; t < 2; ++t) { // the inputs stand still at rest
            r->tick();
            QVERIFY(io == before);
        }
        // What the fault shows in the plant's sensors and the positioner's inputs.
        const auto shows = [&]() -> bool {
            switch (f.kind) {
            case Fault::LimitSwitch:
                return sensor(ax + (detail > 0 ? ".limit_plus" : ".limit_minus"));
            case Fault::DriveNotReady:
                return !sensor(ax + ".drive_ready");
            case Fault::EncoderChannelBreak:
                return detail == 1 ? !io.pulse[ch].line1Ok : !io.pulse[ch].line2Ok;
            case Fault::DacLimit: // a burst of counts on the encoder lines
                return io.pulse[ch].count - before.pulse[ch].count > 100;
            case Fault::PositionerModule:
                return detail == int(PositionerPart::PulseModule2) ? !io.pulseModule2Ok
                       : detail == int(PositionerPart::DacModule)  ? !io.dacModuleOk
                                                                   : !io.memoryOk;
            case Fault::LostLink:
                return !io.plcLinkOk;
            default:
                return false;
            }
        };
        QVERIFY(!shows());
        r->s().inject(f);
        r->tick();
        QVERIFY(shows());
        if (f.kind == Fault::DacLimit)
            return; // the loop answers the burst: the axis moves
        // Cleared, it is gone in the next tick too.
        r->s().clear(f);
        r->tick();
        QVERIFY(!shows());
    }

    // The equipment ticks only while it is awake (machine/equipment.h): a
    // fault that changes what a unit's tick computes wakes it, so it acts in
    // the next tick on equipment at rest — the spindle's drive coasts down,
    // the coolant pump's pressure falls from that tick (the pressure switch
    // opens below half of it), not when the PLC turns the motor off.
    void equipmentFaultsActInTheNextTick() {
        // Spindle at speed, coolant at pressure, the program waiting at M0.
        const auto running = [] {
            auto r = ready();
            if (!r)
                return r;
            r->load("%L5\nN1 M3 M8\nN2 M0\nN3 M30\n");
            if (!r->start(5) || !r->untilState(ProgramState::M0, 10000))
                return decltype(r)();
            r->advance(500); // the equipment at rest
            return r;
        };
        {
            auto r = running();
            QVERIFY(r);
            machine::Spindle& sp = *r->s().equipment().spindle("spindle");
            QCOMPARE(sp.rpm(), sp.settings().rpm);
            r->s().inject({Fault::SpindleDrive, X, 0, "spindle"});
            r->tick();
            QVERIFY2(sp.rpm() < sp.settings().rpm, qPrintable(QString::number(sp.rpm())));
        }
        {
            auto r = running();
            QVERIFY(r);
            machine::Pump& pump = *r->s().equipment().pump("coolant");
            QVERIFY(pump.pressure());
            // The level falls by 1/fall_ms a ms from the tick after the overload.
            int expected = 0;
            for (double level = 1.0; level >= 0.5; ++expected)
                level = std::max(0.0, level - 1.0 / pump.settings().fallMs);
            r->s().inject({Fault::PumpOverload, X, 0, "coolant"});
            int ticks = 0;
            while (pump.pressure() && ticks < 10000) {
                r->tick();
                ++ticks;
            }
            QCOMPARE(ticks, expected);
        }
    }

    // A fault is named by a stable id and its arguments (the desktop
    // translates them); the CLI's English is built from the same id.
    void faultIdsAndArguments() {
        using machine::faultText;
        const auto same = [](const machine::FaultText& t, const std::string& id,
                             const std::vector<std::string>& args) {
            return t.id == id && t.args == args;
        };
        QVERIFY(same(faultText({Fault::EncoderChannelBreak, Z, 2}), "encoder_channel_break", {"Z", "2"}));
        QVERIFY(same(faultText({Fault::LimitSwitch, X, -1}), "limit_switch", {"X", "-"}));
        QVERIFY(same(faultText({Fault::PumpOverload, X, 0, "coolant"}), "pump_overload", {"coolant"}));
        QVERIFY(same(faultText({Fault::PlcModuleFailure, X, 3}), "plc_module_failure", {"3"}));
        QVERIFY(same(faultText({Fault::K923, X, 1}), "k923.plc_link", {}));
        QVERIFY(same(faultText({Fault::PositionerModule, X, 3}), "positioner_module.dac_module", {}));
        QVERIFY(same(faultText({Fault::PlcStopped}), "plc_stopped", {}));
        // The CLI says them from core's catalog (machine::faultTexts()), in
        // English or Russian; a shipped machine's equipment by its name.
        QCOMPARE(machine::describeFault({Fault::EncoderChannelBreak, X, 1}),
                 std::string("Encoder X: channel 1 broken"));
        QCOMPARE(machine::describeFault({Fault::LimitSwitch, Z, 1}), std::string("Limit switch Z+ hit"));
        QCOMPARE(machine::describeFault({Fault::SpindleOverheat, X, 0, "spindle"}),
                 std::string("Motor overheat: spindle"));
        QCOMPARE(machine::describeFault({Fault::PumpOverload, X, 0, "coolant"}, true),
                 std::string("Перегрузка двигателя: насос СОЖ"));
        QCOMPARE(machine::describeFault({Fault::PumpOverload, X, 0, "its-own-pump"}),
                 std::string("Motor overload: its-own-pump"));
        QCOMPARE(machine::describeFault({Fault::K923, X, 4}),
                 std::string("K923: resident software corrupt"));
        QCOMPARE(machine::describeFault({Fault::K923, X, 4}, true), std::string("K923: нарушен резидент"));
        // Every fault of both machines: an id of its own, a text without a
        // placeholder left.
        for (const char* name : {"training-lathe", "grinder-205"}) {
            machine::Simulation sim(name);
            std::set<std::string> ids;
            for (const FaultSpec& f : sim.availableFaults()) {
                const machine::FaultText t = faultText(f);
                std::string key = t.id;
                for (const std::string& a : t.args)
                    key += "|" + a;
                QVERIFY2(ids.insert(key).second, key.c_str());
                for (const bool russian : {false, true}) {
                    const std::string text = machine::describeFault(f, russian);
                    QVERIFY2(text.find('%') == std::string::npos && text != t.id, text.c_str());
                    QVERIFY2(machine::faultTexts().find(t.id), t.id.c_str());
                }
            }
        }
    }

    // Every fault the machine offers can be injected and cleared; a fault that
    // does not fit the machine is refused with the reason.
    void availableAndRefused() {
        MachineRig r;
        const auto faults = r.s().availableFaults();
        QVERIFY(faults.size() >= 20);
        for (const FaultSpec& f : faults) {
            r.s().inject(f);
            QVERIFY(r.s().faultActive(f));
            QVERIFY(!machine::describeFault(f).empty());
        }
        r.advance(100);
        r.s().clearFaults();
        QVERIFY(r.s().faults().empty());
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, r.s().inject({Fault::GaugeFault}));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 r.s().inject({Fault::EncoderChannelBreak, X, 3}));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 r.s().inject({Fault::PumpOverload, X, 0, "hydraulics"}));
        try {
            r.s().inject({Fault::SpindleDrive, X, 0, "wheel"});
            QFAIL("no exception");
        } catch (const std::invalid_argument& e) {
            QVERIFY(std::string(e.what()).find("no spindle 'wheel'") != std::string::npos);
        }
    }
};

QTEST_APPLESS_MAIN(TestFaults)
#include "test_faults.moc"
