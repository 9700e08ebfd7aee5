// The machine-data docks (app/studio/constants, app/studio/rparams):
// editing C22 in the table changes the simulated axis' acceleration (the
// time of a known move changes as the formula says) and keeps a revision
// with its history; a value out of range or one the cross-checks refuse is
// refused with the manual's text and changes nothing; undo/redo; import and
// export (CSV, machine file) on a worker thread with the refusal rules of
// `k528 db import`; the diff of two revisions; the calculator; the
// R-parameters live, edited where the engine allows it, presets kept with
// the machine; screenshots of both docks.
#include "catalog/messages.h"
#include "constants/constants_dialogs.h"
#include "constants/constants_dock.h"
#include "session/catalog_texts.h"
#include "constants/constants_editor.h"
#include "constants/constants_lock.h"
#include "constants/constants_model.h"
#include "controller/simulated_controller.h"
#include "db/explain.h"
#include "db/notes.h"
#include "engine/run.h"
#include "language.h"
#include "machine/run.h"
#include "main_window.h"
#include "parameters/cell_text_delegate.h"
#include "profile/builtin.h"
#include "profile/csv.h"
#include "program/parser.h"
#include "rig/machine_rig.h"
#include "rig/studio_rig.h"
#include "rig/widgets.h"
#include "rparams/rparams_dock.h"
#include "rparams/rparams_model.h"
#include "session/core_texts.h"
#include "session/simulation_session.h"
#include "training/training_pane.h"
#include "units/units.h"

#include <QComboBox>
#include <QDockWidget>
#include <QDir>
#include <QFile>
#include <QLineEdit>
#include <QSettings>
#include <QSignalSpy>
#include <QStyledItemDelegate>
#include <QTableView>
#include <QTableWidget>
#include <QPlainTextEdit>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QLabel>
#include <QPushButton>
#include <QUndoStack>
#include <QtTest>
#include <cmath>

using namespace k528;
using namespace k528::studio;
using testrig::SimulatedSeam;

namespace {

// Each test its own machine in the database; the program runs without the reference cycles.
profile::MachineProfile lathe(const std::string& name) {
    return testrig::latheNamed(name, testrig::noHoming);
}

struct MoveTime {
    double runS = -1;    // «Пуск» to the end, as `k528 run` reports it
    double setpointS = 0; // the setpoint's move
};

// One rapid move of X (diameter 0 -> -100: 100 mm at F УСК.АВТ.).
MoveTime moveTime(SimulationSession& session) {
    program::ParseOptions o;
    const program::ProgramStore store = program::parse("%L1\nN1 G0 X-100\n", o).store;
    // The ticks in which X's setpoint moves (the trapezoid the formula
    // describes; the run's own time adds the settling of the loop).
    std::int64_t movingMs = 0;
    machine::Simulation& sim = session.simulation();
    testrig::WatchedSimulationRun m(sim, [&] {
        if (sim.controller().servo(engine::AxisId::X).moving())
            ++movingMs;
    });
    engine::RunOptions options;
    options.home = false;
    const engine::RunResult r = engine::runProgram(m, store, 1, options);
    MoveTime t;
    if (r.status == engine::RunStatus::Completed)
        t.runS = r.timeS;
    t.setpointS = static_cast<double>(movingMs) / 1000.0;
    return t;
}

QModelIndex valueIndex(ConstantsPane& pane, int number) {
    pane.filter()->setSearch(QString());
    return pane.filter()->mapFromSource(
        pane.model()->index(ConstantsModel::rowOf(number), ConstantsModel::Value));
}

int revisionCount(const ConstantsPane& pane) {
    return static_cast<int>(pane.editor().store().revisions().size());
}

bool waitIdle(ConstantsPane& pane) {
    for (int i = 0; i < 1000 && pane.busy(); ++i)
        QTest::qWait(10);
    return !pane.busy();
}

} // namespace

class TestConstants : public QObject {
    Q_OBJECT
private:
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        qputenv("K528_DB", dir_.filePath("k528.db").toUtf8());
        QCoreApplication::setOrganizationName("K528StudioTestConstants");
        QSettings().clear();
    }

    void editingC22ChangesTheMoveAndKeepsARevision() {
        SimulationSession before(lathe("lathe-c22"));
        const MoveTime t1 = moveTime(before);
        QVERIFY(t1.runS > 0);

        SimulatedSeam sim(lathe("lathe-c22"));
        ConstantsPane pane(sim.seam, sim.session.simulation().profile());
        const QModelIndex i = valueIndex(pane, 22);
        QCOMPARE(i.data().toString(), QStringLiteral("10666"));
        pane.noteField()->setText(QStringLiteral("slower run-up for the trainees"));
        QVERIFY(pane.filter()->setData(i, QStringLiteral("5333")));
        QCOMPARE(sim.session.controller().c()[22], std::int64_t(5333));
        QCOMPARE(i.data().toString(), QStringLiteral("5333"));
        QVERIFY(pane.statusText().contains(QStringLiteral("slower run-up")));

        // The revision with its history: created from the profile (1), the change (2).
        const auto revs = pane.editor().store().revisions();
        QCOMPARE(revs.size(), std::size_t(2));
        QCOMPARE(revs.front().summary, std::string("slower run-up for the trainees"));
        const auto h = pane.editor().store().history("C022");
        QVERIFY(!h.empty());
        QCOMPARE(h.front().revision, 2); // newest first
        QCOMPARE(*h.front().change.before, std::string("10666"));
        QCOMPARE(*h.front().change.after, std::string("5333"));
        QCOMPARE(pane.editor().store().current().cValue(22), std::int64_t(5333));
        HistoryDialog dialog(pane.editor().store(), 22);
        QCOMPARE(dialog.table()->rowCount(), static_cast<int>(h.size()));
        QCOMPARE(dialog.table()->item(0, 4)->text(), QStringLiteral("5333"));

        // The move: t = D/V + V/A; only V/A changes with the acceleration.
        const MoveTime t2 = moveTime(sim.session);
        QVERIFY(t2.runS > t1.runS);
        const units::AxisScale s = profile::axisScale(sim.session.controller().profile(), catalog::Axis::X);
        const double v = units::speedParamToMmPerMin(sim.session.controller().c()[42], s) / 60.0; // F УСК.АВТ., mm/s
        const double a1 = units::accelParamToMmPerS2(10666, s), a2 = units::accelParamToMmPerS2(5333, s);
        const double expected = v / a2 - v / a1;
        const double d = units::discToMm(100000, s); // the move, display mm
        QVERIFY2(std::fabs(t1.setpointS - (d / v + v / a1)) <= 0.003,
                 qPrintable(QString("setpoint %1 s, formula %2 s").arg(t1.setpointS).arg(d / v + v / a1)));
        QVERIFY2(std::fabs((t2.setpointS - t1.setpointS) - expected) <= 0.003,
                 qPrintable(QString("setpoint %1 s -> %2 s: %3 s longer, the formula says %4 s")
                                .arg(t1.setpointS).arg(t2.setpointS).arg(t2.setpointS - t1.setpointS).arg(expected)));
        // The whole run (with the loop settling) is longer by about as much.
        QVERIFY2(std::fabs((t2.runS - t1.runS) - expected) <= 0.25 * expected,
                 qPrintable(QString("run %1 s -> %2 s").arg(t1.runS).arg(t2.runS)));
    }

    void outOfRangeIsRefusedWithTheManualsText() {
        SimulatedSeam sim(lathe("lathe-range"));
        ConstantsPane pane(sim.seam, sim.session.simulation().profile());
        pane.resize(1200, 600);
        pane.show();
        const int revs = revisionCount(pane);
        const QModelIndex i = valueIndex(pane, 22);
        // As it is typed: the editor turns red with message 15.
        pane.table()->setCurrentIndex(i);
        pane.table()->edit(i);
        auto* line = pane.table()->findChild<QLineEdit*>("constants.valueEditor");
        QVERIFY(line);
        line->selectAll();
        QTest::keyClicks(line, "99999");
        QVERIFY(line->property("refused").toBool());
        // The controller's message in the window's language (English here;
        // in Russian the panel's text, studio.ui_language checks all 64).
        const QString m15 = positionerMessageLine(15);
        QVERIFY2(m15.startsWith(QStringLiteral("15. ")) && !m15.contains(QRegularExpression(QStringLiteral("[А-Яа-яЁё]"))),
                 qPrintable(m15));
        QVERIFY2(pane.statusText().contains(m15), qPrintable(pane.statusText()));
        QVERIFY(pane.statusText().contains(QStringLiteral("0...32767")));
        QTest::keyClick(line, Qt::Key_Escape);
        // Committed anyway: refused, nothing changes.
        QVERIFY(!pane.filter()->setData(i, QStringLiteral("99999")));
        QVERIFY(pane.statusText().contains(m15));
        QCOMPARE(sim.session.controller().c()[22], std::int64_t(10666));
        QCOMPARE(pane.editor().undoStack()->count(), 0);
        QCOMPARE(revisionCount(pane), revs);
        QVERIFY(sim.session.controller().alarms().empty());

        // A cross-check: X's encoder on the channel of Z's (37).
        const std::int64_t z = sim.session.controller().c()[69];
        QVERIFY(!pane.filter()->setData(valueIndex(pane, 17), QString::number(z)));
        const QString m37 = positionerMessageLine(37);
        QVERIFY2(pane.statusText().contains(m37), qPrintable(pane.statusText()));
        QCOMPARE(sim.session.controller().c()[17], std::int64_t(1));
        // L ИМП.ДОС = 0: message 13.
        QVERIFY(!pane.editor().set(19, 0));
        QVERIFY(pane.statusText().contains(positionerMessageLine(13)));
        QVERIFY(sim.session.controller().alarms().empty());
        QCOMPARE(revisionCount(pane), revs);
        // Not a number.
        QVERIFY(!pane.filter()->setData(i, QStringLiteral("12a")));
        QCOMPARE(sim.session.controller().c()[22], std::int64_t(10666));
        // A Russian window says the panel's text letter by letter.
        QVERIFY(setLanguage(QStringLiteral("ru")));
        QVERIFY(!pane.filter()->setData(i, QStringLiteral("99999")));
        const QString panel15 = QString::fromUtf8(catalog::positionerMessage(15).panelText().c_str());
        QVERIFY2(pane.statusText().startsWith(panel15 + QStringLiteral(" — ")), qPrintable(pane.statusText()));
        QVERIFY(setLanguage(QStringLiteral("en")));
    }

    void undoAndRedo() {
        SimulatedSeam sim(lathe("lathe-undo"));
        ConstantsPane pane(sim.seam, sim.session.simulation().profile());
        QVERIFY(pane.editor().set(40, 120000));
        QVERIFY(pane.editor().set(41, 400000));
        QCOMPARE(pane.editor().undoStack()->count(), 2);
        pane.editor().undoStack()->undo();
        QCOMPARE(sim.session.controller().c()[41], std::int64_t(500000));
        pane.editor().undoStack()->undo();
        QCOMPARE(sim.session.controller().c()[40], std::int64_t(150000));
        pane.editor().undoStack()->redo();
        QCOMPARE(sim.session.controller().c()[40], std::int64_t(120000));
        QCOMPARE(pane.editor().store().current().cValue(40), std::int64_t(120000));
        QCOMPARE(pane.editor().store().current().cValue(41), std::int64_t(500000));
        // 1 created + 2 sets + 2 undos + 1 redo
        QCOMPARE(revisionCount(pane), 6);
        QCOMPARE(valueIndex(pane, 40).data().toString(), QStringLiteral("120000"));
    }

    // The trainer locks the constants for a class: the dock (an edit, an
    // import, undo) and the K923's F5 refuse with a message naming the lock;
    // the lock is the machine's setting in the database; the trainer's
    // action unlocks it and the same edit goes through.
    void theTrainersLockRefusesChangesUntilUnlocked() {
        QVERIFY(setLanguage(QStringLiteral("en")));
        SimulatedSeam sim(lathe("lathe-lock"));
        ConstantsPane pane(sim.seam, sim.session.simulation().profile());
        QVERIFY(pane.filter()->setData(valueIndex(pane, 22), QStringLiteral("8000"))); // before the lock: taken
        TrainingPane trainer([] { return std::pair<QString, QString>(); });
        QVERIFY(!trainer.lockButton()->isEnabled()); // no machine named yet
        trainer.setMachine(sim.session.simulation().profile());
        QVERIFY(trainer.lockButton()->isEnabled());
        QVERIFY(!trainer.lockConstants(QStringLiteral("  ")).isEmpty()); // a lock names its class
        QCOMPARE(trainer.lockConstants(QStringLiteral("TM-21")), QString());
        QVERIFY2(trainer.lockNote()->text().contains(QStringLiteral("TM-21")), qPrintable(trainer.lockNote()->text()));
        QCOMPARE(trainer.lockButton()->text(), QStringLiteral("Unlock the constants"));
        // Kept in the database as the machine's setting.
        QCOMPARE(pane.editor().store().current().simulation.getString("constants.lock", ""), std::string("TM-21"));
        // Its revision's note is core's, read in each reader's language (a
        // student's window told of a revision made elsewhere says it in Russian).
        const std::string lockNote = pane.editor().store().revisions().front().summary;
        QCOMPARE(QString::fromStdString(db::readNote(lockNote).value_or(db::Note{}).id), QStringLiteral("studio.lock"));
        QVERIFY(setLanguage(QStringLiteral("ru")));
        QCOMPARE(revisionNoteText(lockNote), QStringLiteral("константы заблокированы для группы TM-21 (преподаватель)"));
        QVERIFY(setLanguage(QStringLiteral("en")));
        QCOMPARE(revisionNoteText(lockNote), QStringLiteral("constants locked for the class TM-21 (trainer)"));
        // The dock refuses, naming the lock; nothing changes, nothing is kept.
        const int revs = revisionCount(pane);
        QVERIFY(!pane.filter()->setData(valueIndex(pane, 22), QStringLiteral("5333")));
        QCOMPARE(sim.session.controller().c()[22], std::int64_t(8000));
        QVERIFY2(pane.statusText().contains(QStringLiteral("locked by the trainer")) &&
                     pane.statusText().contains(QStringLiteral("TM-21")),
                 qPrintable(pane.statusText()));
        QCOMPARE(revisionCount(pane), revs);
        // Undo of the change made before the lock: refused too.
        pane.editor().undoStack()->undo();
        QCOMPARE(sim.session.controller().c()[22], std::int64_t(8000));
        // An import: refused before the file is read.
        pane.importFile(QStringLiteral("/nonexistent/constants.csv"));
        QVERIFY(waitIdle(pane));
        QVERIFY2(pane.statusText().contains(QStringLiteral("TM-21")), qPrintable(pane.statusText()));
        // The K923: F5 (РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ) refused with the lock's words; other keys not.
        ConstantsLock* lock = ConstantsLock::of(sim.session.simulation().profile());
        QVERIFY(lock->refusesKey(sim.controller.state(), panel::KeyPress{panel::Key::F5}).contains(QStringLiteral("TM-21")));
        QVERIFY(lock->refusesKey(sim.controller.state(), panel::KeyPress{panel::Key::F2}).isEmpty());
        QVERIFY(lock->refusesKey(sim.controller.state(), panel::KeyPress{panel::Key::Enter}).isEmpty()); // not in F5
        ControllerState inF5 = sim.controller.state();
        inF5.mode = 5;
        QVERIFY(!lock->refusesKey(inF5, panel::KeyPress{panel::Key::Enter}).isEmpty()); // the value written
        // Unlocking is the trainer's action; then the same edit goes through.
        QCOMPARE(trainer.unlockConstants(), QString());
        QCOMPARE(trainer.lockButton()->text(), QStringLiteral("Lock the constants…"));
        QCOMPARE(pane.editor().store().current().simulation.getString("constants.lock", "none"), std::string("none"));
        {
            const std::string unlockNote = pane.editor().store().revisions().front().summary;
            QVERIFY(setLanguage(QStringLiteral("ru")));
            QCOMPARE(revisionNoteText(unlockNote),
                     QStringLiteral("блокировка констант снята (преподаватель; были заблокированы для группы TM-21)"));
            QVERIFY(setLanguage(QStringLiteral("en")));
        }
        QVERIFY(lock->refusesKey(sim.controller.state(), panel::KeyPress{panel::Key::F5}).isEmpty());
        QVERIFY(pane.filter()->setData(valueIndex(pane, 22), QStringLiteral("5333")));
        QCOMPARE(sim.session.controller().c()[22], std::int64_t(5333));
    }

    void filterAndSearch() {
        SimulatedSeam sim(lathe("lathe-filter"));
        ConstantsPane pane(sim.seam, sim.session.simulation().profile());
        QCOMPARE(pane.filter()->rowCount(), 152);
        pane.searchField()->setText(QStringLiteral("ускорение"));
        QCOMPARE(pane.filter()->rowCount(), 4); // C22, C23, C74, C75
        pane.searchField()->setText(QStringLiteral("c022"));
        QCOMPARE(pane.filter()->rowCount(), 1);
        pane.searchField()->setText(QStringLiteral("Z4101"));
        QVERIFY(pane.filter()->rowCount() >= 1);
        pane.searchField()->clear();
        pane.filter()->setAxisFilter(ConstantsFilter::AxisFilter::Common);
        QCOMPARE(pane.filter()->rowCount(), 48);
        pane.filter()->setAxisFilter(ConstantsFilter::AxisFilter::All);
        // What the value means, in core's units.
        const QModelIndex m = pane.filter()->index(pane.filter()->mapFromSource(
                                                       pane.model()->index(ConstantsModel::rowOf(22), 0)).row(),
                                                   ConstantsModel::Means);
        QVERIFY2(m.data().toString().contains(QStringLiteral("0.4166")) ||
                     m.data().toString().contains(QStringLiteral("0.4167")),
                 qPrintable(m.data().toString()));
    }

    // What a value means is core's, in both languages: the column says it in
    // the window's, and again in the other when the window changes language.
    void theMeaningFollowsTheWindowsLanguage() {
        QVERIFY(setLanguage(QStringLiteral("en")));
        SimulatedSeam sim(lathe("lathe-means"));
        ConstantsPane pane(sim.seam, sim.session.simulation().profile());
        const profile::MachineProfile& p = sim.session.simulation().profile();
        const auto means = [&] {
            return pane.model()->index(ConstantsModel::rowOf(22), ConstantsModel::Means).data().toString();
        };
        const QString en = QString::fromStdString(db::explainCValue(p, 22, db::Lang::En));
        const QString ru = QString::fromStdString(db::explainCValue(p, 22, db::Lang::Ru));
        QVERIFY2(!en.isEmpty() && en != ru, qPrintable(en));
        QCOMPARE(means(), en);
        QVERIFY(setLanguage(QStringLiteral("ru")));
        QTRY_COMPARE_WITH_TIMEOUT(means(), ru, 5000); // once the language change reaches the pane
        QVERIFY(setLanguage(QStringLiteral("en")));
        QTRY_COMPARE_WITH_TIMEOUT(means(), en, 5000);
    }

    // The parameter tables keep each cell's text shaped (CellTextDelegate):
    // what they show is what Qt's own delegate draws, pixel for pixel — a
    // selected row, greyed reserved rows, bold right-aligned values, long
    // meanings elided in a narrow table, in both languages — and painting
    // the same cells again shapes nothing anew.
    void theTablesDrawTheirCellsAsQtDoes() {
        SimulatedSeam sim(lathe("lathe-cells"));
        ConstantsPane constants(sim.seam, sim.session.simulation().profile());
        RParamsPane rparams(sim.seam, sim.session.simulation().profile());
        const auto sameAsQt = [](ParameterTablePane& pane, int valueColumn) {
            QTableView* t = pane.table();
            const QImage ours = t->viewport()->grab().toImage();
            QAbstractItemDelegate* all = t->itemDelegate();
            QAbstractItemDelegate* value = t->itemDelegateForColumn(valueColumn);
            QStyledItemDelegate qt;
            t->setItemDelegate(&qt);
            t->setItemDelegateForColumn(valueColumn, &qt);
            const QImage theirs = t->viewport()->grab().toImage();
            t->setItemDelegate(all);
            t->setItemDelegateForColumn(valueColumn, value);
            return !ours.isNull() && ours == theirs;
        };
        for (const char* lang : {"en", "ru"}) {
            QVERIFY(setLanguage(QString::fromLatin1(lang)));
            for (const QSize size : {QSize(1250, 700), QSize(620, 400)}) {
                for (ParameterTablePane* pane : {static_cast<ParameterTablePane*>(&constants),
                                                 static_cast<ParameterTablePane*>(&rparams)}) {
                    const int valueColumn = pane == &constants ? int(ConstantsModel::Value) : int(RParamsModel::Value);
                    pane->resize(size);
                    pane->show();
                    pane->table()->selectRow(14); // among C015, C016: reserved, grey
                    QTest::qWait(20);
                    QVERIFY2(sameAsQt(*pane, valueColumn), lang);
                    pane->searchField()->setText(QStringLiteral("ускор"));
                    QTest::qWait(20);
                    QVERIFY2(sameAsQt(*pane, valueColumn), lang);
                    pane->searchField()->clear();
                    QTest::qWait(20);
                }
            }
        }
        QVERIFY(setLanguage(QStringLiteral("en")));
        // Shaped once: typing again what was typed before paints from the cache.
        auto* cells = qobject_cast<CellTextDelegate*>(constants.table()->itemDelegate());
        QVERIFY(cells);
        for (const QString& typed : {QStringLiteral("c0"), QString(), QStringLiteral("mm"), QString()}) {
            constants.searchField()->setText(typed);
            constants.table()->viewport()->repaint();
        }
        const int shaped = cells->shapedTexts();
        QVERIFY(shaped > 0);
        for (const QString& typed : {QStringLiteral("c0"), QString(), QStringLiteral("mm"), QString()}) {
            constants.searchField()->setText(typed);
            constants.table()->viewport()->repaint();
        }
        QCOMPARE(cells->shapedTexts(), shaped);
    }

    void importExportAndDiff() {
        SimulatedSeam sim(lathe("lathe-files"));
        ConstantsPane pane(sim.seam, sim.session.simulation().profile());
        QVERIFY(pane.editor().set(22, 5000));
        const QString csv = dir_.filePath("lathe.csv");
        pane.exportFile(csv);
        QVERIFY(pane.busy());
        QVERIFY(waitIdle(pane));
        QVERIFY2(QFile::exists(csv), qPrintable(pane.statusText()));
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QString text = QString::fromUtf8(f.readAll());
        f.close();
        QVERIFY(text.contains(QStringLiteral("\n22;X;УСКОРЕНИЕ 1;5000;")));

        // A bad file is refused whole: nothing changes.
        const int revs = revisionCount(pane);
        QString bad = text;
        bad.replace(QStringLiteral("\n22;X;УСКОРЕНИЕ 1;5000;"), QStringLiteral("\n22;X;УСКОРЕНИЕ 1;99999;"));
        const QString badPath = dir_.filePath("bad.csv");
        QFile b(badPath);
        QVERIFY(b.open(QIODevice::WriteOnly));
        b.write(bad.toUtf8());
        b.close();
        QSignalSpy done(&pane, &ConstantsPane::finished);
        pane.importFile(badPath);
        QVERIFY(waitIdle(pane));
        QCOMPARE(done.count(), 1);
        QVERIFY2(pane.statusText().contains(QStringLiteral("Nothing was imported")), qPrintable(pane.statusText()));
        // The place is named: the file and the line of the bad value.
        QVERIFY2(pane.statusText().contains(QStringLiteral("bad.csv, line 23:")), qPrintable(pane.statusText()));
        QCOMPARE(revisionCount(pane), revs);
        QCOMPARE(sim.session.controller().c()[22], std::int64_t(5000));

        // A cross-check error is refused by the database as `k528 db import` refuses it.
        QString clash = text;
        clash.replace(QStringLiteral("\n17;X;N ДОС;1;"), QStringLiteral("\n17;X;N ДОС;3;"));
        QVERIFY(clash != text);
        QFile c(badPath);
        QVERIFY(c.open(QIODevice::WriteOnly | QIODevice::Truncate));
        c.write(clash.toUtf8());
        c.close();
        pane.importFile(badPath);
        QVERIFY(waitIdle(pane));
        QVERIFY2(pane.statusText().contains(QStringLiteral("M37")) || pane.statusText().contains(QStringLiteral("37")),
                 qPrintable(pane.statusText()));
        QCOMPARE(revisionCount(pane), revs);
        QCOMPARE(sim.session.controller().c()[17], std::int64_t(1));

        // A good one: a revision, and the controller takes the values.
        QString good = text;
        good.replace(QStringLiteral("\n22;X;УСКОРЕНИЕ 1;5000;"), QStringLiteral("\n22;X;УСКОРЕНИЕ 1;7000;"));
        QFile g(csv);
        QVERIFY(g.open(QIODevice::WriteOnly | QIODevice::Truncate));
        g.write(good.toUtf8());
        g.close();
        pane.importFile(csv);
        QVERIFY(waitIdle(pane));
        QVERIFY2(pane.statusText().contains(QStringLiteral("imported")), qPrintable(pane.statusText()));
        QCOMPARE(revisionCount(pane), revs + 1);
        QCOMPARE(sim.session.controller().c()[22], std::int64_t(7000));
        QCOMPARE(valueIndex(pane, 22).data().toString(), QStringLiteral("7000"));

        // A machine file, exported and imported.
        const QString k528m = dir_.filePath("lathe.k528m");
        pane.exportFile(k528m);
        QVERIFY(waitIdle(pane));
        QVERIFY(QFile::exists(k528m));
        QVERIFY(pane.editor().set(22, 6000));
        pane.importFile(k528m);
        QVERIFY(waitIdle(pane));
        QCOMPARE(sim.session.controller().c()[22], std::int64_t(7000));

        // The diff of two revisions, on a worker thread.
        const int current = pane.editor().store().revisions().front().revision;
        QFuture<LongResult> diff = pane.diffRevisions(1, current);
        diff.waitForFinished();
        const LongResult r = diff.result();
        QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
        QVERIFY2(r.text.contains(QStringLiteral("C022 УСКОРЕНИЕ 1: 10666 -> 7000")), qPrintable(r.text));
        DiffDialog dd(pane);
        dd.compare();
        QTRY_VERIFY(!dd.result()->toPlainText().isEmpty());
    }

    void calculatorExplainsTheFactorOfTwo() {
        SimulatedSeam sim(lathe("lathe-calc"));
        ConstantsPane pane(sim.seam, sim.session.simulation().profile());
        CalculatorDialog d(pane.editor());
        // Appendix Ж: 2 s from 0 to 5000 mm/min, 0.001 mm: printed 2133, consistent 1066.
        d.setInputs(1, 5000, 2000);
        QCOMPARE(d.consistentValue(), qint64(1066));
        const QString html = d.findChild<QTextBrowser*>("constants.calculatorExplanation")->toPlainText();
        QVERIFY(html.contains(QStringLiteral("2133")));
        QVERIFY(html.contains(QStringLiteral("0.8533")));
        QVERIFY(html.contains(QStringLiteral("factor 2.00")));
        QVERIFY(d.applyToAccel1());
        QCOMPARE(sim.session.controller().c()[22], std::int64_t(1066));
        d.setInputs(3, 0.5, 0);
        QCOMPARE(d.consistentValue(), qint64(12800));
    }

    void rParametersLiveEditablePresets() {
        SimulatedSeam sim(lathe("lathe-r"));
        RParamsPane pane(sim.seam, sim.session.simulation().profile());
        RParamsModel* m = pane.model();
        QCOMPARE(m->rowCount(), 300);
        // Editable where the engine allows it.
        QVERIFY(m->setData(m->index(100, RParamsModel::Value), QStringLiteral("1234")));
        QCOMPARE(sim.session.controller().r(100), 1234);
        QVERIFY(!(m->flags(m->index(240, RParamsModel::Value)) & Qt::ItemIsEditable));
        QVERIFY(!m->setData(m->index(240, RParamsModel::Value), QStringLiteral("1")));
        QVERIFY(pane.statusText().contains(QStringLiteral("R240")));
        // A coordinate in mm (R220: the initial position of X, display discretes).
        QVERIFY(m->setData(m->index(220, RParamsModel::Mm), QStringLiteral("12.5")));
        QCOMPARE(sim.session.controller().r(220), 12500);
        QCOMPARE(m->index(220, RParamsModel::Mm).data().toString(), QStringLiteral("12.500"));
        // Live: the machine's coordinates (R232..) as the controller has them.
        sim.session.advance(100);
        for (int n : {232, 234, 240, 249})
            QCOMPARE(m->index(n, RParamsModel::Value).data().toString(),
                     QString::number(sim.session.controller().r(n)));
        // Presets kept with the machine.
        pane.selectR(100);
        QVERIFY(pane.keepSelectedAsPreset() > 0);
        QCOMPARE(MachineStore(sim.session.simulation().profile()).current().r.at(100), std::int64_t(1234));
        QCOMPARE(m->index(100, RParamsModel::Preset).data().toString(), QStringLiteral("1234"));
        QVERIFY(m->setData(m->index(100, RParamsModel::Value), QStringLiteral("0")));
        pane.applyPresets();
        QCOMPARE(sim.session.controller().r(100), 1234);
        pane.selectR(100);
        QVERIFY(pane.removeSelectedPreset() > 0);
        QVERIFY(!MachineStore(sim.session.simulation().profile()).current().r.count(100));
        // Search and filters.
        pane.filter()->setSearch(QStringLiteral("r204"));
        QCOMPARE(pane.filter()->rowCount(), 1);
        pane.filter()->setSearch(QString());
        pane.filter()->setShow(RParamsFilter::Show::ReadOnly);
        QCOMPARE(pane.filter()->rowCount(), 31);
    }

    void docksInTheWindowAndScreenshots() {
        MainWindow w;
        auto* c = w.findChild<QDockWidget*>("dock.constants");
        auto* r = w.findChild<QDockWidget*>("dock.rparams");
        QVERIFY(c && r);
        auto* cp = c->findChild<ConstantsPane*>();
        QVERIFY(cp);
        c->setFloating(true);
        c->resize(1250, 620);
        c->show();
        cp->selectConstant(22);
        cp->editor().check(22, 99999);
        cp->searchField()->setText(QString());
        QVERIFY(!cp->filter()->setData(valueIndex(*cp, 22), QStringLiteral("99999")));
        QTest::qWait(50);
        K528_VERIFY_SHOT(c->grab(), QStringLiteral("constants.png"));
        {
            // The machine has run: homed, moved (the live coordinates, R232..).
            program::ParseOptions o;
            machine::SimulationRunMachine m(w.session()->simulation());
            engine::runProgram(m, program::parse("%L1\nN1 G0 X150 Z-40\n", o).store, 1, engine::RunOptions{});
        }
        r->findChild<QComboBox*>("rparams.show")->setCurrentIndex(5); // not zero: the live values
        r->setFloating(true);
        r->resize(1000, 620);
        r->show();
        w.session()->advance(200);
        QTest::qWait(50);
        K528_VERIFY_SHOT(r->grab(), QStringLiteral("rparams.png"));
        CalculatorDialog calc(cp->editor());
        calc.setInputs(1, 5000, 2000);
        calc.show();
        QTest::qWait(50);
        K528_VERIFY_SHOT(calc.grab(), QStringLiteral("constants-calculator.png"));
        // In Russian, as the operators read it.
        QVERIFY(setLanguage("ru"));
        QTest::qWait(50);
        K528_VERIFY_SHOT(c->grab(), QStringLiteral("constants-ru.png"));
        K528_VERIFY_SHOT(r->grab(), QStringLiteral("rparams-ru.png"));
        setLanguage("en");
    }
};

QTEST_MAIN(TestConstants)
#include "test_constants.moc"
