// The studio's start: from starting the k528studio process to its
// main window's first painted frame (`k528studio --first-frame` prints a line
// when that frame has been painted and flushed, then quits), in each
// workspace. The first start creates its database and settings and is not
// counted; then `runs` starts a workspace, its figure is their median (each is
// printed). Run under an X server (xvfb-run -a -s "-screen 0 1920x1080x24"
// bench/run studio_startup) — without one it uses Qt's offscreen platform and
// says so. The backplot's first picture follows the first frame (its OpenGL
// context and first render are not in it).
#include "report.h"

#include <QCoreApplication>
#include <QProcess>
#include <QTemporaryDir>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
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
    const auto start = [&](const QString& workspace, double* ms) {
        QProcess p;
        p.setProcessEnvironment(env);
        p.setProcessChannelMode(QProcess::SeparateChannels);
        const double t0 = k528::bench::nowSeconds();
        p.start(studio, {"--lang", "ru", "--profile", "training-lathe", "--workspace", workspace, "--first-frame"});
        bool seen = false;
        while (!seen && p.waitForReadyRead(30000))
            while (p.canReadLine())
                if (p.readLine().startsWith("k528studio: first frame")) {
                    *ms = (k528::bench::nowSeconds() - t0) * 1000.0;
                    seen = true;
                }
        p.waitForFinished(10000);
        if (!seen)
            std::fprintf(stderr, "bench_studio_startup: no first frame (exit %d): %s\n", p.exitCode(),
                         p.readAllStandardError().constData());
        return seen;
    };
    double first = 0;
    if (!start("operator", &first)) // creates the database and the settings
        return 1;
    std::printf("  first start (not counted) %8.1f ms\n", first);
    k528::bench::Report report;
    for (const char* workspace : {"operator", "technologist", "training"}) {
        std::vector<double> ms;
        for (int i = 0; i < runs; ++i) {
            double t = 0;
            if (!start(workspace, &t))
                return 1;
            ms.push_back(t);
        }
        std::sort(ms.begin(), ms.end());
        std::printf("  %-13s", workspace);
        for (double t : ms)
            std::printf(" %6.0f", t);
        std::printf(" ms\n");
        report.figure(std::string("studio.start_to_first_frame_") + workspace, ms[ms.size() / 2], "ms", 1000,
                      k528::bench::Better::Lower);
    }
    return report.exitCode();
}
