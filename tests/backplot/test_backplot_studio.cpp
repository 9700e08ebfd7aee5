// The backplot dock in the studio's main window (needs X: our QOpenGLWidget
// bridge): a picked segment names its frame and the editor goes to its
// line, the editor's line highlights its segments; a run on the session's
// machine grows the path live, frame by frame; and a screenshot of the
// studio from the X server shows wide vertical lines clean (no hatched
// fringe), as the same scene offscreen does.
#include "backplot/backplot_widget.h"
#include "rig/widgets.h"
#include "backplot/path_job.h"
#include "backplot/vtk_gl_widget.h"
#include "editor/editor_tab.h"
#include "editor/program_editor.h"
#include "rig/watched_run.h"
#include "language.h"
#include "main_window.h"
#include "workspace/workspaces.h"
#include "program/parser.h"
#include "proveout/proveout_pane.h"
#include "session/simulation_session.h"

#include <algorithm>
#include <cmath>

#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QLabel>
#include <QLocale>
#include <QOpenGLContext>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTimer>
#include <QToolButton>
#include <QTreeView>
#include <QTabWidget>
#include <QWheelEvent>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>

#include <vtkGenericOpenGLRenderWindow.h>

#include <cmath>

using namespace k528;
using studio::MainWindow;
using studio::backplot::BackplotWidget;

namespace {

// A feed along X at Z-40 (vertical on the screen), a rapid back, a feed along Z.
constexpr const char* kProgram = "%L1\n"
                                 "N1 G1 X60 FX2000\n"
                                 "N2 G1 Z-40 FZ2000\n"
                                 "N3 G1 X20 FX2000\n"
                                 "N4 G0 Z-60\n"
                                 "N5 G1 Z-80 FZ2000\n"
                                 "M30\n";

// Never ends: N5 jumps back to N1 (the blank's cut by the same four legs
// again and again).
constexpr const char* kEndless = "%L1 (ENDLESS)\n"
                                 "; UCG,2,Z-100Z0,X50X0,S0S0,0,-5\n"
                                 "N1 G1 X60 FX2000\n"
                                 "N2 G1 Z-40 FZ2000\n"
                                 "N3 G1 X20 FX2000\n"
                                 "N4 G0 Z0\n"
                                 "N5 GOTO 1\n";

struct Studio {
    QTemporaryDir dir;
    MainWindow w;
    BackplotWidget* view = nullptr;
    studio::EditorTab* editor = nullptr;
    bool exposed = false;
    explicit Studio(const char* text = kProgram) {
        w.workspaces()->activate("technologist"); // the editor with the backplot beside it
        w.show();
        exposed = QTest::qWaitForWindowExposed(&w);
        view = w.findChild<BackplotWidget*>();
        editor = w.findChild<studio::EditorTab*>();
        if (auto* d = w.findChild<QDockWidget*>("dock.backplot")) {
            d->setFloating(false);
            w.resizeDocks({d}, {760}, Qt::Horizontal);
        }
        const QString path = dir.filePath("p.k528");
        QFile f(path);
        f.open(QIODevice::WriteOnly);
        f.write(text);
        f.close();
        editor->setCloseQuestion([](const QString&) { return studio::EditorTab::CloseChoice::Discard; });
        editor->setPreviewBeforeSending(false); // the preview is the controller tests'

        editor->openFile(path);
    }
    // Loads the editor's file into the session's controller and shows L1's path.
    bool showPath() {
        if (!editor->sendToController())
            return false;
        w.findChild<QSpinBox*>("backplot.program")->setValue(1);
        QSignalSpy shown(view, &BackplotWidget::pathShown);
        w.findChild<QPushButton*>("backplot.computePath")->click();
        // Computed on a worker: shown when done.
        return shown.wait(10000) && !view->scene().path().segments.empty();
    }
    // Widget pixel (from the top-left) of world point (Z, X).
    QPoint pixelOf(double z, double x) const {
        auto* gl = view->glWidget();
        const k528::backplot::ViewWindow vw = view->scene().window(gl->width(), gl->height());
        return {static_cast<int>(std::lround((z - vw.x0) / vw.worldPerPixel)),
                gl->height() - 1 - static_cast<int>(std::lround((x - vw.y0) / vw.worldPerPixel))};
    }
};

// The run's machine for a test that drives the session's time: each tick of
// the run advances the session by one tick, a UI frame (advanced()) every 16.
testrig::WatchedSimulationRun steppingRun(studio::SimulationSession& ss) {
    return testrig::WatchedSimulationRun(ss.simulation(), [&ss, ticks = 0]() mutable {
        if (++ticks % 16 == 0)
            ss.advance(0);
    });
}

} // namespace

class TestBackplotStudio : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("K528StudioTest");
        QSettings().clear();
    }
    void pickGoesToTheEditorsLineAndTheLineHighlights() {
        Studio s;
        QVERIFY(s.view);
        QVERIFY(s.showPath());
        QCOMPARE(s.view->scene().path().segments.size(), std::size_t(5));
        QSignalSpy spy(s.view, &BackplotWidget::lineActivated);
        // The middle of N2 (Z -20 at X60) is on source line 3.
        const QPoint p = s.pixelOf(-20, 60);
        QCOMPARE(s.view->pickAt(p.x(), p.y()), 1L);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).toInt(), 1);
        QCOMPARE(spy.at(0).at(1).toInt(), 3);
        QVERIFY(s.view->pickText().contains("N2"));
        int line = -1, index = -1;
        s.editor->currentEditor()->getCursorPosition(&line, &index);
        QCOMPARE(line, 2); // 0-based: line 3
        auto* work = s.w.findChild<QTabWidget*>("workArea");
        QCOMPARE(work->currentWidget(), static_cast<QWidget*>(s.editor));
        QCOMPARE(s.view->scene().highlightedLine(), 3);
        // The editor's cursor on line 6 (N5): its segment highlights.
        s.editor->currentEditor()->setCursorPosition(5, 0);
        QTRY_COMPARE(s.view->scene().highlightedLine(), 6);
        QCOMPARE(s.view->scene().highlightedProgram(), 1);
        // A click by the mouse does the same (N3 at Z-40, X40: line 4).
        const QPoint q = s.pixelOf(-40, 40);
        QTest::mouseClick(s.view->glWidget(), Qt::LeftButton, {}, q);
        QTRY_COMPARE(spy.count(), 2);
        QCOMPARE(spy.at(1).at(1).toInt(), 4);
        s.editor->currentEditor()->getCursorPosition(&line, &index);
        QCOMPARE(line, 3);
    }
    // The prove-out's finding of the editor's file (a facing whose return
    // rapid cuts through the bar) as a red disc at its place on the path
    // the backplot shows, seen on the screen; ringed when its Problems
    // entry is activated; gone when the program is made safe.
    void aFindingIsARedMarkerAtItsPlace() {
        Studio s("; UCG,2,Z-80Z0,X40X0,S0S0,0,-5\n"
                 "%L1 (FACE)\n"
                 "N1 G90 G0 M3 X44 Z2\n"
                 "N2 Z-1\n"
                 "N3 G1 X-1 FX150\n"
                 "N4 G0 X44 Z-20\n"
                 "N5 M30\n");
        QVERIFY(s.showPath());
        auto* pane = s.w.findChild<studio::ProveoutPane*>();
        QVERIFY(pane);
        QTRY_COMPARE_WITH_TIMEOUT(pane->findings().size(), std::size_t(1), 20000);
        const proveout::Finding f = pane->findings()[0];
        QCOMPARE(f.line, 6);
        QTRY_COMPARE(s.view->scene().findingsShown().size(), std::size_t(1));
        QCOMPARE(s.view->scene().findingsShown()[0].z, f.at.z);
        auto* gl = s.view->glWidget();
        const auto& red = k528::backplot::kFindingColour;
        const auto redAt = [&](QPoint p) {
            const QImage img = s.w.screen()->grabWindow(s.w.winId()).toImage();
            const QColor c(img.pixel(gl->mapTo(&s.w, p)));
            return std::abs(c.redF() - red.r) < 0.1 && std::abs(c.greenF() - red.g) < 0.1 &&
                   std::abs(c.blueF() - red.b) < 0.1;
        };
        const QPoint at = s.pixelOf(f.at.z, f.at.x);
        QTRY_VERIFY_WITH_TIMEOUT(redAt(at), 10000);
        QVERIFY(!redAt(at + QPoint(40, 0)));
        // Its Problems entry activated: the editor on the line, the marker ringed.
        QAbstractItemModel* problems = s.editor->problems()->model();
        QCOMPARE(problems->rowCount(), 1);
        QCOMPARE(problems->index(0, 3).data().toString(), QString("rapid into material"));
        QVERIFY(problems->index(0, 3).data(Qt::ToolTipRole).toString().contains("rapid-into-material"));
        const QPoint ring = at + QPoint(k528::backplot::BackplotScene::kFindingRadiusPx + 8, 0);
        const auto whiteAt = [&](QPoint p) {
            const QImage img = s.w.screen()->grabWindow(s.w.winId()).toImage();
            for (int d = -1; d <= 1; ++d)
                if (QColor(img.pixel(gl->mapTo(&s.w, p + QPoint(d, 0)))).lightnessF() > 0.9)
                    return true;
            return false;
        };
        QVERIFY(!whiteAt(ring));
        emit s.editor->problems()->activated(problems->index(0, 0));
        QTRY_VERIFY_WITH_TIMEOUT(whiteAt(ring), 10000);
        // Made safe: the finding and its marker are gone.
        s.editor->currentEditor()->setText("; UCG,2,Z-80Z0,X40X0,S0S0,0,-5\n"
                                           "%L1 (FACE)\n"
                                           "N1 G90 G0 M3 X44 Z2\n"
                                           "N2 Z-1\n"
                                           "N3 G1 X-1 FX150\n"
                                           "N4 G0 Z2\n"
                                           "N5 X44\n"
                                           "N6 M30\n");
        QTRY_VERIFY_WITH_TIMEOUT(pane->findings().empty() && pane->proofs() > 1, 20000);
        QTRY_VERIFY(s.view->scene().findingsShown().empty());
        QTRY_VERIFY_WITH_TIMEOUT(!redAt(at), 10000);
        QCOMPARE(problems->rowCount(), 0);
    }
    void theWheelZoomsToTheCursor() {
        Studio s;
        QVERIFY(s.showPath());
        auto* gl = s.view->glWidget();
        const QPoint at(gl->width() / 4, gl->height() / 3);
        const auto worldAt = [&] {
            const k528::backplot::ViewWindow vw = s.view->scene().window(gl->width(), gl->height());
            return std::pair{vw.x0 + at.x() * vw.worldPerPixel, vw.y0 + (gl->height() - at.y()) * vw.worldPerPixel};
        };
        const auto before = worldAt();
        const double wpp = s.view->scene().window(gl->width(), gl->height()).worldPerPixel;
        QWheelEvent wheel(QPointF(at), gl->mapToGlobal(QPointF(at)), QPoint(), QPoint(0, 120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(gl, &wheel);
        const double zoomed = s.view->scene().window(gl->width(), gl->height()).worldPerPixel;
        QVERIFY2(zoomed < wpp * 0.9, qPrintable(QString("%1 -> %2").arg(wpp).arg(zoomed)));
        const auto after = worldAt();
        QVERIFY(std::fabs(after.first - before.first) < 1e-6);
        QVERIFY(std::fabs(after.second - before.second) < 1e-6);
    }
    void aRunOnTheSessionsMachineGrowsThePathLive() {
        Studio s;
        QVERIFY(s.view);
        const program::ParseResult parsed = program::parse(kProgram);
        QVERIFY(!parsed.hasErrors());
        studio::SimulationSession* session = s.w.findChild<studio::SimulationSession*>();
        QVERIFY(session);
        session->setRunning(false); // the test drives the time
        // Each tick of the run advances the session by one tick and emits
        // advanced(), the views' frame: the dock draws the batch each time.
        std::vector<std::size_t> shown;
        connect(session, &studio::SimulationSession::advanced, this,
                [&] { shown.push_back(s.view->scene().actualPointsShown()); });
        testrig::WatchedSimulationRun stepper = steppingRun(*session);
        engine::RunOptions ro;
        const engine::RunResult r = engine::runProgram(stepper, parsed.store, 1, ro);
        QCOMPARE(r.status, engine::RunStatus::Completed);
        session->advance(1);
        // The programmed path of the running program (computed on a worker
        // when the run began) comes under the actual one, which stays.
        QTRY_VERIFY(!s.view->computing());
        QVERIFY(shown.size() > 100);
        // It grew: a few points early in the run, many at its end, never fewer.
        std::size_t first = 0;
        while (first < shown.size() && shown[first] == 0)
            ++first;
        QVERIFY(first < shown.size());
        QVERIFY(std::is_sorted(shown.begin() + static_cast<long>(first), shown.end()));
        QVERIFY2(shown[first] * 10 < shown.back(),
                 qPrintable(QString("%1 .. %2").arg(shown[first]).arg(shown.back())));
        // The programmed path of the running program under it.
        QCOMPARE(s.view->scene().path().program, 1);
        QCOMPARE(s.view->scene().path().segments.size(), std::size_t(5));
        // The last point is where the run ended (X60 Z-80).
        QVERIFY(s.view->scene().actualPointsShown() >= 10);
    }
    // Following a run on the session's machine, the live tool is the one in
    // the simulated turret: tool 1, none while M62 indexes, then the grooving tool.
    void theLiveEdgeIsTheTurretsTool() {
        Studio s;
        QVERIFY(s.view);
        const program::ParseResult parsed =
            program::parse("%L1\nN1 G1 X60 FX2000\nN2 M62\nN3 R226=R102\nN4 R227=R103\nN5 G1 Z-20 FZ2000\nM30\n");
        QVERIFY(!parsed.hasErrors());
        studio::SimulationSession* session = s.w.findChild<studio::SimulationSession*>();
        QVERIFY(session);
        session->setRunning(false);
        // The live tool's station the dock hands the scene at each UI frame of
        // the run (the edge is drawn for it at the next render: backplot.tool_edge).
        std::vector<int> stations; // changes only; -1 no live tool
        connect(session, &studio::SimulationSession::advanced, this, [&] {
            const auto& live = s.view->scene().liveTool();
            const int st = live ? live->station : -1;
            if (stations.empty() || stations.back() != st)
                stations.push_back(st);
        });
        testrig::WatchedSimulationRun stepper = steppingRun(*session);
        const engine::RunResult r = engine::runProgram(stepper, parsed.store, 1, engine::RunOptions{});
        QCOMPARE(r.status, engine::RunStatus::Completed);
        // Before the program ran no live tool; then tool 1, none while the turret indexed (0), tool 2.
        QCOMPARE(stations, (std::vector<int>{-1, 1, 0, 2}));
    }
    // An endless program (GOTO back to its start): its preview is computed
    // and the blank cut on a worker, up to PathJob::kMaxFrames frames (a
    // count in core, not a time). The window goes on meanwhile: the click
    // returns before the path is there, the event loop turns (a timer fires)
    // while the job runs, the progress row shows how far it got; the view
    // says where the path was cut off. A newer request cancels the one under
    // way, and Cancel stops it.
    void anEndlessProgramNeverFreezesTheWindow() {
        Studio s(kEndless);
        QVERIFY(s.editor->sendToController());
        s.w.findChild<QSpinBox*>("backplot.program")->setValue(1);
        QTRY_VERIFY(!s.view->computing()); // the dock's own first path, if any, is done
        auto* compute = s.w.findChild<QPushButton*>("backplot.computePath");
        auto* busy = s.w.findChild<QWidget*>("backplot.busy");
        auto* bar = s.w.findChild<QProgressBar*>("backplot.progress");
        auto* cancel = s.w.findChild<QToolButton*>("backplot.cancel");
        QVERIFY(compute && busy && bar && cancel);
        QVERIFY(busy->isHidden());
        // What the progress row said each time it appeared.
        struct ShowSpy : QObject {
            QWidget* row = nullptr;
            QStringList said;
            int largest = 0;
            bool eventFilter(QObject* o, QEvent* e) override {
                if (o == row && e->type() == QEvent::Show) {
                    for (QLabel* l : row->findChildren<QLabel*>())
                        said << l->text();
                    largest = std::max(largest, row->findChild<QProgressBar*>()->value());
                }
                return false;
            }
        } rowSpy;
        rowSpy.row = busy;
        busy->installEventFilter(&rowSpy);
        int beatsWhileComputing = 0;
        QTimer beat;
        beat.setInterval(0);
        connect(&beat, &QTimer::timeout, [&] {
            if (s.view->computing())
                ++beatsWhileComputing;
        });
        beat.start();
        QSignalSpy shown(s.view, &BackplotWidget::pathShown);
        compute->click();
        QVERIFY(s.view->computing()); // the click returned before the path was computed
        QCOMPARE(shown.count(), 0);
        QVERIFY(shown.wait(60000));
        beat.stop();
        QVERIFY2(beatsWhileComputing > 0, "the event loop did not turn while the path was computed");
        QVERIFY2(!rowSpy.said.isEmpty(), "the progress row never showed");
        QVERIFY2(rowSpy.said.first().startsWith(QStringLiteral("L1")), qPrintable(rowSpy.said.join(" | ")));
        QVERIFY(busy->isHidden()); // gone with the job
        QCOMPARE(s.view->scene().path().run.status, engine::PreviewStatus::Limit);
        QCOMPARE(s.view->scene().path().run.frames, k528::studio::backplot::PathJob::kMaxFrames);
        QVERIFY(s.view->scene().path().segments.size() > 50000);
        QCOMPARE(s.view->statusText(),
                 BackplotWidget::tr("L%1 does not end within %2 frames (an endless loop?): the path shows those frames")
                     .arg(1)
                     .arg(QLocale(k528::studio::currentLanguage() == "ru" ? QLocale::Russian : QLocale::English)
                              .toString(k528::studio::backplot::PathJob::kMaxFrames)));

        // Two requests: the first is cancelled, only the second is shown.
        shown.clear();
        compute->click();
        compute->click();
        QVERIFY(shown.wait(60000));
        QTRY_VERIFY(!s.view->computing());
        QCOMPARE(shown.count(), 1);
        // Cancel (before the worker's end reaches the window, whenever that
        // is): nothing replaces the path shown, the view says so.
        const std::size_t before = s.view->scene().path().segments.size();
        shown.clear();
        compute->click();
        QVERIFY(s.view->computing());
        cancel->click();
        QTRY_VERIFY_WITH_TIMEOUT(!s.view->computing(), 60000);
        QTest::qWait(50);
        QCOMPARE(shown.count(), 0);
        QCOMPARE(s.view->statusText(), BackplotWidget::tr("L%1: the path was not computed (cancelled)").arg(1));
        QVERIFY(busy->isHidden());
        QCOMPARE(s.view->scene().path().segments.size(), before);
        // Computed again after a cancel: shown as before.
        compute->click();
        QVERIFY(shown.wait(60000));
        QCOMPARE(s.view->scene().path().run.frames, k528::studio::backplot::PathJob::kMaxFrames);
    }
    // The progress row and the note of a path cut off lie inside the main
    // window placed on the screen, in Russian and in English; each is
    // saved as the X server shows it (tests/screenshots/backplot-*.png).
    // A long job: an endless loop of legs that never repeat, the blank cut
    // by every one of them.
    void theProgressAndTheNoteAreInTheWindow() {
        for (const QString& language : {QStringLiteral("ru"), QStringLiteral("en")}) {
            QVERIFY(k528::studio::setLanguage(language));
            Studio s("%L1 (ENDLESS)\n"
                     "; UCG,2,Z-100Z0,X50X0,S0S0,0,-5\n"
                     "N1 G1 X40 FX2000\n"
                     "N2 G91 G1 Z-0.001 FZ2000\n"
                     "N3 GOTO 2\n");
            s.w.placeOnScreen();
            QVERIFY(s.editor->sendToController());
            s.w.findChild<QSpinBox*>("backplot.program")->setValue(1);
            QTRY_VERIFY(!s.view->computing());
            auto* busy = s.w.findChild<QWidget*>("backplot.busy");
            auto* cancel = s.w.findChild<QToolButton*>("backplot.cancel");
            auto* status = s.w.findChild<QLabel*>("backplot.status");
            QVERIFY(busy && cancel && status);
            const QRect inside = s.w.rect();
            const auto within = [&](QWidget* x) {
                const QRect r(x->mapTo(&s.w, QPoint(0, 0)), x->size());
                return x->isVisible() && !r.isEmpty() && inside.contains(r);
            };
            const QString dir = QStringLiteral(K528_BINARY_DIR "/tests/screenshots");
            QDir().mkpath(dir);
            const QString size = QStringLiteral("%1x%2").arg(s.w.screen()->size().width()).arg(s.w.screen()->size().height());
            QSignalSpy shown(s.view, &BackplotWidget::pathShown);
            s.w.findChild<QPushButton*>("backplot.computePath")->click();
            QTRY_VERIFY_WITH_TIMEOUT(busy->isVisible() || !s.view->computing(), 60000);
            QTest::qWait(150); // laid out and painted
            if (s.view->computing()) {
                QVERIFY2(within(busy) && within(cancel), "the progress row is outside the window");
                K528_VERIFY_SHOT(s.w.screen()->grabWindow(s.w.winId()),
                                 QStringLiteral("backplot-progress-%1-%2.png").arg(language, size));
            } else {
                qInfo("the path was computed before its progress could be photographed");
            }
            // Shown already (a fast machine: while the progress was awaited)
            // or shown later; wait() alone waits for a second showing.
            QVERIFY(shown.count() > 0 || shown.wait(120000));
            QTRY_VERIFY_WITH_TIMEOUT(!status->text().isEmpty(), 20000); // laid out with its text
            QVERIFY2(within(status), "the note is outside the window");
            K528_VERIFY_SHOT(s.w.screen()->grabWindow(s.w.winId()),
                             QStringLiteral("backplot-cut-off-%1-%2.png").arg(language, size));
        }
        QVERIFY(k528::studio::setLanguage(QStringLiteral("en")));
    }
    void screenshotOfTheStudioShowsWideVerticalLinesClean() {
        Studio s;
        QVERIFY(s.showPath());
        s.view->selectLine(1, 6); // N5 drawn 4 px wide
        auto* gl = s.view->glWidget();
        gl->update();
        // Painted when the feed's colour is on the screen in the middle of N3
        // (Z-40, X60 to X20): a wait on the picture, not on the clock.
        const auto feedOnScreen = [&] {
            const QImage img = s.w.screen()->grabWindow(s.w.winId()).toImage();
            const QPoint m = gl->mapTo(&s.w, s.pixelOf(-40, 40));
            const auto& fc = k528::backplot::kFeedColour;
            for (int dx = -4; dx <= 4; ++dx) {
                const QColor c(img.pixel(m.x() + dx, m.y()));
                if (std::abs(c.redF() - fc.r) < 0.1 && std::abs(c.greenF() - fc.g) < 0.1 &&
                    std::abs(c.blueF() - fc.b) < 0.1)
                    return true;
            }
            return false;
        };
        QTRY_VERIFY_WITH_TIMEOUT(feedOnScreen(), 20000);
        // From the X server, as a user sees it.
        gl->makeCurrent();
        qInfo() << "max hardware line width" << gl->renderWindow()->GetMaximumHardwareLineWidth()
                << "deprecated functions" << gl->context()->format().testOption(QSurfaceFormat::DeprecatedFunctions)
                << gl->context()->format();
        gl->doneCurrent();
        const QImage shot = s.w.screen()->grabWindow(s.w.winId()).toImage();
        QVERIFY(!shot.isNull());
        K528_VERIFY_SHOT(shot, QStringLiteral("studio_backplot.png"));
        {
            const QPoint c = gl->mapTo(&s.w, s.pixelOf(-40, 50));
            K528_VERIFY_SHOT(shot.copy(c.x() - 30, c.y() - 30, 60, 60).scaled(480, 480),
                             QStringLiteral("studio_backplot_zoom.png"));
        }
        // The feed N3 runs vertically at Z-40 from X60 to X20, 2 px wide as
        // offscreen. Every row across it must hold the same amount of the
        // feed's colour: the coverage, the sum over the pixels of how far each
        // lies from the background towards the feed colour (an edge pixel
        // counts in part, wherever the line falls between pixel centres). A
        // fringe alternates rows; a context without wide lines gives 1.
        const QPoint origin = gl->mapTo(&s.w, QPoint(0, 0));
        // Its rows away from both ends (the corners and the points' diamonds).
        QPoint top = s.pixelOf(-40, 60), bottom = s.pixelOf(-40, 20);
        top.ry() += 6;
        bottom.ry() -= 6;
        const int x = top.x() + origin.x();
        const auto& bg = k528::backplot::kBackground;
        const auto& fc = k528::backplot::kFeedColour;
        const double dr = fc.r - bg.r, dg = fc.g - bg.g, db = fc.b - bg.b;
        const double len2 = dr * dr + dg * dg + db * db;
        QString rows;
        double lowest = 1e9, highest = -1e9;
        int rowsSeen = 0;
        for (int y = top.y() + origin.y(); y <= bottom.y() + origin.y(); ++y, ++rowsSeen) {
            double coverage = 0;
            for (int dx = -4; dx <= 4; ++dx) {
                const QColor c(shot.pixel(x + dx, y));
                const double pr = c.redF() - bg.r, pg = c.greenF() - bg.g, pb = c.blueF() - bg.b;
                const double t = std::clamp((pr * dr + pg * dg + pb * db) / len2, 0.0, 1.0);
                const double off = std::hypot(pr - t * dr, pg - t * dg, pb - t * db);
                if (off < 0.08) // a blend of background and feed, nothing else
                    coverage += t;
            }
            lowest = std::min(lowest, coverage);
            highest = std::max(highest, coverage);
            if (rows.size() < 800)
                rows += QString::number(coverage, 'f', 2) + " ";
        }
        QVERIFY(rowsSeen > 12);
        QVERIFY2(lowest >= 1.6 && highest <= 2.4, qPrintable("coverage per row: " + rows));
        QVERIFY2(highest - lowest <= 0.3, qPrintable("rows differ: " + rows));
    }
};

int main(int argc, char** argv) {
    studio::backplot::VtkGlWidget::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    TestBackplotStudio t;
    return QTest::qExec(&t, argc, argv);
}

#include "test_backplot_studio.moc"
