// The oscilloscope live: 4 traces × 2 axes at the 1 ms servo
// tick over a 60 s window while the machine runs in real time — each frame
// advances the simulated machine by the real time elapsed (as the desktop's
// session does), decimates the window per pixel column and paints both
// charts. Run under Xvfb (llvmpipe): xvfb-run -a bench/run scope.
#include "report.h"

#include "engine/run.h"
#include "machine/run.h"
#include "machine/simulation.h"
#include "profile/builtin.h"
#include "program/parser.h"
#include "scope/scope_view.h"

#include <QApplication>
#include <QChartView>
#include <cstdlib>
#include <ctime>

using namespace k528;

int main(int argc, char** argv) {
    if (!std::getenv("DISPLAY") && !std::getenv("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const double seconds = argc > 1 ? std::atof(argv[1]) : 3.0;
    profile::MachineProfile prof = profile::builtin("training-lathe");
    prof.setC(8, 1);
    prof.setC(60, 1);
    machine::Simulation sim(prof);
    studio::ScopeView view;
    view.resize(1280, 700);
    view.show();
    view.attach(sim);
    view.setWindowSeconds(60);
    // A program that keeps both axes moving back and forth for longer than
    // the measurement, started as an operator does (engine/run.h).
    program::ParseOptions po;
    const auto parsed = program::parse(
        "%L1\nN1 G1 X60 FX3000 Z-40 FZ3000\nN2 G1 X10 FX3000 Z-5 FZ3000\nN3 GOTO 1\n", po);
    machine::SimulationRunMachine m(sim);
    engine::RunOptions options;
    options.home = false;
    options.maxSeconds = 60; // 60 s of motion fill the window first
    engine::runProgram(m, parsed.store, 1, options);
    bench::Report report;
    report.figure("scope.window_samples", static_cast<double>(view.buffer().size()), "ticks",
                  59000, bench::Better::Higher);
    // Live: the machine keeps moving (the loop runs on: the program never ends).
    int frames = 0;
    double refreshS = 0, paintS = 0;
    const std::clock_t cpu0 = std::clock();
    const double t0 = bench::nowSeconds();
    double last = t0, owedMs = 0;
    while (bench::nowSeconds() - t0 < seconds) {
        const double now = bench::nowSeconds();
        owedMs += (now - last) * 1000.0;
        last = now;
        const auto ms = static_cast<std::int64_t>(owedMs);
        sim.advance(ms);
        owedMs -= static_cast<double>(ms);
        const double r0 = bench::nowSeconds();
        view.refresh();
        const double r1 = bench::nowSeconds();
        for (int a = 0; a < 2; ++a)
            view.chartView(a)->viewport()->repaint();
        app.processEvents();
        refreshS += r1 - r0;
        paintS += bench::nowSeconds() - r1;
        ++frames;
    }
    const double elapsed = bench::nowSeconds() - t0;
    const double cpuS = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
    report.figure("scope.live_fps_4x2_traces_60s_1ms", frames / elapsed, "frames/s", 30,
                  bench::Better::Higher);
    report.figure("scope.decimate_ms_per_frame", refreshS * 1000.0 / frames, "ms", 10,
                  bench::Better::Lower);
    report.figure("scope.paint_ms_per_frame", paintS * 1000.0 / frames, "ms", 23,
                  bench::Better::Lower);
    // The process's CPU time a frame (the simulation, the scope, the paint):
    // what the frame rate would be on a core of its own, less affected by the
    // load of a shared machine than the wall clock.
    report.figure("scope.cpu_ms_per_frame", cpuS * 1000.0 / frames, "ms", 33.3,
                  bench::Better::Lower);
    report.figure("scope.points_per_series", static_cast<double>(
                      view.seriesPoints(0, studio::ScopeSignal::FollowingError).size()),
                  "points", 8000, bench::Better::Lower);
    return report.exitCode();
}
