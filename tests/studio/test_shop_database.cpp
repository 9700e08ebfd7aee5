// The workstation's one connection to the shop's database (ShopDatabase):
// every part of the window — machine source, constants dock (MachineStore),
// the editor's database programs, *Keep in the database*, the message
// history — uses it, so the process has one descriptor of the file however
// many operations it makes; changes of other processes are seen; a file
// replaced under it is opened again; a read-only file is read and a change
// is refused in the window's language; the file is never opened as a
// program or written over from the editor.
#include "cli_runner.h"
#include "constants/machine_store.h"
#include "controller/simulated_controller.h"
#include "editor/database_programs.h"
#include "editor/editor_tab.h"
#include "history/history_service.h"
#include "language.h"
#include "main_window.h"
#include "profile/builtin.h"
#include "session/machine_source.h"
#include "session/program_loader.h"
#include "session/shop_database.h"
#include "session/simulation_session.h"

#include <QDir>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>
#include <dirent.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace k528;
using namespace k528::studio;

namespace {

// Descriptors of this process on `file` itself (not its -wal/-shm).
int descriptorsOf(const QString& file) {
    struct stat want {};
    if (::stat(file.toLocal8Bit().constData(), &want) != 0)
        return 0;
    int n = 0;
    DIR* d = opendir("/proc/self/fd");
    while (const dirent* e = readdir(d)) {
        struct stat st {};
        const std::string link = std::string("/proc/self/fd/") + e->d_name;
        if (e->d_name[0] != '.' && ::stat(link.c_str(), &st) == 0 && st.st_dev == want.st_dev &&
            st.st_ino == want.st_ino)
            ++n;
    }
    closedir(d);
    return n;
}

} // namespace

class TestShopDatabase : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString db_;

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("K528StudioTest");
        QVERIFY(setLanguage("en"));
        db_ = dir_.filePath("shop/k528.db");
        qputenv("K528_DB", db_.toUtf8());
    }

    void everyPartSharesOneConnection() {
        QString warning;
        QVERIFY(machineNames(&warning).contains("grinder-205")); // first start: created
        QVERIFY2(warning.isEmpty(), qPrintable(warning));
        const auto shop = ShopDatabase::at();
        QCOMPARE(ShopDatabase::at().get(), shop.get());
        SimulationSession session(loadMachine("training-lathe").profile);
        SimulatedController sim(session);
        HistoryService history(&sim, db_);
        QCOMPARE(history.shop(), shop.get());
        const MachineStore store(session.simulation().profile());
        for (int i = 1; i <= 5; ++i) {
            db::Edit e;
            e.r[100] = i;
            QCOMPARE(store.keep(e, "test").error, QString());
            QCOMPARE(store.revisions().front().revision, 1 + i);
            QCOMPARE(descriptorsOf(db_), 1);
        }
        const DatabasePrograms programs = loadDatabasePrograms("training-lathe");
        QVERIFY2(programs.ok, qPrintable(programs.error));
        QVERIFY(saveDatabasePrograms("training-lathe", programs.text, programs.revision).error.isEmpty());
        profile::MachineProfile kept = store.current();
        kept.r[101] = 7;
        QVERIFY(saveMachine(kept).revision > 0);
        history.flush();
        QCOMPARE(descriptorsOf(db_), 1);

        // Another process's change is seen by the kept connection.
        const auto set = runK528({"db", "set", "training-lathe", "R100=99", "--db", db_});
        QVERIFY2(set.exitCode == 0, qPrintable(set.err));
        QCOMPARE(store.current().r.at(100), std::int64_t(99));
        QCOMPARE(ShopDatabase::at().get(), shop.get());
    }

    // The window's database is not a program file.
    void theDatabaseIsNotAProgram() {
        ShopDatabase::at();
        SimulationSession session(profile::builtin("training-lathe"));
        SimulatedController sim(session);
        ViewedController seam(sim);
        EditorTab editor(&seam);
        QSignalSpy said(&editor, &EditorTab::statusMessage);
        QVERIFY(!editor.openFile(db_));
        QVERIFY(!said.isEmpty());
        QVERIFY(said.last().first().toString().contains("is the database this window uses"));
        QVERIFY(!editor.openFile(db_ + "-shm"));
        const ProgramLoad load = loadProgramFile(session, db_);
        QVERIFY(!load.loaded);
        QVERIFY(load.problem.contains("is the database this window uses"));
        QVERIFY(!ShopDatabase::isOpenDatabaseFile(dir_.filePath("no-such-file").toStdString()));
        QCOMPARE(descriptorsOf(db_), 1);
    }

    // A file the user may only read (as root: in a child process that
    // becomes nobody): the machines are listed and loaded, a change is
    // refused naming the file and why, in the window's language.
    void readOnlyDatabase() {
        const bool root = geteuid() == 0;
        QTemporaryDir top(QDir::temp().filePath("k528-studio-ro-XXXXXX"));
        const QString folder = top.filePath("ro");
        QVERIFY(QDir().mkpath(folder));
        const QString file = folder + "/k528.db";
        QCOMPARE(runK528({"db", "init", "--db", file}).exitCode, 0);
        const auto readable = QFileDevice::ReadOwner | QFileDevice::ReadGroup | QFileDevice::ReadOther;
        const auto traversable = readable | QFileDevice::ExeOwner | QFileDevice::ExeGroup | QFileDevice::ExeOther;
        QFile::setPermissions(top.path(), traversable | QFileDevice::WriteOwner);
        QFile::setPermissions(folder, root ? traversable | QFileDevice::WriteOwner : traversable);
        QFile::setPermissions(file, root ? readable | QFileDevice::WriteOwner : readable);
        std::fflush(stdout);
        const pid_t pid = root ? fork() : 0;
        int failed = 0;
        if (pid == 0) {
            if (root && (setgid(65534) != 0 || setuid(65534) != 0))
                _exit(10);
            qputenv("K528_DB", file.toUtf8());
            QString warning;
            if (!machineNames(&warning).contains("grinder-205") || !warning.isEmpty())
                failed = 1;
            else if (loadMachine("grinder-205").source.text() != "database " + file)
                failed = 2;
            db::Edit e;
            e.r[100] = 1;
            QVERIFY(setLanguage("ru"));
            const QString ru = MachineStore(profile::builtin("grinder-205")).keep(e, "x").error;
            QVERIFY(setLanguage("en"));
            const QString en = MachineStore(profile::builtin("grinder-205")).keep(e, "x").error;
            if (!failed && !ru.contains("база данных доступна только для чтения: " + file + " (нет права на запись)"))
                failed = 3;
            if (!failed && !en.contains("the database is read-only: " + file + " (permission denied)"))
                failed = 4;
            if (!failed && (en.contains("PRAGMA") || en.contains("attempt to write")))
                failed = 5;
            if (failed)
                std::fprintf(stderr, "%s\n%s\n", qPrintable(ru), qPrintable(en));
            if (root)
                _exit(failed);
            qputenv("K528_DB", db_.toUtf8());
        } else {
            int status = 0;
            QCOMPARE(waitpid(pid, &status, 0), pid);
            failed = WIFEXITED(status) ? WEXITSTATUS(status) : 100;
        }
        QFile::setPermissions(folder, traversable | QFileDevice::WriteOwner);
        QCOMPARE(failed, 0);
        QCOMPARE(QDir(folder).entryList(QDir::Files), QStringList{"k528.db"});
    }

    // A new file moved in place of the one the window has open (a backup
    // restored with mv): refused until a restart — a second connection would
    // take the old file's -wal for the new file's (any SQLite program does:
    // docs/database.md tells to restore a backup with the programs closed).
    void replacedFileIsRefused() {
        const QString path = dir_.filePath("replaced.db");
        qputenv("K528_DB", path.toUtf8());
        QVERIFY(machineNames().contains("grinder-205"));
        db::Edit e;
        e.r[12] = 1;
        QVERIFY(MachineStore(profile::builtin("grinder-205")).keep(e, "x").error.isEmpty());
        const QString other = dir_.filePath("restored.db");
        QCOMPARE(runK528({"db", "init", "--db", other}).exitCode, 0);
        QCOMPARE(runK528({"db", "set", "grinder-205", "R12=4242", "--db", other}).exitCode, 0);
        QVERIFY(::rename(other.toLocal8Bit().constData(), path.toLocal8Bit().constData()) == 0);
        e.r[12] = 2;
        const QString error = MachineStore(profile::builtin("grinder-205")).keep(e, "x").error;
        QVERIFY2(error.contains("was replaced or removed while K528 Studio had it open"), qPrintable(error));
        QString warning;
        machineNames(&warning);
        QVERIFY(warning.contains("replaced"));
        qputenv("K528_DB", db_.toUtf8());
    }
};

QTEST_MAIN(TestShopDatabase)
#include "test_shop_database.moc"
