// Loading a program file into the simulated controller (File > Load
// programs): checked for the machine first — errors load nothing, warnings
// are told —, then its programs replace those of the same number, the first
// is selected, and the Program tab shows it.
#include "language.h"
#include "main_window.h"
#include "monitor/program_monitor.h"
#include "profile/builtin.h"
#include "session/program_loader.h"
#include "session/simulation_session.h"

#include "test_util.h"

#include <QApplication>
#include <QListWidget>
#include <QMessageBox>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

using namespace k528;
using namespace k528::studio;

namespace {

using testutil::writeBytes;

// Accepts the message box the next event loop shows (the report of a load).
void closeNextBox() {
    QTimer::singleShot(0, [] {
        if (auto* m = qobject_cast<QMessageBox*>(QApplication::activeModalWidget()))
            m->accept();
    });
}

} // namespace

class TestProgramLoader : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("K528StudioTest");
        QSettings().clear();
        QVERIFY(setLanguage("en"));
    }

    void loadsAndSelects() {
        QTemporaryDir dir;
        MainWindow w;
        w.session()->setRunning(false);
        const QString f = writeBytes(dir, "two.k528",
                                "%L12 (first)\nN1 G1 X40 FX200\nN2 M30\n%L3\nN1 R5=7\nN2 M17\n"
                                "%MESSAGES\n#9=ПРОБА\n");
        const ProgramLoad r = loadProgramFile(*w.session(), f);
        QVERIFY2(r.loaded, qPrintable(r.problem));
        QCOMPARE(r.programs, (QList<int>{12, 3}));
        QVERIFY(r.findings.isEmpty());
        const engine::Positioner& ctl = w.session()->controller();
        QVERIFY(ctl.programs().find(12) && ctl.programs().find(3));
        QCOMPARE(ctl.programView().selectedProgram, 12);
        QVERIFY(ctl.programs().messages.find(9));
        QCOMPARE(w.programMonitor()->shownProgram(), 12);
        QCOMPARE(w.programMonitor()->frames()->item(0)->text(), QString("N1 G1 X40 FX200"));
        // The machine's own programs stay (the lathe's L1), the file's replace theirs.
        QVERIFY(ctl.programs().find(1));
        QVERIFY(w.loadProgramsFrom(f)); // no finding: no dialog, a status message
    }

    void errorsLoadNothing() {
        QTemporaryDir dir;
        MainWindow w;
        w.session()->setRunning(false);
        const engine::Positioner& ctl = w.session()->controller();
        const std::uint64_t before = ctl.programsRevision();
        // G2 is not in table 5 (47); L77 does not exist (45).
        const QString f = writeBytes(dir, "bad.k528", "%L20\nN1 G2 X5\nN2 L77\nN3 M30\n");
        const ProgramLoad r = loadProgramFile(*w.session(), f);
        QVERIFY(!r.loaded);
        QVERIFY(r.problem.contains("bad.k528"));
        QCOMPARE(r.findings.size(), 2);
        QVERIFY2(r.findings[0].startsWith("2:4: error: [M47]"), qPrintable(r.findings[0]));
        QVERIFY2(r.findings[1].contains("[M45]"), qPrintable(r.findings[1]));
        QVERIFY(!ctl.programs().find(20));
        QCOMPARE(ctl.programsRevision(), before);
        // Through the window: a report, and nothing loaded.
        closeNextBox();
        QVERIFY(!w.loadProgramsFrom(f));
        // Outside the machine's soft limits: a warning, the program loads.
        const QString far = writeBytes(dir, "far.k528", "%L21\nN1 G0 Z-900\nN2 M30\n");
        const ProgramLoad g = loadProgramFile(*w.session(), far);
        QVERIFY2(g.loaded, qPrintable(g.problem));
        QCOMPARE(g.findings.size(), 1);
        QVERIFY2(g.findings[0].contains("warning"), qPrintable(g.findings[0]));
        // A missing file.
        const ProgramLoad m = loadProgramFile(*w.session(), dir.filePath("none.k528"));
        QVERIFY(!m.loaded);
        QVERIFY(m.problem.contains("none.k528"));
    }

    void refusedWhileAProgramRuns() {
        profile::MachineProfile p = profile::builtin("training-lathe");
        p.setC(8, 1); // АВТ.БЕЗ ПБТ
        p.setC(60, 1);
        MainWindow w(MachineChoice{p, {}, QString()});
        SimulationSession* s = w.session();
        s->setRunning(false);
        QTemporaryDir dir;
        const QString f = writeBytes(dir, "dwell.k528", "%L30\nN1 G4 X30\nN2 M30\n");
        QVERIFY(loadProgramFile(*s, f).loaded);
        machine::Simulation& sim = s->simulation();
        sim.pressFor(machine::Button::DrivesOn, 100);
        s->advance(600);
        QVERIFY(s->controller().selectMode(engine::Mode::Auto).ok());
        sim.pressFor(machine::Button::CycleStart, 100);
        s->advance(500);
        QVERIFY(engine::programActive(s->controller().state()));
        const ProgramLoad r = loadProgramFile(*s, f);
        QVERIFY(!r.loaded);
        QVERIFY2(r.problem.contains("running"), qPrintable(r.problem));
    }
};

QTEST_MAIN(TestProgramLoader)
#include "test_program_loader.moc"
