// Database speed:
//  - open the database (integrity check included) and load one full machine:
//    target <= 20 ms;
//  - export a full machine (152 C, 269 R presets — every writable R, 99
//    programs of 25..75 frames, 99 messages, 80 PLC texts) and import it
//    again, as a new machine and as a new revision of an existing one with
//    every item changed: target <= 100 ms.
// The database lives in a temporary folder on the same file system as /tmp;
// every write commits with SQLite's default durability (WAL, synchronous=FULL).
// K528_BENCH_KEEP=1 keeps the database for inspection (its path is printed).
#include "db/database.h"
#include "profile/text_format.h"
#include "random_machine.h"
#include "report.h"
#include "stats.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace k528;
namespace fs = std::filesystem;

namespace {

double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v)
        s += x;
    return s / static_cast<double>(v.size());
}

std::vector<double> openAndLoad(const fs::path& path, int runs, const std::string& machine) {
    std::vector<double> ms;
    for (int i = 0; i < runs; ++i) {
        const double t0 = bench::nowSeconds();
        db::Database d = db::Database::open(path);
        const profile::MachineProfile p = d.loadMachine(machine);
        const double t1 = bench::nowSeconds();
        if (p.programs.size() != 99)
            std::exit(2);
        ms.push_back((t1 - t0) * 1000.0);
    }
    return ms;
}

} // namespace

int main(int argc, char** argv) {
    const int openRuns = argc > 1 ? std::atoi(argv[1]) : 50;
    const int importRuns = argc > 2 ? std::atoi(argv[2]) : 20;

    char tmpl[] = "/tmp/k528-bench-db-XXXXXX";
    if (!mkdtemp(tmpl)) {
        std::perror("mkdtemp");
        return 2;
    }
    const fs::path dir = tmpl;
    const fs::path path = dir / "k528.db";
    const profile::MachineProfile full = testing::randomMachine(1, "full");
    const profile::MachineProfile variant = testing::randomMachine(2, "full");
    std::size_t programBytes = 0;
    for (const auto& [n, t] : full.programs)
        programBytes += t.size();
    {
        db::Database d = db::Database::open(path);
        d.createMachine(full);
    }
    std::printf("machine: 152 C, %zu R, %zu programs (%.0f KB), %zu messages, %zu PLC texts; "
                "machine file %.0f KB\n",
                full.r.size(), full.programs.size(), static_cast<double>(programBytes) / 1024.0,
                full.messages.size(),
                full.plcAlarm.size() + full.plcWork.size() + full.plcSystem.size(),
                static_cast<double>(profile::writeMachineText(full).size()) / 1024.0);

    bench::Report report;
    const auto small = openAndLoad(path, openRuns, "full");
    report.figure("db.open_load_median (3 machines)", bench::median(small), "ms", 20,
                  bench::Better::Lower);
    report.figure("db.open_load_p90 (3 machines)", bench::percentile(small, 90), "ms", 20,
                  bench::Better::Lower);

    // Export + import as a new machine: the full write path (revision 1 with
    // every item, history rows, program revisions with SHA-256).
    std::vector<double> asNew, asRevision;
    {
        db::Database d = db::Database::open(path);
        for (int i = 0; i < importRuns; ++i) {
            const double t0 = bench::nowSeconds();
            const std::string text = profile::writeMachineText(d.loadMachine("full"));
            profile::MachineProfile p = profile::readMachineText(text, "full.k528m");
            p.name = "copy-" + std::to_string(i);
            d.createMachine(p);
            const double t1 = bench::nowSeconds();
            asNew.push_back((t1 - t0) * 1000.0);
        }
        // Export + import --replace of a file where every item differs.
        for (int i = 0; i < importRuns; ++i) {
            const std::string text = profile::writeMachineText(i % 2 == 0 ? variant : full);
            const double t0 = bench::nowSeconds();
            const std::string exported = profile::writeMachineText(d.loadMachine("full"));
            const profile::MachineProfile p = profile::readMachineText(text, "variant.k528m");
            const auto r = d.saveMachine("full", p);
            const double t1 = bench::nowSeconds();
            if (!r.changed || exported.empty())
                return 2;
            asRevision.push_back((t1 - t0) * 1000.0);
        }
    }
    report.figure("db.export_import_new_median", bench::median(asNew), "ms", 100, bench::Better::Lower);
    report.figure("db.export_import_new_p90", bench::percentile(asNew, 90), "ms", 100,
                  bench::Better::Lower);
    report.figure("db.export_import_revision_median", bench::median(asRevision), "ms", 100,
                  bench::Better::Lower);
    report.figure("db.export_import_revision_p90", bench::percentile(asRevision, 90), "ms", 100,
                  bench::Better::Lower);

    // Open + load again on the grown database. PRAGMA integrity_check reads
    // every page, so this grows with the file (about 3 ms per MB here): shown
    // for information, not a target (docs/database.md, "Speed").
    const auto big = openAndLoad(path, openRuns, "full");
    std::error_code ec;
    const double mb = static_cast<double>(fs::file_size(path, ec)) / 1e6;
    std::printf("info: open+load median %.2f ms on the grown database (%d machines, %.1f MB, "
                "%.1f ms per MB)\n",
                bench::median(big), 3 + importRuns, mb, bench::median(big) / mb);
    std::printf("(mean open+load %.2f ms small, %.2f ms grown; mean import %.2f / %.2f ms)\n",
                mean(small), mean(big), mean(asNew), mean(asRevision));
    if (!std::getenv("K528_BENCH_KEEP"))
        fs::remove_all(dir, ec);
    else
        std::printf("kept %s\n", path.c_str());
    return report.exitCode();
}
