// The workstation's machines come from the shop's database: created with the
// built-in machines on the first start, its constants are the ones the
// simulated machine runs; File > Machine switches the machine; a damaged
// database is reported, left as it is, and the built-in machines still run.
#include "cli_runner.h"
#include "language.h"
#include "main_window.h"
#include "db/database.h"
#include "profile/builtin.h"
#include "profile/english.h"
#include "resources/embedded.h"
#include "profile/text_format.h"
#include "program/parser.h"
#include "session/machine_source.h"
#include "session/shop_database.h"
#include "session/simulation_session.h"

#include <QAction>
#include <QCryptographicHash>
#include <QFile>
#include <QLabel>
#include <QMenu>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace k528;
using namespace k528::studio;

namespace {

QByteArray fileHash(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256);
}

} // namespace

class TestMachineSource : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString db_;

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("K528StudioTest");
        QSettings().clear();
        QVERIFY(setLanguage("en"));
        db_ = dir_.filePath("new/folder/shop.db"); // a new machine: not even the folder exists
        qputenv("K528_DB", db_.toUtf8());
    }

    void firstStartCreatesTheDatabase() {
        QVERIFY(!QFile::exists(db_));
        QString warning;
        const QStringList names = machineNames(&warning);
        QVERIFY2(warning.isEmpty(), qPrintable(warning));
        QVERIFY(QFile::exists(db_));
        QVERIFY(names.contains("training-lathe"));
        QVERIFY(names.contains("grinder-205"));
    }

    void theDatabasesConstantsRun() {
        const auto set = runK528({"db", "set", "training-lathe", "C094=300000", "--db", db_});
        QVERIFY2(set.exitCode == 0, qPrintable(set.err));
        const MachineChoice c = loadMachine("training-lathe");
        QVERIFY(c.warning.isEmpty());
        QVERIFY(c.source.text().contains(db_));
        QCOMPARE(c.profile.c[94], 300000);
        QCOMPARE(profile::builtin("training-lathe").c[94], 600000);
        MainWindow w(c);
        QCOMPARE(w.session()->controller().c()[94], 300000);
        const QLabel* label = w.findChild<QLabel*>("status.machine");
        QVERIFY2(label->text().contains("Training lathe with the K528-05"), qPrintable(label->text()));
        // The database is named once in the status line, by its own label;
        // the machine's says where it came from in its tooltip, in the
        // window's language, also after the language is changed while the
        // window is open.
        const QLabel* database = w.findChild<QLabel*>("status.database");
        QVERIFY(database);
        QVERIFY2(!label->text().contains(db_) && database->toolTip() == db_, qPrintable(label->text()));
        QCOMPARE(label->toolTip(), "database " + db_);
        QVERIFY(setLanguage("ru"));
        QTRY_COMPARE(label->toolTip(), "база данных " + db_);
        QVERIFY2(label->text().startsWith(QStringLiteral("Станок: ")) && !label->text().contains(db_),
                 qPrintable(label->text()));
        QVERIFY(setLanguage("en"));
        QTRY_COMPARE(label->toolTip(), "database " + db_);
        QVERIFY_THROWS_EXCEPTION(profile::FileError, loadMachine("no-such-machine"));
    }

    // Each source is said in the window's language, a machine the database
    // does not hold (any more) too.
    void eachSourceInTheWindowsLanguage() {
        const MachineSource database{MachineSource::Kind::Database, db_};
        const MachineSource builtin{MachineSource::Kind::Builtin, QString()};
        const MachineSource file{MachineSource::Kind::File, QStringLiteral("/tmp/lathe.k528m")};
        const MachineSource gone{MachineSource::Kind::NotInDatabase, db_};
        QCOMPARE(MachineSource{}.text(), QString());
        QCOMPARE(database.text(), "database " + db_);
        QCOMPARE(builtin.text(), QStringLiteral("built-in"));
        QCOMPARE(file.text(), QStringLiteral("/tmp/lathe.k528m"));
        QCOMPARE(gone.text(), "not in the database " + db_);
        QVERIFY(setLanguage("ru"));
        QCOMPARE(database.text(), "база данных " + db_);
        QCOMPARE(builtin.text(), QStringLiteral("встроенный"));
        QCOMPARE(file.text(), QStringLiteral("/tmp/lathe.k528m"));
        QCOMPARE(gone.text(), "нет в базе данных " + db_);
        QVERIFY(setLanguage("en"));
    }

    void fileMenuSwitchesTheMachine() {
        auto* w = new MainWindow(loadMachine("training-lathe"));
        w->setAttribute(Qt::WA_DeleteOnClose);
        w->show();
        QVERIFY(QTest::qWaitForWindowExposed(w));
        QAction* lathe = w->machineMenu()->findChild<QAction*>("action.machine.training-lathe");
        QAction* grinder = w->machineMenu()->findChild<QAction*>("action.machine.grinder-205");
        QVERIFY(lathe && grinder);
        QVERIFY(lathe->isChecked());
        QVERIFY(!grinder->isChecked());
        QPointer<MainWindow> old(w);
        MainWindow* g = w->switchMachine("grinder-205");
        QVERIFY(g);
        QVERIFY(g->isVisible());
        QTRY_VERIFY(old.isNull()); // closed and deleted
        QCOMPARE(g->session()->simulation().description().name, std::string("grinder-205"));
        QCOMPARE(startMachineName(), QString("grinder-205")); // the next start
        g->close();
        rememberMachine("training-lathe");
    }

    // A window names the machine by its title in the window's language (the
    // machine file's `title`, its `title.en` in English), never by the bare
    // name: the status line, File > Machine, the editor's machine of a file.
    void theMachineIsNamedByItsTitle() {
        const profile::MachineProfile lathe = profile::builtin("training-lathe");
        MainWindow w(loadMachine("training-lathe"));
        auto* label = w.findChild<QLabel*>("status.machine");
        QVERIFY(label);
        for (const char* lang : {"ru", "en"}) {
            QVERIFY(setLanguage(lang));
            QApplication::processEvents(); // LanguageChange reaches every widget
            const QString title = QString::fromStdString(profile::titleText(lathe, QLatin1String(lang) == "en"));
            QVERIFY(title.contains(QLatin1String(lang) == "en" ? "Training lathe" : "Учебный токарный"));
            QVERIFY2(label->text().contains(title), qPrintable(label->text()));
            QVERIFY2(!label->text().contains("training-lathe"), qPrintable(label->text()));
            emit w.machineMenu()->aboutToShow();
            QAction* a = w.machineMenu()->findChild<QAction*>("action.machine.training-lathe");
            QVERIFY(a);
            QCOMPARE(a->text(), title);
            QCOMPARE(machineTitle(lathe), title);
        }
        QVERIFY(setLanguage("en"));
        // A machine without a title is named by its name.
        profile::MachineProfile bare = lathe;
        bare.name = "lathe-7";
        bare.title.clear();
        bare.simulation.erase(profile::englishKey("title"));
        QCOMPARE(machineTitle(bare), QStringLiteral("lathe-7"));
    }

    // Two machines of one title (a second lathe made from the same machine
    // file) are told apart by their names; the rest keep the title alone.
    void twoMachinesOfOneTitleAreToldApart() {
        QVERIFY(setLanguage("ru"));
        ShopDatabase::at()->use([](db::Database& d) {
            profile::MachineProfile p = d.loadMachine("training-lathe");
            p.name = "lathe-2";
            d.createMachine(p);
        });
        const QString title = QString::fromStdString(profile::builtin("training-lathe").title);
        QStringList said;
        for (const TitledMachine& m : titledMachines())
            said << m.name + '=' + m.title;
        const QString grinder = QString::fromStdString(profile::builtin("grinder-205").title);
        QCOMPARE(said, (QStringList{"grinder-205=" + grinder, "lathe-2=" + title + " — lathe-2",
                                    "training-lathe=" + title + " — training-lathe"}));
        ShopDatabase::at()->use([](db::Database& d) { d.removeMachine("lathe-2"); });
        QVERIFY(setLanguage("en"));
    }

    // The sample programs are data shipped for Russian shops: the titles the
    // program lists and tabs show are Russian (their English is in the
    // file's «; EN:» comments).
    void theSamplesProgramTitlesAreRussian() {
        int titles = 0;
        for (const auto& r : resources::under("samples/")) {
            const program::ParseResult parsed = program::parse(r.data);
            for (const program::Program& p : parsed.store.programs()) {
                QVERIFY2(p.title, qPrintable(QStringLiteral("%1: L%2").arg(QString::fromUtf8(r.path.data(), r.path.size())).arg(p.number)));
                const QString t = QString::fromStdString(*p.title);
                QVERIFY2(t.contains(QRegularExpression("[а-яё]")), qPrintable(t));
                QVERIFY2(!t.contains(QRegularExpression("[A-Za-z]")), qPrintable(t));
                ++titles;
            }
        }
        QVERIFY(titles >= 7);
    }

    // File > Keep: the controller's memory becomes the next revision of the
    // machine, and the next start runs it.
    void keepTheMemory() {
        MainWindow w(loadMachine("training-lathe"));
        SimulationSession* s = w.session();
        s->setRunning(false);
        engine::Positioner& ctl = s->controller();
        QVERIFY(ctl.setR(100, 4321).ok());
        program::ProgramStore* store = ctl.editablePrograms();
        QVERIFY(store);
        const auto parsed = program::parse("%L42 (kept)\nN1 G1 X40 FX100\nN2 M30\n");
        for (const program::Program& p : parsed.store.programs())
            store->insert(p);
        QVERIFY(ctl.programsEdited().ok());
        const int rev = w.keepInDatabase();
        QVERIFY(rev >= 2);
        const MachineChoice again = loadMachine("training-lathe");
        QCOMPARE(again.profile.r.at(100), std::int64_t(4321));
        QVERIFY(again.profile.programs.count(42));
        QCOMPARE(again.profile.programs.at(42), std::string("%L42 (kept)\nN1 G1 X40 FX100\nN2 M30\n"));
        QVERIFY(again.profile.programs.count(1)); // the machine's own programs stay
        QCOMPARE(again.profile.c, w.session()->simulation().profile().c);
        // Nothing new: the same revision.
        QCOMPARE(w.keepInDatabase(), rev);
        // The history says who and what (k528 db show --history).
        const auto history = runK528({"db", "show", "training-lathe", "--history", "1", "--db", db_});
        QVERIFY2(history.out.contains("R100"), qPrintable(history.out));
    }

    void damagedDatabaseIsReportedAndLeftAlone() {
        const QString bad = dir_.filePath("damaged.db");
        {
            QFile f(bad);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(QByteArray(8192, 'x'));
        }
        const QByteArray before = fileHash(bad);
        qputenv("K528_DB", bad.toUtf8());
        const MachineChoice c = loadMachine("grinder-205");
        QVERIFY(!c.warning.isEmpty());
        QCOMPARE(c.profile.name, std::string("grinder-205")); // the built-in one runs
        QString warning;
        QCOMPARE(machineNames(&warning), (QStringList{"grinder-205", "training-lathe"}));
        QVERIFY(!warning.isEmpty());
        QCOMPARE(fileHash(bad), before);
        qputenv("K528_DB", db_.toUtf8());
    }
};

QTEST_MAIN(TestMachineSource)
#include "test_machine_source.moc"
