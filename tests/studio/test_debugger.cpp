// The editor's debugger on the simulated machine: a breakpoint
// then «Run» (drives on, homing as the operator would, АВТОМАТ, «Пуск»)
// stops before that frame with the engine's frame pointer on it and the
// executing marker in the margin; single frame steps one frame per «Пуск»;
// run to cursor stops inside a subprogram with the call stack; the watch
// list shows live R values and writes them where the engine allows; a
// screenshot of the editor with a breakpoint and the executing frame.
#include "controller/simulated_controller.h"
#include "editor/debug_panel.h"
#include "editor/debug_session.h"
#include "editor/editor_tab.h"
#include "editor/program_editor.h"
#include "profile/builtin.h"
#include "rig/widgets.h"
#include "session/simulation_session.h"

#include <QComboBox>
#include <QDialog>
#include <QPushButton>
#include <QLabel>
#include <QMainWindow>
#include <QSignalSpy>
#include <QTreeWidget>
#include <QtTest>
#include <functional>
#include <memory>

using namespace k528;
using namespace k528::studio;
using engine::ProgramState;

namespace {

// Lines (1-based): 1 %L1, 2 N1, 3 N2, 4 N3, 5 N4, 6 N5, 7 N6, 8 %L5, 9 N1, 10 N2.
const char* kProgram = "%L1 (debug)\n"
                       "N1 R1=5\n"
                       "N2 G91 G1 Z-2 FZ3000\n"
                       "N3 R2=R1+1\n"
                       "N4 L5\n"
                       "N5 R4=R3+R2\n"
                       "N6 M30\n"
                       "%L5 (sub)\n"
                       "N1 R3=7\n"
                       "N2 M17\n";

struct Bench {
    QMainWindow window;
    std::unique_ptr<SimulationSession> session;
    std::unique_ptr<SimulatedController> seamSim;
    std::unique_ptr<ViewedController> seam;
    EditorTab* tab = nullptr;
    ProgramEditor* ed = nullptr;
    DebugPanel* panel = nullptr;

    QList<DebugSession::Phase> phases; // the debugger's phases, in order

    explicit Bench(const std::function<void(profile::MachineProfile&)>& tweak = {}) {
        profile::MachineProfile prof = profile::builtin("training-lathe");
        if (tweak)
            tweak(prof);
        session = std::make_unique<SimulationSession>(prof);
        session->setRunning(false); // the test advances the machine itself
        seamSim = std::make_unique<SimulatedController>(*session);
        seam = std::make_unique<ViewedController>(*seamSim);
        tab = new EditorTab(seam.get(), &window);
        window.setCentralWidget(tab);
        window.resize(1200, 700);
        tab->newFile();
        ed = tab->currentEditor();
        ed->setText(kProgram);
        ed->validateNow();
        panel = tab->debugPanel();
        QObject::connect(panel->debugger(), &DebugSession::changed, panel, [this] {
            if (phases.isEmpty() || phases.back() != panel->debugger()->phase())
                phases << panel->debugger()->phase();
        });
    }
    engine::Positioner& ctl() { return session->controller(); }
    bool until(const std::function<bool()>& done, std::int64_t maxMs) {
        for (std::int64_t t = 0; t < maxMs; t += 10) {
            session->advance(10);
            if (done())
                return true;
        }
        return false;
    }
    bool untilHeldOrEnd(std::int64_t maxMs = 300000) {
        return until(
            [&] {
                const ProgramState s = ctl().state();
                return (panel->debugger()->phase() == DebugSession::Phase::Active ||
                        panel->debugger()->phase() == DebugSession::Phase::Idle) &&
                       (s == ProgramState::Interrupted || s == ProgramState::Ended || s == ProgramState::Alarm);
            },
            maxMs);
    }
    // «Пуск» on the held program: until the controller took it (and ran
    // on to the next stop or the end).
    bool resume(std::int64_t maxMs = 300000) {
        const std::int64_t stops = panel->debugger()->gate().stops();
        panel->resume();
        if (!until([&] { return panel->debugger()->gate().stops() > stops || ctl().state() != ProgramState::Interrupted; },
                   5000))
            return false;
        return untilHeldOrEnd(maxMs);
    }
    bool executingMarkerAt(int line0) {
        return (ed->markersAtLine(line0) & (1 << ProgramEditor::kExecutingMarker)) != 0;
    }
};

} // namespace

class TestDebugger : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QCoreApplication::setOrganizationName("k528-test-debugger"); }

    void breakpointThenRunStopsBeforeThatFrame() {
        Bench b;
        QVERIFY(b.panel);
        b.ed->toggleBreakpoint(3); // line 4: N3 R2=R1+1
        QVERIFY(b.panel->run());
        QVERIFY2(b.untilHeldOrEnd(), qPrintable(b.panel->status()->text()));
        QCOMPARE(b.ctl().state(), ProgramState::Interrupted);
        QVERIFY(b.panel->debugger()->heldByGate());
        const engine::ProgramView v = b.ctl().programView();
        QCOMPARE(v.program, 1);
        QCOMPARE(v.frameNumber, 3);
        QCOMPARE(v.line, 4);
        QCOMPARE(b.ctl().r(254), 3);
        QCOMPARE(b.ctl().r(1), 5);
        QCOMPARE(b.ctl().r(2), 0); // N3 has not executed
        QVERIFY(b.executingMarkerAt(3));
        QVERIFY(b.panel->status()->text().contains("N3"));
        // The training lathe needs its reference points (АВТ.БЕЗ ПБТ = 0):
        // drives on, homing, «Пуск», as the operator would.
        QVERIFY(b.ctl().axisView(engine::AxisId::X).referenced);
        QVERIFY(b.ctl().axisView(engine::AxisId::Z).referenced);
        QVERIFY(b.phases.contains(DebugSession::Phase::Homing));
        QVERIFY(b.phases.contains(DebugSession::Phase::Starting));
        // «Пуск» continues with that frame, to the end.
        QVERIFY(b.resume());
        QCOMPARE(b.ctl().state(), ProgramState::Ended);
        QCOMPARE(b.ctl().r(2), 6);
        QCOMPARE(b.ctl().r(4), 13);
        QVERIFY(!b.executingMarkerAt(3));
    }

    // «Run» on a held program whose «Пуск» the positioner does not take (the
    // K923 turned to РУЧНОЙ meanwhile): the debugger says why within a few
    // seconds of machine time, it does not wait silently.
    void neverASilentWaitForStart() {
        Bench b;
        QSignalSpy said(b.panel->debugger(), &DebugSession::message);
        b.ed->toggleBreakpoint(3);
        QVERIFY(b.panel->run());
        QVERIFY2(b.untilHeldOrEnd(), qPrintable(b.panel->status()->text()));
        QVERIFY(b.panel->debugger()->heldByGate());
        const engine::OpResult manual = b.ctl().selectMode(engine::Mode::Manual);
        QVERIFY2(manual.ok(), "the K923 cannot leave АВТОМАТ while the program is held");
        b.session->advance(50);
        said.clear();
        QVERIFY(b.panel->run()); // continues: «Пуск»
        const auto toldWhy = [&] {
            for (const QList<QVariant>& m : said)
                if (m.first().toString().contains("not in automatic mode"))
                    return true;
            return false;
        };
        QVERIFY(b.until(toldWhy, 5000));
        QCOMPARE(b.ctl().state(), ProgramState::Interrupted);
        // Back in АВТОМАТ, «Run» continues.
        QVERIFY(b.ctl().selectMode(engine::Mode::Auto).ok());
        b.session->advance(50);
        QVERIFY(b.resume());
        QCOMPARE(b.ctl().state(), ProgramState::Ended);
    }

    void homingSkippedWhereTheMachineAllowsIt() {
        Bench b([](profile::MachineProfile& p) {
            p.setC(8, 1); // АВТ.БЕЗ ПБТ X
            p.setC(60, 1);
        });
        b.ed->toggleBreakpoint(3);
        QVERIFY(b.panel->run());
        QVERIFY(b.untilHeldOrEnd());
        QCOMPARE(b.ctl().state(), ProgramState::Interrupted);
        QCOMPARE(b.ctl().programView().frameNumber, 3);
        QVERIFY(!b.phases.contains(DebugSession::Phase::Homing));
        QVERIFY(!b.ctl().axisView(engine::AxisId::X).referenced);
    }

    void singleFrameStepsOneFramePerStart() {
        Bench b;
        b.panel->setSingleFrame(true);
        QVERIFY(b.panel->debugger()->gate().singleFrame());
        QVERIFY(b.panel->run());
        QVERIFY(b.untilHeldOrEnd());
        QCOMPARE(b.ctl().state(), ProgramState::Interrupted);
        QCOMPARE(b.ctl().framesExecuted(), std::int64_t{1});
        QCOMPARE(b.ctl().programView().frameNumber, 2);
        QVERIFY(b.executingMarkerAt(2));
        // N2 (motion), N3, N4 (the call), L5 N1, L5 N2 (M17), N5, N6 (M30).
        const int expected[] = {3, 4, 1, 2, 5, 6};
        const int program[] = {1, 1, 5, 5, 1, 1};
        for (int k = 0; k < 6; ++k) {
            const std::int64_t before = b.ctl().framesExecuted();
            QVERIFY2(b.resume(), qPrintable(QString("step %1: %2, state %3").arg(k).arg(b.panel->status()->text()).arg(int(b.ctl().state()))));
            QCOMPARE(b.ctl().state(), ProgramState::Interrupted);
            QCOMPARE(b.ctl().framesExecuted(), before + 1); // one frame per «Пуск»
            QCOMPARE(b.ctl().programView().program, program[k]);
            QCOMPARE(b.ctl().programView().frameNumber, expected[k]);
            QVERIFY(b.executingMarkerAt(b.ctl().programView().line - 1));
        }
        QVERIFY(b.resume());
        QCOMPARE(b.ctl().state(), ProgramState::Ended);
        QCOMPARE(b.ctl().framesExecuted(), std::int64_t{8});
    }

    void runToCursorStopsInsideTheSubprogramWithTheCallStack() {
        Bench b;
        b.ed->setCursorPosition(8, 0); // line 9: L5 N1
        QVERIFY(b.panel->runToCursor());
        QVERIFY(b.untilHeldOrEnd());
        QCOMPARE(b.ctl().state(), ProgramState::Interrupted);
        const engine::ProgramView v = b.ctl().programView();
        QCOMPARE(v.program, 5);
        QCOMPARE(v.frameNumber, 1);
        QCOMPARE(v.nesting, 1);
        QVERIFY(b.executingMarkerAt(8));
        QTreeWidget* stack = b.panel->callStack();
        QCOMPARE(stack->topLevelItemCount(), 2);
        QCOMPARE(stack->topLevelItem(0)->text(0), QString("1")); // R158 of the innermost
        QCOMPARE(stack->topLevelItem(0)->text(1), QString("L5"));
        QCOMPARE(stack->topLevelItem(0)->text(2), QString("N1"));
        QCOMPARE(stack->topLevelItem(1)->text(0), QString("0"));
        QCOMPARE(stack->topLevelItem(1)->text(1), QString("L1"));
        QCOMPARE(stack->topLevelItem(1)->text(2), QString("N4")); // the L5 frame
        QCOMPARE(stack->topLevelItem(1)->text(3), QString("5"));
        // Run to a cursor back in the main program, continuing from here.
        b.ed->setCursorPosition(5, 0); // line 6: N5
        const std::int64_t stops = b.panel->debugger()->gate().stops();
        QVERIFY(b.panel->runToCursor());
        QVERIFY(b.until([&] { return b.panel->debugger()->gate().stops() > stops; }, 5000));
        QVERIFY(b.untilHeldOrEnd());
        QCOMPARE(b.ctl().state(), ProgramState::Interrupted);
        QCOMPARE(b.ctl().programView().program, 1);
        QCOMPARE(b.ctl().programView().frameNumber, 5);
        QCOMPARE(b.ctl().r(3), 7);
        QCOMPARE(b.ctl().r(4), 0);
        QCOMPARE(stack->topLevelItemCount(), 1);
        b.panel->stop();
        QVERIFY(b.until([&] { return b.ctl().state() == ProgramState::Idle; }, 2000));
        QCOMPARE(stack->topLevelItemCount(), 0);
    }

    void watchShowsLiveValuesAndWritesWhereAllowed() {
        Bench b;
        QVERIFY(b.panel->addWatch(2));
        QVERIFY(b.panel->addWatch(12));
        QVERIFY(!b.panel->addWatch(300));
        QTreeWidget* w = b.panel->watch();
        const auto itemOf = [&](int n) -> QTreeWidgetItem* {
            for (int i = 0; i < w->topLevelItemCount(); ++i)
                if (w->topLevelItem(i)->data(0, Qt::UserRole).toInt() == n)
                    return w->topLevelItem(i);
            return nullptr;
        };
        QVERIFY(itemOf(2) && itemOf(12) && itemOf(158));
        QVERIFY(!itemOf(158)->text(2).isEmpty()); // appendix Л's meaning
        b.ed->setText("%L1\nN1 R2=3\nN2 G91 G1 Z-2 FZ200\nN3 R2=R12\nN4 M30\n");
        b.ed->validateNow();
        b.ed->toggleBreakpoint(3); // N3
        QVERIFY(b.panel->run());
        // While N2's motion executes, the engine refuses a write.
        QVERIFY(b.until([&] { return b.ctl().r(2) == 3 && b.ctl().state() == ProgramState::Running; }, 300000));
        QCOMPARE(itemOf(2)->text(1), QString("3"));
        QVERIFY(!b.panel->setWatchValue(12, 5));
        QVERIFY(b.untilHeldOrEnd());
        QCOMPARE(b.ctl().state(), ProgramState::Interrupted);
        // Held: the value typed in the watch list goes to the controller.
        itemOf(12)->setText(1, "77");
        QCOMPARE(b.ctl().r(12), 77);
        QCOMPARE(itemOf(12)->text(1), QString("77"));
        itemOf(12)->setText(1, "x");
        QCOMPARE(b.ctl().r(12), 77);
        QCOMPARE(itemOf(12)->text(1), QString("77"));
        QVERIFY(b.resume());
        QCOMPARE(b.ctl().state(), ProgramState::Ended);
        QCOMPARE(itemOf(2)->text(1), QString("77"));
        // A read-only parameter is refused.
        QVERIFY(!b.panel->setWatchValue(254, 1));
    }

    void speedChoices() {
        Bench b;
        QComboBox* s = b.panel->speed();
        QCOMPARE(s->count(), 8);
        s->setCurrentIndex(s->findData(100.0));
        QCOMPARE(b.session->speed(), 100.0);
        QVERIFY(!b.session->isFastest());
        s->setCurrentIndex(s->findData(0.0));
        QVERIFY(b.session->isFastest());
        b.session->setFastest(false);
        b.session->setSpeed(2);
        QCOMPARE(s->currentData().toDouble(), 2.0);
    }

    // Start here: the state before the frame at the cursor rebuilt by the
    // preview, listed in a dialog before the machine moves; Start runs the
    // program from there (homing first, the safe path to the start point)
    // and it ends as the run from the top does; Cancel starts nothing.
    void startHereRebuildsTheStateAndEndsAsTheFullRun() {
        Bench full;
        QVERIFY(full.panel->run());
        QVERIFY(full.untilHeldOrEnd());
        QCOMPARE(full.ctl().state(), ProgramState::Ended);

        Bench b;
        b.window.show();
        b.ed->setCursorPosition(5, 0); // line 6: N5 R4=R3+R2
        QVERIFY(b.panel->startHere());
        QDialog* dlg = b.panel->startDialog();
        QVERIFY(dlg);
        QCOMPARE(b.ctl().state(), ProgramState::Idle); // nothing moves before Start
        auto* list = dlg->findChild<QTreeWidget*>("debug.startHere.state");
        QVERIFY(list);
        QStringList rows;
        for (int i = 0; i < list->topLevelItemCount(); ++i)
            rows << list->topLevelItem(i)->text(0) + ": " + list->topLevelItem(i)->text(1);
        const QString all = rows.join('\n');
        QVERIFY2(all.contains("N5 (line 6)"), qPrintable(all));
        QVERIFY2(all.contains("R1=5 R2=6 R3=7"), qPrintable(all));
        QVERIFY2(all.contains("G01 G54 G55 G91"), qPrintable(all));
        QVERIFY2(all.contains("FZ3000.000"), qPrintable(all));
        QTest::qWait(50);
        K528_VERIFY_SHOT(dlg->grab(), QStringLiteral("debugger-start-here.png"));
        auto* start = dlg->findChild<QPushButton*>("debug.startHere.start");
        QVERIFY(start);
        start->click();
        QVERIFY2(b.untilHeldOrEnd(), qPrintable(b.panel->status()->text()));
        QCOMPARE(b.ctl().state(), ProgramState::Ended);
        QCOMPARE(b.ctl().framesExecuted(), std::int64_t{2}); // N5, N6
        for (int n : {1, 2, 3, 4})
            QCOMPARE(b.ctl().r(n), full.ctl().r(n));
        QCOMPARE(b.ctl().modal(), full.ctl().modal());
        for (engine::AxisId a : {engine::AxisId::X, engine::AxisId::Z})
            QVERIFY(std::llabs(b.ctl().axisView(a).machineDisc - full.ctl().axisView(a).machineDisc) <= 10);

        // Cancel: nothing starts.
        Bench c;
        c.ed->setCursorPosition(8, 0); // line 9: L5 N1
        QVERIFY(c.panel->startHere());
        QVERIFY(c.panel->startDialog());
        c.panel->startDialog()->findChild<QPushButton*>("debug.startHere.cancel")->click();
        c.session->advance(2000);
        QCOMPARE(c.ctl().state(), ProgramState::Idle);
        QCOMPARE(c.panel->debugger()->phase(), DebugSession::Phase::Idle);
        QVERIFY(!c.ctl().startPoint());
    }

    void screenshotWithBreakpointAndExecutingFrame() {
        Bench b;
        b.window.show();
        b.ed->toggleBreakpoint(3);
        b.ed->toggleBreakpoint(8);
        b.panel->addWatch(2);
        b.panel->addWatch(3);
        QVERIFY(b.panel->run());
        QVERIFY(b.untilHeldOrEnd());
        QVERIFY(b.resume());
        QCOMPARE(b.ctl().state(), ProgramState::Interrupted);
        QVERIFY(b.executingMarkerAt(8)); // the breakpoint's line, inside L5
        QTest::qWait(50);
        const QImage img = b.window.grab().toImage();
        K528_VERIFY_SHOT(img, QStringLiteral("debugger-screenshot.png"));
    }
};

QTEST_MAIN(TestDebugger)
#include "test_debugger.moc"
