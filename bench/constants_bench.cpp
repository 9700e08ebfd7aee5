// The machine-constants dock, through the dock's own path (Qt,
// offscreen): typing into the search field filters the table of 152 rows —
// the proxy re-filters and the view lays out and paints what it shows.
// Figures: the slowest and the mean of the filter steps.
//   bench_constants [REPEATS]
#include "constants/constants_dock.h"
#include "constants/constants_model.h"
#include "profile/builtin.h"
#include "report.h"
#include "controller/simulated_controller.h"
#include "session/simulation_session.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QLineEdit>
#include <QTableView>
#include <QTemporaryDir>
#include <algorithm>
#include <cstdlib>
#include <ctime>

using namespace k528;
using namespace k528::studio;

namespace {
// CPU time of this thread: the figure that does not depend on how many
// other processes share the cores.
double threadCpuMs() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) / 1e6;
}
} // namespace

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QTemporaryDir dir; // the dock's database is never the developer's
    qputenv("K528_DB", dir.filePath("k528.db").toUtf8());
    const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 100;
    bench::Report report;

    SimulationSession session(profile::builtin(profile::kDefaultProfile));
    SimulatedController seamSim(session);
    ViewedController seam(seamSim);
    ConstantsPane pane(seam, session.simulation().profile());
    pane.resize(1250, 700);
    pane.show();
    QApplication::processEvents();
    // What a technologist types: a letter at a time, then clears it.
    const QStringList steps{"у", "ус", "уск", "уско", "ускорение", "", "c", "c0", "c02", "c022", "",
                            "f", "f у", "f ус", "", "z4", "z41", "z410", "z4101", "", "дос", "", "mm", ""};
    double worstMs = 0, sumMs = 0, worstCpuMs = 0, sumCpuMs = 0;
    int n = 0, shown = 0;
    for (int r = 0; r < repeats; ++r) {
        for (const QString& s : steps) {
            QElapsedTimer t;
            t.start();
            const double cpu0 = threadCpuMs();
            pane.searchField()->setText(s);
            QApplication::processEvents(); // the view lays out and paints (its posted update)
            const double ms = static_cast<double>(t.nsecsElapsed()) / 1e6;
            const double cpu = threadCpuMs() - cpu0;
            worstCpuMs = std::max(worstCpuMs, cpu);
            sumCpuMs += cpu;
            worstMs = std::max(worstMs, ms);
            sumMs += ms;
            ++n;
            shown += pane.filter()->rowCount();
        }
    }
    if (shown == 0)
        return 2; // nothing was ever shown: the benchmark measured nothing
    report.figure("constants.filter_152_rows_max", worstMs, "ms", 16, bench::Better::Lower);
    report.figure("constants.filter_152_rows_mean", sumMs / n, "ms", 16, bench::Better::Lower);
    report.figure("constants.filter_152_rows_cpu_max", worstCpuMs, "ms", 16, bench::Better::Lower);
    report.figure("constants.filter_152_rows_cpu_mean", sumCpuMs / n, "ms", 16, bench::Better::Lower);
    return report.exitCode();
}
