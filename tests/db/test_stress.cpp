// The shop's database shared by processes, as on a shop PC: studio-like
// processes (db_stress_peer: the desktop's one kept connection, revisions
// from the constants dock, message history batches, now and then a short
// connection of its own) write while `k528 db …` processes read and write in
// a loop — first one studio, then two. Afterwards no revision and no message
// is lost (counted), the values are the last ones written, PRAGMA
// integrity_check is ok, and no descriptor of a studio ever pointed at a
// deleted database, -wal or -shm (/proc/PID/fd, sampled all along).
//
// K528_STRESS_SECONDS (default 12) is the length of each phase; the long run
// by hand: K528_STRESS_SECONDS=300 ctest -R db.stress --timeout 1000.
#include "cli_runner.h"
#include "db/database.h"
#include "db/message_log.h"
#include "db_test_util.h"

#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>
#include <dirent.h>
#include <memory>
#include <unistd.h>

using namespace k528;
using namespace k528::testing;
namespace fs = std::filesystem;

namespace {

// Links in /proc/PID/fd that point at a removed file of the database.
QStringList deletedDescriptors(qint64 pid, const QString& dbPath) {
    QStringList found;
    const std::string dir = "/proc/" + std::to_string(pid) + "/fd";
    DIR* d = opendir(dir.c_str());
    if (!d)
        return found;
    while (const dirent* e = readdir(d)) {
        if (e->d_name[0] == '.')
            continue;
        char target[4096];
        const std::string link = dir + "/" + e->d_name;
        const ssize_t n = readlink(link.c_str(), target, sizeof target - 1);
        if (n <= 0)
            continue;
        const QString t = QString::fromUtf8(target, static_cast<int>(n));
        if (t.startsWith(dbPath) && t.contains("(deleted)"))
            found << QString::fromStdString(link) + " -> " + t;
    }
    closedir(d);
    return found;
}

struct PeerResult {
    int revisions = -1, last = -1, busy = 0, deleted = 0, failures = 0, conflicts = 0;
    long messages = -1;
};

PeerResult parsePeer(const QString& out) {
    PeerResult r;
    const QRegularExpression re("revisions (\\d+) last (\\d+) messages (\\d+) extra-opens \\d+ "
                                "busy (\\d+) deleted (\\d+) failures (\\d+) conflicts (\\d+)");
    const auto m = re.match(out);
    if (m.hasMatch()) {
        r.revisions = m.captured(1).toInt();
        r.last = m.captured(2).toInt();
        r.messages = m.captured(3).toLong();
        r.busy = m.captured(4).toInt();
        r.deleted = m.captured(5).toInt();
        r.failures = m.captured(6).toInt();
        r.conflicts = m.captured(7).toInt();
    }
    return r;
}

} // namespace

class TestStress : public QObject {
    Q_OBJECT

    // `studios` studio-like processes and the command line, for K528_STRESS_SECONDS.
    void run(int studios) {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString db = dir.filePath("shop.db");
        const auto init = runK528({"db", "init", "--db", db});
        QVERIFY2(init.exitCode == 0, qPrintable(init.err));
        int startRevision = 0;
        {
            db::Database d = db::Database::open(db.toStdString(), testOptions());
            startRevision = d.machine("grinder-205")->revision;
        }
        const double seconds = envNumber("K528_STRESS_SECONDS", 12);
        std::vector<std::unique_ptr<QProcess>> peers;
        for (int i = 0; i < studios; ++i) {
            auto p = std::make_unique<QProcess>();
            p->setProgram(QStringLiteral(K528_STRESS_PEER));
            p->setArguments({"--db", db, "--machine", "grinder-205", "--r", QString::number(150 + i),
                             "--seconds", QString::number(seconds)});
            p->start();
            QVERIFY(p->waitForStarted());
            peers.push_back(std::move(p));
        }
        // The command line beside them: reads and writes, one process each.
        int cliSets = 0, cliBusy = 0, cliReads = 0, samples = 0;
        QStringList deleted, cliFailures;
        const auto running = [&] {
            for (const auto& p : peers)
                if (p->state() != QProcess::NotRunning)
                    return true;
            return false;
        };
        for (int i = 1; running(); ++i) {
            for (const auto& p : peers)
                if (p->state() == QProcess::Running) {
                    deleted << deletedDescriptors(p->processId(), db);
                    ++samples;
                }
            QStringList args;
            switch (i % 4) {
            case 0:
                args = {"db", "set", "grinder-205", QString("R200=%1").arg(cliSets + 1), "--author", "cli"};
                break;
            case 1:
                args = {"db", "machines"};
                break;
            case 2:
                args = {"db", "show", "grinder-205", "--r", "150"};
                break;
            case 3:
                args = {"db", "export", "grinder-205"};
                break;
            }
            const auto r = runK528(args + QStringList{"--db", db});
            if (r.exitCode == 0) {
                if (i % 4 == 0)
                    ++cliSets;
                else
                    ++cliReads;
            } else if (r.err.contains("busy")) {
                ++cliBusy;
            } else {
                cliFailures << args.join(' ') + ": " + r.err;
            }
            for (const auto& p : peers)
                p->waitForFinished(0);
        }
        std::vector<PeerResult> results;
        for (const auto& p : peers) {
            QVERIFY(p->state() == QProcess::NotRunning || p->waitForFinished(120000));
            const QString out = QString::fromUtf8(p->readAllStandardOutput());
            const QString err = QString::fromUtf8(p->readAllStandardError());
            QVERIFY2(p->exitStatus() == QProcess::NormalExit && p->exitCode() == 0,
                     qPrintable(QString("peer exit %1: %2 %3").arg(p->exitCode()).arg(out, err)));
            results.push_back(parsePeer(out));
            QVERIFY2(results.back().revisions > 0, qPrintable(out));
        }
        QVERIFY2(deleted.isEmpty(), qPrintable(deleted.join('\n')));
        QVERIFY2(cliFailures.isEmpty(), qPrintable(cliFailures.join('\n')));
        QVERIFY(cliSets > 0);

        // Nothing lost: every revision counted, the last values, every message.
        db::Database d = db::Database::open(db.toStdString(), testOptions());
        QCOMPARE(integrityText(d), std::string());
        int peerRevisions = 0;
        long peerMessages = 0;
        const profile::MachineProfile now = d.loadMachine("grinder-205");
        for (int i = 0; i < studios; ++i) {
            peerRevisions += results[static_cast<std::size_t>(i)].revisions;
            peerMessages += results[static_cast<std::size_t>(i)].messages;
            QCOMPARE(now.r.at(150 + i), std::int64_t(results[static_cast<std::size_t>(i)].last));
        }
        QCOMPARE(now.r.at(200), std::int64_t(cliSets));
        const int revision = d.machine("grinder-205")->revision;
        QCOMPARE(revision, startRevision + peerRevisions + cliSets);
        QCOMPARE(static_cast<int>(d.revisions("grinder-205").size()), revision);
        db::MessageLog log(d);
        db::MessageFilter ofGrinder;
        ofGrinder.machine = "grinder-205";
        QCOMPARE(log.count(ofGrinder), std::int64_t(peerMessages));
        qInfo("%d studio(s), %.0f s: %d studio revisions, %ld messages, %d k528 db set, %d k528 "
              "reads, busy %d (studios) %d (k528), %d refused as based on an older revision and applied "
              "again on top, %d /proc samples, 0 deleted descriptors",
              studios, seconds, peerRevisions, peerMessages, cliSets, cliReads,
              results[0].busy + (studios > 1 ? results[1].busy : 0), cliBusy,
              results[0].conflicts + (studios > 1 ? results[1].conflicts : 0), samples);
    }

private slots:
    void initTestCase() {
        qputenv("K528_DB", QDir::temp().filePath("k528-stress-must-not-be-used.db").toUtf8());
    }
    void oneStudioBesideTheCommandLine() { run(1); }
    void twoStudiosBesideTheCommandLine() { run(2); }
};

QTEST_GUILESS_MAIN(TestStress)
#include "test_stress.moc"
