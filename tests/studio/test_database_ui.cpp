// The studio on a shop database shared by many PCs: File > Database… opens a
// file or a PostgreSQL database (and refuses a bad one, keeping the one
// open), another process's `k528 db set` reaches the constants dock live
// (PRAGMA data_version on SQLite, LISTEN/NOTIFY on PostgreSQL), and a change
// based on an older revision is refused with who made the newer one, the
// differences and the change applied again on top. Runs on SQLite, and as
// studio.database_ui.postgresql inside its own pg_virtualenv cluster.
#include "db/db_test_util.h"

#include "constants/constants_dialogs.h"
#include "constants/constants_dock.h"
#include "constants/constants_editor.h"
#include "constants/constants_follow.h"
#include "controller/simulated_controller.h"
#include "database/database_ui.h"
#include "language.h"
#include "main_window.h"
#include "profile/builtin.h"
#include "session/shop_database.h"
#include "session/simulation_session.h"

#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QComboBox>
#include <QTableWidget>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QtTest>

using namespace k528;
using namespace k528::studio;

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

profile::MachineProfile lathe(const std::string& name) {
    profile::MachineProfile p = profile::builtin("training-lathe");
    p.name = name;
    return p;
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
                d.createMachine(lathe("lathe-live"));
        });
        SimulationSession session(lathe("lathe-live"));
        SimulatedController sim(session);
        ViewedController seam(sim);
        ConstantsPane pane(seam, session.simulation().profile());
        auto* follow = pane.findChild<ConstantsFollow*>();
        QVERIFY(follow);
        QSignalSpy followed(follow, &ConstantsFollow::followed);
        QSignalSpy told(DatabaseWatch::instance(), &DatabaseWatch::revision);
        QTest::qWait(2 * DatabaseWatch::kPollMs); // the watch has seen the database as it is

        const std::int64_t before = pane.editor().values()[22];
        const std::int64_t wanted = before == 5000 ? 6000 : 5000;
        const Ran set = runK528({"db", "set", "lathe-live", QStringLiteral("C022=%1").arg(wanted), "--author",
                              "petrov", "--db", location_});
        QVERIFY2(set.exitCode == 0, qPrintable(set.err));
        QTRY_COMPARE_WITH_TIMEOUT(followed.count(), 1, 10000);
        QCOMPARE(pane.editor().values()[22], wanted); // the dock shows the other process's value
        QCOMPARE(session.simulation().profile().c[22], wanted);
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
                d.createMachine(lathe("lathe-race"));
        });
        SimulationSession session(lathe("lathe-race"));
        SimulatedController sim(session);
        ViewedController seam(sim);
        ConstantsPane pane(seam, session.simulation().profile());
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
                    d.createMachine(lathe(name));
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
};

QTEST_MAIN(TestDatabaseUi)
#include "test_database_ui.moc"
