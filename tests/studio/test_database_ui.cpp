// The studio on a shop database shared by many PCs: File > Database… opens a
// file or a PostgreSQL database (and refuses a bad one, keeping the one
// open), another process's `k528 db set` reaches the constants dock live
// (PRAGMA data_version on SQLite, LISTEN/NOTIFY on PostgreSQL), and a change
// based on an older revision is refused with who made the newer one, the
// differences and the change applied again on top. Runs on SQLite, and as
// studio.database_ui.postgresql inside its own pg_virtualenv cluster.
#include "db/db_test_util.h"
#include "rig/widgets.h"

#include "constants/constants_dialogs.h"
#include "constants/constants_dock.h"
#include "constants/constants_editor.h"
#include "constants/constants_follow.h"
#include "constants/constants_model.h"
#include "controller/link_controller.h"
#include "controller/push_preview.h"
#include "controller/simulated_controller.h"
#include "db/message_log.h"
#include "editor/editor_tab.h"
#include "editor/program_releases.h"
#include "history/history_dock.h"
#include "history/history_model.h"
#include "link_plugins.h"
#include "session/machine_source.h"
#include "database/database_ui.h"
#include "language.h"
#include "main_window.h"
#include "profile/builtin.h"
#include "rparams/rparams_dock.h"
#include "rparams/rparams_model.h"
#include "pty_line.h"
#include "session/shop_database.h"
#include "session/simulation_session.h"
#include "rig/studio_rig.h"

#include <QDialog>
#include <QDockWidget>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMainWindow>
#include <QStackedWidget>
#include <QTreeWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QComboBox>
#include <QTableWidget>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QtTest>
#include <tuple>

using namespace k528;
using namespace k528::studio;
using testrig::latheNamed;
using testrig::SimulatedSeam;

namespace {

struct Ran {
    int exitCode = -1;
    QString out, err;
};

// `k528 ARGS` as another process (another PC's change, as far as the
// database can tell).
Ran runK528(const QStringList& args) {
    QProcess p;
    p.start(QStringLiteral(K528_CLI), args);
    Ran r;
    if (!p.waitForFinished(60000))
        return r;
    r.exitCode = p.exitCode();
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

// K528_TEST_SCREENSHOTS=DIR: the window `w` with its dock `dock` shown, at
// 1366x768 and 1920x1080, as DIR/NAME-WxH.png (to look at; nothing is compared).
void screenshot(QMainWindow& w, const char* dock, const QString& name) {
    const QString dir = qEnvironmentVariable("K528_TEST_SCREENSHOTS");
    if (dir.isEmpty())
        return;
    w.show();
    if (auto* d = w.findChild<QDockWidget*>(dock)) {
        d->show();
        d->raise(); // before the docks tabbed with it
    }
    for (const QSize size : {QSize(1366, 768), QSize(1920, 1080)}) {
        w.resize(size);
        QTest::qWait(400);
        K528_VERIFY_SHOT(w.grab(), QStringLiteral("%1-%2x%3.png").arg(name).arg(size.width()).arg(size.height()));
    }
}

} // namespace

class TestDatabaseUi : public QObject {
    Q_OBJECT
private:
    QTemporaryDir dir_;
    QString location_; // the database of the tests, as a user writes it

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        QCoreApplication::setOrganizationName("K528StudioTestDatabaseUi");
        QSettings().clear();
        qunsetenv("K528_DB");
        qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8()); // the default, never the user's
        location_ = QString::fromStdString(testing::testLocation(dir_, "shop.db").text());
        QVERIFY(setLanguage("en"));
    }

    void fileDatabaseOpensAndRefuses() {
        MainWindow w;
        // A bad location: said, and the database open before stays.
        const QString before = ShopDatabase::currentText();
        DatabaseDialog bad(&w);
        bad.setLocation(QStringLiteral("mysql://host/shop"));
        bad.accept();
        QVERIFY2(bad.error().contains("not a database location"), qPrintable(bad.error()));
        QCOMPARE(ShopDatabase::currentText(), before);
        const QString foreign = dir_.filePath("notes.txt");
        QFile f(foreign);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("not a database at all, just text that is long enough to be looked at\n");
        f.close();
        QCOMPARE(openDatabase(foreign).isEmpty(), false);
        QCOMPARE(ShopDatabase::currentText(), before);
        QVERIFY(setLanguage("ru"));
        const QString ru = openDatabase(QStringLiteral("mysql://host/shop"));
        QVERIFY2(ru.contains(QStringLiteral("не адрес базы данных")), qPrintable(ru));
        QVERIFY(setLanguage("en"));

        // The shop's database: open, named in the title and the status bar, remembered.
        QSignalSpy switched(DatabaseWatch::instance(), &DatabaseWatch::switched);
        DatabaseDialog good(&w);
        good.setLocation(location_);
        good.accept();
        QVERIFY2(good.error().isEmpty(), qPrintable(good.error()));
        QCOMPARE(switched.count(), 1);
        QCOMPARE(ShopDatabase::currentText(), location_);
        QVERIFY2(w.windowTitle().endsWith(location_), qPrintable(w.windowTitle()));
        auto* label = w.statusBar()->findChild<QLabel*>("status.database");
        QVERIFY(label);
        QCOMPARE(label->toolTip(), location_);
        QCOMPARE(QSettings().value("database/location").toString(), location_);
        QCOMPARE(recentDatabases().first(), location_);
    }

    void anotherProcessChangeReachesTheDock() {
        QVERIFY(openDatabase(location_).isEmpty());
        const auto shop = ShopDatabase::at();
        shop->use([](db::Database& d) {
            if (!d.hasMachine("lathe-live"))
                d.createMachine(latheNamed("lathe-live"));
        });
        SimulatedSeam sim(latheNamed("lathe-live"));
        ConstantsPane pane(sim.seam, sim.session.simulation().profile());
        auto* follow = pane.findChild<ConstantsFollow*>();
        QVERIFY(follow);
        QSignalSpy followed(follow, &ConstantsFollow::followed);
        QSignalSpy told(DatabaseWatch::instance(), &DatabaseWatch::revision);
        DatabaseWatch::instance()->check(); // the watch has seen the database as it is (its timer may not have yet)

        const std::int64_t before = pane.editor().values()[22];
        const std::int64_t wanted = before == 5000 ? 6000 : 5000;
        const Ran set = runK528({"db", "set", "lathe-live", QStringLiteral("C022=%1").arg(wanted), "--author",
                              "petrov", "--db", location_});
        QVERIFY2(set.exitCode == 0, qPrintable(set.err));
        QTRY_COMPARE_WITH_TIMEOUT(followed.count(), 1, 10000);
        QCOMPARE(pane.editor().values()[22], wanted); // the dock shows the other process's value
        QCOMPARE(sim.session.simulation().profile().c[22], wanted);
        QVERIFY(told.count() >= 1);
        const auto r = told.last().first().value<RevisionElsewhere>();
        QCOMPARE(r.machine, QString("lathe-live"));
        QVERIFY2(pane.statusText().contains("changed on another PC") && pane.statusText().contains("C022"),
                 qPrintable(pane.statusText()));
        if (!testing::onPostgres())
            QVERIFY2(pane.statusText().contains("petrov"), qPrintable(pane.statusText()));

        // This window's own change is not told as another's.
        const int toldBefore = told.count();
        QSignalSpy refused(&pane.editor(), &ConstantsEditor::refused);
        QVERIFY(pane.editor().set(22, wanted == 5000 ? 6000 : 5000, "ours"));
        QTRY_VERIFY2(pane.statusText().contains("kept as revision"),
                     qPrintable(pane.statusText() + " / " +
                                (refused.isEmpty() ? QString() : refused.last().first().toString())));
        QTest::qWait(3 * DatabaseWatch::kPollMs);
        QCOMPARE(told.count(), toldBefore);
    }

    void olderRevisionIsRefusedAndReapplied() {
        QVERIFY(openDatabase(location_).isEmpty());
        ShopDatabase::at()->use([](db::Database& d) {
            if (!d.hasMachine("lathe-race"))
                d.createMachine(latheNamed("lathe-race"));
        });
        SimulatedSeam sim(latheNamed("lathe-race"));
        ConstantsPane pane(sim.seam, sim.session.simulation().profile());
        auto* follow = pane.findChild<ConstantsFollow*>();
        QVERIFY(follow);
        const int known = pane.editor().store().known();
        QVERIFY(known >= 1);
        // Another PC changes the machine; this window has not looked yet (the
        // watch is stopped for the moment of the race).
        DatabaseWatch::instance()->blockSignals(true);
        const std::int64_t theirs = pane.editor().values()[21] == 1200 ? 1000 : 1200;
        const Ran set = runK528({"db", "set", "lathe-race", QStringLiteral("C021=%1").arg(theirs), "--author", "sidorov",
                              "--db", location_});
        QVERIFY2(set.exitCode == 0, qPrintable(set.err));
        const std::int64_t mine = pane.editor().values()[22] == 5000 ? 6000 : 5000;
        QVERIFY(pane.editor().set(22, mine, "my change"));
        QTRY_VERIFY(follow->offer() != nullptr);
        DatabaseWatch::instance()->blockSignals(false);
        ConflictDialog* offer = follow->offer();
        QVERIFY2(pane.statusText().startsWith("Not kept in the database"), qPrintable(pane.statusText()));
        QVERIFY2(offer->message()->text().contains(QString::number(known + 1)), qPrintable(offer->message()->text()));
        if (!testing::onPostgres())
            QVERIFY2(offer->message()->text().contains("sidorov"), qPrintable(offer->message()->text()));
        // The differences: the other PC's change.
        offer->diffButton()->click();
        DiffDialog* diff = pane.findChild<DiffDialog*>();
        QVERIFY(diff);
        QTRY_VERIFY_WITH_TIMEOUT(diff->result()->toPlainText().contains("C021"), 10000);
        // Applied again on top: a revision after the other's with both changes.
        offer->applyButton()->click();
        QTRY_VERIFY(pane.statusText().contains("kept as revision"));
        const profile::MachineProfile now = pane.editor().store().current();
        QCOMPARE(now.c[21], theirs);
        QCOMPARE(now.c[22], mine);
        QCOMPARE(pane.editor().store().known(), known + 2);
    }

    void transfersListedByMachine() {
        QVERIFY(openDatabase(location_).isEmpty());
        ShopDatabase::at()->use([](db::Database& d) {
            for (const char* name : {"lathe-log-a", "lathe-log-b"}) {
                if (!d.hasMachine(name))
                    d.createMachine(latheNamed(name));
                db::TransferEntry t;
                t.machine = name;
                t.revision = 1;
                t.controller = "/dev/ttyUSB0#1 K528-05";
                t.direction = "push";
                t.result = "ok";
                t.items.push_back({"program", 11, "1a2b3c4d", std::string(64, 'a'), "new"});
                d.recordTransfer(t);
            }
        });
        TransfersDialog d(QStringLiteral("lathe-log-a"));
        QCOMPARE(d.table()->rowCount(), 1);
        QCOMPARE(d.table()->item(0, 3)->text(), QString("lathe-log-a"));
        QCOMPARE(d.table()->item(0, 5)->text(), QString("push"));
        QVERIFY2(d.table()->item(0, 6)->text().contains("L11 1a2b3c4d new"), qPrintable(d.table()->item(0, 6)->text()));
        QCOMPARE(d.table()->item(0, 7)->text(), QString("ok"));
        QVERIFY(!d.table()->item(0, 1)->text().isEmpty()); // the user: the OS's, or the server's current_user
        d.machineFilter()->setCurrentIndex(0); // every machine
        QVERIFY(d.table()->rowCount() >= 2);
    }

    // The studio's push and pull on a real line (`k528 serve` on a socat pty
    // pair) go on record as `k528 link push/pull` do: another process's
    // `k528 db log --json` sees them, a failed push with its failure.
    void studioTransfersAreOnRecord() {
#ifndef K528_RTU_PLUGIN
        QSKIP("built without the link plugins");
#else
        QVERIFY(openDatabase(location_).isEmpty());
        // L77 released, L78 a draft: the push of the database's machine
        // sends L77 and leaves L78 out (as `k528 link push --machine`).
        const std::string l77text = "%L77 (on record)\nN1 G1 X10 FX100\nN2 M02\n";
        const std::string l78text = "%L78 (a draft)\nN1 G1 X20 FX100\nN2 M02\n";
        int revision = 0;
        ShopDatabase::at()->use([&](db::Database& d) {
            if (!d.hasMachine("lathe-push")) {
                profile::MachineProfile m = latheNamed("lathe-push");
                m.programs.clear(); // L77 and L78 only
                m.programs[77] = l77text;
                m.programs[78] = l78text;
                d.createMachine(m);
                d.releaseProgram("lathe-push", 77);
            }
            revision = d.machine("lathe-push")->revision;
        });
        qputenv("K528_PLUGIN_PATH", QFileInfo(QStringLiteral(K528_RTU_PLUGIN)).absolutePath().toUtf8());
        // Stopped (the ports' lock files removed) on every way out.
        ptytest::PtyPair pty;
        ptytest::Serve serve;
        QVERIFY(pty.start(dir_.path(), "dbl"));
        const QString b = pty.b();
        // training-lathe in F7 «РАБОТА С ПЭВМ».
        QVERIFY2(serve.start(pty.a(), {"--profile", "training-lathe", "--keys", "F7 1 1 1 1 ENTER DOWN DOWN ENTER"}),
                 serve.said().constData());

        QString error;
        linkplugin::LinkPlugin* plugin = linkplugin::find(QStringLiteral("modbus-rtu"), error);
        QVERIFY2(plugin, qPrintable(error));
        linkplugin::LineSettings line;
        line.port = b;
        LinkController link(*plugin, line, latheNamed("lathe-push"));
        QSignalSpy opened(&link, &LinkController::opened);
        link.open();
        QVERIFY(opened.wait(15000));
        QVERIFY2(opened.first().first().toBool(), qPrintable(opened.first().last().toString()));

        QSignalSpy recorded(&link, &LinkController::transferRecorded);
        QSignalSpy pushed(&link, &LinkController::pushed);
        profile::MachineProfile p = latheNamed("lathe-push");
        p.programs.clear();
        p.programs[77] = l77text;
        p.programs[78] = l78text;
        const ReleasedPush sent = releasedPush(p, QStringLiteral("lathe-push"));
        QVERIFY2(sent.error.isEmpty(), qPrintable(sent.error));
        QVERIFY(!sent.overridden);
        QVERIFY2(sent.leftOut.size() == 1, qPrintable(sent.leftOut.join('|')));
        QVERIFY2(sent.leftOut.first().startsWith("L78: draft"), qPrintable(sent.leftOut.first()));
        QVERIFY(sent.file.programs.count(77) && !sent.file.programs.count(78));
        // The preview says what is left out and why.
        QDialog* preview = showPushPreview(nullptr, QStringLiteral("lathe-push"), p, afterPush(p, sent.file),
                                           QStringLiteral("Push"), [](bool) {}, sent.leftOut);
        auto* leftOut = preview->findChild<QLabel*>("controller.pushPreview.leftOut");
        QVERIFY(leftOut);
        QVERIFY2(leftOut->text().contains("L78: draft, never released: not sent"), qPrintable(leftOut->text()));
        preview->reject();
        link.push(p, QStringLiteral("lathe-push"));
        QVERIFY(pushed.wait(60000));
        QVERIFY2(pushed.first().first().toBool(), qPrintable(pushed.first().at(1).toString()));
        QCOMPARE(recorded.count(), 1);
        QVERIFY2(recorded.first().first().toBool(), qPrintable(recorded.first().last().toString()));
        QVERIFY(link.lastTransfer().id > 0);

        QSignalSpy pulled(&link, &LinkController::pulled);
        link.pull();
        QVERIFY(pulled.wait(60000));
        QVERIFY(pulled.first().first().toBool());
        QCOMPARE(recorded.count(), 2);

        // Another process reads the log: the pull newest, then the push.
        Ran log = runK528({"db", "log", "lathe-push", "--json", "--db", location_});
        QVERIFY2(log.exitCode == 0, qPrintable(log.err));
        QJsonArray t = QJsonDocument::fromJson(log.out.toUtf8()).object().value("transfers").toArray();
        QVERIFY2(t.size() >= 2, qPrintable(log.out));
        const QJsonObject pull = t.at(0).toObject(), push = t.at(1).toObject();
        QCOMPARE(pull.value("direction").toString(), QString("pull"));
        QCOMPARE(pull.value("result").toString(), QString("ok"));
        QCOMPARE(push.value("direction").toString(), QString("push"));
        QCOMPARE(push.value("result").toString(), QString("ok"));
        QCOMPARE(push.value("machine").toString(), QString("lathe-push"));
        QCOMPARE(push.value("revision").toInt(), revision);
        // The line as `k528 link` names it, and what the controller says it is.
        QVERIFY2(push.value("controller").toString().startsWith("serial:" + b + "?baud=115200&address=1"),
                 qPrintable(push.value("controller").toString()));
        QVERIFY(!push.value("user").toString().isEmpty() && !push.value("host").toString().isEmpty());
        bool l77 = false;
        for (const QJsonValue& v : push.value("items").toArray()) {
            const QJsonObject item = v.toObject();
            QCOMPARE(item.value("crc32").toString().size(), 8);
            QVERIFY2(!(item.value("kind").toString() == "program" && item.value("number").toInt() == 78),
                     qPrintable(log.out)); // the draft is not sent
            if (item.value("kind").toString() == "program" && item.value("number").toInt() == 77) {
                l77 = true;
                QCOMPARE(item.value("state").toString(), QString("new"));
                QCOMPARE(item.value("sha256").toString().size(), 64);
            }
        }
        QVERIFY2(l77, qPrintable(log.out));
        QVERIFY(pull.value("items").toArray().size() >= 3); // C, R, the messages, the programs

        // The controller goes away: the push fails, and its failure is on record.
        serve.stop();
        QVERIFY(!serve.running());
        pushed.clear();
        link.push(p, QStringLiteral("lathe-push"));
        QVERIFY(pushed.wait(120000));
        QVERIFY(!pushed.first().first().toBool());
        QCOMPARE(recorded.count(), 3);
        log = runK528({"db", "log", "lathe-push", "--json", "--limit", "1", "--db", location_});
        QVERIFY2(log.exitCode == 0, qPrintable(log.err));
        t = QJsonDocument::fromJson(log.out.toUtf8()).object().value("transfers").toArray();
        QCOMPARE(t.size(), 1);
        QCOMPARE(t.at(0).toObject().value("direction").toString(), QString("push"));
        QCOMPARE(t.at(0).toObject().value("result").toString(), QString("failed"));
        QVERIFY(!t.at(0).toObject().value("detail").toString().isEmpty());
#endif
    }

    // The release states beside the editor's database programs: Release and
    // Withdraw of the studio are those `k528 db` sees, and a refused one says why.
    void releasesBesideTheEditor() {
        QVERIFY(openDatabase(location_).isEmpty());
        const int n = ShopDatabase::at()->use([](db::Database& d) {
            if (!d.hasMachine("lathe-rel"))
                d.createMachine(latheNamed("lathe-rel"));
            return d.programReleases("lathe-rel").front().number;
        });
        EditorTab tab(nullptr);
        QVERIFY(!tab.releases()->isVisibleTo(&tab)); // no database document yet
        QVERIFY(tab.openFromDatabase("lathe-rel"));
        ProgramReleases* r = tab.releases();
        QVERIFY(r->isVisibleTo(&tab));
        QCOMPARE(r->machine(), QString("lathe-rel"));
        QVERIFY(r->list()->topLevelItemCount() >= 1);
        QTreeWidgetItem* item = r->list()->topLevelItem(0);
        QCOMPARE(item->text(0), QStringLiteral("L%1").arg(n));
        QCOMPARE(item->text(1), QString("draft"));
        QVERIFY2(item->toolTip(1).contains("Never released"), qPrintable(item->toolTip(1)));
        r->list()->setCurrentItem(item);
        QVERIFY(r->releaseButton()->isEnabled());
        QVERIFY(!r->withdrawButton()->isEnabled());

        // Release with a note, as the button does.
        QString asked;
        r->setNoteQuestion([&](const QString& title) -> std::optional<QString> {
            asked = title;
            return QStringLiteral("checked on the machine");
        });
        QSignalSpy said(&tab, &EditorTab::statusMessage);
        r->releaseButton()->click();
        QVERIFY2(asked.contains(QStringLiteral("L%1").arg(n)), qPrintable(asked));
        QVERIFY(!said.isEmpty());
        QVERIFY2(said.last().first().toString().startsWith(QStringLiteral("Released L%1").arg(n)),
                 qPrintable(said.last().first().toString()));
        item = r->list()->topLevelItem(0);
        QCOMPARE(item->text(1), QString("released"));
        QVERIFY2(item->toolTip(1).contains("checked on the machine") && item->toolTip(1).contains("Released as of"),
                 qPrintable(item->toolTip(1)));
        QVERIFY(!item->text(2).isEmpty()); // who
        Ran show = runK528({"db", "show", "lathe-rel", "--programs", "--json", "--db", location_});
        QVERIFY2(show.exitCode == 0, qPrintable(show.err));
        auto stateOf = [&](const Ran& ran) {
            for (const QJsonValue& v : QJsonDocument::fromJson(ran.out.toUtf8()).object().value("programs").toArray())
                if (v.toObject().value("number").toInt() == n)
                    return v.toObject().value("state").toString();
            return QString();
        };
        QCOMPARE(stateOf(show), QString("released"));

        // Released again: refused with the reason, nothing written.
        const QString again = r->release(n, QString());
        QVERIFY2(again.contains("released already"), qPrintable(again));

        // Withdraw: `k528 db` sees it; withdrawn twice is refused.
        r->list()->setCurrentItem(r->list()->topLevelItem(0));
        QVERIFY(r->withdrawButton()->isEnabled());
        r->withdrawButton()->click();
        QCOMPARE(r->list()->topLevelItem(0)->text(1), QString("withdrawn"));
        show = runK528({"db", "show", "lathe-rel", "--programs", "--json", "--db", location_});
        QCOMPARE(stateOf(show), QString("withdrawn"));
        const QString twice = r->withdraw(n, QString());
        QVERIFY2(twice.contains("withdrawn already"), qPrintable(twice));
        QVERIFY(!r->withdrawButton()->isEnabled());

        // A release by `k528 db release` elsewhere is read again; the words in Russian.
        const Ran rel = runK528({"db", "release", "lathe-rel", QStringLiteral("L%1").arg(n), "--note", "снова",
                                 "--db", location_});
        QVERIFY2(rel.exitCode == 0, qPrintable(rel.err));
        QVERIFY(setLanguage("ru"));
        r->refresh();
        QCOMPARE(r->list()->topLevelItem(0)->text(1), QStringLiteral("выпущена"));
        QCOMPARE(ProgramReleases::stateText(db::ProgramState::Draft), QStringLiteral("черновик"));
        QCOMPARE(ProgramReleases::stateText(db::ProgramState::Withdrawn), QStringLiteral("отозвана"));
        QVERIFY(r->list()->topLevelItem(0)->toolTip(1).contains(QStringLiteral("снова")));
        QVERIFY(setLanguage("en"));
    }

    // After File > Database… the message history records into the new
    // database and shows its messages, and the machine's label names it.
    void historyFollowsTheDatabase() {
        QVERIFY(openDatabase(location_).isEmpty());
        const QString second = QString::fromStdString(testing::testLocation(dir_, "second.db").text());
        // The second database holds a message of the window's machine.
        const QString text = QStringLiteral("ТОЛЬКО ВО ВТОРОЙ БАЗЕ");
        ShopDatabase::at(db::Location::parse(second.toStdString()))->useLog([&](db::MessageLog& log) {
            const std::int64_t now = QDateTime::currentMSecsSinceEpoch();
            const std::int64_t run = log.beginRun("training-lathe", now);
            db::MessageEvent e;
            e.kind = db::MessageEvent::Kind::Raised;
            e.seq = 1;
            e.machineMs = 10;
            e.dayMs = now;
            e.message.machine = "training-lathe";
            e.message.source = db::MessageSource::Program;
            e.message.number = 42;
            e.message.text = text.toStdString();
            e.message.textEn = "only in the second database";
            log.write(run, std::span<const db::MessageEvent>(&e, 1));
        });
        MainWindow w(loadMachine("training-lathe"));
        auto* label = w.statusBar()->findChild<QLabel*>("status.machine");
        QVERIFY(label);
        auto* dock = w.findChild<QDockWidget*>("dock.history");
        QVERIFY(dock);
        auto shown = [&]() -> HistoryView* {
            auto* pages = dock->findChild<QStackedWidget*>("history.pages");
            return pages ? qobject_cast<HistoryView*>(pages->currentWidget()) : nullptr;
        };
        auto holds = [&](HistoryView* v) {
            v->model()->refresh();
            for (int i = 0; i < v->model()->rowCount(); ++i)
                if (QString::fromStdString(v->model()->record(i).text) == text)
                    return true;
            return false;
        };
        QVERIFY(shown());
        QVERIFY(!holds(shown()));

        QVERIFY(openDatabase(second).isEmpty());
        QTRY_VERIFY(shown() && holds(shown()));
        // The machine's label says it comes from the new database as a start
        // on it would (its tooltip: the database label beside it names it).
        const QString secondName = QString::fromStdString(ShopDatabase::at()->path().string());
        QVERIFY2(label->toolTip().contains(secondName), qPrintable(label->toolTip()));
        // Back: the first database's history again, without that message.
        QVERIFY(openDatabase(location_).isEmpty());
        QTRY_VERIFY(shown() && !holds(shown()) && shown()->model()->error().isEmpty());
        QVERIFY2(label->toolTip().contains(location_) || label->text().contains("not in the database"),
                 qPrintable(label->text() + " / " + label->toolTip()));
    }

    // After File > Database… the constants dock and the R-parameter presets
    // show the machine as the new database holds it, and a change is kept
    // there, based on that database's revision; back again, the first one's.
    void constantsFollowTheDatabase() {
        QVERIFY(openDatabase(location_).isEmpty());
        const QString second = QString::fromStdString(testing::testLocation(dir_, "switch.db").text());
        const std::string name = "lathe-switch";
        // One machine, two databases: C022 5000 at revision 1 in the first,
        // 6000 at revision 2 in the second; R10's preset 15 and 25.
        for (const QString& where : {location_, second}) {
            const bool first = where == location_;
            ShopDatabase::at(db::Location::parse(where.toStdString()))->use([&](db::Database& d) {
                if (d.hasMachine(name))
                    d.removeMachine(name);
                profile::MachineProfile p = latheNamed(name);
                p.c[22] = 5000;
                p.r[10] = first ? 15 : 25;
                d.createMachine(p);
                if (!first) {
                    db::Edit e;
                    e.c[22] = 6000;
                    d.applyEdit(name, e);
                }
            });
        }
        MainWindow w(loadMachine(QString::fromStdString(name)));
        auto* pane = w.findChild<ConstantsPane*>("constantsPane");
        auto* presets = w.findChild<RParamsPane*>("rparamsPane");
        QVERIFY(pane && presets);
        auto* follow = pane->findChild<ConstantsFollow*>();
        QVERIFY(follow);
        const auto shownC22 = [&] {
            return pane->model()->data(pane->model()->index(ConstantsModel::rowOf(22), ConstantsModel::Value)).toString();
        };
        const auto preset10 = [&]() -> std::int64_t {
            const auto& m = presets->model()->presets();
            const auto it = m.find(10);
            return it == m.end() ? -1 : it->second;
        };
        QCOMPARE(shownC22(), QString("5000"));
        QCOMPARE(preset10(), std::int64_t(15));
        QCOMPARE(pane->editor().store().known(), 1);

        QSignalSpy followed(follow, &ConstantsFollow::databaseFollowed);
        QVERIFY(openDatabase(second).isEmpty());
        QTRY_COMPARE(followed.count(), 1);
        QCOMPARE(followed.last().first().toInt(), 2);
        QCOMPARE(shownC22(), QString("6000")); // the dock shows the new database's value
        QCOMPARE(pane->editor().values()[22], std::int64_t(6000));
        QCOMPARE(preset10(), std::int64_t(25));
        QVERIFY2(pane->statusText().contains("revision 2"), qPrintable(pane->statusText()));
        QVERIFY2(presets->statusText().contains("revision 2"), qPrintable(presets->statusText()));
        pane->selectConstant(22);
        screenshot(w, "dock.constants", "switch-constants-en");
        screenshot(w, "dock.rparams", "switch-rparams-en");
        // A change now is kept in the second database, on its revision 2 (not
        // refused as based on the first one's revision 1).
        QVERIFY(pane->editor().set(22, 5500, "after the switch"));
        QTRY_VERIFY2(pane->statusText().contains("kept as revision 3"), qPrintable(pane->statusText()));
        ShopDatabase::at()->use([&](db::Database& d) { QCOMPARE(d.loadMachine(name).c[22], std::int64_t(5500)); });
        ShopDatabase::at(db::Location::parse(location_.toStdString()))->use([&](db::Database& d) {
            QCOMPARE(d.machine(name)->revision, 1);
        });

        // Back to the first: its value again; in Russian the pane says so too.
        QVERIFY(setLanguage("ru"));
        QVERIFY(openDatabase(location_).isEmpty());
        QTRY_COMPARE(followed.count(), 2);
        QCOMPARE(followed.last().first().toInt(), 1);
        QCOMPARE(shownC22(), QString("5000"));
        QCOMPARE(preset10(), std::int64_t(15));
        QVERIFY2(pane->statusText().contains(QStringLiteral("ревизии 1")), qPrintable(pane->statusText()));
        screenshot(w, "dock.constants", "switch-constants-ru");
        screenshot(w, "dock.rparams", "switch-rparams-ru");
        QVERIFY(setLanguage("en"));

        // A database without the machine: the constants stay, the first change creates it there.
        const QString empty = QString::fromStdString(testing::testLocation(dir_, "without.db").text());
        QVERIFY(openDatabase(empty).isEmpty());
        QTRY_COMPARE(followed.count(), 3);
        QCOMPARE(followed.last().first().toInt(), 0);
        QCOMPARE(shownC22(), QString("5000"));
        QVERIFY2(pane->statusText().contains("has no machine"), qPrintable(pane->statusText()));
        QCOMPARE(pane->editor().store().known(), 0);
        QVERIFY(openDatabase(location_).isEmpty());
    }

    // On PostgreSQL a studio connected as a viewer is refused a change of a
    // constant, and one connected as an operator the release of a program:
    // the window says which role it needs, in English and in Russian, and
    // nothing is written.
    void roleRefusalIsShown() {
        if (!testing::onPostgres())
            QSKIP("PostgreSQL's roles");
        const db::Location owner = testing::testLocation(dir_, "roles.db");
        const QString ownerText = QString::fromStdString(owner.text());
        const QString dbName = ownerText.mid(ownerText.lastIndexOf('/') + 1);
        const std::string name = "lathe-roles";
        // The shop as its owner sets it up: a machine, the roles, a viewer and an operator.
        QVERIFY(openDatabase(ownerText).isEmpty());
        const int program = ShopDatabase::at()->use([&](db::Database& d) {
            if (!d.hasMachine(name))
                d.createMachine(latheNamed(name));
            return d.programReleases(name).front().number;
        });
        Ran ran = runK528({"db", "roles", "--db", ownerText});
        QVERIFY2(ran.exitCode == 0, qPrintable(ran.err));
        const QString password = qEnvironmentVariable("PGPASSWORD");
        for (const char* user : {"view1", "oper1"}) {
            QProcess psql;
            psql.start("psql", {"-v", "ON_ERROR_STOP=1", "-d", dbName, "-c",
                                QStringLiteral("DO $$ BEGIN IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = "
                                               "'%1') THEN CREATE ROLE %1 LOGIN PASSWORD '%2'; END IF; END $$")
                                    .arg(user, password)});
            QVERIFY(psql.waitForFinished(60000));
            QVERIFY2(psql.exitCode() == 0, psql.readAllStandardError().constData());
        }
        ran = runK528({"db", "roles", "grant", "view1", "viewer", "--db", ownerText});
        QVERIFY2(ran.exitCode == 0, qPrintable(ran.err));
        ran = runK528({"db", "roles", "grant", "oper1", "operator", "--db", ownerText});
        QVERIFY2(ran.exitCode == 0, qPrintable(ran.err));
        const auto stored = [&] {
            return ShopDatabase::at(owner)->use([&](db::Database& d) {
                const db::ProgramState state = d.programReleases(name).front().state;
                return std::make_tuple(d.machine(name)->revision, d.loadMachine(name).c[22], state);
            });
        };
        const auto before = stored();

        // The viewer changes C022 in the constants dock: the simulated
        // controller takes it, the database refuses it, naming the role.
        QVERIFY(openDatabase(QStringLiteral("postgresql://view1@/%1").arg(dbName)).isEmpty());
        MainWindow w(loadMachine(QString::fromStdString(name)));
        auto* pane = w.findChild<ConstantsPane*>("constantsPane");
        QVERIFY(pane);
        for (const char* lang : {"en", "ru"}) {
            QVERIFY(setLanguage(lang));
            const std::int64_t wanted = pane->editor().values()[22] == 5000 ? 6000 : 5000;
            QSignalSpy notKept(&pane->editor(), &ConstantsEditor::notKept);
            QVERIFY(pane->editor().set(22, wanted, "a viewer's change"));
            QTRY_COMPARE(notKept.count(), 1);
            const QString said = pane->statusText();
            QVERIFY2(said.contains("k528_technologist") && said.contains("view1"), qPrintable(said));
            if (QLatin1String(lang) == QLatin1String("en"))
                QVERIFY2(said.contains("needs the role k528_technologist") && said.contains("the user has k528_viewer") &&
                             said.contains("nothing was written"),
                         qPrintable(said));
            else
                QVERIFY2(said.contains(QStringLiteral("требуется роль k528_technologist")) &&
                             said.contains(QStringLiteral("у пользователя: k528_viewer")) &&
                             said.contains(QStringLiteral("ничего не записано")),
                         qPrintable(said));
            QVERIFY(stored() == before); // nothing written
            pane->selectConstant(22);
            screenshot(w, "dock.constants", QStringLiteral("role-refusal-constants-%1").arg(lang));
        }
        w.close();

        // The operator releases a program beside the editor: refused, naming the role.
        QVERIFY(openDatabase(QStringLiteral("postgresql://oper1@/%1").arg(dbName)).isEmpty());
        EditorTab tab(nullptr);
        QVERIFY(tab.openFromDatabase(QString::fromStdString(name)));
        ProgramReleases* r = tab.releases();
        for (const char* lang : {"en", "ru"}) {
            QVERIFY(setLanguage(lang));
            const QString why = r->release(program, QStringLiteral("by an operator"));
            QVERIFY2(why.contains("k528_technologist") && why.contains("oper1"), qPrintable(why));
            if (QLatin1String(lang) == QLatin1String("ru"))
                QVERIFY2(why.contains(QStringLiteral("не выпущена")) &&
                             why.contains(QStringLiteral("у пользователя: k528_operator")) &&
                             why.contains(QStringLiteral("ничего не записано")),
                         qPrintable(why));
            else
                QVERIFY2(why.contains("the user has k528_operator") && why.contains("nothing was written"),
                         qPrintable(why));
            QVERIFY(stored() == before);
        }
        QVERIFY(setLanguage("en"));
        QVERIFY(openDatabase(location_).isEmpty());
    }
};

QTEST_MAIN(TestDatabaseUi)
#include "test_database_ui.moc"
