// The studio's start (issue 23): from starting the k528studio process to its
// main window's first painted frame (`k528studio --first-frame` prints a line
// when that frame has been painted and flushed, then quits). The first start
// creates its database and settings and is not counted; then `runs` starts,
// the figure is their median (each is printed). Run under an X server
// (xvfb-run -a bench/run studio_startup) — without one it uses Qt's offscreen
// platform and says so.
#include "report.h"

#include <QCoreApplication>
#include <QProcess>
#include <QTemporaryDir>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_studio_startup PATH-TO-k528studio [RUNS]\n");
        return 2;
    }
    const QString studio = QString::fromLocal8Bit(argv[1]);
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 7;
    QTemporaryDir home;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("HOME", home.path());
    env.insert("XDG_CONFIG_HOME", home.filePath("config"));
    env.insert("XDG_DATA_HOME", home.filePath("data"));
    env.insert("XDG_RUNTIME_DIR", home.path());
    env.insert("K528_DB", home.filePath("k528.db"));
    const bool x = env.contains("DISPLAY") && env.value("QT_QPA_PLATFORM").isEmpty();
    if (!x)
        env.insert("QT_QPA_PLATFORM", "offscreen");
    std::printf("studio start on %s (%s)\n", x ? "the X server" : "the offscreen platform (no DISPLAY)",
                qPrintable(env.value("DISPLAY")));
    // Once to create the database and the settings (a first start), not counted.
    std::vector<double> ms;
    for (int i = 0; i <= runs; ++i) {
        QProcess p;
        p.setProcessEnvironment(env);
        p.setProcessChannelMode(QProcess::SeparateChannels);
        const double t0 = k528::bench::nowSeconds();
        p.start(studio, {"--lang", "ru", "--profile", "training-lathe", "--first-frame"});
        bool seen = false;
        double t = 0;
        while (!seen && p.waitForReadyRead(30000)) {
            while (p.canReadLine())
                if (p.readLine().startsWith("k528studio: first frame")) {
                    t = (k528::bench::nowSeconds() - t0) * 1000.0;
                    seen = true;
                }
        }
        p.waitForFinished(10000);
        if (!seen) {
            std::fprintf(stderr, "bench_studio_startup: no first frame (exit %d): %s\n", p.exitCode(),
                         p.readAllStandardError().constData());
            return 1;
        }
        std::printf("  %s %8.1f ms\n", i == 0 ? "first start (not counted)" : "start                    ", t);
        if (i > 0)
            ms.push_back(t);
    }
    std::sort(ms.begin(), ms.end());
    k528::bench::Report report;
    report.figure("studio.start_to_first_frame_median", ms[ms.size() / 2], "ms", 1000, k528::bench::Better::Lower);
    return report.exitCode();
}
