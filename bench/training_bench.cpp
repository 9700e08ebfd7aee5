// The training course's grading speed (docs/training-course.md), as a
// trainer meets it — the `k528` command line, start to exit:
//  - grading one lathe exercise: `k528 grade ID FILE --json` of each lathe
//    exercise's reference (the slowest of them, each the best of `runs`):
//    target <= 0.5 s;
//  - a class of 30 files graded by one command on 2 cores: `k528 grade
//    lathe-06-r-pass-depth FILE x30 --json --jobs 2` (the longest lathe
//    program; in every third file the operator sets the finishing diameter
//    0.3 mm under), the best of
//    `runs`: target <= 10 s.
// Usage: bench_training K528 [RUNS]
#include "report.h"
#include "training/exercise.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

using namespace k528;
namespace fs = std::filesystem;

namespace {

std::string quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s)
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

// Seconds `command` took, its output thrown away; exits 2 if it could not
// run or ended with another code than `wantExit` (-1: 0 or 1, graded).
double timed(const std::string& command, int wantExit) {
    const double t0 = bench::nowSeconds();
    const int rc = std::system((command + " >/dev/null").c_str());
    const double t1 = bench::nowSeconds();
    if (rc == -1 || !WIFEXITED(rc) || (wantExit >= 0 ? WEXITSTATUS(rc) != wantExit : WEXITSTATUS(rc) > 1)) {
        std::fprintf(stderr, "bench_training: '%s' ended with %d (expected exit %d)\n",
                     command.c_str(), rc, wantExit);
        std::exit(2);
    }
    return t1 - t0;
}

void write(const fs::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary);
    out << text;
    if (!out) {
        std::fprintf(stderr, "bench_training: cannot write %s\n", p.c_str());
        std::exit(2);
    }
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_training K528 [RUNS]\n");
        return 2;
    }
    const std::string k528 = quoted(argv[1]);
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
    const fs::path dir = fs::temp_directory_path() / ("k528-bench-training-" + std::to_string(::getpid()));
    fs::create_directories(dir);

    bench::Report report;
    double slowest = 0;
    std::string slowestId;
    for (const training::Exercise& e : training::shippedExercises()) {
        if (!e.lathe())
            continue;
        const fs::path file = dir / (e.id + ".k528");
        write(file, e.reference);
        double best = 1e300;
        for (int i = 0; i < runs; ++i)
            best = std::min(best, timed(k528 + " grade " + e.id + " " + quoted(file) + " --json", 0));
        std::printf("  %-40s %8.3f s\n", e.id.c_str(), best);
        if (best > slowest) {
            slowest = best;
            slowestId = e.id;
        }
    }
    report.figure("training.grade_one_lathe_s (" + slowestId + ")", slowest, "s", 0.5,
                  bench::Better::Lower);

    const training::Exercise* e = training::findExercise("lathe-06-r-pass-depth");
    if (!e)
        return 2;
    std::string command = k528 + " grade " + e->id + " --json --jobs 2";
    for (int i = 1; i <= 30; ++i) {
        std::string text = e->reference;
        if (i % 3 == 0) { // the operator sets the finishing diameter 0.3 mm under
            const auto at = text.find("R11=32000");
            if (at == std::string::npos)
                return 2;
            text.replace(at, 9, "R11=31700");
        }
        const fs::path file = dir / ("student" + std::to_string(i) + ".k528");
        write(file, text);
        command += " " + quoted(file);
    }
    double best = 1e300;
    for (int i = 0; i < runs; ++i)
        best = std::min(best, timed(command, -1));
    report.figure("training.grade_class_of_30_s", best, "s", 10, bench::Better::Lower);
    fs::remove_all(dir);
    return report.exitCode();
}
