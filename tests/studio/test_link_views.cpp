// Every view of the main window on a real controller: `k528 serve` on a
// socat pty pair, reached through the Modbus RTU plugin (LinkController).
// The K923, the messages, the Program tab, the constants, the R-parameters,
// the history, the oscilloscope, the backplot and the editor follow the
// controller shown (the seam of controller/controller.h); the machine's
// control panel and the debugger, which only the simulated machine has, are
// greyed with the reason. Writes go with the controller's rules (F7
// «РАБОТА С ПЭВМ»); a lost line makes every view say since when and keep
// its last values, and the views come back by themselves when the
// controller answers again (another `k528 serve` on the same line, running
// a program: the backplot's actual path and the oscilloscope grow from its
// live positions).
//
// K528_TEST_LANG=ru runs it in Russian (the texts are then not compared);
// whole-window screenshots (link_views_*.png) go to the current folder.
#include "backplot/backplot_widget.h"
#include "constants/constants_dock.h"
#include "constants/constants_editor.h"
#include "constants/constants_model.h"
#include "controller/controller_dock.h"
#include "controller/link_controller.h"
#include "controller/simulated_controller.h"
#include "controller/view_notice.h"
#include "editor/debug_panel.h"
#include "editor/editor_tab.h"
#include "editor/program_editor.h"
#include "history/history_dock.h"
#include "history/history_model.h"
#include "k923/k923_widget.h"
#include "language.h"
#include "machine/machine_panel.h"
#include "main_window.h"
#include "monitor/program_monitor.h"
#include "pty_line.h"
#include "rig/widgets.h"
#include "rparams/rparams_dock.h"
#include "rparams/rparams_model.h"
#include "scope/scope_view.h"
#include "session/machine_source.h"
#include "test_util.h"
#include "workspace/workspaces.h"

#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QProcess>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QSignalSpy>
#include <QStackedWidget>
#include <QStandardItemModel>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>
#include <algorithm>

using namespace k528;
using namespace k528::studio;
using testutil::finished;

namespace {

bool en() { return currentLanguage() == QLatin1String("en"); }

} // namespace

class TestLinkViews : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    ptytest::PtyPair line_;
    ptytest::Serve serve_;
    QString lang_;
    QString alarmFile_, runFile_;

    bool k528(const QStringList& args) {
        QProcess p;
        p.start(QStringLiteral(K528_CLI), args);
        return p.waitForFinished(30000) && p.exitCode() == 0;
    }
    bool startServe(const QString& file, const QString& keys) {
        if (serve_.start(line_.a(), {"--profile", file, "--keys", keys}, 15000))
            return true;
        qWarning("serve: %s", serve_.said().constData());
        return false;
    }
    // The whole window in `workspace` with `dock` raised, at the screen's size.
    void shot(MainWindow& w, QDockWidget* dock, const QString& name, const QString& workspace = "technologist") {
        w.workspaces()->activate(workspace);
        if (dock) {
            dock->show();
            dock->raise();
        }
        QTest::qWait(400);
        const QSize s = w.screen()->size();
        K528_VERIFY_SHOT(w.grab(), QStringLiteral("link_views_%1_%2_%3x%4.png").arg(name, lang_).arg(s.width()).arg(s.height()));
    }
    static ViewNotice* noticeOf(QWidget* content) {
        for (QWidget* p = content; p; p = p->parentWidget())
            if (auto* n = qobject_cast<ViewNotice*>(p))
                return n;
        return nullptr;
    }

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("K528StudioTestLinkViews");
        QSettings().clear();
        lang_ = qEnvironmentVariable("K528_TEST_LANG", "en");
        QVERIFY(setLanguage(lang_));
        QVERIFY(dir_.isValid());
        qputenv("K528_DB", dir_.filePath("shop.db").toUtf8());
        qputenv("K528_PLUGIN_PATH", QFileInfo(QStringLiteral(K528_RTU_PLUGIN)).absolutePath().toUtf8());
        // Two served machines made from the training lathe: one that overran
        // its X+ limit switch (an alarm to record), one that runs L1 without
        // homing (АВТ.БЕЗ ПБТ) for the live path.
        const QString db = dir_.filePath("serve.db");
        const QString lathe = dir_.filePath("lathe.k528m");
        QVERIFY(k528({"db", "init", "--db", db}));
        QVERIFY(k528({"db", "export", "training-lathe", "--db", db, "--out", lathe}));
        const QString text = testutil::readFile(lathe);
        QString alarm = text;
        alarm.replace("\nname=training-lathe\n", "\nname=overrun-lathe\n");
        alarmFile_ = testutil::writeFile(dir_, "overrun.k528m", alarm + "x.limit_plus_mm=80\nx.start_mm=85\n");
        QString run = text;
        run.replace("\nC008=0", "\nC008=1").replace("\nC060=0", "\nC060=1");
        runFile_ = testutil::writeFile(dir_, "run.k528m", run);
        QVERIFY(line_.start(dir_.path(), "lv"));
    }
    void cleanupTestCase() {
        serve_.stop();
        line_.stop();
    }

    void everyViewOnTheLinkedController() {
        QVERIFY(startServe(alarmFile_, "F7 1 1 1 1 ENTER DOWN DOWN ENTER"));
        MainWindow w(loadMachine("training-lathe"));
        w.placeOnScreen();
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* dock = w.findChild<ControllerDock*>("dock.controller");
        QVERIFY(dock);
        dock->portBox()->setEditText(line_.b());
        QSignalSpy connected(dock, &ControllerDock::connectedChanged);
        dock->connectLine();
        QVERIFY(finished(connected, 15000));
        QVERIFY2(connected.first().first().toBool(), qPrintable(dock->lastMessage()));
        LinkController* link = dock->link();
        QVERIFY(link && w.viewedController() == link);
        QVERIFY(link->memoryRevision() > 0); // C and R read as it opened
        QTRY_VERIFY_WITH_TIMEOUT(link->state().pcReady, 5000);

        // The K923: the controller's LEDs, and the dock says what the line lacks.
        auto* k923Dock = w.k923Dock();
        if (en())
            QVERIFY2(k923Dock->windowTitle().contains("no LCD text"), qPrintable(k923Dock->windowTitle()));
        // The messages: the overrun alarm of the served machine.
        QTRY_VERIFY_WITH_TIMEOUT(!link->state().alarms.empty(), 5000);
        // The machine's control panel and the debugger: greyed, with the reason.
        ViewNotice* machine = noticeOf(w.machinePanel());
        QVERIFY(machine);
        QCOMPARE(machine->level(), ViewNotice::Level::Unavailable);
        QVERIFY(!machine->content()->isEnabled());
        if (en())
            QVERIFY2(machine->text().contains("simulated machine"), qPrintable(machine->text()));
        ViewNotice* debugger = noticeOf(w.programEditor()->debugPanel());
        QVERIFY(debugger);
        QCOMPARE(debugger->level(), ViewNotice::Level::Unavailable);
        shot(w, w.machineDock(), "machine", "operator");

        // The constants: the controller's, written in F7 and kept in the database.
        auto* constants = w.findChild<ConstantsPane*>("constantsPane");
        QVERIFY(constants);
        ConstantsEditor& editor = constants->editor();
        QVERIFY(&editor.controller() == link);
        QTRY_VERIFY_WITH_TIMEOUT(constants->model()->index(ConstantsModel::rowOf(17), ConstantsModel::Value).data().toString() ==
                                     QString::number(link->cValues()[17]),
                                 3000);
        QCOMPARE(noticeOf(constants)->level(), ViewNotice::Level::Info);
        const int number = 22; // УСКОРЕНИЕ 1 of X
        const std::int64_t before = link->cValues()[number];
        const std::int64_t after = before + 7;
        QVERIFY(editor.check(number, after).ok);
        QSignalSpy kept(&editor, &ConstantsEditor::kept);
        QVERIFY(editor.set(number, after, "from the link test"));
        QVERIFY(finished(kept, 10000));
        QCOMPARE(link->cValues()[number], after);
        QCOMPARE(editor.undoStack()->count(), 1);
        shot(w, w.findChild<QDockWidget*>("dock.constants"), "constants");
        editor.undoStack()->undo();
        QTRY_COMPARE_WITH_TIMEOUT(link->cValues()[number], before, 10000);

        // The R-parameters: R200 written over the line, R158 refused with the reason.
        auto* rparams = w.findChild<RParamsPane*>("rparamsPane");
        QVERIFY(rparams);
        RParamsModel* rm = rparams->model();
        QVERIFY(rm->setData(rm->index(200, RParamsModel::Value), "12345"));
        QTRY_COMPARE_WITH_TIMEOUT(link->rValues()[200], 12345, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(rm->index(200, RParamsModel::Value).data().toString(), QString("12345"), 3000);
        QSignalSpy refused(rm, &RParamsModel::refused);
        QVERIFY(!rm->setData(rm->index(158, RParamsModel::Value), "3"));
        QCOMPARE(refused.size(), 1);
        if (en())
            QVERIFY2(refused.first().first().toString().contains("positioner's own"),
                     qPrintable(refused.first().first().toString()));
        shot(w, w.findChild<QDockWidget*>("dock.rparams"), "rparams");
        // Controller > Clear the R area (manual 2.6.8, F7 only).
        QSignalSpy cleared(dock, &ControllerDock::memoryCleared);
        dock->clearMemory(MemoryArea::R, false);
        QVERIFY(finished(cleared, 10000));
        QVERIFY2(cleared.takeFirst().first().toBool(), qPrintable(dock->lastMessage()));
        QTRY_COMPARE_WITH_TIMEOUT(link->rValues()[200], 0, 5000);

        // The history: the real controller's alarm, in this PC's time; ESC is its own K923's.
        auto* history = w.findChild<QStackedWidget*>("history.pages");
        QVERIFY(history);
        auto* hv = qobject_cast<HistoryView*>(history->currentWidget());
        QVERIFY(hv);
        QVERIFY(!hv->acknowledgeButton()->isEnabled());
        const qint64 now = QDateTime::currentMSecsSinceEpoch();
        QTRY_VERIFY_WITH_TIMEOUT((hv->applyFilter(), hv->model()->rowCount() > 0), 5000);
        const db::MessageRecord& rec = hv->model()->record(0);
        QVERIFY2(QString::fromStdString(rec.machine).contains(" @ "), rec.machine.c_str());
        QVERIFY2(std::abs(rec.dayMs - now) < 120000, qPrintable(QString::number(rec.dayMs - now)));
        shot(w, w.findChild<QDockWidget*>("dock.history"), "history");

        // The editor: open the controller's programs, send a program after the preview.
        EditorTab* ed = w.programEditor();
        QSignalSpy opened(ed, &EditorTab::openedFromController);
        QVERIFY(ed->openFromController());
        QVERIFY(finished(opened, 30000));
        QVERIFY2(opened.first().first().toBool(), qPrintable(opened.first().last().toString()));
        QVERIFY(ed->currentEditor()->text().contains("%L1"));
        ed->newFile();
        ed->currentEditor()->setText("%L42 (from the editor)\nN1 G1 X10 FX100\nN2 M30\n");
        QSignalSpy preview(ed, &EditorTab::sendPreviewShown);
        QSignalSpy sent(ed, &EditorTab::sent);
        QVERIFY(ed->sendToController());
        QVERIFY(finished(preview, 30000));
        QVERIFY(ed->sendPreview());
        const QString diff = ed->sendPreview()->findChild<QPlainTextEdit*>("controller.pushPreview.diff")->toPlainText();
        QVERIFY2(diff.contains("L42"), qPrintable(diff));
        K528_VERIFY_SHOT(ed->sendPreview()->grab(), QStringLiteral("link_views_editor_send_preview_%1.png").arg(lang_));
        ed->sendPreview()->accept();
        QVERIFY(finished(sent, 30000));
        QVERIFY2(sent.first().first().toBool(), qPrintable(sent.first().last().toString()));
        QTRY_VERIFY_WITH_TIMEOUT(std::ranges::count(link->state().programNumbers, 42) == 1, 5000);

        // File > Load programs and Keep in the database: the controller's memory.
        QSignalSpy loaded(&w, &MainWindow::programsLoaded);
        w.loadProgramsFrom(testutil::writeFile(dir_, "p43.k528", "%L43\nN1 G1 Z-5 FZ100\nN2 M30\n"));
        QVERIFY(finished(loaded, 30000));
        QVERIFY2(loaded.first().first().toBool(), qPrintable(loaded.first().last().toString()));
        QTRY_VERIFY_WITH_TIMEOUT(std::ranges::count(link->state().programNumbers, 43) == 1, 5000);
        QSignalSpy keptMemory(&w, &MainWindow::memoryKept);
        w.keepInDatabase();
        QVERIFY(finished(keptMemory, 30000));
        QVERIFY2(keptMemory.first().first().toInt() > 0, qPrintable(keptMemory.first().last().toString()));
        const profile::MachineProfile inDb = loadMachine("training-lathe").profile;
        QVERIFY(inDb.programs.count(42) && inDb.programs.count(43));

        // The oscilloscope: the link's poll, said; no DAC.
        auto* scope = w.findChild<ScopeView*>("scope");
        QVERIFY(scope);
        QTRY_VERIFY_WITH_TIMEOUT(scope->buffer().size() > 10, 5000);
        QVERIFY2(scope->sampleRateHz() > 4 && scope->sampleRateHz() < 12, qPrintable(QString::number(scope->sampleRateHz())));
        if (en())
            QVERIFY2(scope->rateLabel()->text().contains("the link's poll"), qPrintable(scope->rateLabel()->text()));
        auto* extra = w.findChild<QComboBox*>("scope.extra");
        QVERIFY(!qobject_cast<QStandardItemModel*>(extra->model())->item(1)->isEnabled());

        // The line lost: every view says since when and keeps its last values.
        const std::int64_t c17 = link->cValues()[17];
        serve_.stop();
        QTRY_VERIFY_WITH_TIMEOUT(link->stale(), 10000);
        QTRY_COMPARE_WITH_TIMEOUT(noticeOf(constants)->level(), ViewNotice::Level::Stale, 3000);
        QCOMPARE(noticeOf(rparams)->level(), ViewNotice::Level::Stale);
        QCOMPARE(link->cValues()[17], c17);
        QVERIFY(!link->whyNotWritable(MemoryArea::C).isEmpty());
        if (en()) {
            QVERIFY2(noticeOf(constants)->text().contains("has not answered since"), qPrintable(noticeOf(constants)->text()));
            QVERIFY(dock->monitorLabel()->text().contains("has not answered since"));
        }
        shot(w, w.findChild<QDockWidget*>("dock.constants"), "stale");
        shot(w, w.k923Dock(), "stale_operator", "operator");

        // Another controller answers on the line, running L1: the views come back by themselves.
        QVERIFY(startServe(runFile_, "PUSH:DRIVES_ON WAIT:1 L4 F1 ACK 1 ENTER PUSH:START"));
        QTRY_VERIFY_WITH_TIMEOUT(!link->stale(), 15000);
        QCOMPARE(noticeOf(constants)->level(), ViewNotice::Level::Info);
        QTRY_VERIFY_WITH_TIMEOUT(link->state().program.state == engine::ProgramState::Running, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(w.programMonitor()->shownProgram(), 1, 10000);
        // Writes outside F7 are refused with the manual's condition named.
        QSignalSpy refusedC(&editor, &ConstantsEditor::refused);
        QVERIFY(!editor.set(number, after));
        QCOMPARE(refusedC.size(), 1);
        if (en())
            QVERIFY2(refusedC.first().first().toString().contains("not in F7 «РАБОТА С ПЭВМ» (mode F1 now)"),
                     qPrintable(refusedC.first().first().toString()));
        dock->clearMemory(MemoryArea::C, false);
        QVERIFY(finished(cleared, 10000));
        QVERIFY(!cleared.takeFirst().first().toBool());
        if (en())
            QVERIFY2(dock->lastMessage().contains("not in F7"), qPrintable(dock->lastMessage()));
        // The oscilloscope's samples move with the axes.
        const std::size_t had = scope->buffer().size();
        QTRY_VERIFY_WITH_TIMEOUT(scope->buffer().size() > had + 20, 10000);
        bool moved = false;
        for (std::size_t i = had; i + 1 < scope->buffer().size(); ++i)
            for (int a = 0; a < 2; ++a)
                moved = moved || scope->buffer().at(i).axes[static_cast<std::size_t>(a)].positionMm !=
                                     scope->buffer().at(i + 1).axes[static_cast<std::size_t>(a)].positionMm;
        QVERIFY(moved);
        shot(w, w.findChild<QDockWidget*>("dock.scope"), "scope");
        // The backplot: L1 read from the controller, its actual path growing.
        if (auto* bp = w.findChild<k528::studio::backplot::BackplotWidget*>()) {
            QTRY_VERIFY_WITH_TIMEOUT(bp->scene().path().program == 1 && !bp->scene().path().segments.empty(), 20000);
            QTRY_VERIFY_WITH_TIMEOUT(bp->scene().actualPointsShown() > 5, 10000);
            shot(w, w.findChild<QDockWidget*>("dock.backplot"), "backplot");
        } else {
            qInfo("no backplot on the %s platform", qPrintable(QGuiApplication::platformName()));
        }
        shot(w, w.k923Dock(), "k923", "operator");
        shot(w, dock, "controller", "operator");

        // Disconnected: every view on the simulated controller again.
        dock->disconnectLine();
        QVERIFY(w.viewedController() == w.simulatedController());
        QCOMPARE(noticeOf(constants)->level(), ViewNotice::Level::None);
        QCOMPARE(machine->level(), ViewNotice::Level::None);
        QVERIFY(machine->content()->isEnabled());
        QVERIFY(qobject_cast<HistoryView*>(history->currentWidget())->acknowledgeButton()->isEnabled());
        QCOMPARE(history->count(), 1); // the real controller's page went with it (its run is kept)
        serve_.stop();
    }
};

QTEST_MAIN(TestLinkViews)
#include "test_link_views.moc"
