// The machine's control panel on the desktop: pressing its buttons with the
// mouse drives the simulated machine (the engine reacts through the PLC),
// its lamps follow the machine; the messages and axes docks show it; the
// session advances with real time, pauses and runs faster.
#include "engine/interface_words.h"
#include "rig/widgets.h"
#include "k923/k923_widget.h"
#include "k923/panel_key.h"
#include "language.h"
#include "machine/machine_panel.h"
#include "machine/pendant_controls.h"
#include "controller/simulated_controller.h"
#include "machine/status_views.h"
#include "main_window.h"
#include "monitor/program_monitor.h"
#include <QComboBox>
#include <QListWidget>
#include "profile/builtin.h"
#include "program/parser.h"
#include "session/program_loader.h"
#include "session/simulation_session.h"

#include <QDockWidget>
#include <QLabel>
#include <QTableWidget>
#include <QTreeWidget>
#include <QtTest>

using namespace k528;
using namespace k528::studio;
namespace z = engine::z;

namespace {

QPoint capCentre(PendantButton* b) {
    return b->capRect().center().toPoint();
}

// Holds a button with the mouse for `ms` of machine time.
void hold(SimulationSession& s, PendantButton* b, std::int64_t ms) {
    QTest::mousePress(b, Qt::LeftButton, {}, capCentre(b));
    s.advance(ms);
    QTest::mouseRelease(b, Qt::LeftButton, {}, capCentre(b));
    s.advance(20);
}

bool waitFor(SimulationSession& s, const std::function<bool()>& done, std::int64_t maxMs) {
    for (std::int64_t t = 0; t < maxMs; t += 10) {
        if (done())
            return true;
        s.advance(10);
    }
    return done();
}

// The text of message `number` ("#2", "W10") in the messages view, "" if not shown.
QString messageShown(MessagesView& v, const QString& number) {
    v.refresh();
    for (int i = 0; i < v.list()->topLevelItemCount(); ++i)
        if (v.list()->topLevelItem(i)->text(1) == number)
            return v.list()->topLevelItem(i)->text(2);
    return {};
}

bool hasMessage(MessagesView& v, const QString& number) {
    for (int i = 0; i < v.list()->topLevelItemCount(); ++i)
        if (v.list()->topLevelItem(i)->text(1) == number)
            return true;
    return false;
}

} // namespace

class TestMachinePanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("K528StudioTest");
        QSettings().clear();
        QVERIFY(setLanguage("en"));
    }

    void buttonsDriveTheMachine() {
        SimulationSession session(profile::builtin("training-lathe"));
        session.setRunning(false); // time by hand: deterministic
        MachinePanelWidget panel(session);
        SimulatedController controller(session);
        MessagesView messages(controller);
        AxesView axes(controller);
        panel.resize(panel.sizeHint());
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        session.advance(20);
        engine::Positioner& ctl = session.controller();
        PendantButton* drives = panel.button(machine::Button::DrivesOn);
        QVERIFY(!drives->lit());
        QVERIFY(hasMessage(messages, "W10")); // «Включите приводы»

        // Drives on: the PLC enables the regulators, the button lights.
        hold(session, drives, 100);
        QVERIFY(waitFor(
            session, [&] { return ctl.axisView(engine::AxisId::X).loopClosed; }, 2000));
        QVERIFY(ctl.words().bit(z::regulatorEnable(engine::AxisId::X)));
        QVERIFY(drives->lit());
        QVERIFY(!hasMessage(messages, "W10"));

        // Reference point: F3 on the K923, then +X / +Z held briefly.
        QVERIFY(ctl.selectMode(engine::Mode::Reference).ok());
        session.advance(20);
        hold(session, panel.button(machine::Button::JogXPlus), 80);
        QVERIFY(ctl.axisView(engine::AxisId::X).homing);
        QVERIFY(waitFor(
            session, [&] { return ctl.axisView(engine::AxisId::X).referenced; }, 120000));
        hold(session, panel.button(machine::Button::JogZPlus), 80);
        QVERIFY(waitFor(
            session, [&] { return ctl.axisView(engine::AxisId::Z).referenced; }, 120000));
        session.advance(30);
        QVERIFY(panel.lamp("reference")->isOn());
        QVERIFY(axes.table()->item(0, 8)->text().contains("homed"));

        // Jog -Z while the button is held, rapid with it.
        QVERIFY(ctl.selectMode(engine::Mode::Manual).ok());
        session.advance(20);
        PendantButton* zMinus = panel.button(machine::Button::JogZMinus);
        const std::int64_t z0 = ctl.axisView(engine::AxisId::Z).currentDisc;
        QTest::mousePress(zMinus, Qt::LeftButton, {}, capCentre(zMinus));
        session.advance(300);
        QVERIFY(ctl.words().bit(z::jogMinus(engine::AxisId::Z)));
        QVERIFY(ctl.axisView(engine::AxisId::Z).moving);
        QTest::mouseRelease(zMinus, Qt::LeftButton, {}, capCentre(zMinus));
        session.advance(300);
        QVERIFY(!ctl.axisView(engine::AxisId::Z).moving);
        QVERIFY(ctl.axisView(engine::AxisId::Z).currentDisc < z0 - 5000);
        QVERIFY(axes.bits()->text().contains("jog -"));

        // The handwheel: axis X, step x10, three detents of the mouse wheel.
        SelectorSwitch* axis = panel.handwheelAxis();
        QTest::mouseClick(axis, Qt::LeftButton, {}, axis->legendCentre(1).toPoint());
        QCOMPARE(axis->position(), 1);
        SelectorSwitch* step = panel.handwheelMultiplier();
        QTest::mouseClick(step, Qt::LeftButton, {}, step->legendCentre(1).toPoint());
        QCOMPARE(step->position(), 1);
        session.advance(30);
        const double t0 = ctl.servo(engine::AxisId::X).target();
        QWheelEvent wheel(QPointF(80, 80), panel.handwheel()->mapToGlobal(QPointF(80, 80)), {},
                          QPoint(0, 360), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(panel.handwheel(), &wheel);
        session.advance(500);
        // 3 detents x МНОЖИТ.М1 10 discretes x 2 internal units.
        QCOMPARE(ctl.servo(engine::AxisId::X).target() - t0, 60.0);

        // The override selector: 50 %.
        SelectorSwitch* ov = panel.overrideSelector();
        QVERIFY(ov);
        QTest::mouseClick(ov, Qt::LeftButton, {}, ov->legendCentre(8).toPoint());
        QCOMPARE(ov->positions().at(ov->position()), QString("50"));
        session.advance(30);
        QCOMPARE(ctl.programView().overridePercent, 50);
        QTest::mouseClick(ov, Qt::LeftButton, {}, ov->legendCentre(11).toPoint());
        session.advance(30);
        QCOMPARE(ctl.programView().overridePercent, 100);

        // A program: «Пуск» lights the start button, «Стоп» interrupts it.
        program::ParseResult parsed = program::parse("%L7\nN1 G1 Z-50 FZ500\nN2 M30\n");
        for (const program::Program& p : parsed.store.programs())
            ctl.editablePrograms()->insert(p);
        QVERIFY(ctl.programsEdited().ok());
        ctl.selectMode(engine::Mode::Auto);
        ctl.selectProgram(7);
        session.advance(20);
        hold(session, panel.button(machine::Button::CycleStart), 100);
        QCOMPARE(ctl.state(), engine::ProgramState::Running);
        session.advance(200);
        QVERIFY(panel.button(machine::Button::CycleStart)->lit());
        hold(session, panel.button(machine::Button::CycleStop), 100);
        QCOMPARE(ctl.state(), engine::ProgramState::Interrupted);
        QVERIFY(panel.button(machine::Button::CycleStop)->lit());

        // E-stop: the mushroom latches; message 9 in the messages dock.
        QTest::mouseClick(panel.emergencyStop(), Qt::LeftButton, {},
                          panel.emergencyStop()->rect().center());
        QVERIFY(panel.emergencyStop()->isChecked());
        session.advance(50);
        QVERIFY(!ctl.words().bit(z::EmergencyStopOk));
        QVERIFY(hasMessage(messages, "9"));
        QVERIFY(hasMessage(messages, "A23"));
        QVERIFY(panel.lamp("alarm")->isOn());
        QVERIFY(messages.list()->topLevelItem(0)->text(2).contains("STOP"));
        // Released by a second click, acknowledged with RESET.
        QTest::mouseClick(panel.emergencyStop(), Qt::LeftButton, {},
                          panel.emergencyStop()->rect().center());
        QVERIFY(!panel.emergencyStop()->isChecked());
        session.advance(50);
        hold(session, panel.button(machine::Button::Reset), 100);
        QVERIFY(!hasMessage(messages, "9"));
        QVERIFY(!hasMessage(messages, "A23"));
        QVERIFY(!panel.lamp("alarm")->isOn());

        // The door: opens (no spindle, no program), its lamp lights.
        QVERIFY(panel.doorButton());
        QTest::mouseClick(panel.doorButton(), Qt::LeftButton, {}, capCentre(panel.doorButton()));
        session.advance(30);
        QVERIFY(!session.simulation().view().doorClosed);
        QVERIFY(panel.lamp("door")->isOn());
        QVERIFY(hasMessage(messages, "W01"));
    }

    // The grinder's panel shows its gauge read-out and its wheel lamp.
    // A click shorter than a push (the mouse down and up between two frames)
    // still reaches the machine: the button stays down for a push's time.
    void aShortClickIsAPush() {
        SimulationSession session(profile::builtin("training-lathe"));
        session.setRunning(false);
        MachinePanelWidget panel(session);
        panel.resize(panel.sizeHint());
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        session.advance(20);
        engine::Positioner& ctl = session.controller();
        PendantButton* drives = panel.button(machine::Button::DrivesOn);
        QTest::mouseClick(drives, Qt::LeftButton, {}, capCentre(drives)); // no time between
        QVERIFY(session.simulation().buttonDown(machine::Button::DrivesOn));
        session.advance(MachinePanelWidget::kShortestPushMs - 10);
        QVERIFY(session.simulation().buttonDown(machine::Button::DrivesOn));
        session.advance(20);
        QVERIFY(!session.simulation().buttonDown(machine::Button::DrivesOn));
        QVERIFY(waitFor(
            session, [&] { return ctl.axisView(engine::AxisId::X).loopClosed; }, 2000));
        // A long hold is released when the mouse lets go.
        PendantButton* start = panel.button(machine::Button::CycleStart);
        QTest::mousePress(start, Qt::LeftButton, {}, capCentre(start));
        session.advance(300);
        QTest::mouseRelease(start, Qt::LeftButton, {}, capCentre(start));
        QVERIFY(!session.simulation().buttonDown(machine::Button::CycleStart));
    }

    // The same in the main window, in real time, right after a K923 key took
    // a click (and the keyboard's focus): a press and release 0 ms and 10 ms
    // apart on the machine's panel each reach the machine as a push — DRIVES
    // ON closes the loops, a jog key is down when the mouse is already up.
    void aShortClickInTheWindowAfterAK923Key() {
        MainWindow w;
        w.placeOnScreen();
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        SimulationSession* s = w.session();
        auto* panel = w.machineDock()->findChild<MachinePanelWidget*>();
        QVERIFY(panel && panel->isVisible());
        QTest::mouseClick(w.k923()->key(panel::Key::F2), Qt::LeftButton); // РУЧ
        QCOMPARE(s->controller().mode(), engine::Mode::Manual);
        PendantButton* drives = panel->button(machine::Button::DrivesOn);
        QTest::mousePress(drives, Qt::LeftButton, {}, capCentre(drives));
        QTest::mouseRelease(drives, Qt::LeftButton, {}, capCentre(drives)); // 0 ms
        QVERIFY(s->simulation().buttonDown(machine::Button::DrivesOn));
        QTRY_VERIFY_WITH_TIMEOUT(s->controller().axisView(engine::AxisId::X).loopClosed, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(!s->simulation().buttonDown(machine::Button::DrivesOn), 10000);
        QTest::mouseClick(w.k923()->key(panel::Key::F2), Qt::LeftButton);
        PendantButton* jog = panel->button(machine::Button::JogXPlus);
        QTest::mousePress(jog, Qt::LeftButton, {}, capCentre(jog));
        QTest::mouseRelease(jog, Qt::LeftButton, {}, capCentre(jog), 10); // 10 ms
        QVERIFY(s->simulation().buttonDown(machine::Button::JogXPlus));
        QTRY_VERIFY_WITH_TIMEOUT(!s->simulation().buttonDown(machine::Button::JogXPlus), 10000);
    }

    // The legends of the lamps, buttons and switches are whole on the
    // smallest panel (a shop PC's training workspace, the panel as tight as
    // its dock holds it): set at the smallest legible size, a word still
    // wider than its plate narrower on one line — never cut at the plate's
    // edges or wrapped onto a plate of one line's height.
    void legendsAreWholeOnTheSmallestPanel() {
        QVERIFY(setLanguage("ru"));
        for (const char* machineName : {"training-lathe", "grinder-205"}) {
            SimulationSession session(profile::builtin(machineName));
            session.setRunning(false);
            MachinePanelWidget panel(session);
            panel.setScale(0.6);
            panel.show();
            QVERIFY(QTest::qWaitForWindowExposed(&panel));
            // At the size it asks for, then as tight as its dock may hold it.
            for (const bool tight : {false, true}) {
                panel.resize(tight ? panel.minimumSizeHint() : panel.sizeHint());
                QCoreApplication::sendPostedEvents();
                QList<std::pair<QString, QRectF>> plates;
                for (PilotLamp* l : panel.findChildren<PilotLamp*>())
                    if (!l->legend().isEmpty())
                        plates.append({l->legend(), l->legendPlate()});
                for (PendantButton* b : panel.findChildren<PendantButton*>())
                    if (!b->legend().isEmpty())
                        plates.append({b->legend(), b->legendPlate()});
                for (SelectorSwitch* sw : panel.findChildren<SelectorSwitch*>())
                    if (!sw->caption().isEmpty())
                        plates.append({sw->caption(), sw->captionPlate()});
                QVERIFY2(plates.size() >= 12, qPrintable(QString::number(plates.size())));
                int narrowed = 0;
                for (const auto& [text, plate] : plates) {
                    const PlateText t = plateText(plate, text);
                    const double width = QFontMetricsF(t.font).horizontalAdvance(text) * t.xScale;
                    const QString what =
                        QStringLiteral("%1 «%2» on a plate %3 px wide: %4 px at %5 px, x%6")
                            .arg(machineName, text)
                            .arg(plate.width())
                            .arg(width)
                            .arg(t.font.pixelSize())
                            .arg(t.xScale);
                    QVERIFY2(width <= t.room + 0.01, qPrintable(what));
                    QVERIFY2(t.font.pixelSize() >= 7, qPrintable(what));
                    if (!tight) // still letters, not a smear (КРУГ НОВЫЙ of the grinder: 0.48)
                        QVERIFY2(t.xScale > 0.45, qPrintable(what));
                    // One line on the plate: its height holds one line only.
                    QVERIFY2(text.contains('\n') ||
                                 QFontMetricsF(t.font).height() <= plate.height() + 3,
                             qPrintable(what));
                    narrowed += t.xScale < 1;
                }
                qInfo("%s%s: %lld legends, %d set narrower", machineName, tight ? " (tight)" : "",
                      static_cast<long long>(plates.size()), narrowed);
            }
        }
    }

    void grinderPanel() {
        SimulationSession session(profile::builtin("grinder-205"));
        session.setRunning(false);
        MachinePanelWidget panel(session);
        session.advance(20);
        QVERIFY(panel.lamp("wheel"));
        QVERIFY(panel.lamp("gauge"));
        auto* gauge = panel.findChild<QLabel*>("machine.gauge");
        QVERIFY(gauge);
        QVERIFY(gauge->text().contains("24.7000"));
        QVERIFY(panel.findChild<PendantButton*>("machine.changeWheel"));
        QVERIFY(panel.findChild<PendantButton*>("machine.door"));
    }

    // Real time: the session advances by what elapsed, paused it stands,
    // at 10x it runs ten times faster; a stalled frame is capped. Waits on
    // the simulated time, not for a fixed wall time: on a busy machine the
    // timer fires late, and what is checked is that the simulation never runs
    // ahead of the clock (at 1x) and clearly ahead of it (at 10x).
    void realTime() {
        SimulationSession session(profile::builtin("training-lathe"));
        QSignalSpy spy(&session, &SimulationSession::advanced);
        QElapsedTimer wall;
        wall.start();
        QTRY_VERIFY_WITH_TIMEOUT(session.timeMs() >= 200 && spy.count() >= 5, 20000);
        const double sim = static_cast<double>(session.timeMs());
        const double real = static_cast<double>(wall.elapsed());
        QVERIFY2(sim <= real + 20, qPrintable(QString("%1 ms simulated in %2 ms").arg(sim).arg(real)));
        session.setRunning(false);
        const std::int64_t paused = session.timeMs();
        QTest::qWait(100);
        QCOMPARE(session.timeMs(), paused);
        session.setSpeed(10);
        session.setRunning(true);
        wall.restart();
        QTRY_VERIFY_WITH_TIMEOUT(session.timeMs() - paused >= 2000, 20000);
        const double fast = static_cast<double>(session.timeMs() - paused);
        const double real2 = static_cast<double>(wall.elapsed());
        QVERIFY2(fast >= 2 * real2 && fast <= 10 * (real2 + 20),
                 qPrintable(QString("%1 ms simulated in %2 ms at 10x").arg(fast).arg(real2)));
    }

    // The main window builds the session and puts the views into the docks.
    void mainWindowDocks() {
        MainWindow w;
        QVERIFY(w.session());
        QVERIFY(w.machineDock()->findChild<MachinePanelWidget*>());
        QCOMPARE(w.messagesDock()->widget(), static_cast<QWidget*>(w.messagesView()));
        QCOMPARE(w.axesDock()->findChild<AxesView*>(), w.axesView()); // in a scroll area (a wide table)
        QCOMPARE(w.session()->simulation().description().name, std::string("training-lathe"));
        // The trainer's faults menu: inject the E-stop circuit fault.
        QAction* a = w.findChild<QAction*>("action.fault.emergency_stop.x.0.");
        QVERIFY(a);
        w.session()->setRunning(false);
        a->setChecked(true);
        w.session()->advance(30);
        QVERIFY(w.session()->controller().alarmRegistry().latched(9));
        a->setChecked(false);
        QVERIFY(w.session()->simulation().faults().empty());
    }

    // The K923 in the main window is the session's panel model: its LCD shows
    // the engine's screens, its keys reach the engine, its LEDs follow Z1906.
    void k923DrivesTheEngine() {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        SimulationSession* s = w.session();
        s->setRunning(false);
        s->advance(50);
        K923Widget* k = w.k923();
        QVERIFY(k);
        QCOMPARE(QString::fromStdString(k->display().lcd.lines[0]).left(3), QString("РУЧ"));
        QTest::mouseClick(k->key(panel::Key::F1), Qt::LeftButton);
        QCOMPARE(s->controller().mode(), engine::Mode::Auto);
        QCOMPARE(QString::fromStdString(k->display().lcd.lines[0]).left(3), QString("АВТ"));
        // The PC keyboard: F2 is РУЧНОЙ.
        k->setFocus();
        QTest::keyClick(k, Qt::Key_F2);
        QCOMPARE(s->controller().mode(), engine::Mode::Manual);
        // The display follows the machine as time passes (no key pressed).
        s->controller().selectMode(engine::Mode::Reference);
        s->advance(20);
        QCOMPARE(QString::fromStdString(k->display().lcd.lines[0]).left(3), QString("ПБТ"));
    }

    // The work area's "Program" tab follows the controller: the selected
    // program's frames, the frame being executed marked (a subprogram while
    // it runs), a pinned program stays shown; an edit on the K923 shows up.
    void programMonitorFollows() {
        profile::MachineProfile p = profile::builtin("training-lathe");
        p.setC(8, 1); // АВТ.БЕЗ ПБТ of X and Z: no homing for this test
        p.setC(60, 1);
        MainWindow w(MachineChoice{p, {}, QString()});
        SimulationSession* s = w.session();
        s->setRunning(false);
        ProgramMonitor* m = w.programMonitor();
        QVERIFY(m);
        QCOMPARE(w.workArea()->widget(0), static_cast<QWidget*>(m));
        // Nothing selected after power-on: the catalog's first program.
        s->advance(10);
        QCOMPARE(m->shownProgram(), s->controller().programs().programs().front().number);
        engine::Positioner& ctl = s->controller();
        program::ProgramStore* store = ctl.editablePrograms();
        QVERIFY(store);
        const auto parsed =
            program::parse("%L7\nN1 R1=1\nN2 L8\nN3 G4 X5\n%L8\nN1 G4 X5\nN2 M17\n");
        for (const program::Program& prog : parsed.store.programs())
            store->insert(prog);
        QVERIFY(ctl.programsEdited().ok());
        s->advance(10);
        QVERIFY(m->programChoice()->findData(8) >= 0); // the new programs are offered
        machine::Simulation& sim = s->simulation();
        sim.pressFor(machine::Button::DrivesOn, 100);
        s->advance(600);
        QVERIFY(ctl.selectMode(engine::Mode::Auto).ok());
        QVERIFY(ctl.selectProgram(7).ok());
        s->advance(20);
        QCOMPARE(m->shownProgram(), 7);
        QCOMPARE(m->frames()->count(), 3);
        QCOMPARE(m->frames()->item(1)->text(), QString("N2 L8"));
        QCOMPARE(m->executingRow(), -1); // nothing runs yet
        sim.pressFor(machine::Button::CycleStart, 100);
        QVERIFY(waitFor(*s, [&] { return ctl.programView().program == 8; }, 3000));
        s->advance(100);
        QCOMPARE(m->shownProgram(), 8); // the subprogram while it runs
        QCOMPARE(m->executingRow(), 0);
        QCOMPARE(m->frames()->item(0)->text(), QString("N1 G4 X5"));
        // Pinned on L7, it stays while L8 runs.
        m->programChoice()->setCurrentIndex(m->programChoice()->findData(7));
        m->refresh();
        QCOMPARE(m->shownProgram(), 7);
        QCOMPARE(m->executingRow(), -1);
        QVERIFY(waitFor(*s, [&] { return ctl.programView().program == 7; }, 10000));
        s->advance(50);
        QCOMPARE(m->executingRow(), 2); // back in L7: N3
        m->programChoice()->setCurrentIndex(0); // follow again
        QVERIFY(waitFor(*s, [&] { return ctl.state() == engine::ProgramState::Ended; }, 10000));
        s->advance(20);
        QCOMPARE(m->shownProgram(), 7);
        QCOMPARE(m->executingRow(), -1);
    }

    // A program's technological message in the messages view: the machine
    // file's in the English the file gives (in an English window), a program
    // file's own text as written even where it reads as the machine's.
    void programMessageInTheWindowsLanguage() {
        QVERIFY(setLanguage("en"));
        profile::MachineProfile p = profile::builtin("training-lathe");
        p.setC(8, 1); // АВТ.БЕЗ ПБТ of X and Z: no homing for this test
        p.setC(60, 1);
        SimulationSession s(p);
        s.setRunning(false);
        SimulatedController controller(s);
        MessagesView messages(controller);
        s.advance(10);
        // The lathe's file: #1=ПОДВОД (APPROACH), #2=ТОРЦОВКА (FACING).
        const ProgramLoad load = loadProgramText(
            s, "%L7\nN1 #1 M0\nN2 #2 M0\nN3 M30\n%MESSAGES\n#2=ТОРЦОВКА\n", "own.k528");
        QVERIFY2(load.loaded, qPrintable(load.problem));
        engine::Positioner& ctl = s.controller();
        s.simulation().pressFor(machine::Button::DrivesOn, 100);
        s.advance(600);
        QVERIFY(ctl.selectMode(engine::Mode::Auto).ok());
        QVERIFY(ctl.selectProgram(7).ok());
        const auto nextStop = [&](int message) {
            s.advance(200); // the button of the last start is up again
            s.simulation().pressFor(machine::Button::CycleStart, 100);
            return waitFor(s, [&] { return ctl.programView().messageNumber == message &&
                                           ctl.state() == engine::ProgramState::M0; }, 3000);
        };
        QVERIFY(nextStop(1));
        QCOMPARE(messageShown(messages, "#1"), QString("APPROACH"));
        QVERIFY(setLanguage("ru"));
        QCOMPARE(messageShown(messages, "#1"), QString("ПОДВОД"));
        QVERIFY(setLanguage("en"));
        QVERIFY(nextStop(2));
        QCOMPARE(messageShown(messages, "#2"), QString("ТОРЦОВКА"));
    }

    // The trainer breaks the K923's link to the PLC: the desktop K923 says
    // «НЕТ СВЯЗИ С ПЛК» at once and its K keys no longer reach Z1300.
    void k923FaultsFromTheMenu() {
        MainWindow w;
        SimulationSession* s = w.session();
        s->setRunning(false);
        s->advance(50);
        QAction* a = w.findChild<QAction*>("action.fault.k923.x.1.");
        QVERIFY(a);
        a->setChecked(true);
        K923Widget* k = w.k923();
        QCOMPARE(QString::fromStdString(k->display().lcd.lines[1]).trimmed(),
                 QString("НЕТ СВЯЗИ С ПЛК"));
        QTest::mouseClick(k->key(panel::Key::K1), Qt::LeftButton);
        QCOMPARE(int(s->controller().words().word(z::KeysWord)), 0);
        a->setChecked(false);
        QCOMPARE(QString::fromStdString(k->display().lcd.lines[1]).trimmed(), QString());
        // The PLC in debug stop: «Режим ПЛК СТОП !».
        QAction* stop = w.findChild<QAction*>("action.fault.plc_stopped.x.0.");
        QVERIFY(stop);
        stop->setChecked(true);
        QCOMPARE(QString::fromStdString(k->display().lcd.lines[1]).trimmed(),
                 QString("Режим ПЛК СТОП !"));
        stop->setChecked(false);
    }

    // With K528_SCREENSHOTS=<dir>: pictures of the workstation in use (a
    // running program on the lathe, a grinding cycle), to look at.
    void screenshots() {
        const QString dir = qEnvironmentVariable("K528_SCREENSHOTS");
        if (dir.isEmpty())
            QSKIP("set K528_SCREENSHOTS=<dir> to save pictures");
        QVERIFY(setLanguage("ru"));
        for (const char* machine : {"training-lathe", "grinder-205"}) {
            MainWindow w;
            w.resize(1600, 900);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            SimulationSession* s = w.session();
            s->setRunning(false);
            // The main window runs the default profile; the grinder gets its own session.
            std::unique_ptr<SimulationSession> own;
            std::unique_ptr<MachinePanelWidget> ownPanel;
            if (std::string(machine) != "training-lathe") {
                own = std::make_unique<SimulationSession>(profile::builtin(machine));
                own->setRunning(false);
                s = own.get();
            }
            machine::Simulation& sim = s->simulation();
            sim.pressFor(machine::Button::DrivesOn, 100);
            s->advance(600);
            engine::Positioner& ctl = s->controller();
            ctl.selectMode(engine::Mode::Reference);
            for (auto [a, b] :
                 {std::pair{engine::AxisId::X,
                            ctl.c()[9] ? machine::Button::JogXMinus : machine::Button::JogXPlus},
                  std::pair{engine::AxisId::Z, machine::Button::JogZPlus}}) {
                sim.pressFor(b, 100);
                waitFor(
                    *s, [&] { return ctl.axisView(a).homing; }, 1000);
                waitFor(
                    *s, [&] { return !ctl.axisView(a).homing; }, 600000);
            }
            ctl.selectMode(engine::Mode::Auto);
            ctl.selectProgram(1);
            s->advance(50);
            sim.pressFor(machine::Button::CycleStart, 100);
            if (own) {
                // The gauge cycle: stop in the middle of finishing.
                waitFor(
                    *s, [&] { return ctl.programView().frameNumber == 6; }, 60000);
                sim.selectHandwheel(machine::HandwheelAxis::X);
                ownPanel = std::make_unique<MachinePanelWidget>(*s);
                ownPanel->resize(560, 520);
                s->advance(10);
                K528_VERIFY_SHOT(ownPanel->grab(), QStringLiteral("grinder-panel.png"));
            } else {
                sim.selectHandwheel(machine::HandwheelAxis::Z);
                sim.setOverrideSwitch(9);
                waitFor(
                    *s, [&] { return ctl.programView().frameNumber == 8; }, 60000);
                s->advance(700);
                w.axesDock()->raise();
                QApplication::processEvents();
                K528_VERIFY_SHOT(w.grab(), QStringLiteral("lathe-axes.png"));
                w.messagesDock()->raise();
                QApplication::processEvents();
                K528_VERIFY_SHOT(w.grab(), QStringLiteral("lathe-running.png"));
            }
        }
        QVERIFY(setLanguage("en"));
    }
};

QTEST_MAIN(TestMachinePanel)
#include "test_machine_panel.moc"
