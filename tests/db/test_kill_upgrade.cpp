// `k528` killed (SIGKILL) at any moment while it upgrades a database of
// schema version 6 to the latest (version 7: every recorded change takes its
// revision's author and time — new columns of `changes` and an UPDATE of all
// its rows; version 8: on PostgreSQL the history's index rebuilt with the
// columns the history reads; version 9: each item's whole history built into
// its row of item_history; all in the one transaction of the upgrade, then
// on PostgreSQL a VACUUM of `changes` after it) never leaves a database that
// later commands refuse, nor a half-upgraded one: after each kill the
// database opens read-only at version 6 untouched or at the latest version
// complete, its integrity check is clean, every machine keeps every revision
// and the same history; `k528 db machines` then lists what it listed before
// the kill, and the next open upgrades it with the same history.
//
// Kills at random moments of a whole run of `k528 db machines` on the old
// database (start, checks, upgrade, listing) and at the moment of the
// upgrade's first write: on SQLite when its first pages reach the
// write-ahead log, on PostgreSQL (the same test as
// db.kill_upgrade.postgresql) when another session sees its transaction
// holding a transaction id. The server rolls back the killed session's
// transaction; the next command waits for its locks.
//
// K528_KILL_ITERATIONS (default 45 on SQLite, 16 on PostgreSQL) is the number
// of runs killed; the long campaign by hand:
// K528_KILL_ITERATIONS=1000 ctest -R db.kill_upgrade --timeout 3000.
#include "cli_runner.h"
#include "db/database.h"
#include "db_test_util.h"
#include "random_machine.h"

#include "rig/kill_campaign.h"

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QtTest>
#include <map>
#include <sys/stat.h>
#include <sys/wait.h>

using namespace k528;
using namespace k528::testing;
namespace fs = std::filesystem;

namespace {

pid_t startK528(const std::vector<std::string>& args) {
    return testrig::startSilenced(K528_CLI, args);
}

// The version a killed upgrade leaves or completes.
constexpr int kOldVersion = 6;

std::int64_t sizeOf(const std::string& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 ? static_cast<std::int64_t>(st.st_size) : -1;
}

// What a database holds that an upgrade must keep: each machine's
// revisions and its whole history.
struct Kept {
    std::map<std::string, std::vector<db::RevisionInfo>> revisions;
    std::map<std::string, std::vector<db::HistoryEntry>> history;
};

Kept keptOf(const db::Database& d) {
    Kept k;
    for (const db::MachineInfo& m : d.machines()) {
        k.revisions[m.name] = d.revisions(m.name);
        k.history[m.name] = d.history(m.name);
    }
    return k;
}

// "" when `now` keeps everything of `before`, else the first difference.
std::string difference(const Kept& before, const Kept& now) {
    if (now.revisions.size() != before.revisions.size())
        return std::to_string(now.revisions.size()) + " machines instead of " +
               std::to_string(before.revisions.size());
    for (const auto& [name, revs] : before.revisions) {
        const auto it = now.revisions.find(name);
        if (it == now.revisions.end())
            return "machine " + name + " is gone";
        if (it->second.size() != revs.size())
            return "machine " + name + " has " + std::to_string(it->second.size()) +
                   " revisions instead of " + std::to_string(revs.size());
        for (std::size_t i = 0; i < revs.size(); ++i) {
            const db::RevisionInfo& a = revs[i];
            const db::RevisionInfo& b = it->second[i];
            if (a.revision != b.revision || a.author != b.author || a.at != b.at ||
                a.summary != b.summary || a.changeCount != b.changeCount)
                return "machine " + name + " revision " + std::to_string(a.revision) + " differs";
        }
        const auto& ha = before.history.at(name);
        const auto& hb = now.history.at(name);
        if (ha.size() != hb.size())
            return "machine " + name + ": " + std::to_string(hb.size()) +
                   " history entries instead of " + std::to_string(ha.size());
        for (std::size_t i = 0; i < ha.size(); ++i)
            if (ha[i].revision != hb[i].revision || ha[i].author != hb[i].author ||
                ha[i].at != hb[i].at || !(ha[i].change == hb[i].change))
                return "machine " + name + ": history entry " + std::to_string(i) + " (" +
                       ha[i].change.key + " of revision " + std::to_string(ha[i].revision) +
                       ") differs";
    }
    return {};
}

// Runs a program to its end: "" or what it said on failure.
std::string run(const QString& program, const QStringList& args) {
    QProcess p;
    p.start(program, args);
    if (!p.waitForFinished(120000) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0)
        return (program + " " + args.join(' ') + ": ").toStdString() +
               p.readAllStandardError().toStdString();
    return {};
}

// The database's name in a `postgresql:///NAME` location.
std::string pgName(const db::Location& where) {
    const std::string t = where.text();
    return t.substr(t.rfind('/') + 1);
}

} // namespace

class TestKillUpgrade : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;
    db::Location template_ = db::Location(fs::path("unset"));
    Kept kept_;
    int copies_ = 0;

    // A fresh copy of the old database (a file copy; on PostgreSQL a
    // new database made from it as a template).
    db::Location copyOfTemplate() {
        const int n = copies_++;
        if (onPostgres()) {
            const std::string name = pgName(template_) + "_" + std::to_string(n);
            const std::string failed = run("createdb", {"-T", QString::fromStdString(pgName(template_)),
                                                        QString::fromStdString(name)});
            if (!failed.empty())
                qFatal("%s", failed.c_str());
            return db::Location::parse("postgresql:///" + name);
        }
        const fs::path to = tempPath(dir_, "k") += std::to_string(n) + ".db";
        fs::copy_file(template_.file(), to, fs::copy_options::overwrite_existing);
        return db::Location(to);
    }

    void dropCopy(const db::Location& where) {
        if (onPostgres()) {
            run("dropdb", {"--if-exists", QString::fromStdString(pgName(where))});
            return;
        }
        std::error_code ec;
        for (const char* suffix : {"", "-wal", "-shm", "-journal"})
            fs::remove(where.file().string() + suffix, ec);
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        qputenv("K528_DB", QDir::temp().filePath("k528-kill-must-not-be-used.db").toUtf8());
        // A shop at schema version 6 (kOldVersion): the built-in machines with revisions of
        // several authors and twelve full machines (~9000 recorded changes:
        // the upgrade's UPDATE has work to do).
        template_ = testLocation(dir_, "v6.db");
        auto o = testOptions();
        o.migrations = db::schemaMigrations().subspan(0, kOldVersion);
        db::Database d = db::Database::open(template_, o);
        QCOMPARE(d.schemaVersion(), kOldVersion);
        for (int i = 0; i < 12; ++i)
            d.createMachine(randomMachine(static_cast<std::uint32_t>(700 + i),
                                          "m" + std::to_string(i)),
                            by(i % 2 ? "Петров" : "Иванов И.И."));
        for (int i = 0; i < 25; ++i) {
            db::Edit e;
            e.c[22] = 1000 + i;
            e.r[i] = i;
            d.applyEdit(i % 2 ? "grinder-205" : "m3", e, by(i % 3 ? "Петров" : "Сидоров"));
        }
        kept_ = keptOf(d);
        QVERIFY(kept_.revisions.size() >= 14);
        QCOMPARE(kept_.history.at("grinder-205").front().author, std::string("Петров"));
    }

    void killedAnywhereLeavesTheOldVersionOrTheLatest() {
        const int latest = db::latestSchemaVersion();
        // How long a whole run takes here (open, upgrade, list): the random
        // kills fall within it. What it lists is what every later run must.
        qint64 runNs = 0;
        QString listing;
        for (int i = 0; i < 3; ++i) {
            const db::Location where = copyOfTemplate();
            QElapsedTimer t;
            t.start();
            const pid_t pid = startK528({"db", "machines", "--db", where.text()});
            QVERIFY(pid > 0);
            int status = 0;
            QCOMPARE(waitpid(pid, &status, 0), pid);
            QVERIFY(WIFEXITED(status) && WEXITSTATUS(status) == 0);
            runNs = std::max(runNs, t.nsecsElapsed());
            const auto r = runK528({"db", "machines", "--db", QString::fromStdString(where.text())});
            QCOMPARE(r.exitCode, 0);
            QVERIFY(listing.isEmpty() || listing == r.out);
            listing = r.out;
            const db::Database d = db::Database::open(where, testOptions());
            QCOMPARE(d.schemaVersion(), latest);
            QCOMPARE(difference(kept_, keptOf(d)), std::string());
            dropCopy(where);
        }
        QVERIFY(listing.contains("grinder-205"));

        testrig::KillCampaign campaign(runNs);
        const int n = static_cast<int>(envNumber("K528_KILL_ITERATIONS", onPostgres() ? 16 : 45));
        int old = 0, upgraded = 0;
        for (int i = 0; i < n; ++i) {
            const db::Location where = copyOfTemplate();
            const QString loc = QString::fromStdString(where.text());
            const pid_t pid = startK528({"db", "machines", "--db", where.text()});
            QVERIFY(pid > 0);
            testrig::KillOutcome outcome;
            if (onPostgres() && i % 3 == 2) {
                // The moment the upgrade's transaction has written (the
                // server gave it a transaction id), seen from another session.
                // (Or, when this session came too late, once it is upgraded.)
                std::string failed;
                outcome = campaign.atSign(pid, [&] {
                    failed = run(
                        "psql", {"-XAtq", "-v", "ON_ERROR_STOP=1", "-d",
                                 QString::fromStdString(pgName(where)), "-c",
                                 "SET statement_timeout = '30s'; DO $$ BEGIN LOOP PERFORM "
                                 "pg_stat_clear_snapshot(); EXIT WHEN EXISTS (SELECT 1 FROM "
                                 "pg_stat_activity WHERE datname = current_database() AND pid <> "
                                 "pg_backend_pid() AND backend_xid IS NOT NULL) OR (SELECT version "
                                 "FROM k528_schema) >= " + QString::number(latest) +
                                 "; PERFORM pg_sleep(0.001); END LOOP; END $$"});
                    return true;
                });
                QVERIFY2(failed.empty() || !outcome.killed(), failed.c_str());
            } else if (!onPostgres() && i % 3 == 2) {
                // The moment the upgrade's first pages reach the write-ahead log.
                const std::string wal = where.file().string() + "-wal";
                outcome = campaign.atSign(pid, [&] { return sizeOf(wal) > 0; });
            } else {
                outcome = campaign.atRandom(pid);
            }
            const QString which = QString("kill %1 (%2)").arg(i).arg(
                outcome.killed() ? "killed" : "ended first");
            {
                // As the kill left it: the old version untouched or the latest complete.
                auto o = testOptions();
                o.readOnly = true;
                const db::Database d = db::Database::open(where, o);
                const int version = d.schemaVersion();
                QVERIFY2(version == kOldVersion || version == latest,
                         qPrintable(which + ": schema version " + QString::number(version)));
                (version == kOldVersion ? old : upgraded) += 1;
                const std::string problems = integrityText(d);
                QVERIFY2(problems.empty(), qPrintable(which + ": " + QString::fromStdString(problems)));
                const std::string lost = difference(kept_, keptOf(d));
                QVERIFY2(lost.empty(), qPrintable(which + QString(" at version %1: ").arg(version) +
                                                  QString::fromStdString(lost)));
            }
            // The next command opens it (upgrading what was left at the old version).
            const auto machines = runK528({"db", "machines", "--db", loc});
            QVERIFY2(machines.exitCode == 0, qPrintable(which + ": k528 db machines: " + machines.err));
            QCOMPARE(machines.out, listing);
            {
                const db::Database d = db::Database::open(where, testOptions());
                QCOMPARE(d.schemaVersion(), latest);
                QCOMPARE(integrityText(d), std::string());
                QCOMPARE(difference(kept_, keptOf(d)), std::string());
            }
            dropCopy(where);
        }
        qInfo("%d kills (%d runs at the upgrade's first write), %d runs ended first; found "
              "%d at version %d untouched, %d at version %d complete; every database usable "
              "afterwards (a run %.1f ms)",
              campaign.killed(), campaign.atSignRuns(), campaign.completed(), old, kOldVersion,
              upgraded, latest, runNs / 1e6);
        QVERIFY(campaign.killed() > n / 2);
    }
};

QTEST_GUILESS_MAIN(TestKillUpgrade)
#include "test_kill_upgrade.moc"
