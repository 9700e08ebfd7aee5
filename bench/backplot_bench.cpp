// Backplot benchmarks, llvmpipe 1280×800:
//   backplot.path_1M_s          the programmed path of a 1,000,000-segment program (engine preview)
//   backplot.first_frame_s      scene load (index, level of detail) and the first frame of it
//   backplot.interaction_fps    frames/s while panning and zooming that scene
//   backplot.lod_rebuild_ms     rebuilding the level of detail when an interaction ends
//   backplot.pick_max_ms        picking a segment through our own 2D index (worst of 1000)
//   backplot.stock_100k_s       material removal of 100,000 moves (Boost.Geometry)
//   backplot.live_tick_us       the live path's cost a simulated tick: a run on the simulated
//                               machine with it (every tick sampled, a flush every 16 ticks)
//                               against the same run without, over the ticks sampled
//   backplot.live_frame_p95_ms  one UI frame of the live path at ×100 (1600 ticks): flush,
//                               append to the scene's buffers, the tool (95th percentile)
// Needs an X server (Debian's VTK): without DISPLAY it runs itself under xvfb-run.
#include "backplot/backplot_scene.h"
#include "engine/forwarding_run_machine.h"
#include "profile/builtin.h"
#include "program/parser.h"
#include "report.h"
#include "machine/run.h"
#include "machine/simulation.h"
#include "stock/stock.h"
#include "toolpath/actual_path.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkPropCollection.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <unistd.h>
#include <vector>

using namespace k528;

namespace {

// A roughing loop: 4 motion frames an iteration (feed along Z, feed up X,
// rapid back, rapid down), X stepping down 2 µm on the diameter.
std::string roughing(int iterations) {
    return "%L1\nN1 G192 X800\nN2 G292 Z0\nN3 R1=" + std::to_string(iterations) +
           "\nN10 G91 G1 Z-50 FZ1000\nN11 G1 X0.002 FX500\nN12 G0 Z50\nN13 G0 X-0.004\n"
           "N14 R1=R1-1\nN15 IF R1>0 GOTO 10\nN16 G90 M30\n";
}

} // namespace

int main(int argc, char** argv) {
    const char* display = std::getenv("DISPLAY");
    if ((!display || !*display) && !std::getenv("K528_BENCH_UNDER_XVFB")) {
        setenv("K528_BENCH_UNDER_XVFB", "1", 1);
        std::vector<char*> a = {const_cast<char*>("xvfb-run"), const_cast<char*>("-a"),
                                const_cast<char*>("-s"), const_cast<char*>("-screen 0 1280x800x24")};
        for (int i = 0; i < argc; ++i)
            a.push_back(argv[i]);
        a.push_back(nullptr);
        execvp("xvfb-run", a.data());
        std::perror("xvfb-run");
        return 2;
    }
    const int segments = argc > 1 ? std::atoi(argv[1]) : 1'000'000;
    bench::Report report;
    const profile::MachineProfile prof = profile::builtin("training-lathe");

    // 1. The programmed path.
    const program::ParseResult parsed = program::parse(roughing(segments / 4));
    if (parsed.hasErrors())
        return 2;
    toolpath::PathOptions po;
    po.preview.maxFrames = 10'000'000;
    double t0 = bench::nowSeconds();
    const toolpath::ProgrammedPath path = toolpath::programmedPath(prof, parsed.store, 1, po);
    const double pathS = bench::nowSeconds() - t0;
    std::printf("# %zu segments, %zu points, %lld frames, status %s\n", path.segments.size(),
                path.points.size(), static_cast<long long>(path.run.frames),
                std::string(engine::previewStatusName(path.run.status)).c_str());
    report.figure("backplot.path_1M_s", pathS, "s", 1.0, bench::Better::Lower);

    // 2. Load and first frame.
    constexpr int kW = 1280, kH = 800;
    vtkNew<vtkRenderWindow> win;
    win->SetOffScreenRendering(1);
    win->SetMultiSamples(0);
    win->SetSize(kW, kH);
    t0 = bench::nowSeconds();
    backplot::BackplotScene scene;
    const std::size_t pathSegments = path.segments.size();
    scene.setPath(std::move(path));
    const double tSet = bench::nowSeconds();
    win->AddRenderer(scene.renderer());
    scene.fit(kW, kH);
    const double tFit = bench::nowSeconds();
    win->Render();
    std::printf("# first frame: set path %.3f s, fit and level of detail %.3f s, render %.3f s\n",
                tSet - t0, tFit - tSet, bench::nowSeconds() - tFit);
    report.figure("backplot.first_frame_s", bench::nowSeconds() - t0, "s", 1.0, bench::Better::Lower);

    // 3. Interaction: 60 frames of pan and zoom on the static buffers.
    vtkCamera* cam = scene.renderer()->GetActiveCamera();
    constexpr int kFrames = 60;
    scene.setInteracting(true); // as the widget does while a button or the wheel moves the view
    t0 = bench::nowSeconds();
    for (int i = 0; i < kFrames; ++i) {
        double f[3], p[3];
        cam->GetFocalPoint(f);
        cam->GetPosition(p);
        const double d = cam->GetParallelScale() * 0.01 * (i % 20 < 10 ? 1 : -1);
        cam->SetFocalPoint(f[0] + d, f[1], f[2]);
        cam->SetPosition(p[0] + d, p[1], p[2]);
        cam->SetParallelScale(cam->GetParallelScale() * (i % 30 < 15 ? 0.97 : 1 / 0.97));
        win->Render();
    }
    const double fps = kFrames / (bench::nowSeconds() - t0);
    {
        vtkPropCollection* props = scene.renderer()->GetViewProps();
        props->InitTraversal();
        std::vector<vtkProp*> hidden;
        while (vtkProp* p = props->GetNextProp())
            if (!vtkActor::SafeDownCast(p) && p->GetVisibility()) {
                p->VisibilityOff();
                hidden.push_back(p);
            }
        const double s = bench::nowSeconds();
        for (int i = 0; i < 20; ++i) {
            cam->SetParallelScale(cam->GetParallelScale() * (i % 2 ? 0.99 : 1 / 0.99));
            win->Render();
        }
        std::printf("# without the 2D overlays (legend, texts): %.1f fps\n", 20 / (bench::nowSeconds() - s));
        for (vtkProp* p : hidden)
            p->VisibilityOn();
    }
    report.figure("backplot.interaction_fps", fps, "fps", 25, bench::Better::Higher);
    // The level of detail rebuilt when an interaction ends (then one frame).
    t0 = bench::nowSeconds();
    scene.setInteracting(false);
    scene.refresh(kW, kH);
    win->Render();
    report.figure("backplot.lod_rebuild_ms", (bench::nowSeconds() - t0) * 1000, "ms", 250,
                  bench::Better::Lower);

    // 4. Picking: 1000 positions over the window.
    double worst = 0, sum = 0;
    long hits = 0;
    std::vector<double> times;
    for (int i = 0; i < 1000; ++i) {
        const double x = (i * 7919 % kW) + 0.5, y = (i * 104729 % kH) + 0.5;
        const double s = bench::nowSeconds();
        hits += scene.pick(x, y, kW, kH) >= 0;
        const double dt = bench::nowSeconds() - s;
        worst = std::max(worst, dt);
        sum += dt;
        times.push_back(dt);
    }
    std::sort(times.begin(), times.end());
    std::printf("# pick over %zu segments: %ld of 1000 positions on a segment, mean %.3f ms, "
                "max %.3f ms (a loaded machine's scheduling shows in the max)\n",
                pathSegments, hits, sum, worst * 1000);
    report.figure("backplot.pick_p99_ms", times[989] * 1000, "ms", 16, bench::Better::Lower);
    win->RemoveRenderer(scene.renderer());

    // 5. Stock removal of 100,000 moves (the first 25,000 roughing passes).
    const program::ParseResult small = program::parse(roughing(25'000));
    const toolpath::ProgrammedPath cuts = toolpath::programmedPath(prof, small.store, 1, po);
    std::size_t moves = 0;
    for (const toolpath::Segment& s : cuts.segments)
        moves += s.pointCount - 1;
    stock::Stock blank(*stock::parseUcg("UCG,2,Z-100Z0,X802X0,S0S0,0,-5"));
    t0 = bench::nowSeconds();
    blank.cutPath(cuts, stock::Tool{});
    const double stockS = bench::nowSeconds() - t0;
    std::printf("# stock: %zu moves, area %.3f mm2 left, %zu polygons\n", moves, blank.areaMm2(),
                blank.polygons());
    report.figure("backplot.stock_100k_s", stockS, "s", 2.0, bench::Better::Lower);

    // 6. The live path: the same run with and without it (best of 3 each, alternating).
    {
        const program::ParseResult lp =
            program::parse("%L1\nN1 R1=4\nN2 G1 X40 FX2000 Z-30 FZ1000\nN3 G1 X20 FX2000\n"
                           "N4 G1 Z-60 FZ500\nN5 G0 X80\nN6 G0 Z0\nN7 R1=R1-1\nN8 IF R1>0 GOTO 2\nM30\n");
        if (lp.hasErrors())
            return 2;
        engine::RunOptions ro;
        double plain = 1e9, live = 1e9, frameP95 = 0;
        std::vector<double> frameTimes;
        std::size_t kept = 0, raw = 0;
        for (int round = 0; round < 3; ++round) {
            {
                machine::Simulation sim(prof);
                machine::SimulationRunMachine m(sim);
                const double t = bench::nowSeconds();
                engine::runProgram(m, lp.store, 1, ro);
                plain = std::min(plain, bench::nowSeconds() - t);
            }
            {
                machine::Simulation sim(prof);
                toolpath::LiveActualPath path(1.0);
                path.attach(sim);
                machine::SimulationRunMachine m(sim);
                struct Frames final : engine::ForwardingRunMachine {
                    toolpath::LiveActualPath& p;
                    int ticks = 0;
                    Frames(engine::RunMachine& inner, toolpath::LiveActualPath& l) : ForwardingRunMachine(inner), p(l) {}
                    void tick() override {
                        ForwardingRunMachine::tick();
                        if (++ticks % 16 == 0)
                            p.flush();
                    }
                } frames(m, path);
                const double t = bench::nowSeconds();
                engine::runProgram(frames, lp.store, 1, ro);
                path.flush();
                live = std::min(live, bench::nowSeconds() - t);
                kept = path.path().samples.size();
                raw = path.path().rawSamples;
            }
        }
        // One UI frame at ×100: 1600 ticks sampled, then flushed and appended to the scene.
        {
            machine::Simulation sim(prof);
            toolpath::LiveActualPath path(1.0);
            path.attach(sim);
            machine::SimulationRunMachine m(sim);
            struct Frame final : engine::ForwardingRunMachine {
                toolpath::LiveActualPath& p;
                backplot::BackplotScene& scene;
                std::vector<double>& times;
                int ticks = 0;
                Frame(engine::RunMachine& inner, toolpath::LiveActualPath& l, backplot::BackplotScene& s,
                      std::vector<double>& t)
                    : ForwardingRunMachine(inner), p(l), scene(s), times(t) {}
                void tick() override {
                    ForwardingRunMachine::tick();
                    if (++ticks % 1600 == 0) {
                        const double t = bench::nowSeconds();
                        const toolpath::LiveActualPath::Batch b = p.flush();
                        scene.appendActual(&p.path(), b.restarted ? 0 : b.firstNew);
                        scene.refreshTool(1280, 800);
                        if (b.raw > 0 && !b.restarted) // the first builds the buffers
                            times.push_back(bench::nowSeconds() - t);
                    }
                }
            };
            backplot::BackplotScene liveScene;
            liveScene.setPath(toolpath::programmedPath(prof, lp.store, 1));
            Frame frame(m, path, liveScene, frameTimes);
            engine::runProgram(frame, lp.store, 1, ro);
            std::sort(frameTimes.begin(), frameTimes.end());
            if (!frameTimes.empty())
                frameP95 = frameTimes[frameTimes.size() * 95 / 100];
        }
        std::printf("# live: %zu ticks sampled, %zu kept; run %.3f s plain, %.3f s live\n", raw, kept,
                    plain, live);
        // Per simulated tick: at ×1 the session runs 1000 ticks a second, at
        // ×100 (its fastest) 100,000: 1 µs a tick is then 10 % of a core.
        report.figure("backplot.live_tick_us", raw > 0 ? (live - plain) / static_cast<double>(raw) * 1e6 : 1e9,
                      "us", 1.0, bench::Better::Lower);
        std::printf("# live frames at x100: %zu, p95 %.3f ms\n", frameTimes.size(), frameP95 * 1000);
        report.figure("backplot.live_frame_p95_ms", frameP95 * 1000, "ms", 4, bench::Better::Lower);
    }
    return report.exitCode();
}
