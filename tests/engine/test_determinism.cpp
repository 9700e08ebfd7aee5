// Same inputs, same outputs, bit for bit: two runs of the same program give
// identical end states, and identical interface words and R-parameters at
// every tick.
#include "engine/run.h"
#include "rig/engine_rig.h"

#include <QtTest>

#include <algorithm>
#include <vector>

using namespace k528;
using namespace k528::testrig;

namespace {
std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
    h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    return h;
}

// `fullTicks`: an operator function that changes nothing (the program
// number again) before every tick, so that no tick takes a shortcut (the
// settled tick, the routine tick, program control's): the trace must be the
// same as with them.
std::uint64_t traceHash(const char* text, bool fullTicks = false) {
    EngineRig r;
    std::uint64_t h = 0;
    if (!r.home())
        return 0;
    r.load(text);
    r.start(1);
    for (int i = 0; i < 60000 && r.ctl->state() != ProgramState::Ended; ++i) {
        if (fullTicks && !r.ctl->selectProgram(1).ok())
            return 0;
        r.tick();
        for (int a : {1000, 1001, 1005, 1008, 2000, 2001, 2005, 2006, 2007, 2008})
            h = mix(h, r.w().word(a));
        for (std::int32_t v : r.ctl->r().values())
            h = mix(h, static_cast<std::uint32_t>(v));
        for (int d : r.ctl->io().dac)
            h = mix(h, static_cast<std::uint32_t>(d));
    }
    return h;
}

const char* kProgram =
    "%L1\nN1 G0 X60 Z5 M3\nN2 G281 Z-10 FZ2000\nN3 G1 X40 FX200\nN4 G280\nN5 G4 X0.5\n"
    "N6 R1=R1+1\nN7 G91 G1 X5 Z-3 FX500 FZ800\nN8 M30\n";
// Frames between moves that change what the outputs show besides the axes:
// a zero offset (R234), the wheel below its Dmin (Z2000.15, Z2005.11), an
// exclusion and its end (G53, G54).
const char* kOutputsProgram =
    "%L1\nN1 G0 X60 Z5 M3\nN2 G1 X40 Z-10 FX500 FZ800\nN3 R228=200\nN4 G1 X50 FX500\n"
    "N5 R205=1000\nN6 R207=900\nN7 G1 X45 Z-5 FX500 FZ800\nN8 G53\nN9 G1 X40 FX500\n"
    "N10 G54\nN11 M30\n";
} // namespace

class TestDeterminism : public QObject {
    Q_OBJECT
private slots:
    void everyTick() {
        const std::uint64_t a = traceHash(kProgram);
        const std::uint64_t b = traceHash(kProgram);
        QVERIFY(a != 0);
        QCOMPARE(a, b);
    }
    // The shortcuts of the tick (docs/engine.md, "Speed") change nothing:
    // every tick taken in full gives the same trace.
    void shortcutsChangeNothing() {
        for (const char* program : {kProgram, kOutputsProgram}) {
            const std::uint64_t a = traceHash(program);
            const std::uint64_t b = traceHash(program, true);
            QVERIFY(a != 0);
            QCOMPARE(a, b);
        }
    }
    // Both paths of the routine tick: with the check on (a debug build has
    // it on), every routine tick also reads its inputs in full and computes
    // Z2000, the wheel's bits and the offsets anew; none of it may differ
    // from what the shortcut left, on programs that change the offsets, the
    // wheel and the exclusion between moves.
    void routineTickBothPathsAgree() {
        for (const char* program : {kProgram, kOutputsProgram}) {
            EngineRig r;
            r.ctl->setCheckShortcuts(true);
            QVERIFY(r.home());
            r.load(program);
            r.start(1);
            QVERIFY(r.until([&] { return r.ctl->state() == ProgramState::Ended; }, 60000));
            QVERIFY2(r.ctl->shortcutChecks() > 1000, std::to_string(r.ctl->shortcutChecks()).c_str());
            QCOMPARE(r.ctl->shortcutDisagreements(), std::int64_t(0));
        }
    }
    // Both paths of program control within a full reading: in РУЧНОЙ every
    // tick reads its inputs in full (a hand may move an axis), and while a
    // jog is held and nothing else changes, program control takes its
    // shortcut; with the check on it also reads the edges in full, and the
    // two must leave the same. Then «Сброс» and a mode from the PLC still act
    // in the tick that reads them.
    void programControlBothPathsAgree() {
        EngineRig r;
        r.ctl->setCheckShortcuts(true);
        QVERIFY(r.home());
        QVERIFY(r.ctl->selectMode(Mode::Manual).ok());
        r.tick();
        const std::int64_t checks = r.ctl->shortcutChecks();
        r.m->setJog(engine::AxisId::X, -1);
        r.advance(300);
        r.m->setJog(engine::AxisId::X, 0);
        r.advance(300);
        QVERIFY2(r.ctl->shortcutChecks() - checks > 400, std::to_string(r.ctl->shortcutChecks() - checks).c_str());
        QCOMPARE(r.ctl->shortcutDisagreements(), std::int64_t(0));
        // A word of program control changes while a jog is held: the PLC's
        // mode code acts in the tick that reads it, and stops the jog.
        r.m->setJog(engine::AxisId::X, 1);
        r.advance(50);
        QVERIFY(r.ctl->servo(engine::AxisId::X).moving());
        r.m->setModeCode(static_cast<int>(Mode::Auto));
        r.tick();
        QCOMPARE(r.ctl->mode(), Mode::Auto);
        QVERIFY(r.bit(engine::z::ModeAuto));
        QCOMPARE(r.ctl->shortcutDisagreements(), std::int64_t(0));
    }
    // Both paths of the settled tick: with the check on, every tick that
    // would be a settled one runs in full instead, and must leave what the
    // settled tick would (words, I/O, R-parameters, messages, servos) and
    // find the machine still settled. A key, a changed input word, a
    // message, the machine's I/O (a health flag, an encoder's count) and an
    // R-parameter each end the state and act in the next tick; the machine
    // then settles again, checked again.
    void settledTickBothPathsAgree() {
        EngineRig r;
        r.ctl->setCheckShortcuts(true);
        QVERIFY(r.home());
        // Ticks of the last `ms` that were settled (checked), and whether the
        // tick just taken was (it must not be, after a change).
        const auto settledIn = [&](std::int64_t ms) {
            const std::int64_t before = r.ctl->settledChecks();
            r.advance(ms);
            return r.ctl->settledChecks() - before;
        };
        const auto tickIsFull = [&] {
            const std::int64_t before = r.ctl->settledChecks();
            r.tick();
            return r.ctl->settledChecks() == before;
        };
        QVERIFY2(settledIn(1000) > 900, std::to_string(r.ctl->settledChecks()).c_str());
        QCOMPARE(r.ctl->shortcutDisagreements(), std::int64_t(0));

        // A key: АВТОМАТ.
        QVERIFY(!r.bit(engine::z::ModeAuto));
        QVERIFY(r.ctl->selectMode(Mode::Auto).ok());
        QVERIFY(tickIsFull());
        QVERIFY(r.bit(engine::z::ModeAuto));
        QVERIFY(settledIn(500) > 400);

        // An input word: the PLC's override switch (R249 shows its percent).
        int code = 0;
        while (code <= 10 && units::overrideCodeToPercent(code) == r.ctl->r(engine::r::Override))
            ++code;
        QVERIFY(code <= 10);
        r.m->setOverrideCode(code);
        QVERIFY(tickIsFull());
        QCOMPARE(r.ctl->r(engine::r::Override), units::overrideCodeToPercent(code));
        QVERIFY(settledIn(500) > 400);

        // A message: a system message of the PLC (55) comes and goes.
        QVERIFY(!r.hasAlarm(55));
        r.m->setPlcSystem(1, true);
        QVERIFY(tickIsFull());
        QVERIFY(r.hasAlarm(55));
        QVERIFY(settledIn(500) > 400);
        r.m->setPlcSystem(1, false);
        QVERIFY(tickIsFull());
        QVERIFY(settledIn(500) > 400);

        // A health flag of the machine I/O: message 30 (memory test).
        QVERIFY(!r.hasAlarm(30));
        r.ctl->io().memoryOk = false;
        QVERIFY(tickIsFull());
        QVERIFY(r.hasAlarm(30));
        r.ctl->io().memoryOk = true;
        QVERIFY(tickIsFull());
        QVERIFY(settledIn(500) > 400);

        // An encoder's count: the slide of X pushed by 2 µm at rest (within ДОПУСК КП).
        const double actual = r.ctl->servo(engine::AxisId::X).actual();
        r.m->mechanics(engine::AxisId::X)->pushSlide(0.002);
        QVERIFY(tickIsFull());
        QVERIFY(r.ctl->servo(engine::AxisId::X).actual() != actual);
        QVERIFY(settledIn(1000) > 500);

        // An R-parameter set by the operator.
        QVERIFY(r.ctl->setR(1, 4711).ok());
        QVERIFY(tickIsFull());
        QCOMPARE(r.ctl->r(1), 4711);
        QVERIFY(settledIn(500) > 400);
        QCOMPARE(r.ctl->r(1), 4711);

        QVERIFY2(r.ctl->settledChecks() > 3000, std::to_string(r.ctl->settledChecks()).c_str());
        QCOMPARE(r.ctl->shortcutDisagreements(), std::int64_t(0));
    }
    // The routine tick: while a program moves the axes and nothing else
    // changes, a changed word or an operator function acts in the next tick.
    void routineTick() {
        EngineRig r;
        QVERIFY(r.home());
        r.load("%L1\nN1 G0 X60 Z5\nN2 G1 X20 Z-60 FX100 FZ100\nN3 M30\n");
        r.start(1);
        r.advance(3000);
        QVERIFY2(r.ctl->state() == ProgramState::Running,
                 r.ctl->alarms().empty() ? "not running"
                                         : std::to_string(r.ctl->alarms().front().number).c_str());
        // An L key of another override: R249 shows it in the next tick.
        int key = 0, percent = 100;
        for (int l = 1; l <= 4 && key == 0; ++l) {
            const int code = static_cast<int>(r.ctl->c()[engine::c::overrideKey(l)]);
            if (units::overrideCodeToPercent(code) != 100) {
                key = l;
                percent = units::overrideCodeToPercent(code);
            }
        }
        QVERIFY(key != 0);
        r.tick();
        QCOMPARE(r.ctl->r(engine::r::Override), 100);
        QVERIFY(r.ctl->pressOverrideKey(key).ok());
        r.tick();
        QCOMPARE(r.ctl->r(engine::r::Override), percent);
        r.advance(200);
        // «Стоп» from the PLC: interrupted in the tick that reads the edge.
        r.m->pressStop();
        r.tick();
        QCOMPARE(r.ctl->state(), ProgramState::Interrupted);
        // «Пуск» again, then the emergency stop word: message 9 at once.
        r.advance(500);
        r.m->pressStart();
        r.tick();
        QCOMPARE(r.ctl->state(), ProgramState::Running);
        r.advance(200);
        r.m->setEmergencyStop(true);
        r.tick();
        QVERIFY(r.ctl->alarmRegistry().active(9));
    }
    void endState() {
        const profile::MachineProfile p = profile::builtin("training-lathe");
        const program::ParseResult parsed = program::parse(kProgram);
        const auto r1 = engine::runProgram(p, parsed.store, 1, {});
        const auto r2 = engine::runProgram(p, parsed.store, 1, {});
        QCOMPARE(r1.status, engine::RunStatus::Completed);
        QCOMPARE(r1.timeS, r2.timeS);
        QCOMPARE(r1.homeTimeS, r2.homeTimeS);
        QCOMPARE(r1.frames, r2.frames);
        QCOMPARE(r1.r, r2.r);
        QCOMPARE(r1.axes[0].currentDisc, r2.axes[0].currentDisc);
        QCOMPARE(r1.axes[1].machineDisc, r2.axes[1].machineDisc);
        QCOMPARE(r1.mFunctions, r2.mFunctions);
        QCOMPARE(r1.r[1], 1);
    }
    // The settled tick (docs/engine.md, "Speed"): a machine at rest for a
    // while advances its clock and nothing else; an operator function or a
    // changed word ends the shortcut at once, and what a full tick computes
    // then equals what the settled ticks left.
    void settledTick() {
        EngineRig r;
        QVERIFY(r.home());
        QVERIFY(r.ctl->selectProgram(1).ok());
        r.advance(2000); // at rest: the shortcut is on
        const std::int64_t t0 = r.ctl->timeMs();
        const engine::InterfaceWords words = r.w();
        const std::vector<std::int32_t> rs(r.ctl->r().values().begin(), r.ctl->r().values().end());
        r.advance(1000);
        QCOMPARE(r.ctl->timeMs(), t0 + 1000);
        QVERIFY(r.w() == words);
        // A full tick (an operator function that changes nothing wakes it)
        // computes the same words and R-parameters.
        QVERIFY(r.ctl->selectProgram(1).ok());
        r.tick();
        QVERIFY(r.w() == words);
        QVERIFY(std::equal(rs.begin(), rs.end(), r.ctl->r().values().begin()));
        // An operator function between settled ticks acts in the next tick.
        r.advance(1000);
        QVERIFY(!r.bit(engine::z::ModeAuto));
        QVERIFY(r.ctl->selectMode(Mode::Auto).ok());
        r.tick();
        QVERIFY(r.bit(engine::z::ModeAuto));
        // So does a word the PLC changes: jog + (Z1005.7) moves the setpoint
        // in the tick that reads it.
        QVERIFY(r.ctl->selectMode(Mode::Manual).ok());
        r.advance(1000);
        const double before = r.ctl->servo(engine::AxisId::X).setpoint();
        r.m->setJog(engine::AxisId::X, 1);
        r.tick();
        QVERIFY(r.bit(engine::z::jogPlus(engine::AxisId::X)));
        QVERIFY(r.ctl->servo(engine::AxisId::X).setpoint() > before);
    }
};

QTEST_APPLESS_MAIN(TestDeterminism)
#include "test_determinism.moc"
