// The whole trace of a run on the training lathe, tick by tick, against a
// golden file captured before the tick was made lean (docs/engine.md, "Speed"):
// every interface word, every R-parameter, the DAC codes, the regulator
// enables, the encoder counts and both slides' positions (bit patterns of
// the doubles) go into one digest per phase, and the end state is written
// out in full. A change of the engine, the PLC or the plant that changes any
// output at any tick fails here. K528_UPDATE_GOLDEN=1 rewrites the file
// (only for an intended change of behaviour; say why in the commit).
#include "engine/run.h"
#include "machine/run.h"
#include "machine/simulation.h"
#include "profile/builtin.h"
#include "program/parser.h"
#include "rig/machine_rig.h"

#include <QtTest>

#include <bit>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

using namespace k528;

namespace {

// The engine benchmark's program (bench/engine_bench.cpp), shortened: moves of
// both axes at cutting feeds and rapids, computations and a loop.
const char* kProgram = R"(%L1 (trace)
N1 G90 G54 G0 M61 M3 M8 X80 Z2
N2 R1=12
N3 G1 X60 FX3000 Z-90 FZ2500
N4 G1 X40 FX1500 Z-20 FZ3000
N5 G0 X80 Z2
N6 R2=R2+1
N7 R1=R1-1
N8 IF R1>0 GOTO 3
N9 M5 M9
N10 M30
)";

struct Digest {
    std::uint64_t h = 1469598103934665603ULL; // FNV-1a
    std::int64_t ticks = 0;
    void add(std::uint64_t v) {
        for (int i = 0; i < 8; ++i) {
            h ^= (v >> (8 * i)) & 0xFF;
            h *= 1099511628211ULL;
        }
    }
    void addDouble(double d) { add(std::bit_cast<std::uint64_t>(d)); }

    void sample(machine::Simulation& sim) {
        ++ticks;
        const engine::Positioner& c = sim.controller();
        for (int a = 1000; a <= 1013; ++a)
            add(c.words().word(a));
        for (int a = 2000; a <= 2008; ++a)
            add(c.words().word(a));
        for (std::int32_t v : c.rValues())
            add(static_cast<std::uint32_t>(v));
        for (int d : c.io().dac)
            add(static_cast<std::uint32_t>(d));
        for (bool e : c.io().regulatorEnable)
            add(e ? 1 : 0);
        for (const engine::PulseChannel& p : c.io().pulse)
            add(static_cast<std::uint64_t>(p.count));
        for (engine::AxisId a : {engine::AxisId::X, engine::AxisId::Z}) {
            addDouble(sim.slideMm(a));
            addDouble(c.servo(a).actual());
            addDouble(c.servo(a).setpoint());
        }
        add(static_cast<std::uint64_t>(c.alarms().size()));
    }
};

std::string hex(std::uint64_t v) {
    std::ostringstream s;
    s << std::hex << v;
    return s.str();
}

// The run's trace digests and its end state, one fact a line.
std::string traceText(const char* profileName, const std::string& programText) {
    const profile::MachineProfile prof = profile::builtin(profileName);
    const program::ParseResult parsed = program::parse(programText);
    std::ostringstream out;

    machine::Simulation sim(prof);
    Digest run;
    testrig::WatchedSimulationRun m(sim, [&] { run.sample(sim); }); // the whole machine after every tick
    const engine::RunResult r = engine::runProgram(m, parsed.store, 1, engine::RunOptions{});
    out << "run.status " << engine::runStatusName(r.status) << "\n";
    out << "run.ticks " << run.ticks << "\n";
    out << "run.trace " << hex(run.h) << "\n";
    out << "run.timeMs " << std::llround(r.timeS * 1000) << "\n";
    out << "run.homeTimeMs " << std::llround(r.homeTimeS * 1000) << "\n";
    out << "run.frames " << r.frames << "\n";
    for (int a = 0; a < 2; ++a)
        out << "run.axis" << a << " " << r.axes[static_cast<std::size_t>(a)].machineDisc << " "
            << r.axes[static_cast<std::size_t>(a)].currentDisc << "\n";
    for (int n = 0; n < 300; ++n)
        if (r.r[static_cast<std::size_t>(n)] != 0)
            out << "run.R" << n << " " << r.r[static_cast<std::size_t>(n)] << "\n";
    out << "run.m";
    for (int mcode : r.mFunctions)
        out << " " << mcode;
    out << "\n";
    for (const engine::AlarmView& a : r.alarms)
        out << "run.alarm " << a.number << "\n";

    // Idle afterwards: drives on, nothing moving, 20 s.
    Digest idle;
    for (int i = 0; i < 20000; ++i) {
        sim.tick();
        idle.sample(sim);
    }
    out << "idle.trace " << hex(idle.h) << "\n";
    for (engine::AxisId a : {engine::AxisId::X, engine::AxisId::Z})
        out << "idle.slide" << engine::axisIndex(a) << " " << hex(std::bit_cast<std::uint64_t>(sim.slideMm(a)))
            << "\n";
    return out.str();
}

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace

class TestTraceGolden : public QObject {
    Q_OBJECT
private slots:
    void trace_data() {
        QTest::addColumn<QString>("profileName");
        QTest::addColumn<QString>("program");
        QTest::addColumn<QString>("golden");
        QTest::newRow("training-lathe") << "training-lathe" << QString::fromUtf8(kProgram)
                                        << "training_lathe_trace.txt";
        QTest::newRow("grinder-205")
            << "grinder-205"
            << QString::fromStdString(readFile(K528_SOURCE_DIR "/resources/samples/grinder-bore-205.k528"))
            << "grinder_205_trace.txt";
    }
    void trace() {
        QFETCH(QString, profileName);
        QFETCH(QString, program);
        QFETCH(QString, golden);
        QVERIFY(!program.isEmpty());
        const std::string got = traceText(profileName.toStdString().c_str(), program.toStdString());
        QVERIFY(got.find("run.status completed") != std::string::npos);
        const std::string path = K528_SOURCE_DIR "/tests/machine/golden/" + golden.toStdString();
        if (qgetenv("K528_UPDATE_GOLDEN") == "1") { // =0 updates nothing, as in golden.py
            std::ofstream(path, std::ios::binary) << got;
            QSKIP("golden file rewritten");
        }
        const std::string want = readFile(path);
        QVERIFY2(!want.empty(), path.c_str());
        QCOMPARE(QString::fromStdString(got), QString::fromStdString(want));
    }
};

QTEST_APPLESS_MAIN(TestTraceGolden)
#include "test_trace_golden.moc"
