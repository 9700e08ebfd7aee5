// The prove-out's speed (docs/proveout.md): a full store, 99 programs × 999
// frames, proved against a blank. L1 calls L2..L99 in turn; each of them is
// 999 frames of a lathe's work on its own stretch of a Ø60 × 200 mm bar —
// roughing passes of 10..59 mm, facing, rapids back, a chamfer — so every
// program cuts material and every frame runs once (98,901 frames). Figures:
// the preview and the rules together (what `k528 check --profile` spends per
// file) and the rules alone; the best of N runs.
#include "profile/builtin.h"
#include "program/parser.h"
#include "proveout/proveout.h"
#include "report.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace k528;

namespace {

// Program k (2..99): passes along its stretch of the bar.
std::string subprogram(int k) {
    std::string s = "%L" + std::to_string(k) + "\n";
    int n = 0;
    const auto frame = [&](const std::string& body) { s += "N" + std::to_string(++n) + " " + body + "\n"; };
    const double zStart = -1.0 * ((k - 2) % 3);             // three programs share a stretch
    const double length = 10 + (k * 7) % 50;                 // 10..59 mm
    double d = 60.0 - 0.12 * ((k - 2) / 3);                  // the stretch's diameter so far
    frame("G90 G0 M3");
    while (n < 996 - 5) {
        d -= 0.2;
        char buf[160];
        std::snprintf(buf, sizeof buf, "G0 X%.3f Z%.3f", d + 4, zStart + 2);
        frame(buf);
        std::snprintf(buf, sizeof buf, "X%.3f", d);
        frame(buf);
        std::snprintf(buf, sizeof buf, "G1 Z%.3f FZ250", zStart - length);
        frame(buf);
        std::snprintf(buf, sizeof buf, "X%.3f Z%.3f FX120 FZ120", d + 1, zStart - length - 0.5);
        frame(buf);
        std::snprintf(buf, sizeof buf, "G0 X%.3f", d + 4);
        frame(buf);
    }
    while (n < 998)
        frame("G0 Z5");
    s += "N" + std::to_string(++n) + " M17\n";
    return s;
}

std::string store() {
    std::string s = "; UCG,2,Z-200Z0,X60X0,S0S0,0,-5\n%L1\nN1 G90 G0 M3 X70 Z5\n";
    int n = 1;
    for (int k = 2; k <= 99; ++k)
        s += "N" + std::to_string(++n) + " L" + std::to_string(k) + "\n";
    while (n < 998)
        s += "N" + std::to_string(++n) + " G0 Z5\n";
    s += "N999 M30\n";
    for (int k = 2; k <= 99; ++k)
        s += subprogram(k);
    return s;
}

} // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::atoi(argv[1]) : 5;
    const std::string text = store();
    const program::ParseResult parsed = program::parse(text);
    std::size_t frames = 0;
    for (const program::Program& p : parsed.store.programs())
        frames += p.frames.size();
    if (parsed.hasErrors() || frames != 99u * 999u) {
        std::fprintf(stderr, "the generated store is not 99 x 999 valid frames (%zu)\n", frames);
        return 2;
    }
    const profile::MachineProfile machine = profile::builtin("training-lathe");
    const std::optional<stock::Blank> blank = stock::findUcg(text);
    const proveout::MachineGeometry g = proveout::geometryOf(machine);
    const proveout::Options o = proveout::optionsFor(machine, {}, blank);
    engine::PreviewOptions po;
    po.fromReferencePoint = true;
    double bestAll = 1e9, bestRules = 1e9;
    proveout::Proof proof;
    for (int i = 0; i < runs; ++i) {
        const double t0 = bench::nowSeconds();
        proof = proveout::proveProgram(machine, parsed.store, 1, po, blank);
        const double t1 = bench::nowSeconds();
        const proveout::Result again = proveout::prove(proof.path, g, o);
        const double t2 = bench::nowSeconds();
        bestAll = std::min(bestAll, t1 - t0);
        bestRules = std::min(bestRules, t2 - t1);
        if (again.findings.size() != proof.result.findings.size())
            return 2;
    }
    std::printf("store: 99 programs x 999 frames; %lld frames run, %zu segments, %zu findings, "
                "%.0f mm2 cut of the half profile\n",
                static_cast<long long>(proof.path.run.frames), proof.path.segments.size(),
                proof.result.findings.size(), proof.result.removedMm2);
    if (proof.path.run.status != engine::PreviewStatus::Completed || proof.result.removedMm2 < 100) {
        std::fprintf(stderr, "the store did not run to its end, or cut nothing\n");
        return 2;
    }
    bench::Report report;
    report.figure("proveout.store_99x999_s", bestAll, "s", 0.5, bench::Better::Lower);
    report.figure("proveout.rules_99x999_s", bestRules, "s", 0.5, bench::Better::Lower);
    return report.exitCode();
}
