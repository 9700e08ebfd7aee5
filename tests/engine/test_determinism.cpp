// Same inputs, same outputs, bit for bit: two runs of the same program give
// identical end states, and identical interface words and R-parameters at
// every tick.
#include "engine/run.h"
#include "engine_rig.h"

#include <QtTest>

#include <algorithm>
#include <vector>

using namespace rig;

namespace {
std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
    h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    return h;
}

std::uint64_t traceHash(const char* text) {
    Rig r;
    std::uint64_t h = 0;
    if (!r.home())
        return 0;
    r.load(text);
    r.start(1);
    for (int i = 0; i < 60000 && r.ctl->state() != ProgramState::Ended; ++i) {
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
        Rig r;
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
