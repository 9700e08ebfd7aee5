// The speed of `k528 run`: simulated time over wall time at the 1 ms tick, one
// core, for a long two-axis program on the training lathe — the positioner,
// the simulated PLC running the machine description, the plant (both drives,
// spindle, coolant, turret, pumps, switches) — and for the idle machine with
// its drives on; for comparison the engine alone on its ideal test double.
// Targets: ≥ 10,000× real time for the program on the training
// lathe and ≤ 200 ns for everything in one tick; ≥ 20,000× for the idle machine.
//
// The program's figure is the best of REPEATS whole runs (10 in bench/run,
// about 1 s). The build machine is a VM whose core the host shares at times:
// for seconds on end a run then takes about 1.6× as long (a loop of
// independent additions runs at half its usual rate), whatever the code
// does. The fastest of several runs is the code's own speed, and ten runs
// nearly always include one the host left alone (docs/engine.md, "Speed").
//
// bench_engine [REPEATS [IDLE_TICKS]]   (smaller for callgrind: bench_engine 1 200000)
#include "engine/positioner.h"
#include "engine/ideal_machine.h"
#include "engine/run.h"
#include "machine/run.h"
#include "machine/simulation.h"
#include "profile/builtin.h"
#include "program/parser.h"

#include "engine_program.h"
#include "report.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace k528;

int main(int argc, char** argv) {
    const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 10;
    const std::int64_t idleTicks = argc > 2 ? std::max(1000LL, std::atoll(argv[2])) : 2000000;
    bench::Report report;
    const profile::MachineProfile prof = profile::builtin("training-lathe");
    const std::string text = bench::engineProgram(200);
    const program::ParseResult parsed = program::parse(text);

    // Program: the whole `k528 run` path (homing, program, end state).
    double best = 0, simS = 0;
    for (int i = 0; i < repeats; ++i) {
        const double t0 = bench::nowSeconds();
        const engine::RunResult r = machine::runProgram(prof, parsed.store, 1, engine::RunOptions{});
        const double wall = bench::nowSeconds() - t0;
        if (r.status != engine::RunStatus::Completed) {
            std::fprintf(stderr, "bench_engine: the program did not complete (%s)\n",
                         std::string(engine::runStatusName(r.status)).c_str());
            return 1;
        }
        simS = r.timeS + r.homeTimeS;
        const double ratio = simS / wall;
        best = ratio > best ? ratio : best;
    }
    std::printf("# %.1f s of machine time per run (program and reference-point cycles)\n", simS);
    report.figure("engine.program_realtime_ratio", best, "x", 10000, bench::Better::Higher);
    report.figure("engine.program_ns_per_tick", 1e9 / (best * 1000.0), "ns", 200,
                  bench::Better::Lower);

    // Idle: powered, drives on, in РУЧНОЙ, nothing moving.
    {
        machine::Simulation sim(prof);
        machine::SimulationRunMachine m(sim);
        sim.powerOn();
        if (!m.switchOn(10000)) {
            std::fprintf(stderr, "bench_engine: the machine did not switch on\n");
            return 1;
        }
        sim.advance(1000);
        const std::int64_t ticks = idleTicks;
        const double t0 = bench::nowSeconds();
        sim.advance(ticks);
        const double wall = bench::nowSeconds() - t0;
        const double ratio = static_cast<double>(ticks) / 1000.0 / wall;
        report.figure("engine.idle_realtime_ratio", ratio, "x", 20000, bench::Better::Higher);
    }
    // The engine alone on its ideal test double (no target: for comparison).
    {
        double bestIdeal = 0;
        for (int i = 0; i < std::min(repeats, 3); ++i) {
            const double t0 = bench::nowSeconds();
            const engine::RunResult r = engine::runProgram(prof, parsed.store, 1, engine::RunOptions{});
            const double wall = bench::nowSeconds() - t0;
            bestIdeal = std::max(bestIdeal, (r.timeS + r.homeTimeS) / wall);
        }
        std::printf("# the engine on its ideal machine: %.0fx real time\n", bestIdeal);
    }
    return report.exitCode();
}
