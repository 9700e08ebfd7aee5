// Connections, locks and read-only files:
//   - opening a database again never drops the locks the process's other
//     connections hold (SQLite's "How To Corrupt", 2.2: closing any
//     descriptor of the file drops them all): a child process sees the
//     parent's SHARED lock on the file after a second open and close;
//   - a file the user may only read is read and never written: its
//     machines load, every write is refused with ReadOnlyError naming the
//     file and the reason (not the SQL), the file stays byte for byte and no
//     -wal/-shm of the reader's is left beside it. Tested with SQLite's
//     read-only open and with real permissions: as root (CI) in a child
//     process that becomes `nobody`, as another user with chmod.
#include "db/database.h"
#include "db/message_log.h"
#include "db_test_util.h"

#include <QtTest>
#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <grp.h>
#include <sqlite3.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace k528;
using namespace k528::testing;
namespace fs = std::filesystem;

namespace {

constexpr uid_t kNobody = 65534;

// Runs `body` in a child process (as `nobody` when the test runs as root);
// returns "" or what failed there.
template <typename F> std::string inChild(bool asNobody, F body) {
    int pipeFd[2];
    if (pipe(pipeFd) != 0)
        return "pipe failed";
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t pid = fork();
    if (pid == 0) {
        close(pipeFd[0]);
        std::string failure;
        try {
            if (asNobody && (setgroups(0, nullptr) != 0 || setgid(kNobody) != 0 || setuid(kNobody) != 0))
                failure = "cannot become nobody";
            else
                failure = body();
        } catch (const std::exception& e) {
            failure = std::string("exception: ") + e.what();
        }
        if (!failure.empty() && write(pipeFd[1], failure.data(), failure.size()) < 0)
            _exit(3);
        _exit(failure.empty() ? 0 : 1);
    }
    close(pipeFd[1]);
    std::string out;
    char buf[512];
    for (ssize_t n; (n = read(pipeFd[0], buf, sizeof buf)) > 0;)
        out.append(buf, static_cast<std::size_t>(n));
    close(pipeFd[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status))
        return "child died: " + out;
    if (WEXITSTATUS(status) != 0 && out.empty())
        return "child exit " + std::to_string(WEXITSTATUS(status));
    return out;
}

// Whether another process holds a lock on any byte of SQLite's shared range
// of `p` (F_GETLK for a write lock: a conflict is reported whatever its type).
bool otherProcessLocks(const fs::path& p) {
    const int fd = ::open(p.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return false;
    struct flock fl {};
    fl.l_type = F_WRLCK;
    fl.l_whence = SEEK_SET;
    fl.l_start = 0x40000000; // PENDING_BYTE: PENDING, RESERVED and the SHARED range follow
    fl.l_len = 512;
    const bool locked = fcntl(fd, F_GETLK, &fl) == 0 && fl.l_type != F_UNLCK;
    ::close(fd);
    return locked;
}

std::vector<std::string> filesIn(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
        names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// "" when `f` throws ReadOnlyError for `path` with `reason`, else what it did.
template <typename F>
std::string refusedReadOnly(F f, const fs::path& path, db::ReadOnlyReason reason) {
    try {
        f();
    } catch (const db::ReadOnlyError& e) {
        const std::string what = e.what();
        if (e.path() != path || e.reason() != reason)
            return "wrong path or reason: " + what;
        if (what.find(path.string()) == std::string::npos || what.find("read-only") == std::string::npos ||
            what.find(std::string(db::readOnlyReasonText(reason))) == std::string::npos)
            return "the message does not say the file and why: " + what;
        if (what.find("PRAGMA") != std::string::npos || what.find("attempt to write") != std::string::npos)
            return "the message names the SQL: " + what;
        return {};
    } catch (const std::exception& e) {
        return std::string("another error: ") + e.what();
    }
    return "nothing was refused";
}

// Everything a reader does with a read-only database: "" or what failed.
std::string readAndRefuse(const fs::path& p, db::ReadOnlyReason reason, db::OpenOptions o = testOptions()) {
    db::Database d = db::Database::open(p, o);
    if (d.readOnly() != reason)
        return "read-only reason " + std::string(db::readOnlyReasonText(d.readOnly())) + ", expected " +
               std::string(db::readOnlyReasonText(reason));
    if (d.machines().size() != 2)
        return "machines not listed";
    if (d.loadMachine("grinder-205").r.at(12) != 777)
        return "the stored value was not read";
    if (d.revisions("grinder-205").size() != 2 || d.history("grinder-205", "R12").size() != 1)
        return "history not read";
    if (!integrityText(d).empty())
        return "integrity";
    if (db::MessageLog(d).count() != 0)
        return "message log not read";
    db::Edit e;
    e.r[12] = 5;
    if (auto r = refusedReadOnly([&] { d.applyEdit("grinder-205", e); }, p, reason); !r.empty())
        return "applyEdit: " + r;
    if (auto r = refusedReadOnly([&] { d.removeMachine("training-lathe"); }, p, reason); !r.empty())
        return "removeMachine: " + r;
    if (auto r = refusedReadOnly([&] { db::MessageLog(d).beginRun("grinder-205", 0); }, p, reason);
        !r.empty())
        return "beginRun: " + r;
    return {};
}

// A database with one change (R12 = 777 at revision 2), closed.
fs::path makeShop(const fs::path& dir) {
    const fs::path p = dir / "shop.db";
    db::Database d = db::Database::open(p, testOptions());
    db::Edit e;
    e.r[12] = 777;
    d.applyEdit("grinder-205", e, by("technologist"));
    return p;
}

} // namespace

class TestConnections : public QObject {
    Q_OBJECT

private slots:
    // The process keeps its locks when it opens the file again: before, the
    // header was read with an ifstream whose close dropped them.
    void openingAgainKeepsTheLocks() {
        QTemporaryDir dir;
        const fs::path p = makeShop(fs::path(dir.path().toStdString()));
        db::Database kept = db::Database::open(p, testOptions());
        QCOMPARE(kept.machines().size(), std::size_t(2)); // reads: holds its SHARED lock (WAL)
        QVERIFY(inChild(false, [&] { return otherProcessLocks(p) ? "" : "no lock before"; }).empty());
        for (int i = 0; i < 3; ++i) {
            db::Database again = db::Database::open(p, testOptions());
            QCOMPARE(again.machines().size(), std::size_t(2));
            db::OpenOptions ro = testOptions();
            ro.readOnly = true;
            db::Database reader = db::Database::open(p, ro);
            QCOMPARE(reader.machines().size(), std::size_t(2));
        }
        const std::string e = inChild(false, [&] {
            return otherProcessLocks(p) ? "" : "the kept connection's lock was dropped";
        });
        QVERIFY2(e.empty(), e.c_str());
        QCOMPARE(kept.loadMachine("grinder-205").r.at(12), std::int64_t(777));
    }

    // OpenOptions::readOnly: SQLite's read-only open.
    void openedReadOnly() {
        QTemporaryDir dir;
        const fs::path folder = fs::path(dir.path().toStdString());
        const fs::path p = makeShop(folder);
        const std::string bytes = fileBytes(p);
        const auto before = filesIn(folder);
        db::OpenOptions o = testOptions();
        o.readOnly = true;
        const std::string e = readAndRefuse(p, db::ReadOnlyReason::Requested, o);
        QVERIFY2(e.empty(), e.c_str());
        QVERIFY(fileBytes(p) == bytes);
        QCOMPARE(filesIn(folder), before); // no -wal, no -shm of the reader's
    }

    // A root-owned 0644 file in a root-owned folder, read by another user.
    void fileTheUserMayNotWrite() {
        QTemporaryDir dir;
        const fs::path folder = fs::path(dir.path().toStdString());
        const fs::path p = makeShop(folder);
        const bool root = geteuid() == 0;
        fs::permissions(folder, fs::perms(root ? 0755 : 0555));
        fs::permissions(p, fs::perms(root ? 0644 : 0444));
        const std::string bytes = fileBytes(p);
        const auto before = filesIn(folder);
        const std::string e = inChild(root, [&] {
            if (::access(p.c_str(), W_OK) == 0)
                return std::string("the test user may write the file: the test would prove nothing");
            return readAndRefuse(p, db::ReadOnlyReason::Permission);
        });
        fs::permissions(folder, fs::perms(0755));
        fs::permissions(p, fs::perms(0644));
        QVERIFY2(e.empty(), e.c_str());
        QVERIFY(fileBytes(p) == bytes);
        QCOMPARE(filesIn(folder), before);
    }

    // The same while a writer has it open: the reader uses the writer's
    // -wal and -shm (read-only) and sees its latest commit.
    void fileTheUserMayNotWriteWhileAWriterHasItOpen() {
        QTemporaryDir dir;
        const fs::path folder = fs::path(dir.path().toStdString());
        const fs::path p = makeShop(folder);
        db::Database writer = db::Database::open(p, testOptions());
        db::Edit e;
        e.r[12] = 778;
        writer.applyEdit("grinder-205", e);
        QVERIFY(fs::exists(p.string() + "-wal"));
        const bool root = geteuid() == 0;
        fs::permissions(folder, fs::perms(root ? 0755 : 0555));
        fs::permissions(p, fs::perms(root ? 0644 : 0444));
        const std::string failed = inChild(root, [&] {
            db::Database d = db::Database::open(p, testOptions());
            if (d.readOnly() != db::ReadOnlyReason::Permission)
                return std::string("not read-only");
            if (d.loadMachine("grinder-205").r.at(12) != 778)
                return std::string("the writer's last commit was not seen");
            db::Edit again;
            again.r[12] = 1;
            return refusedReadOnly([&] { d.applyEdit("grinder-205", again); }, p, db::ReadOnlyReason::Permission);
        });
        fs::permissions(folder, fs::perms(0755));
        fs::permissions(p, fs::perms(0644));
        QVERIFY2(failed.empty(), failed.c_str());
        QCOMPARE(writer.loadMachine("grinder-205").r.at(12), std::int64_t(778));
        QCOMPARE(integrityText(writer), std::string());
    }

    // A file the user may write in a folder where SQLite cannot create the
    // -wal and -shm: read as a snapshot, writes refused naming the folder.
    void folderTheUserMayNotWrite() {
        QTemporaryDir dir;
        const fs::path folder = fs::path(dir.path().toStdString()) / "shop";
        fs::create_directory(folder);
        const fs::path p = makeShop(folder);
        const bool root = geteuid() == 0;
        if (root)
            QCOMPARE(::chown(p.c_str(), kNobody, kNobody), 0);
        fs::permissions(folder.parent_path(), fs::perms(0755));
        fs::permissions(folder, fs::perms(root ? 0755 : 0555));
        const std::string bytes = fileBytes(p);
        const std::string e = inChild(root, [&] { return readAndRefuse(p, db::ReadOnlyReason::Folder); });
        fs::permissions(folder, fs::perms(0755));
        QVERIFY2(e.empty(), e.c_str());
        QVERIFY(fileBytes(p) == bytes);
    }

    // The snapshot knows when a writer has changed the file since.
    void snapshotSeesAWriter() {
        QTemporaryDir dir;
        const fs::path p = makeShop(fs::path(dir.path().toStdString()));
        db::OpenOptions o = testOptions();
        o.readOnly = true;
        db::Database reader = db::Database::open(p, o);
        QVERIFY(!reader.snapshotOutdated());
        {
            db::Database writer = db::Database::open(p, testOptions());
            db::Edit e;
            e.r[12] = 779;
            writer.applyEdit("grinder-205", e);
            QVERIFY(reader.snapshotOutdated()); // a -wal appeared
        }
        QVERIFY(reader.snapshotOutdated()); // checkpointed into the file
        QCOMPARE(db::Database::open(p, o).loadMachine("grinder-205").r.at(12), std::int64_t(779));
    }

    // Nothing to read, or nothing that may be created: said, not attempted.
    void emptyOrMissingReadOnly() {
        QTemporaryDir dir;
        const fs::path p = tempPath(dir, "empty.db");
        writeBytes(p, "");
        db::OpenOptions o = testOptions();
        o.readOnly = true;
        try {
            db::Database::open(p, o);
            QFAIL("opened");
        } catch (const db::ReadOnlyError& e) {
            QCOMPARE(int(e.refusal()), int(db::ReadOnlyRefusal::Create));
            QVERIFY(std::string(e.what()).find(p.string()) != std::string::npos);
        }
        QCOMPARE(fs::file_size(p), std::uintmax_t(0));
        QVERIFY_THROWS_EXCEPTION(db::Error, db::Database::open(tempPath(dir, "missing.db"), o));
        QVERIFY(!fs::exists(tempPath(dir, "missing.db")));
    }
};

QTEST_GUILESS_MAIN(TestConnections)
#include "test_connections.moc"
