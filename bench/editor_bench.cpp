// The program editor, through the editor's own path (Qt,
// offscreen): re-validating a 999-frame program after one keystroke, opening
// a 99 x 999-frame file coloured with diagnostics, and the longest stall of
// the event loop while a scripted edit types into that file.
//   bench_editor [REPEATS]
#include "editor/editor_tab.h"
#include "editor/program_editor.h"
#include "program/formatter.h"
#include "random_program.h"
#include "report.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QKeyEvent>
#include <QTimer>
#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <vector>

using namespace k528;
using namespace k528::studio;

namespace {

// Valid frames (as a real file mostly is), then `errors` bad ones spread
// over it so that there are diagnostics to show.
std::string storeText(int programs, int frames, std::uint64_t seed, int errors = 0) {
    program::testing::GeneratorOptions o;
    o.comments = true;
    o.validOnly = true;
    program::testing::ProgramGenerator gen(seed, o);
    program::ProgramStore store = gen.store(programs, frames);
    std::string text = program::format(store);
    std::size_t at = 0;
    for (int i = 0; i < errors; ++i) {
        at = text.find('\n', at + text.size() / static_cast<std::size_t>(errors + 1));
        if (at == std::string::npos)
            break;
        text.insert(at + 1, "G4 X1 Z1\n");
    }
    return text;
}

} // namespace

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 30;
    bench::Report report;

    // 1. One program of 999 frames: one keystroke, then the validation the
    //    editor does (core's check, squiggles, the validated() signal).
    {
        EditorTab tab(nullptr);
        tab.newFile();
        ProgramEditor* ed = tab.currentEditor();
        ed->setText(QString::fromStdString(storeText(1, 999, 7)));
        ed->validateNow();
        std::vector<double> ms;
        for (int i = 0; i < repeats; ++i) {
            ed->setCursorPosition(500, 0);
            const double t0 = bench::nowSeconds();
            ed->insert(i % 2 ? QStringLiteral(" ") : QStringLiteral(";"));
            ed->validateNow();
            ms.push_back((bench::nowSeconds() - t0) * 1000.0);
            ed->undo();
        }
        std::sort(ms.begin(), ms.end());
        report.figure("revalidate 999 frames after a key (median)", ms[ms.size() / 2], "ms", 2.0,
                      bench::Better::Lower);
    }

    // 2. Open 99 x 999 frames: text, validation, colours of the first screen.
    const std::string big = storeText(99, 999, 11, 200);
    std::printf("big file: %.2f MB\n", static_cast<double>(big.size()) / 1e6);
    EditorTab tab(nullptr);
    tab.resize(1200, 800);
    tab.show();
    app.processEvents();
    const double t0 = bench::nowSeconds();
    tab.newFile();
    ProgramEditor* ed = tab.currentEditor();
    ed->setText(QString::fromUtf8(big.data(), static_cast<qsizetype>(big.size())));
    ed->validateNow();
    ed->repaint();
    app.processEvents();
    const double openS = bench::nowSeconds() - t0;
    std::printf("diagnostics in the big file: %zu\n", ed->diagnostics().size());
    report.figure("open 99x999 frames coloured + diagnostics", openS * 1000.0, "ms", 1000.0,
                  bench::Better::Lower);

    // 3. A scripted edit: a key every 40 ms for 5 s, a pause of 1 s after
    //    each line (validations are applied meanwhile); a 1 ms timer measures
    //    the longest gap of the event loop.
    ed->setCursorPosition(50000, 0);
    ed->setFocus();
    // Beside the wall-clock gap, the CPU time this thread used in it: on a
    // loaded machine a gap can be the scheduler's (other processes ran), and
    // the CPU time tells how much of it was the editor's own work.
    double longest = 0, longestCpu = 0, cpuInLongest = 0;
    int keys = 0;
    QElapsedTimer clock;
    clock.start();
    qint64 last = clock.nsecsElapsed();
    auto threadCpuNs = [] {
        timespec ts{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
        return static_cast<qint64>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
    };
    qint64 lastCpu = threadCpuNs();
    QTimer probe;
    probe.setInterval(1);
    QObject::connect(&probe, &QTimer::timeout, [&] {
        const qint64 now = clock.nsecsElapsed();
        const qint64 cpu = threadCpuNs();
        const double gap = static_cast<double>(now - last) / 1e6;
        const double gapCpu = static_cast<double>(cpu - lastCpu) / 1e6;
        if (gap > longest) {
            longest = gap;
            cpuInLongest = gapCpu;
        }
        longestCpu = std::max(longestCpu, gapCpu);
        last = now;
        lastCpu = cpu;
    });
    QTimer typist;
    typist.setInterval(40);
    const QString script = QString::fromLocal8Bit(qgetenv("K528_BENCH_SCRIPT").isEmpty() ? QByteArray("N5 G1 X12.5 FX100\r") : qgetenv("K528_BENCH_SCRIPT"));
    QObject::connect(&typist, &QTimer::timeout, [&] {
        const QChar c = script.at(keys % script.size());
        const int key = c == QChar(13) ? static_cast<int>(Qt::Key_Return) : static_cast<int>(c.toUpper().unicode());
        QKeyEvent press(QEvent::KeyPress, key, Qt::NoModifier, c == '\r' ? QString("\r") : QString(c));
        QApplication::sendEvent(ed, &press);
        QKeyEvent release(QEvent::KeyRelease, key, Qt::NoModifier);
        QApplication::sendEvent(ed, &release);
        ++keys;
        // A pause at each line's end, as a technologist pauses: the debounced
        // validation runs and its result is applied while the edit goes on.
        if (c == QChar(13)) {
            typist.stop();
            QTimer::singleShot(1000, &typist, [&typist] { typist.start(); });
        }
    });
    const int validationsBefore = ed->validations();
    // The jump to line 50000 is painted (and coloured) before the edit starts:
    // the stalls measured are those of typing.
    {
        QEventLoop settle;
        QTimer::singleShot(300, &settle, &QEventLoop::quit);
        settle.exec();
    }
    probe.start();
    typist.start();
    QTimer::singleShot(5000, &app, &QCoreApplication::quit);
    last = clock.nsecsElapsed();
    lastCpu = threadCpuNs();
    app.exec();
    std::printf("keys typed: %d, validations applied: %d\n", keys, ed->validations() - validationsBefore);
    std::printf("the longest stall held %.2f ms of this thread's CPU time\n", cpuInLongest);
    report.figure("longest event-loop stall while typing", longest, "ms", 16.0, bench::Better::Lower);
    report.figure("longest event-loop stall while typing, CPU time", longestCpu, "ms", 16.0, bench::Better::Lower);
    return report.exitCode();
}
