// The machine's signals on the simulated machine: contact bounce and the
// PLC's debounce (GOST 26642 6.1.7), the M strobe timing of GOST 26642 §6.4
// between the positioner and the PLC, encoder zero marks once per motor
// revolution, switch placement, the GOST mandatory signals, determinism,
// and `k528 run` on the simulated machines.
#include "engine/interface_words.h"
#include "machine/run.h"
#include "rig/machine_rig.h"
#include "plc/description.h"
#include "resources/embedded.h"

#include <set>

using namespace k528;
using namespace k528::testrig;
namespace z = engine::z;

class TestSignals : public QObject {
    Q_OBJECT
private slots:
    // A push-button bounces for 3 ms; the PLC passes it on once it has
    // stood for its debounce time (8 ms), exactly once.
    void debounceOfTheBouncingButton() {
        MachineRig r;
        QVERIFY(r.drivesOn());
        r.c().selectMode(Mode::Manual);
        r.advance(20);
        const auto pos = r.s().machineSignals().findSensor("pendant.jog_z_minus");
        QVERIFY(pos);
        r.s().press(Button::JogZMinus);
        std::vector<int> contact, plcBit;
        for (int t = 0; t < 14; ++t) {
            r.tick();
            contact.push_back(r.s().machineSignals().sensor(*pos));
            plcBit.push_back(r.bit(z::jogMinus(Z)));
        }
        // The contact: 1 0 1 (3 ms of bounce), then 1.
        QCOMPARE(std::vector<int>(contact.begin(), contact.begin() + 5),
                 (std::vector<int>{1, 0, 1, 1, 1}));
        // The PLC's bit rose once, 8..10 ms after the press, and stayed.
        int rises = 0, first = -1;
        for (std::size_t i = 0; i < plcBit.size(); ++i)
            if (plcBit[i] && (i == 0 || !plcBit[i - 1])) {
                ++rises;
                first = static_cast<int>(i);
            }
        QCOMPARE(rises, 1);
        QVERIFY2(first >= 8 && first <= 10, qPrintable(QString::number(first)));
        QVERIFY(plcBit.back());
        r.s().release(Button::JogZMinus);
        r.advance(20);
        QVERIFY(!r.bit(z::jogMinus(Z)));
    }

    // A tap shorter than the debounce time does nothing.
    void shortGlitchIgnored() {
        MachineRig r;
        QVERIFY(r.drivesOn());
        r.c().selectMode(Mode::Manual);
        r.advance(20);
        r.s().pressFor(Button::JogZMinus, 4);
        for (int t = 0; t < 30; ++t) {
            r.tick();
            QVERIFY(!r.bit(z::jogMinus(Z)));
        }
    }

    // GOST 26642 §6.4 between the positioner and the PLC: the code stands
    // ≥ T2 before the strobe, the PLC acknowledges ≥ T3 after the strobe
    // and drops the acknowledgement when the strobe drops; the next code
    // comes after that.
    void mStrobeTiming() {
        MachineRig r;
        QVERIFY(r.drivesOn());
        QVERIFY(r.home());
        r.load("%L5\nN1 M9 M0\nN2 M8 M9\nN3 M30\n");
        QVERIFY(r.start(5));
        QVERIFY(r.untilState(ProgramState::M0, 2000));
        r.sim->pressFor(Button::CycleStart, 100);
        QVERIFY(r.runToEnd(10000));
        QCOMPARE(r.c().state(), ProgramState::Ended);
        const auto& log = r.s().plc().mLog();
        QCOMPARE(r.s().mCodes(), (std::vector<int>{9, 0, 8, 9, 30}));
        const plc::PlcTiming& t = r.s().description().timing;
        for (std::size_t i = 0; i < log.size(); ++i) {
            const plc::MEvent& e = log[i];
            QVERIFY(e.described);
            QVERIFY2(e.strobeMs - e.codeMs >= t.t2Ms,
                     qPrintable(QString("M%1 T2 %2").arg(e.code).arg(e.strobeMs - e.codeMs)));
            QVERIFY2(e.ackMs - e.strobeMs >= t.t3Ms,
                     qPrintable(QString("M%1 T3 %2").arg(e.code).arg(e.ackMs - e.strobeMs)));
            QVERIFY(e.dropMs > e.ackMs);
            if (i > 0)
                QVERIFY(e.codeMs >= log[i - 1].dropMs);
        }
        // M8 waited for the coolant pressure (400 ms to 80 %).
        QVERIFY(log[2].ackMs - log[2].strobeMs >= 300);
    }

    // The encoder's zero mark: once per motor revolution, at the same count
    // modulo a revolution.
    void zeroMarksOncePerRevolution() {
        MachineRig r;
        QVERIFY(r.drivesOn());
        r.c().selectMode(Mode::Manual);
        r.advance(20);
        r.s().press(Button::JogZMinus);
        std::vector<std::int64_t> marks;
        const int ch = static_cast<int>(r.c().c()[69]) - 1;
        for (int t = 0; t < 3000; ++t) {
            r.tick();
            const engine::PulseChannel& p = r.c().io().pulse[static_cast<std::size_t>(ch)];
            if (p.zeroMark)
                marks.push_back(p.zeroMarkCount);
        }
        r.s().release(Button::JogZMinus);
        // 2000 mm/min for 3 s: 100 mm of slide, 5 mm per motor revolution.
        QVERIFY2(marks.size() >= 18 && marks.size() <= 21,
                 qPrintable(QString::number(marks.size())));
        const std::int64_t perRev = 2000 * 4;
        for (std::size_t i = 1; i < marks.size(); ++i)
            QCOMPARE(marks[i - 1] - marks[i], perRev);
    }

    // The limit switches lie beyond the soft limits: a jog stops at the
    // soft limit (12/28) before the switch.
    void limitSwitchesBeyondSoftLimits() {
        MachineRig r;
        const engine::AxisPlacement& p = r.s().placement(Z);
        const double softPlus = 295.0, softMinus = -115.0;
        QVERIFY(p.limitPlusMm > softPlus && p.limitMinusMm < softMinus);
        QVERIFY(p.camLoMm < p.camHiMm && p.camHiMm < p.limitPlusMm);
        QVERIFY(r.drivesOn());
        QVERIFY(r.home());
        r.c().selectMode(Mode::Manual);
        r.s().press(Button::JogZPlus);
        r.s().press(Button::Rapid);
        r.advance(5000);
        r.s().release(Button::JogZPlus);
        r.s().release(Button::Rapid);
        r.advance(200);
        QVERIFY(r.hasAlarm(28));
        QVERIFY(!r.hasAlarm(27));
        QVERIFY(std::fabs(r.mm(Z) - softPlus) < 0.02);
        QVERIFY(!r.s().view().axes[1].limitPlus);
    }

    // The cam and the limit switches read what the slide's position says in
    // every tick (the plant looks at them only when the slide leaves the
    // stretch between two switch points): a jog over the cam to the limit
    // switch and back.
    void switchesFollowTheSlide() {
        MachineRig r;
        QVERIFY(r.drivesOn());
        r.c().selectMode(Mode::Manual);
        r.advance(20);
        const machine::Signals& sig = r.s().machineSignals();
        const engine::AxisPlacement& p = r.s().placement(Z);
        const int cam = *sig.findSensor("z.cam"), plus = *sig.findSensor("z.limit_plus"),
                  minus = *sig.findSensor("z.limit_minus");
        int camChanges = 0, plusTicks = 0;
        bool camBefore = sig.sensor(cam);
        const auto jog = [&](Button b, int ms) {
            r.s().press(b);
            r.s().press(Button::Rapid);
            for (int t = 0; t < ms; ++t) {
                const double s = r.s().slideMm(Z); // the sensors are read at a tick's start
                r.tick();
                QCOMPARE(sig.sensor(cam), s >= p.camLoMm && s <= p.camHiMm);
                QCOMPARE(sig.sensor(plus), s >= p.limitPlusMm);
                QCOMPARE(sig.sensor(minus), s <= p.limitMinusMm);
                camChanges += sig.sensor(cam) != camBefore;
                camBefore = sig.sensor(cam);
                plusTicks += sig.sensor(plus);
            }
            r.s().release(b);
            r.s().release(Button::Rapid);
            r.advance(300);
        };
        jog(Button::JogZPlus, 12000);
        QVERIFY2(plusTicks > 0, qPrintable(QString("%1 %2 %3 %4 %5").arg(r.s().slideMm(Z)).arg(p.camLoMm).arg(p.camHiMm).arg(p.limitPlusMm).arg(p.limitMinusMm)));
        jog(Button::JogZMinus, 12000);
        QVERIFY2(camChanges >= 4, qPrintable(QString::number(camChanges)));
    }

    // The drives' contactor closes with the PLC's output in the next tick
    // (drives.on), their ready contacts drivesReadyDelayMs later, to the
    // tick — the plant looks at the drives while the delay runs — and they
    // open with the contactor.
    void driveReadyAfterItsDelay() {
        MachineRig r;
        const machine::Signals& sig = r.s().machineSignals();
        const int on = *sig.findSensor("drives.on"), readyX = *sig.findSensor("x.drive_ready"),
                  readyZ = *sig.findSensor("z.drive_ready");
        r.s().pressFor(Button::DrivesOn, 100);
        std::int64_t closedAt = -1, readyAt = -1;
        for (int t = 0; t < 2000 && readyAt < 0; ++t) {
            const bool power = r.s().view().drivesPower; // the actuator after this tick's scan
            r.tick();
            if (closedAt < 0 && sig.sensor(on)) {
                QVERIFY(power); // the tick after the PLC switched it
                closedAt = r.s().timeMs();
            }
            QCOMPARE(sig.sensor(readyX), sig.sensor(readyZ));
            if (sig.sensor(readyX))
                readyAt = r.s().timeMs();
        }
        QVERIFY(closedAt >= 0 && readyAt >= 0);
        QCOMPARE(readyAt - closedAt,
                 static_cast<std::int64_t>(r.s().equipment().drivesReadyDelayMs));
        r.s().inject({Fault::EmergencyStop});
        QVERIFY(r.until([&] { return !r.s().view().drivesPower; }, 1000));
        r.tick();
        QVERIFY(!sig.sensor(on));
        QVERIFY(!sig.sensor(readyX));
    }

    // The handwheel's counts reach the positioner's pulse channel in the
    // tick after a turn, on a machine at rest.
    void handwheelCountsInTheNextTick() {
        MachineRig r;
        QVERIFY(r.drivesOn());
        r.advance(500);
        const int ch = static_cast<int>(r.c().c()[105]) - 1; // C105: handwheel 1
        const std::int64_t before = r.c().io().pulse[static_cast<std::size_t>(ch)].count;
        r.s().selectHandwheel(machine::HandwheelAxis::X); // wheel 1
        r.s().turnHandwheel(7);
        r.tick();
        QCOMPARE(r.c().io().pulse[static_cast<std::size_t>(ch)].count, before + 7);
        r.s().turnHandwheel(-3);
        r.tick();
        QCOMPARE(r.c().io().pulse[static_cast<std::size_t>(ch)].count, before + 4);
    }

    // GOST 26642 appendix 1, 2.2: when «готовность УЧПУ» drops the machine
    // stops: a system message (module failure) makes Z2000.0 = 0, the PLC
    // takes the drives off.
    void readyDropStopsTheMachine() {
        MachineRig r;
        QVERIFY(r.drivesOn());
        r.s().inject({Fault::PlcModuleFailure, X, 3}); // the lamps' module: nothing else
        r.advance(20);
        QVERIFY(!r.bit(z::Ready));
        QVERIFY(r.plcAlarm(14));
        QVERIFY(r.until([&] { return !r.s().view().drivesPower; }, 2000));
    }

    // Same inputs, same machine: two runs give the same trace, bit for bit.
    void deterministic() {
        const auto trace = [] {
            MachineRig r;
            std::uint64_t h = 1469598103934665603ull;
            const auto mix = [&](std::uint64_t v) { h = (h ^ v) * 1099511628211ull; };
            r.drivesOn();
            r.home();
            r.start(1);
            for (int t = 0; t < 20000; ++t) {
                r.tick();
                for (int w = 1000; w <= 1013; ++w)
                    mix(r.w().word(w));
                for (int w = 2000; w <= 2008; ++w)
                    mix(r.w().word(w));
                mix(static_cast<std::uint64_t>(r.c().io().dac[0] + 5000));
                mix(static_cast<std::uint64_t>(r.s().view().spindles[0].rpm * 1000));
            }
            return h;
        };
        QCOMPARE(trace(), trace());
    }

    // `k528 run` on the simulated machines: the samples complete; the
    // override is set at the machine's selector.
    void runOnTheSimulatedMachines() {
        const profile::MachineProfile lathe = profile::builtin("training-lathe");
        const auto parse = [](std::string_view name) {
            const auto text = resources::find("samples/" + std::string(name));
            return program::parse(std::string(*text));
        };
        const auto shaft = parse("lathe-shaft.k528");
        const engine::RunResult a = machine::runProgram(lathe, shaft.store, 1, {});
        QCOMPARE(a.status, engine::RunStatus::Completed);
        QVERIFY(a.alarms.empty());
        QCOMPARE(a.mFunctions.front(), 3);
        engine::RunOptions slow;
        slow.overridePercent = 50;
        const engine::RunResult b = machine::runProgram(lathe, shaft.store, 1, slow);
        QCOMPARE(b.status, engine::RunStatus::Completed);
        QVERIFY(b.timeS > a.timeS * 1.5);
        const engine::RunResult c = machine::runProgram(lathe, shaft.store, 1, {});
        QCOMPARE(c.timeS, a.timeS);
        QCOMPARE(c.r, a.r);

        const profile::MachineProfile grinder = profile::builtin("grinder-205");
        const auto bore = parse("grinder-bore-205.k528");
        const engine::RunResult g = machine::runProgram(grinder, bore.store, 5, {});
        QCOMPARE(g.status, engine::RunStatus::Completed);
        QCOMPARE(g.r[20], 1);           // one ring
        QCOMPARE(g.r[207], 18500 - 20); // dressed once
        QCOMPARE(g.r[224], 20);         // compensated by the PLC (M60)
        QVERIFY(g.r[242] != 0);         // the last gauge signal's lag
        QVERIFY(std::find(g.mFunctions.begin(), g.mFunctions.end(), 60) != g.mFunctions.end());
    }

    // A run that never starts says why: the wheel below R205 Dmin ends with
    // message 44 (as above R206 Dmax with 43), never a silent timeout; a
    // «Пуск» the PLC holds back ends "blocked" with the PLC's message and the
    // missing Z1000.2.
    void aRunThatDoesNotStartSaysWhy() {
        const auto text = resources::find("samples/grinder-bore-205.k528");
        const auto bore = program::parse(std::string(*text));
        const profile::MachineProfile grinder = profile::builtin("grinder-205");
        engine::RunOptions small;
        small.rPresets[207] = 13000;
        const engine::RunResult a = machine::runProgram(grinder, bore.store, 5, small);
        QCOMPARE(a.status, engine::RunStatus::Alarm);
        QCOMPARE(a.frames, std::int64_t(0));
        QVERIFY(!a.alarms.empty());
        QCOMPARE(a.alarms.front().number, 44);
        QCOMPARE(a.alarms.front().textRu, std::string("D круга < Dmin"));
        engine::RunOptions large;
        large.rPresets[207] = 21000;
        const engine::RunResult b = machine::runProgram(grinder, bore.store, 5, large);
        QCOMPARE(b.status, engine::RunStatus::Alarm);
        QCOMPARE(b.alarms.front().number, 43);

        // The wheel guard open: the PLC withholds «Деблокировка пуска» (A07).
        machine::Simulation sim(grinder);
        QVERIFY(sim.openDoor());
        machine::SimulationRunMachine m(sim);
        engine::RunOptions noHome;
        noHome.home = false;
        const engine::RunResult c = engine::runProgram(m, bore.store, 5, noHome);
        QCOMPARE(c.status, engine::RunStatus::Blocked);
        QCOMPARE(engine::runStatusName(c.status), std::string_view("blocked"));
        QVERIFY(c.alarms.empty());
        QVERIFY(c.timeS < 5);
        std::vector<std::string> why;
        for (const engine::RunBlocker& w : c.blockedBy)
            why.push_back(w.source + " " + engine::describeBlocker(w, true));
        const auto has = [&](const std::string& line) {
            return std::find(why.begin(), why.end(), line) != why.end();
        };
        QVERIFY2(has("start_enable Z1000.2 «Деблокировка пуска программы» = 0"), why.front().c_str());
        const std::string guard = grinder.plcTexts(catalog::PlcGroup::Alarm).at(7);
        QVERIFY2(has("plc_alarm A07 " + guard), why.front().c_str());
        QCOMPARE(c.blockedBy.back().source, std::string("start"));
    }

    // A profile with another name runs on the generic machine, or on the
    // description its simulation key names.
    void descriptionLookup() {
        profile::MachineProfile p = profile::builtin("training-lathe");
        p.name = "my-lathe";
        // The shipped profile names its description, so a copy keeps it.
        QCOMPARE(machine::Simulation::descriptionFor(p).name, std::string("training-lathe"));
        p.simulation.erase("machine");
        QCOMPARE(machine::Simulation::descriptionFor(p).name, std::string("generic"));
        machine::Simulation generic(p);
        QVERIFY(!generic.hasDoor());
        QVERIFY(generic.warnings().empty());
        p.simulation.set("machine", "training-lathe");
        QCOMPARE(machine::Simulation::descriptionFor(p).name, std::string("training-lathe"));
        p.simulation.set("machine", "no-such-machine");
        QVERIFY_THROWS_EXCEPTION(plc::DescriptionError, machine::Simulation::descriptionFor(p));
        // The generic machine runs programs too (every M acknowledged).
        p.simulation.erase("machine");
        const auto parsed = program::parse("%L1\nN1 G0 M3 X100 Z100\nN2 M30\n");
        const engine::RunResult r = machine::runProgram(p, parsed.store, 1, {});
        QCOMPARE(r.status, engine::RunStatus::Completed);
        QCOMPARE(r.mFunctions, (std::vector<int>{3, 30}));
    }

    // The shipped machines build without warnings: every message they raise
    // has its text in the profile.
    void shippedMachinesAreComplete() {
        for (const char* name : {"training-lathe", "grinder-205"}) {
            machine::Simulation s(name);
            for (const std::string& w : s.warnings())
                qWarning("%s", w.c_str());
            QVERIFY(s.warnings().empty());
            QCOMPARE(s.description().name, std::string(name));
        }
        const profile::MachineProfile lathe = profile::builtin("training-lathe");
        QCOMPARE(lathe.plcAlarm.size(), std::size_t(32));
        QCOMPARE(lathe.plcWork.size(), std::size_t(32));
        // Every alarm and work message of the lathe has a source in its description.
        machine::Simulation s("training-lathe");
        std::set<int> a, w;
        const plc::MachineDescription& d = s.description();
        for (const auto& m : d.alarms)
            a.insert(m.k);
        for (const auto& m : d.work)
            w.insert(m.k);
        for (const auto& il : d.interlocks) {
            if (il.alarm)
                a.insert(il.alarm);
            if (il.work)
                w.insert(il.work);
        }
        for (const auto& f : d.mFunctions) {
            if (f.timeoutAlarm)
                a.insert(f.timeoutAlarm);
            if (f.waitWork)
                w.insert(f.waitWork);
        }
        a.insert(d.unknownM.alarm);
        QCOMPARE(a.size(), std::size_t(32));
        QCOMPARE(w.size(), std::size_t(32));
    }
};

QTEST_APPLESS_MAIN(TestSignals)
#include "test_signals.moc"
