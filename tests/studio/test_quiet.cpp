// A quiet studio (needs X: the backplot's OpenGL view is part of the window):
// while nothing changes, the session's frames slow to the idle rate and no
// view repaints but the machine-time clock once a second; an input wakes the
// session at once; while a program runs, each view repaints at most at its
// frame rate; and the machine keeps real time at either rate.
#include <QtTest>

#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QLabel>
#include <QMap>
#include <QTemporaryDir>

#include "backplot/backplot_widget.h"
#include "backplot/vtk_gl_widget.h"
#include "editor/debug_panel.h"
#include "editor/debug_session.h"
#include "editor/editor_tab.h"
#include "editor/program_editor.h"
#include "main_window.h"
#include "profile/builtin.h"
#include "rig/loop_program.h"
#include "scope/scope_view.h"
#include "session/simulation_session.h"
#include "workspace/workspaces.h"

using k528::studio::MainWindow;
using k528::studio::SimulationSession;

namespace {

// Counts the paint events of every widget of the application.
class PaintCounter : public QObject {
public:
    PaintCounter() { qApp->installEventFilter(this); }
    ~PaintCounter() override { qApp->removeEventFilter(this); }
    QMap<QString, int> byWidget;
    int total = 0;
    bool eventFilter(QObject* o, QEvent* e) override {
        if (e->type() == QEvent::Paint && o->isWidgetType()) {
            ++total;
            QString name = o->objectName();
            for (QObject* p = o->parent(); name.isEmpty() && p; p = p->parent())
                name = p->objectName().isEmpty() ? QString() : p->objectName() + "/";
            ++byWidget[QString::fromLatin1(o->metaObject()->className()) + " " + name];
        }
        return false;
    }
    QString report() const {
        QStringList l;
        for (auto it = byWidget.begin(); it != byWidget.end(); ++it)
            l << QStringLiteral("%1: %2").arg(it.key()).arg(it.value());
        return l.join("; ");
    }
    void clear() {
        byWidget.clear();
        total = 0;
    }
};

} // namespace

class TestQuiet : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("K528StudioTest");
        QSettings().clear();
    }

    void idleWindowRepaintsOnlyTheClock() {
        MainWindow w;
        w.resize(1366, 740);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        SimulationSession* s = w.session();
        // Start-up settles: the idle rate.
        QTRY_VERIFY_WITH_TIMEOUT(s->isIdle(), 5000);
        QCOMPARE(s->frameIntervalMs(), SimulationSession::kIdleIntervalMs);
        QTest::qWait(1000); // what start-up posted (layouts, the first status texts)
        PaintCounter paints;
        QElapsedTimer real;
        real.start();
        const std::int64_t sim0 = s->timeMs();
        QTest::qWait(3000);
        const std::int64_t simMs = s->timeMs() - sim0;
        const qint64 realMs = real.elapsed();
        qInfo() << "idle paints in 3 s:" << paints.total << paints.report();
        // The machine keeps real time at the idle rate (within a frame).
        QVERIFY2(std::llabs(simMs - realMs) <= 2 * SimulationSession::kIdleIntervalMs,
                 qPrintable(QStringLiteral("simulated %1 ms in %2 ms").arg(simMs).arg(realMs)));
        // The clock of the status bar once a second: the strip of the status
        // bar (its labels, the size grip, the window under them), about once
        // a second each; nothing else.
        for (auto it = paints.byWidget.begin(); it != paints.byWidget.end(); ++it) {
            const bool strip = it.key().contains("status") || it.key().startsWith("QStatusBar") ||
                               it.key().startsWith("QSizeGrip") || it.key().contains("MainWindow");
            QVERIFY2(strip, qPrintable(paints.report()));
            QVERIFY2(it.value() <= 2 * 4, qPrintable(paints.report()));
        }
        QVERIFY(s->isIdle());
    }

    void anInputWakesTheSessionAtOnce() {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        SimulationSession* s = w.session();
        QTRY_VERIFY_WITH_TIMEOUT(s->isIdle(), 5000);
        QSignalSpy frames(s, &SimulationSession::advanced);
        // A click anywhere in the window: a frame at once, then the fast rate.
        QTest::mouseClick(w.workArea(), Qt::LeftButton);
        QVERIFY(frames.count() >= 1);
        QCOMPARE(s->frameIntervalMs(), SimulationSession::kFrameIntervalMs);
        QVERIFY(!s->isIdle());
        // Nothing changed: idle again after the settling time.
        QTRY_VERIFY_WITH_TIMEOUT(s->isIdle(), 3000);
    }

    void aRunningProgramRepaintsAtMostAtTheFrameRate() {
        QTemporaryDir dir;
        const QString path = dir.filePath("loop.k528");
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(k528::testrig::kLoopProgram);
        }
        k528::profile::MachineProfile p = k528::profile::builtin("training-lathe");
        p.setC(8, 1); // АВТ.БЕЗ ПБТ: no homing
        p.setC(60, 1);
        MainWindow w(k528::studio::MachineChoice{p, {}, QString()});
        w.resize(1366, 740);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.workspaces()->activate("training")); // the backplot beside the panels
        k528::studio::EditorTab* editor = w.programEditor();
        editor->setCloseQuestion([](const QString&) { return k528::studio::EditorTab::CloseChoice::Discard; });
        QVERIFY(editor->openFile(path));
        QVERIFY(editor->debugPanel()->run());
        SimulationSession* s = w.session();
        QTRY_VERIFY_WITH_TIMEOUT(editor->debugPanel()->debugger()->phase() ==
                                     k528::studio::DebugSession::Phase::Active,
                                 10000);
        QTest::qWait(500);
        PaintCounter paints;
        QSignalSpy frames(s, &SimulationSession::advanced);
        auto* bp = w.findChild<k528::studio::backplot::BackplotWidget*>();
        QVERIFY(bp);
        const long gl0 = bp->glWidget()->framesPainted();
        QElapsedTimer real;
        real.start();
        const std::int64_t sim0 = s->timeMs();
        QTest::qWait(2000);
        const double seconds = static_cast<double>(real.elapsed()) / 1000.0;
        const std::int64_t simMs = s->timeMs() - sim0;
        qInfo() << "running:" << frames.count() << "frames," << paints.total << "paints in" << seconds
                << "s; backplot" << bp->glWidget()->framesPainted() - gl0 << paints.report();
        QVERIFY(!s->isIdle());
        QVERIFY(std::llabs(simMs - real.elapsed()) <= 100);
        // The session's frames at its rate (30 Hz), not more.
        QVERIFY(frames.count() <= seconds * 1000.0 / SimulationSession::kFrameIntervalMs + 3);
        QVERIFY(frames.count() >= seconds * 1000.0 / SimulationSession::kFrameIntervalMs / 3);
        // The backplot draws the live path at most at its own rate.
        QVERIFY(bp->glWidget()->framesPainted() - gl0 <=
                seconds * 1000.0 / k528::studio::backplot::BackplotWidget::kLiveIntervalMs + 3);
        QVERIFY(bp->glWidget()->framesPainted() - gl0 >= 2);
        // The oscilloscope's charts at most at theirs.
        const int scopeMax = static_cast<int>(seconds * 1000.0 / k528::studio::ScopeView::kLiveIntervalMs) + 3;
        for (auto it = paints.byWidget.begin(); it != paints.byWidget.end(); ++it)
            if (it.key().contains("scope.chart"))
                QVERIFY2(it.value() <= scopeMax && it.value() >= 2, qPrintable(paints.report()));
        // No widget repaints more often than the frames come (the window
        // itself is painted under each of its children that changed).
        for (auto it = paints.byWidget.begin(); it != paints.byWidget.end(); ++it)
            QVERIFY2(it.value() <= (it.key().contains("MainWindow") ? 2 : 1) * frames.count() + 3,
                     qPrintable(paints.report()));
    }
};

QTEST_MAIN(TestQuiet)
#include "test_quiet.moc"
