// Reliability across processes: a writer killed (SIGKILL) in the middle of a
// large transaction leaves the database intact and as before; killed after
// the commit, as after; two processes writing one file wait for each other.
#include "db/database.h"
#include "db_test_util.h"
#include "profile/text_format.h"
#include "random_machine.h"

#include <QtTest>
#include <csignal>
#include <poll.h>
#include <random>
#include <sys/wait.h>
#include <unistd.h>

using namespace k528;
using namespace k528::testing;
namespace fs = std::filesystem;
using profile::MachineProfile;

namespace {

// Runs `body` in a child process; its return value is the exit status. The
// child never returns into the test framework.
template <typename F> pid_t spawn(F body) {
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t pid = fork();
    if (pid == 0) {
        int code = 100;
        try {
            code = body();
        } catch (const std::exception& e) {
            std::fprintf(stderr, "child %d: %s\n", static_cast<int>(getpid()), e.what());
            code = 101;
        } catch (...) {
            code = 102;
        }
        std::fflush(stderr);
        _exit(code);
    }
    return pid;
}

// Waits for one byte on `fd` (up to `ms`); false on timeout or end of file.
bool waitByte(int fd, int ms) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, ms) != 1)
        return false;
    char c;
    return read(fd, &c, 1) == 1;
}

void sendByte(int fd) {
    const char c = 'x';
    if (write(fd, &c, 1) != 1)
        _exit(104);
}

// Blocks the calling (child) process until it is killed.
[[noreturn]] void hang() {
    for (;;)
        pause();
}

int exitStatus(pid_t pid) {
    int status = 0;
    if (waitpid(pid, &status, 0) != pid)
        return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status)
                             : 1000 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

db::OpenOptions opts(int busyMs = 20000) {
    auto o = testOptions(db::systemClock());
    o.busyTimeoutMs = busyMs;
    return o;
}

// Opens after a crash: open() runs integrity_check and refuses a damaged file.
std::string reopenCheck(const db::Location& p) {
    db::Database d = db::Database::open(p, opts());
    return integrityText(d);
}

} // namespace

class TestProcesses : public QObject {
    Q_OBJECT
private slots:
    void killedInTheMiddleOfATransaction() {
        QTemporaryDir dir;
        const db::Location path = testLocation(dir, "kill.db");
        const MachineProfile before = randomMachine(11, "big");
        {
            db::Database d = db::Database::open(path, opts());
            d.createMachine(before, by("setup"));
        }
        const std::size_t auditBefore = db::Database::open(path, opts()).audit().size();
        int toParent[2];
        QVERIFY(pipe(toParent) == 0);
        const pid_t child = spawn([&] {
            close(toParent[0]);
            db::Database d = db::Database::open(path, opts());
            db::WriteOptions o = by("killed writer");
            o.progress = [&](std::size_t done, std::size_t total) {
                if (done == total / 2) {
                    sendByte(toParent[1]); // half the rows are written, nothing committed
                    hang();
                }
            };
            d.saveMachine("big", randomMachine(12, "big"), o);
            return 3; // never: killed above
        });
        close(toParent[1]);
        QVERIFY2(waitByte(toParent[0], 60000), "the writer did not reach the middle of its write");
        // The writer holds the write lock: another writer with a short busy
        // timeout gives up with a clear message (nothing half-done).
        {
            db::Database other = db::Database::open(path, opts(200));
            try {
                db::Edit e;
                e.c[22] = 2100;
                other.applyEdit("big", e, by("impatient"));
                QFAIL("a second writer got in during the first one's transaction");
            } catch (const db::Error& e) {
                QCOMPARE(e.kind(), db::ErrorKind::Busy);
                QVERIFY2(std::string(e.what()).find("busy timeout") != std::string::npos, e.what());
            }
            // Readers still see the committed state.
            QVERIFY(other.loadMachine("big") == before);
        }
        QVERIFY(kill(child, SIGKILL) == 0);
        QCOMPARE(exitStatus(child), 1000 + SIGKILL);
        close(toParent[0]);

        QCOMPARE(reopenCheck(path), std::string());
        db::Database d = db::Database::open(path, opts());
        QCOMPARE(d.machine("big")->revision, 1);
        QVERIFY(d.loadMachine("big") == before);
        QCOMPARE(d.audit().size(), auditBefore);
        // And the next writer proceeds normally.
        db::Edit e;
        e.c[22] = 2100;
        QCOMPARE(d.applyEdit("big", e, by("next")).revision, 2);
    }

    void killedAfterTheCommit() {
        QTemporaryDir dir;
        const db::Location path = testLocation(dir, "after.db");
        {
            db::Database d = db::Database::open(path, opts());
            d.createMachine(randomMachine(21, "big"), by("setup"));
        }
        const MachineProfile after = randomMachine(22, "big");
        int toParent[2];
        QVERIFY(pipe(toParent) == 0);
        const pid_t child = spawn([&] {
            close(toParent[0]);
            db::Database d = db::Database::open(path, opts());
            d.saveMachine("big", after, by("writer"));
            sendByte(toParent[1]);
            hang();
            return 0;
        });
        close(toParent[1]);
        QVERIFY(waitByte(toParent[0], 60000));
        kill(child, SIGKILL);
        QCOMPARE(exitStatus(child), 1000 + SIGKILL);
        close(toParent[0]);
        QCOMPARE(reopenCheck(path), std::string());
        db::Database d = db::Database::open(path, opts());
        QCOMPARE(d.machine("big")->revision, 2);
        QVERIFY(d.loadMachine("big") == after);
    }

    // Killed at random moments of a stream of writes: the state is always one
    // of the committed ones, and the current tables agree with the history.
    void killedAtRandomMoments() {
        QTemporaryDir dir;
        const db::Location path = testLocation(dir, "random.db");
        const MachineProfile a = randomMachine(31, "m");
        const MachineProfile b = randomMachine(32, "m");
        {
            db::Database d = db::Database::open(path, opts());
            d.createMachine(a, by("setup"));
        }
        std::mt19937 rng(7);
        int lastRevision = 1;
        for (int round = 0; round < 8; ++round) {
            int started[2];
            QVERIFY(pipe(started) == 0);
            const pid_t child = spawn([&] {
                close(started[0]);
                db::Database d = db::Database::open(path, opts());
                for (;;) {
                    d.saveMachine("m", (d.loadMachine("m") == a) ? b : a, by("writer"));
                    sendByte(started[1]); // one byte a commit
                }
                return 0;
            });
            close(started[1]);
            // The kill comes after at least one commit of this round, at a
            // random moment of the ones after it (a slow build commits less,
            // but never nothing).
            QVERIFY(waitByte(started[0], 60000));
            usleep(static_cast<useconds_t>(20000 + rng() % 150000));
            kill(child, SIGKILL);
            QCOMPARE(exitStatus(child), 1000 + SIGKILL);
            close(started[0]);
            QCOMPARE(reopenCheck(path), std::string());
            db::Database d = db::Database::open(path, opts());
            const int rev = d.machine("m")->revision;
            QVERIFY(rev > lastRevision);
            lastRevision = rev;
            const MachineProfile now = d.loadMachine("m");
            QVERIFY(now == a || now == b);
            QVERIFY(now == (rev % 2 == 1 ? a : b));
            QVERIFY(d.loadMachine("m", rev) == now);
        }
        QVERIFY2(lastRevision > 3, "the writer committed too little to test anything");
    }

    // Two processes set constants of one machine at the same time, 100 times
    // each: both finish, each change is its own revision, none is lost.
    void concurrentWriters() {
        QTemporaryDir dir;
        const db::Location path = testLocation(dir, "two.db");
        { db::Database::open(path, opts()); }
        constexpr int kEach = 100;
        int go[2];
        QVERIFY(pipe(go) == 0);
        std::vector<pid_t> children;
        for (int w = 0; w < 2; ++w)
            children.push_back(spawn([&, w] {
                close(go[1]);
                db::Database d = db::Database::open(path, opts(30000));
                if (!waitByte(go[0], 60000))
                    return 5;
                for (int i = 0; i < kEach; ++i) {
                    db::Edit e;
                    e.c[22 + w] = 1000 + i + 1;
                    e.r[w * 100 + i] = i + 1;
                    d.applyEdit("grinder-205", e, by("writer" + std::to_string(w)));
                }
                return 0;
            }));
        close(go[0]);
        sendByte(go[1]);
        sendByte(go[1]);
        close(go[1]);
        for (pid_t c : children)
            QCOMPARE(exitStatus(c), 0);
        db::Database d = db::Database::open(path, opts());
        QCOMPARE(d.machine("grinder-205")->revision, 1 + 2 * kEach);
        QCOMPARE(static_cast<int>(d.revisions("grinder-205").size()), 1 + 2 * kEach);
        const MachineProfile p = d.loadMachine("grinder-205");
        for (int w = 0; w < 2; ++w) {
            QCOMPARE(p.cValue(22 + w), std::int64_t(1000 + kEach));
            for (int i = 0; i < kEach; ++i)
                QCOMPARE(p.r.at(w * 100 + i), std::int64_t(i + 1));
        }
        int byWriter0 = 0;
        for (const auto& r : d.revisions("grinder-205"))
            byWriter0 += r.author == "writer0";
        QCOMPARE(byWriter0, kEach);
        QCOMPARE(static_cast<int>(d.history("grinder-205", "C022").size()), kEach + 1);
        QCOMPARE(integrityText(d), std::string());
    }

    // Two processes start on a database that does not exist yet: it is
    // created once, with the built-in machines once.
    void concurrentFirstStart() {
        for (int round = 0; round < 6; ++round) {
            QTemporaryDir dir;
            const db::Location path = testLocation(dir, "first.db");
            constexpr int kProcesses = 4;
            int go[2];
            QVERIFY(pipe(go) == 0);
            std::vector<pid_t> children;
            for (int w = 0; w < kProcesses; ++w)
                children.push_back(spawn([&] {
                    close(go[1]);
                    if (!waitByte(go[0], 60000))
                        return 5;
                    db::Database d = db::Database::open(path, opts(30000));
                    return d.machines().size() == 2 ? 0 : 6;
                }));
            close(go[0]);
            for (int w = 0; w < kProcesses; ++w)
                sendByte(go[1]);
            close(go[1]);
            for (pid_t c : children)
                QCOMPARE(exitStatus(c), 0);
            db::Database d = db::Database::open(path, opts());
            QCOMPARE(d.machines().size(), std::size_t(2));
            int created = 0, seeded = 0;
            for (const auto& a : d.audit()) {
                created += a.action == "create-database";
                seeded += a.action == "seed";
            }
            QCOMPARE(created, 1);
            QCOMPARE(seeded, 2);
        }
    }
};

QTEST_APPLESS_MAIN(TestProcesses)
#include "test_processes.moc"
