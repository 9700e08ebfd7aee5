// The studio as its three users use it, on the real main window under an X
// server at the screen size CTest gives it (xvfb-run: 1366×768, 1920×1080):
//   the trainee      — Training workspace: drives on, reference points, АВТОМАТ,
//                      the program to its end, the actual path drawn;
//   the technologist — Technologist workspace: open a file, type an error and
//                      see it in Problems, fix it, run to a breakpoint in the
//                      debugger, Ctrl+S saves;
//   the operator     — Operator workspace: Controller > Connect to `k528 serve`
//                      on a socat pty pair, the live state, an alarm.
// Every control a scenario uses must lie inside the screen (none reached by
// moving the window); each saves a screenshot of its workspace under
// build/…/tests/screenshots/. Waits are on conditions with generous bounds.
#include "backplot/backplot_widget.h"
#include "backplot/vtk_gl_widget.h"
#include "controller/controller_dock.h"
#include "controller/link_controller.h"
#include "editor/debug_panel.h"
#include "editor/debug_session.h"
#include "editor/editor_tab.h"
#include "editor/program_editor.h"
#include "k923/k923_widget.h"
#include "k923/panel_key.h"
#include "language.h"
#include "machine/machine_panel.h"
#include "machine/pendant_controls.h"
#include "machine/status_views.h"
#include "main_window.h"
#include "pty_line.h"
#include "session/machine_source.h"
#include "session/simulation_session.h"
#include "workspace/workspaces.h"

#include "rig/widgets.h"

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QProcess>
#include <QPushButton>
#include <QScreen>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QTreeView>
#include <QTreeWidget>
#include <QtTest>
#include <functional>

using namespace k528;
using namespace k528::studio;

namespace {

QRect screenArea() { return QGuiApplication::primaryScreen()->availableGeometry(); }

QString screenName() {
    const QRect a = QGuiApplication::primaryScreen()->geometry();
    return QStringLiteral("%1x%2").arg(a.width()).arg(a.height());
}

using k528::testrig::shownRect;

// A control the user is about to use: shown, whole (not cut by a pane), and
// inside the screen.
bool reachable(const QWidget* w, QString* why) {
    if (!w || !w->isVisible()) {
        *why = QStringLiteral("%1 is not shown").arg(w ? w->objectName() : QStringLiteral("(none)"));
        return false;
    }
    const QRect r = shownRect(w);
    if (r.isEmpty() || !screenArea().contains(r)) {
        *why = QStringLiteral("%1 at %2,%3 %4x%5 is not inside the screen %6x%7")
                   .arg(w->objectName())
                   .arg(r.x())
                   .arg(r.y())
                   .arg(r.width())
                   .arg(r.height())
                   .arg(screenArea().width())
                   .arg(screenArea().height());
        return false;
    }
    return true;
}


// The window's menu title `object` ("menu.controller") inside the screen.
bool menuReachable(MainWindow& w, QMenu* menu, QString* why) {
    const QRect r(w.menuBar()->mapToGlobal(w.menuBar()->actionGeometry(menu->menuAction()).topLeft()),
                  w.menuBar()->actionGeometry(menu->menuAction()).size());
    if (r.isEmpty() || !screenArea().contains(r)) {
        *why = menu->title() + QStringLiteral(" is not inside the screen");
        return false;
    }
    return true;
}

// Waits for `done` up to `ms` of wall time (QTRY counts its steps, and a
// busy event loop makes each step longer than it says).
bool until(const std::function<bool()>& done, int ms) {
    QElapsedTimer t;
    t.start();
    while (!done()) {
        if (t.elapsed() > ms)
            return false;
        QTest::qWait(20);
    }
    return true;
}

#define UNTIL(cond, ms) QVERIFY2(until([&] { return static_cast<bool>(cond); }, (ms)), "waited in vain for " #cond)

// A control the user is about to use, reachable once the window has laid it
// out (a pane shown a moment ago gets its size with the next layout pass,
// later on a busy machine); one that never gets there fails.
#define REACH(w)                                                                                                       \
    do {                                                                                                               \
        QString why_;                                                                                                  \
        QVERIFY2(until([&] { return reachable((w), &why_); }, 5000), qPrintable(why_));                               \
    } while (false)

void clickCap(PendantButton* b) { QTest::mouseClick(b, Qt::LeftButton, {}, b->capRect().center().toPoint()); }

// The workspace switched with its button in the menu bar's corner.
bool switchTo(MainWindow& w, const QString& id, QString* why) {
    auto* button = w.workspaces()->switcher()->findChild<QAbstractButton*>("workspaces.button." + id);
    if (!reachable(button, why))
        return false;
    QTest::mouseClick(button, Qt::LeftButton);
    // Switched; the deferred share of the docks is awaited by REACH, the
    // checks that follow.
    return until([&] { return w.workspaces()->current() == id; }, 5000);
}

void screenshot(MainWindow& w, const QString& what) {
    // What the X server shows (the backplot's OpenGL as composed there).
    QApplication::processEvents();
    K528_VERIFY_SHOT(w.screen()->grabWindow(w.winId()), QStringLiteral("scenario-%1-%2.png").arg(screenName(), what));
}

struct Window {
    MainWindow w;
    Window() : w(loadMachine("training-lathe")) {
        w.setAttribute(Qt::WA_DeleteOnClose, false);
        w.placeOnScreen();
        w.show();
        // The keyboard's shortcuts act in the active window.
        w.activateWindow();
        active = QTest::qWaitForWindowActive(&w);
    }
    bool active = false;
    ~Window() {
        w.programEditor()->setCloseQuestion([](const QString&) { return EditorTab::CloseChoice::Discard; });
        w.close();
    }
};

} // namespace

class TestScenarios : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("K528StudioTestScenarios");
        QSettings().clear();
        QVERIFY(setLanguage("ru"));
        QVERIFY(dir_.isValid());
        QVERIFY2(QGuiApplication::platformName() == QLatin1String("xcb"), "run under an X server (xvfb-run)");
        qInfo("screen %s, available %dx%d", qPrintable(screenName()), screenArea().width(), screenArea().height());
    }
    void init() { QSettings().clear(); }

    void trainee() {
        Window win;
        MainWindow& w = win.w;
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QString why;
        QVERIFY2(switchTo(w, "training", &why), qPrintable(why));
        QVERIFY(screenArea().contains(w.frameGeometry()));
        engine::Positioner& ctl = w.session()->controller();
        // Ten times real time (Simulation > Speed), as a trainer does to get on.
        QAction* fast = w.findChild<QAction*>("action.simulation.speed10");
        QVERIFY(fast);
        QVERIFY2(menuReachable(w, w.findChild<QMenu*>("menu.simulation"), &why), qPrintable(why));
        fast->trigger();
        MachinePanelWidget* panel = w.machinePanel();
        K923Widget* k923 = w.k923();

        // Drives on at the machine's panel.
        PendantButton* drives = panel->button(machine::Button::DrivesOn);
        REACH(drives);
        clickCap(drives);
        UNTIL(ctl.axisView(engine::AxisId::X).loopClosed && ctl.axisView(engine::AxisId::Z).loopClosed,
                                 30000);
        UNTIL(drives->lit(), 10000);

        // Reference points: F3 on the K923, then +X and +Z on the machine's panel.
        PanelKey* f3 = k923->key(panel::Key::F3);
        REACH(f3);
        QTest::mouseClick(f3, Qt::LeftButton);
        UNTIL((ctl.mode()) == (engine::Mode::Reference), 10000);
        for (const auto& [button, axis] : {std::pair{machine::Button::JogXPlus, engine::AxisId::X},
                                           std::pair{machine::Button::JogZPlus, engine::AxisId::Z}}) {
            PendantButton* jog = panel->button(button);
            REACH(jog);
            clickCap(jog);
            UNTIL(ctl.axisView(axis).referenced, 180000);
        }
        UNTIL(panel->lamp("reference")->isOn(), 10000);

        // АВТОМАТ (F1), the program selected there (L1), «Пуск».
        PanelKey* f1 = k923->key(panel::Key::F1);
        REACH(f1);
        QTest::mouseClick(f1, Qt::LeftButton);
        UNTIL((ctl.mode()) == (engine::Mode::Auto), 10000);
        // ACK, the program's number, ENTER (table 3: the program of АВТОМАТ).
        for (panel::Key k : {panel::Key::Ack, panel::Key::D1, panel::Key::Enter}) {
            PanelKey* key = k923->key(k);
            REACH(key);
            QTest::mouseClick(key, Qt::LeftButton);
        }
        UNTIL((ctl.programView().selectedProgram) == (1), 10000);
        auto* plot = w.findChild<k528::studio::backplot::BackplotWidget*>();
        QVERIFY(plot);
        REACH(plot->glWidget());
        PendantButton* start = panel->button(machine::Button::CycleStart);
        REACH(start);
        clickCap(start);
        UNTIL(engine::programActive(ctl.state()), 10000);
        // To its end (M30).
        UNTIL(ctl.state() == engine::ProgramState::Ended || ctl.state() == engine::ProgramState::Alarm,
                                 600000);
        QCOMPARE(ctl.state(), engine::ProgramState::Ended);
        // The actual path drawn over the programmed one.
        UNTIL(plot->scene().actualPointsShown() > 50, 10000);
        QCOMPARE(plot->scene().path().program, 1);
        screenshot(w, "training");
    }

    void technologist() {
        const QString path = dir_.filePath("shaft.k528");
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("%L7 (shaft)\n"
                    "N1 G90 G1 X40 FX2000\n"
                    "N2 G1 Z-20 FZ2000\n"
                    "N3 R1=5\n"
                    "N4 G1 X30 FX2000\n"
                    "N5 M30\n");
        }
        Window win;
        MainWindow& w = win.w;
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(win.active);
        QString why;
        QVERIFY2(switchTo(w, "technologist", &why), qPrintable(why));
        EditorTab* tab = w.programEditor();
        REACH(tab);

        // Open the file: Ctrl+O, the file dialog, its name typed, Enter.
        QString dialogSeen;
        QTimer poll;
        poll.setInterval(100);
        connect(&poll, &QTimer::timeout, this, [&] {
            auto* d = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
            if (!d)
                return;
            dialogSeen = d->windowTitle();
            auto* name = d->findChild<QLineEdit*>("fileNameEdit");
            if (name) {
                name->setText(path);
                QTest::keyClick(name, Qt::Key_Return);
            } else {
                d->selectFile(path);
                QMetaObject::invokeMethod(d, "accept");
            }
        });
        poll.start();
        // The first start shows the machine's sample: the file opens beside it.
        QCOMPARE(tab->documentCount(), 1);
        QVERIFY(tab->pathOf(0).isEmpty());
        tab->setFocus();
        QTest::keyClick(tab, Qt::Key_O, Qt::ControlModifier);
        UNTIL(tab->documentCount() == 2, 20000);
        poll.stop();
        // The dialog had the focus: back to the window, as the user is.
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(!dialogSeen.isEmpty());
        QCOMPARE(tab->pathOf(1), QFileInfo(path).absoluteFilePath());
        ProgramEditor* ed = tab->currentEditor();
        REACH(ed);
        REACH(tab->problems());

        // An error typed: a new frame after N3 with «X5..3».
        ed->setFocus();
        ed->setCursorPosition(4, 0);
        QTest::keyClicks(ed, "N9 G1 X5..3 FX100");
        QTest::keyClick(ed, Qt::Key_Return);
        QAbstractItemModel* problems = tab->problems()->model();
        UNTIL(problems->rowCount() == 1, 10000);
        QCOMPARE(problems->index(0, 2).data().toString(), QString("5"));
        QCOMPARE(problems->index(0, 3).data().toString(), QString("[M33] неверное число"));
        QCOMPARE(problems->index(0, 3).data(Qt::ToolTipRole).toString(), QString("bad-number"));
        // Fixed: one «.» deleted («X5.3»).
        const int dot = static_cast<int>(ed->text(4).indexOf(".."));
        QVERIFY(dot > 0);
        ed->setCursorPosition(4, dot);
        QTest::keyClick(ed, Qt::Key_Delete);
        UNTIL(problems->rowCount() == 0, 10000);
        QCOMPARE(ed->text(4).trimmed(), QString("N9 G1 X5.3 FX100"));

        // The debugger, on demand (View menu): a breakpoint on N4 (line 6)
        // clicked in the margin, the speed ×20, F5.
        QAction* showDebugger = w.debuggerDock()->toggleViewAction();
        QMenu* view = nullptr;
        for (QAction* m : w.menuBar()->actions())
            if (m->menu() && m->menu()->actions().contains(showDebugger))
                view = m->menu();
        QVERIFY(view);
        QVERIFY2(menuReachable(w, view, &why), qPrintable(why));
        showDebugger->trigger();
        UNTIL(w.debuggerDock()->isVisible(), 5000);
        DebugPanel* debug = tab->debugPanel();
        REACH(debug->findChild<QComboBox*>("debug.speed"));
        debug->speed()->setCurrentIndex(debug->speed()->findData(20.0));
        const int line = 5; // 0-based: N4
        const int y = static_cast<int>(ed->SendScintilla(QsciScintilla::SCI_POINTYFROMPOSITION, 0L,
                                                         ed->positionFromLineIndex(line, 0))) +
                      ed->textHeight(line) / 2;
        const QPoint margin(ed->marginWidth(0) + ed->marginWidth(1) / 2, y);
        QTest::mouseClick(ed->viewport(), Qt::LeftButton, {}, margin);
        QCOMPARE(ed->breakpointLines(), QList<int>{line});
        for (QAction* a : debug->findChildren<QAction*>())
            if (a->objectName() == "debug.run") {
                QWidget* runButton = nullptr;
                for (QObject* o : a->associatedObjects())
                    if (auto* b = qobject_cast<QAbstractButton*>(o))
                        runButton = b;
                REACH(runButton);
            }
        ed->setFocus();
        QTest::keyClick(ed, Qt::Key_F5);
        UNTIL(debug->debugger()->heldByGate(), 240000);
        const engine::ProgramView v = w.session()->controller().programView();
        QCOMPARE(v.program, 7);
        QCOMPARE(v.frameNumber, 4);
        QCOMPARE(w.session()->controller().r(1), 5); // N3 ran, N4 has not
        QVERIFY2(debug->status()->text().contains("N4"), qPrintable(debug->status()->text()));
        REACH(debug->status());

        // Ctrl+S saves the file.
        QVERIFY(ed->isModified());
        QTest::keyClick(ed, Qt::Key_S, Qt::ControlModifier);
        UNTIL(!ed->isModified(), 5000);
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(QString::fromUtf8(f.readAll()), ed->text());
        screenshot(w, "technologist");
        debug->reset();
    }

    void operatorOnTheLine() {
#ifndef K528_RTU_PLUGIN
        QSKIP("built without the link plugins");
#else
        // A machine that overran its X+ limit switch (a training file made
        // from the built-in lathe): the served controller shows the alarm.
        const QString file = dir_.filePath("overrun-lathe.k528m");
        const QString db = dir_.filePath("serve.db");
        for (const QStringList& args : {QStringList{"db", "init", "--db", db},
                                        QStringList{"db", "export", "training-lathe", "--db", db, "--out", file}}) {
            QProcess cmd;
            cmd.start(QStringLiteral(K528_CLI), args);
            QVERIFY(cmd.waitForFinished(30000));
            QVERIFY2(cmd.exitCode() == 0, cmd.readAllStandardError().constData());
        }
        {
            QFile f(file);
            QVERIFY(f.open(QIODevice::ReadOnly));
            QString text = QString::fromUtf8(f.readAll());
            text.replace("\nname=training-lathe\n", "\nname=overrun-lathe\n");
            text += "x.limit_plus_mm=80\nx.start_mm=85\n";
            f.close();
            QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
            f.write(text.toUtf8());
        }
        qputenv("K528_PLUGIN_PATH", QFileInfo(QStringLiteral(K528_RTU_PLUGIN)).absolutePath().toUtf8());
        // Stopped (the ports' lock files removed) on every way out.
        ptytest::PtyPair line;
        ptytest::Serve serve;
        QVERIFY(line.start(dir_.path(), "op", 10000));
        QVERIFY2(serve.start(line.a(), {"--profile", file, "--db", db, "--keys", "F7 1 1 1 1 ENTER DOWN DOWN ENTER"},
                             20000),
                 serve.said().constData());

        {
            Window win;
            MainWindow& w = win.w;
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QString why;
            QVERIFY2(switchTo(w, "operator", &why), qPrintable(why));
            auto* dock = w.findChild<ControllerDock*>("dock.controller");
            QVERIFY(dock);
            // Controller > Connect: the dock asks for the line.
            QVERIFY2(menuReachable(w, dock->menu(), &why), qPrintable(why));
            w.findChild<QAction*>("action.controller.connect")->trigger();
            UNTIL(dock->isVisible(), 5000);
            REACH(dock->portBox());
            dock->portBox()->lineEdit()->selectAll();
            QTest::keyClicks(dock->portBox()->lineEdit(), line.b());
            auto* connectButton = dock->findChild<QPushButton*>("controller.connect");
            REACH(connectButton);
            QSignalSpy connected(dock, &ControllerDock::connectedChanged);
            QTest::mouseClick(connectButton, Qt::LeftButton);
            UNTIL(!connected.isEmpty(), 20000);
            QVERIFY2(connected.first().first().toBool(), qPrintable(dock->lastMessage()));
            // The live state: the monitor, and the window's views on the real controller.
            UNTIL(dock->monitorLabel()->text().contains("РАБОТА С ПЭВМ"), 15000);
            REACH(dock->monitorLabel());
            QCOMPARE(w.viewedController(), static_cast<Controller*>(dock->link()));
            // The alarm: the limit switch, in the live monitor and the messages.
            UNTIL(dock->monitorLabel()->text().contains("Конечник оси X"), 15000);
            MessagesView* messages = w.messagesView();
            REACH(messages);
            const auto listed = [&] {
                for (int i = 0; i < messages->list()->topLevelItemCount(); ++i)
                    if (messages->list()->topLevelItem(i)->text(2).contains("Конечник оси X"))
                        return true;
                return false;
            };
            UNTIL(listed(), 15000);
            screenshot(w, "operator");
            dock->disconnectLine();
        }
#endif
    }
};

QTEST_MAIN(TestScenarios)
#include "test_scenarios.moc"
