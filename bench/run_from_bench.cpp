// Start from a frame (docs/engine.md, "Start from a frame"): from «Пуск» of
// `k528 run --from 900` on a 999-frame program to the first motion of the
// axes — the preview run up to frame N900 that rebuilds the state, the
// start with it on the simulated training lathe (homed before the clock
// starts, as the machine stands when an operator resumes a job), the M
// functions handed again, until the first axis moves. Target ≤ 50 ms.
// The best of `runs` (argument 1, default 5): the build machine is shared.
#include "engine/positioner.h"
#include "engine/load_programs.h"
#include "engine/preview_run.h"
#include "engine/run.h"
#include "machine/run.h"
#include "machine/simulation.h"
#include "profile/builtin.h"
#include "program/parser.h"

#include "report.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace k528;

namespace {

// 999 frames: the approach, then moves at feeds and rapids with
// computations between them, as a long turning program is.
std::string program999() {
    std::string t = "%L1 (start from a frame: 999 frames)\nN1 G90 G54 G0 M3 M8 X80 Z2\n";
    for (int n = 2; n <= 998; ++n) {
        const int k = n % 4;
        const std::string x = std::to_string(40 + (n * 7) % 40);
        const std::string z = std::to_string(-((n * 13) % 90));
        if (k == 0)
            t += "N" + std::to_string(n) + " R" + std::to_string(n % 100) + "=R" +
                 std::to_string((n + 1) % 100) + "+" + std::to_string(n) + "\n";
        else if (k == 1)
            t += "N" + std::to_string(n) + " G1 X" + x + " FX1500 Z" + z + " FZ2000\n";
        else if (k == 2)
            t += "N" + std::to_string(n) + " G1 Z" + z + " FZ2500\n";
        else
            t += "N" + std::to_string(n) + " G0 X" + x + " Z2\n";
    }
    t += "N999 M5 M9 M30\n";
    return t;
}

} // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
    const profile::MachineProfile prof = profile::builtin("training-lathe");
    const program::ParseResult parsed = program::parse(program999());
    if (parsed.hasErrors() || !parsed.store.find(1) || parsed.store.find(1)->frames.size() != 999) {
        std::fprintf(stderr, "the benchmark's program does not parse to 999 frames\n");
        return 2;
    }
    const int index = parsed.store.find(1)->indexOfN(900);
    double best = 1e9, bestPreview = 1e9;
    for (int i = 0; i < runs; ++i) {
        machine::Simulation sim(prof);
        machine::SimulationRunMachine run(sim);
        engine::Positioner& ctl = sim.controller();
        ctl.powerOn();
        engine::loadPrograms(ctl, parsed.store);
        if (!run.switchOn(10000) || engine::homeAxes(run).status != engine::RunStatus::Completed) {
            std::fprintf(stderr, "the lathe did not get ready\n");
            return 2;
        }
        const double t0 = bench::nowSeconds();
        engine::PreviewOptions po;
        po.fromReferencePoint = true;
        const engine::StartSearch s = engine::findStartPoint(prof, parsed.store, 1, {1, index, 1}, po);
        const double t1 = bench::nowSeconds();
        if (s.outcome != engine::StartSearch::Outcome::Found) {
            std::fprintf(stderr, "frame N900 was not reached\n");
            return 2;
        }
        ctl.selectMode(engine::Mode::Auto);
        ctl.selectProgram(1);
        ctl.setStartPoint(s.point);
        run.pressStart();
        bool moved = false;
        for (int t = 0; t < 600000 && !moved; ++t) {
            run.tick();
            moved = ctl.servo(engine::AxisId::X).moving() || ctl.servo(engine::AxisId::Z).moving();
            if (ctl.alarmRegistry().anyLatched())
                break;
        }
        const double t2 = bench::nowSeconds();
        if (!moved) {
            std::fprintf(stderr, "the axes never moved\n");
            return 2;
        }
        best = std::min(best, (t2 - t0) * 1000.0);
        bestPreview = std::min(bestPreview, (t1 - t0) * 1000.0);
    }
    bench::Report report;
    std::printf("%-40s %12.3f ms   (the preview to N900, part of the figure below)\n",
                "run_from.rebuild_state_ms", bestPreview);
    report.figure("run_from.first_motion_ms", best, "ms", 50, bench::Better::Lower);
    return report.exitCode();
}
