// Opening, creating and migrating the database; refusing files that are not
// ours, damaged or newer — and leaving them byte for byte as they were.
#include "catalog/cparams.h"
#include "db/database.h"
#include "db/state_times.h"
#include "db_test_util.h"
#include "profile/builtin.h"

#include <QtTest>
#include <csignal>
#include <filesystem>
#include <functional>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace k528;
using namespace k528::testing;
namespace fs = std::filesystem;

namespace {

// A plain SQLite connection for looking under the hood.
struct Raw {
    sqlite3* db = nullptr;
    explicit Raw(const fs::path& p) {
        if (sqlite3_open(p.c_str(), &db) != SQLITE_OK)
            qFatal("cannot open %s", p.c_str());
    }
    ~Raw() { sqlite3_close(db); }
    // Runs SQL; returns "" or SQLite's error message.
    std::string exec(const std::string& sql) {
        char* err = nullptr;
        if (sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &err) == SQLITE_OK)
            return {};
        std::string e = err ? err : "error";
        sqlite3_free(err);
        return e;
    }
    std::string text(const std::string& sql) {
        sqlite3_stmt* st = nullptr;
        if (sqlite3_prepare_v2(db, sql.c_str(), -1, &st, nullptr) != SQLITE_OK)
            return "<prepare failed: " + std::string(sqlite3_errmsg(db)) + ">";
        std::string r;
        if (sqlite3_step(st) == SQLITE_ROW && sqlite3_column_text(st, 0))
            r = reinterpret_cast<const char*>(sqlite3_column_text(st, 0));
        sqlite3_finalize(st);
        return r;
    }
    long long integer(const std::string& sql) { return std::stoll(text(sql)); }
};

// The error of opening `p`, checking its kind; "" if it opened.
std::string openError(const fs::path& p, db::ErrorKind expected,
                      const db::OpenOptions& o = testOptions()) {
    try {
        db::Database::open(p, o);
    } catch (const db::Error& e) {
        if (e.kind() != expected)
            return std::string("wrong kind ") + std::string(db::errorKindName(e.kind())) + ": " +
                   e.what();
        return e.what();
    }
    return {};
}

fs::path makeDb(const QTemporaryDir& dir, const char* name = "k528.db") {
    const fs::path p = tempPath(dir, name);
    db::Database::open(p, testOptions());
    return p;
}

// Leaves `p` as another program would after being killed in the middle of a
// write: a child process begins a transaction large enough to spill into the
// file (rollback journal), and is killed (SIGKILL) before it commits. The
// -journal is then hot: the next read-write SQLite connection rolls it back.
void leaveHotJournal(const fs::path& p) {
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t pid = fork();
    if (pid == 0) {
        sqlite3* db = nullptr;
        if (sqlite3_open(p.c_str(), &db) != SQLITE_OK)
            _exit(3);
        if (sqlite3_exec(db,
                         "PRAGMA cache_size = 2; BEGIN; CREATE TABLE junk (x BLOB);"
                         "WITH RECURSIVE c(i) AS (SELECT 1 UNION ALL SELECT i + 1 FROM c "
                         "WHERE i < 3000) INSERT INTO junk SELECT randomblob(300) FROM c;",
                         nullptr, nullptr, nullptr) != SQLITE_OK)
            _exit(4);
        kill(getpid(), SIGKILL);
        _exit(5);
    }
    int status = 0;
    QCOMPARE(waitpid(pid, &status, 0), pid);
    QVERIFY2(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL, "the writer was not killed");
    const fs::path journal = p.string() + "-journal";
    QVERIFY(fs::exists(journal) && fs::file_size(journal) > 0);
}

// The refusal of `p` (kind `kind`, message with `text`) leaves the file and
// its -journal byte for byte as they were; afterwards a plain SQLite
// connection rolls the journal back (it was hot, the refusal was not moot).
void refusedWithHotJournal(const fs::path& p, db::ErrorKind kind, const std::string& text) {
    const fs::path journal = p.string() + "-journal";
    const std::string bytes = fileBytes(p), journalBytes = fileBytes(journal);
    const std::string e = openError(p, kind);
    QVERIFY2(e.find(text) != std::string::npos, e.c_str());
    QVERIFY2(e.find(p.string()) != std::string::npos, e.c_str());
    QVERIFY2(e.find("left untouched") != std::string::npos, e.c_str());
    QVERIFY(fileBytes(p) == bytes);
    QVERIFY(fileBytes(journal) == journalBytes);
    {
        Raw raw(p);
        QCOMPARE(raw.integer("SELECT count(*) FROM sqlite_schema WHERE name = 'junk'"), 0LL);
    }
    QVERIFY(!fs::exists(journal));
    QVERIFY(fileBytes(p) != bytes);
}

// A database file at schema `version` (the first migrations only) with C22 of
// grinder-205 set to 2133; `more` writes the rest at that version.
void writeAtVersion(const fs::path& p, int version,
                    const std::function<void(db::Database&)>& more = {}) {
    auto o = testOptions();
    o.migrations = db::schemaMigrations().subspan(0, static_cast<std::size_t>(version));
    db::Database d = db::Database::open(p, o);
    QCOMPARE(d.schemaVersion(), version);
    db::Edit e;
    e.c[22] = 2133;
    d.applyEdit("grinder-205", e, by("Петров"));
    if (more)
        more(d);
}

// The file of writeAtVersion opened by this program: upgraded to the latest
// schema, its machine kept, the upgrade in the audit; `more` checks the rest,
// then the integrity check finds nothing.
void checkUpgradedFrom(const fs::path& p, int version,
                       const std::function<void(db::Database&)>& more = {}) {
    db::Database d = db::Database::open(p, testOptions());
    QCOMPARE(d.openReport().fromVersion, version);
    QCOMPARE(d.openReport().version, db::latestSchemaVersion());
    QCOMPARE(d.schemaVersion(), db::latestSchemaVersion());
    QCOMPARE(d.loadMachine("grinder-205").cValue(22), std::int64_t(2133));
    QCOMPARE(d.audit(1).front().detail, "schema version " + std::to_string(version) + " -> " +
                                            std::to_string(db::latestSchemaVersion()));
    if (more)
        more(d);
    QVERIFY(integrityText(d).empty());
}

const char* const kV2Sql =
    "CREATE TABLE workshops (id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE);"
    "ALTER TABLE machines ADD COLUMN workshop_id INTEGER REFERENCES workshops(id);";

} // namespace

class TestSchema : public QObject {
    Q_OBJECT
private slots:
    void newFileGetsSchemaDefinitionsAndBuiltins() {
        QTemporaryDir dir;
        const fs::path p = tempPath(dir, "new.db");
        QVERIFY(!fs::exists(p));
        {
            db::Database d = db::Database::open(p, testOptions());
            const auto& r = d.openReport();
            QVERIFY(r.created);
            QCOMPARE(r.fromVersion, 0);
            QCOMPARE(r.version, db::latestSchemaVersion());
            QCOMPARE(r.seeded, profile::builtinNames());
            QCOMPARE(d.schemaVersion(), db::latestSchemaVersion());
            // The built-ins are stored exactly.
            for (const auto& name : profile::builtinNames()) {
                QVERIFY(d.loadMachine(name) == profile::builtin(name));
                QCOMPARE(d.machine(name)->revision, 1);
                QCOMPARE(d.machine(name)->changedBy, std::string("tester"));
            }
            const auto audit = d.audit();
            QCOMPARE(audit.back().action, std::string("create-database"));
            QVERIFY(std::any_of(audit.begin(), audit.end(),
                                [](const auto& a) { return a.action == "definitions"; }));
            QCOMPARE(std::count_if(audit.begin(), audit.end(),
                                   [](const auto& a) { return a.action == "seed"; }),
                     2);
        }
        Raw raw(p);
        QCOMPARE(raw.integer("PRAGMA application_id"), static_cast<long long>(db::kApplicationId));
        QCOMPARE(raw.integer("PRAGMA user_version"), static_cast<long long>(db::latestSchemaVersion()));
        QCOMPARE(raw.text("PRAGMA journal_mode"), std::string("wal"));
        QCOMPARE(raw.integer("SELECT count(*) FROM c_definitions"), 152LL);
        // Appendix Е as printed: name, address, kind.
        QCOMPARE(raw.text("SELECT name || '|' || address || '|' || kind || '|' || unit FROM "
                          "c_definitions WHERE number = 22"),
                 std::string("УСКОРЕНИЕ 1|Z4106|integer|25600*A/Kd"));
        QCOMPARE(raw.text("SELECT name || '|' || address || '|' || kind FROM c_definitions WHERE "
                          "number = 107"),
                 std::string("N Б.ВХ. X1|Z4202, Мл.байт|code"));
        QCOMPARE(raw.text("SELECT axis || '|' || kind || '|' || min_value || '..' || max_value "
                          "FROM c_definitions WHERE number = 57"),
                 std::string("Z|flag|0..1"));
        QVERIFY(
            raw.text("SELECT description_ru FROM c_definitions WHERE number = 22").find("0,8533") !=
            std::string::npos);
        // Every definition equals the catalog's.
        for (const auto& def : catalog::cParams()) {
            const std::string n = std::to_string(def.number);
            QCOMPARE(raw.text("SELECT name FROM c_definitions WHERE number = " + n),
                     std::string(def.name));
            QCOMPARE(raw.integer("SELECT max_value FROM c_definitions WHERE number = " + n),
                     static_cast<long long>(def.max));
        }
        QCOMPARE(raw.integer("SELECT count(*) FROM c_values"), 2LL * 152);
    }

    void emptyFileIsCreated() {
        QTemporaryDir dir;
        const fs::path p = tempPath(dir, "empty.db");
        writeBytes(p, "");
        db::Database d = db::Database::open(p, testOptions());
        QVERIFY(d.openReport().created);
        QCOMPARE(d.machines().size(), std::size_t(2));
    }

    void withoutSeedingTheDatabaseIsEmpty() {
        QTemporaryDir dir;
        auto o = testOptions();
        o.seedBuiltins = false;
        db::Database d = db::Database::open(tempPath(dir, "e.db"), o);
        QVERIFY(d.machines().empty());
    }

    void reopeningWritesNothing() {
        QTemporaryDir dir;
        const fs::path p = makeDb(dir);
        const std::string before = fileBytes(p);
        {
            db::Database d = db::Database::open(p, testOptions());
            QVERIFY(!d.openReport().created);
            QCOMPARE(d.openReport().fromVersion, db::latestSchemaVersion());
            QVERIFY(!d.openReport().definitionsUpdated);
            QCOMPARE(d.machines().size(), std::size_t(2));
            (void)d.loadMachine("grinder-205");
        }
        QVERIFY(fileBytes(p) == before);
        QVERIFY(!fs::exists(p.string() + "-wal"));
    }

    void missingFileWithoutCreate() {
        QTemporaryDir dir;
        auto o = testOptions();
        o.create = false;
        const fs::path p = tempPath(dir, "none.db");
        const std::string e = openError(p, db::ErrorKind::Io, o);
        QVERIFY2(e.find("no database at") != std::string::npos, e.c_str());
        QVERIFY(!fs::exists(p));
        const std::string e2 = openError(tempPath(dir, "no/such/folder.db"), db::ErrorKind::Io);
        QVERIFY2(e2.find("does not exist") != std::string::npos, e2.c_str());
    }

    // A later schema step is applied to a version-1 file in one transaction,
    // keeping every machine.
    void migrationFromVersion1() {
        QTemporaryDir dir;
        const fs::path p = makeDb(dir);
        {
            db::Database d = db::Database::open(p, testOptions());
            d.applyEdit(
                "grinder-205",
                [] {
                    db::Edit e;
                    e.c[22] = 2133;
                    return e;
                }(),
                by("Петров"));
        }
        std::vector<db::Migration> steps(db::schemaMigrations().begin(),
                                         db::schemaMigrations().end());
        const int latest = db::latestSchemaVersion(), next = latest + 1;
        steps.push_back({next, "workshops", kV2Sql});
        auto o = testOptions();
        o.migrations = steps;
        {
            db::Database d = db::Database::open(p, o);
            QVERIFY(!d.openReport().created);
            QCOMPARE(d.openReport().fromVersion, latest);
            QCOMPARE(d.openReport().version, next);
            QVERIFY(d.openReport().seeded.empty());
            QCOMPARE(d.schemaVersion(), next);
            QCOMPARE(d.loadMachine("grinder-205").cValue(22), std::int64_t(2133));
            QCOMPARE(d.machine("grinder-205")->revision, 2);
            QCOMPARE(d.audit(1).front().action, std::string("migrate"));
            QCOMPARE(d.audit(1).front().detail, "schema version " + std::to_string(latest) + " -> " +
                                                    std::to_string(next));
        }
        {
            Raw raw(p);
            QCOMPARE(raw.integer("PRAGMA user_version"), static_cast<long long>(next));
            QVERIFY(raw.exec("INSERT INTO workshops (name) VALUES ('цех 3')").empty());
        }
        // This program (an older schema) now refuses the file and leaves it alone.
        const std::string bytes = fileBytes(p);
        const std::string e = openError(p, db::ErrorKind::TooNew);
        QVERIFY2(e.find("schema version " + std::to_string(next)) != std::string::npos, e.c_str());
        QVERIFY(fileBytes(p) == bytes);
    }

    // Version 1 -> 2: the message history's tables beside every machine kept.
    void messageHistoryFromVersion1() {
        QTemporaryDir dir;
        const fs::path p = tempPath(dir, "v1.db");
        writeAtVersion(p, 1);
        {
            Raw raw(p);
            QCOMPARE(raw.integer("SELECT count(*) FROM sqlite_schema WHERE name = 'message_history'"), 0LL);
        }
        checkUpgradedFrom(p, 1);
        if (QTest::currentTestFailed())
            return;
        Raw raw(p);
        QCOMPARE(raw.integer("PRAGMA user_version"), static_cast<long long>(db::latestSchemaVersion()));
        QVERIFY(raw.exec("INSERT INTO message_runs (machine, started_at, started_ms, author) "
                         "VALUES ('grinder-205', '2024-05-17T08:30:00.000Z', 0, 'x')").empty());
        QVERIFY(raw.exec("INSERT INTO message_history (run_id, seq, machine, machine_ms, day_ms, "
                         "source, number, text, text_en, program, line) VALUES (1, 1, "
                         "'grinder-205', 5, 0, 'positioner', 9, 't', 't', 0, 0)").empty());
        // The schema's rules hold: an unknown source is refused.
        QVERIFY(!raw.exec("INSERT INTO message_history (run_id, seq, machine, machine_ms, day_ms, "
                          "source, number, text, text_en, program, line) VALUES (1, 2, "
                          "'grinder-205', 5, 0, 'elsewhere', 9, 't', 't', 0, 0)").empty());
    }

    // A new file gets every step at once.
    void newFileWithTwoSteps() {
        QTemporaryDir dir;
        std::vector<db::Migration> steps(db::schemaMigrations().begin(),
                                         db::schemaMigrations().end());
        const int next = db::latestSchemaVersion() + 1;
        steps.push_back({next, "workshops", kV2Sql});
        auto o = testOptions();
        o.migrations = steps;
        db::Database d = db::Database::open(tempPath(dir, "two.db"), o);
        QCOMPARE(d.openReport().fromVersion, 0);
        QCOMPARE(d.schemaVersion(), next);
        QCOMPARE(d.machines().size(), std::size_t(2));
    }

    void failedMigrationChangesNothing() {
        QTemporaryDir dir;
        const fs::path p = makeDb(dir);
        const std::string bytes = fileBytes(p);
        std::vector<db::Migration> steps(db::schemaMigrations().begin(),
                                         db::schemaMigrations().end());
        const int latest = db::latestSchemaVersion();
        steps.push_back({latest + 1, "broken",
                         "CREATE TABLE good (a INTEGER); INSERT INTO missing VALUES (1);"});
        auto o = testOptions();
        o.migrations = steps;
        const std::string e = openError(p, db::ErrorKind::Sql, o);
        QVERIFY2(e.find("migration to schema version " + std::to_string(latest + 1) + " failed") !=
                     std::string::npos,
                 e.c_str());
        QVERIFY2(e.find("no such table: missing") != std::string::npos, e.c_str());
        // Said in Russian too: where, what kind of error and SQLite's words,
        // then that the migration failed and changed nothing.
        try {
            db::Database::open(p, o);
            QFAIL("a broken migration succeeded");
        } catch (const db::Error& error) {
            const QString ru = QString::fromStdString(error.text(db::Lang::Ru));
            QVERIFY2(ru.startsWith(QString::fromStdString(p.string() + ": ")) && ru.contains(QStringLiteral("«")) &&
                         ru.endsWith(QStringLiteral("; переход на версию схемы %1 не удался, ничего не изменено")
                                         .arg(latest + 1)) &&
                         !hasEnglishSentence(ru, false),
                     qPrintable(ru));
        }
        QVERIFY(fileBytes(p) == bytes);
        db::Database d = db::Database::open(p, testOptions());
        QCOMPARE(d.schemaVersion(), latest);
        Raw raw(p);
        QCOMPARE(raw.integer("SELECT count(*) FROM sqlite_schema WHERE name = 'good'"), 0LL);
    }

    // Version 2 -> 3: releases and the transfer log beside every machine and
    // message kept; the new tables keep their rules.
    void releasesAndTransfersFromVersion2() {
        QTemporaryDir dir;
        const fs::path p = tempPath(dir, "v2.db");
        writeAtVersion(p, 2);
        checkUpgradedFrom(p, 2, [](db::Database& d) {
            QCOMPARE(d.releaseProgram("grinder-205", 11, "", by("Петров")).revision, 1);
        });
        if (QTest::currentTestFailed())
            return;
        Raw raw(p);
        raw.exec("PRAGMA foreign_keys = ON");
        QVERIFY(!raw.exec("INSERT INTO transfers (at, db_user, host, machine, revision, controller, "
                          "direction, result, detail) VALUES ('x', 'u', 'h', 'm', 0, 'c', 'sideways', "
                          "'ok', '')").empty());
        QVERIFY(!raw.exec("INSERT INTO program_states (machine_id, number, revision, sha256, state, at, "
                          "author, note) VALUES (1, 11, 99, '" + std::string(64, 'a') +
                          "', 'released', 'x', 'y', '')").empty()); // no such version
    }

    // Version 3 -> 4: the training attempts beside every machine, release and
    // transfer kept; the new table keeps its rules.
    void trainingAttemptsFromVersion3() {
        QTemporaryDir dir;
        const fs::path p = tempPath(dir, "v3.db");
        writeAtVersion(p, 3, [](db::Database& d) {
            d.releaseProgram("grinder-205", 11, "", by("Петров"));
            // A version-3 database has no attempts: said, not an SQL error.
            QVERIFY_THROWS_EXCEPTION(db::Error, d.attempts());
        });
        checkUpgradedFrom(p, 3, [](db::Database& d) {
            QCOMPARE(d.releaseHistory("grinder-205", 11).size(), std::size_t(1));
            QVERIFY(d.attempts().empty());
            db::AttemptEntry a;
            a.student = "Иванов";
            a.exercise = "lathe-03-step";
            a.program = "%L1\nM30\n";
            a.score = 87;
            a.status = "completed";
            a.grade = "{}";
            const db::AttemptEntry stored = d.recordAttempt(a);
            QVERIFY(stored.id > 0);
            QCOMPARE(stored.sha256.size(), std::size_t(64));
            QCOMPARE(d.attempts().size(), std::size_t(1));
            QCOMPARE(d.attempts().front(), stored);
        });
        if (QTest::currentTestFailed())
            return;
        Raw raw(p);
        QVERIFY(!raw.exec("INSERT INTO training_attempts (at, recorded_by, host, student, exercise, file, "
                          "program, sha256, score, passed, status, cycle_time_ms, grade) VALUES ('x', 'u', "
                          "'h', 's', 'e', '', '', '" + std::string(64, 'a') +
                          "', 101, 0, 'completed', 0, '{}')").empty()); // a score above 100
    }

    // Version 4 -> 5: the shop's time in each state beside every machine and
    // attempt; a poller's rows add up; the table keeps its rules.
    void stateTimesFromVersion4() {
        QTemporaryDir dir;
        const fs::path p = tempPath(dir, "v4.db");
        writeAtVersion(p, 4, [](db::Database& d) {
            db::AttemptEntry a;
            a.student = "Иванов";
            a.exercise = "lathe-03-step";
            a.grade = "{}";
            d.recordAttempt(a);
            // A version-4 database has no times: said, not an SQL error.
            QVERIFY_THROWS_EXCEPTION(db::Error, db::stateTimes(d, ""));
        });
        checkUpgradedFrom(p, 4, [](db::Database& d) {
            QCOMPARE(d.attempts().size(), std::size_t(1));
            QVERIFY(db::stateTimes(d, "").empty());
            db::addStateTimes(d, {{"m01", "2026-12-06", "studio@pc1", "idle", 60000, {}},
                             {"m01", "2026-12-06", "studio@pc1", "run", 1500, {}}});
            db::addStateTimes(d, {{"m01", "2026-12-06", "studio@pc1", "idle", 2500, {}},
                             {"m01", "2026-12-06", "shop@pc2", "idle", 100, {}},
                             {"m02", "2026-12-07", "studio@pc1", "offline", 7, {}}});
            const auto day = db::stateTimes(d, "2026-12-06");
            QCOMPARE(day.size(), std::size_t(3));
            QCOMPARE(day[0].source, std::string("shop@pc2"));
            QCOMPARE(day[1].state, std::string("idle"));
            QCOMPARE(day[1].ms, std::int64_t(62500));
            QCOMPARE(day[2].state, std::string("run"));
            QCOMPARE(day[2].ms, std::int64_t(1500));
            QVERIFY(!day[2].changedAt.empty());
            QCOMPARE(db::stateTimes(d, "", "studio@pc1").size(), std::size_t(3));
            QCOMPARE(db::stateTimes(d, "2026-12-07").size(), std::size_t(1));
            // A state that is not one, a bad day: refused whole, nothing written.
            QVERIFY_THROWS_EXCEPTION(db::Error, db::addStateTimes(d, {{"m01", "2026-12-06", "x", "idle", 5, {}},
                                                                 {"m01", "2026-12-06", "x", "sleeping", 5, {}}}));
            QVERIFY_THROWS_EXCEPTION(db::Error, db::addStateTimes(d, {{"m01", "6.12.2026", "x", "idle", 5, {}}}));
            QCOMPARE(db::stateTimes(d, "", "x").size(), std::size_t(0));
        });
        if (QTest::currentTestFailed())
            return;
        Raw raw(p);
        QVERIFY(!raw.exec("INSERT INTO state_times (machine, day, source, state, ms, changed_at) VALUES "
                          "('m', '2026-12-06', 's', 'idle', -1, 'x')").empty()); // a negative time
    }

    void foreignSqliteFileIsRefused() {
        QTemporaryDir dir;
        const fs::path p = tempPath(dir, "other.db");
        {
            Raw raw(p);
            QVERIFY(raw.exec("CREATE TABLE customers (id INTEGER, name TEXT);"
                             "INSERT INTO customers VALUES (1, 'ООО Ромашка');")
                        .empty());
        }
        const std::string bytes = fileBytes(p);
        const std::string e = openError(p, db::ErrorKind::Foreign);
        QVERIFY2(e.find("not a K528 Studio database") != std::string::npos, e.c_str());
        QVERIFY2(e.find("left untouched") != std::string::npos, e.c_str());
        QVERIFY(fileBytes(p) == bytes);
        QVERIFY(!fs::exists(p.string() + "-wal"));
        // Another program's application_id, even without tables.
        const fs::path q = tempPath(dir, "tagged.db");
        {
            Raw raw(q);
            QVERIFY(raw.exec("PRAGMA application_id = 305419896").empty()); // 0x12345678
        }
        const std::string qbytes = fileBytes(q);
        const std::string e2 = openError(q, db::ErrorKind::Foreign);
        QVERIFY2(e2.find("0x12345678") != std::string::npos, e2.c_str());
        QVERIFY(fileBytes(q) == qbytes);
    }

    // Another program's file with an unfinished transaction of its own: it
    // is refused from the file header, never opened with SQLite (which would
    // roll the journal back).
    void foreignFileWithHotJournalIsRefusedUntouched() {
        QTemporaryDir dir;
        const fs::path p = tempPath(dir, "other.db");
        {
            Raw raw(p);
            QVERIFY(raw.exec("PRAGMA application_id = 305419896;" // 0x12345678
                             "CREATE TABLE customers (id INTEGER, name TEXT);"
                             "INSERT INTO customers VALUES (1, 'ООО Ромашка');")
                        .empty());
        }
        leaveHotJournal(p);
        refusedWithHotJournal(p, db::ErrorKind::Foreign, "0x12345678");
    }

    // The same without an application_id: SQLite has to look at it (an empty
    // SQLite file is ours to fill), but on a read-only connection, which
    // cannot roll the journal back.
    void untaggedFileWithHotJournalIsRefusedUntouched() {
        QTemporaryDir dir;
        const fs::path p = tempPath(dir, "untagged.db");
        {
            Raw raw(p);
            QVERIFY(raw.exec("CREATE TABLE customers (id INTEGER, name TEXT);"
                             "INSERT INTO customers VALUES (1, 'ООО Ромашка');")
                        .empty());
        }
        leaveHotJournal(p);
        refusedWithHotJournal(p, db::ErrorKind::Foreign, "not ours to roll back");
    }

    // A program killed in the first transaction of a new file (an
    // interrupted `k528 db init`, or another program's): the journal began on
    // an empty file, so rolling it back gives the empty file again — nothing
    // committed is lost — and the empty file is ours to fill.
    void hotJournalOfANewFileIsRolledBack() {
        QTemporaryDir dir;
        const fs::path p = tempPath(dir, "new.db");
        leaveHotJournal(p);
        QVERIFY(fs::file_size(p) > 0);
        {
            db::Database d = db::Database::open(p, testOptions());
            QVERIFY(d.openReport().recovered);
            QVERIFY(d.openReport().created);
            QCOMPARE(d.machines().size(), std::size_t(2));
            QCOMPARE(integrityText(d), std::string());
        }
        QVERIFY(!fs::exists(p.string() + "-journal"));
        Raw raw(p);
        QCOMPARE(raw.integer("SELECT count(*) FROM sqlite_schema WHERE name = 'junk'"), 0LL);
    }

    void newerSchemaWithHotJournalIsRefusedUntouched() {
        QTemporaryDir dir;
        const fs::path p = makeDb(dir);
        const std::string newer = std::to_string(db::latestSchemaVersion() + 1);
        {
            Raw raw(p);
            QCOMPARE(raw.text("PRAGMA journal_mode = DELETE"), std::string("delete"));
            QVERIFY(raw.exec("PRAGMA user_version = " + newer).empty());
        }
        leaveHotJournal(p);
        refusedWithHotJournal(p, db::ErrorKind::TooNew, "schema version " + newer);
    }

    // Our own file (converted to a rollback journal by another tool) with an
    // unfinished transaction: SQLite's crash recovery rolls it back, and the
    // database opens as of its last commit.
    void ownFileWithHotJournalIsRecovered() {
        QTemporaryDir dir;
        const fs::path p = makeDb(dir);
        {
            Raw raw(p);
            QCOMPARE(raw.text("PRAGMA journal_mode = DELETE"), std::string("delete"));
        }
        leaveHotJournal(p);
        {
            db::Database d = db::Database::open(p, testOptions());
            QVERIFY(!d.openReport().created);
            QCOMPARE(d.machines().size(), std::size_t(2));
            QCOMPARE(integrityText(d), std::string());
        }
        QVERIFY(!fs::exists(p.string() + "-journal"));
        Raw raw(p);
        QCOMPARE(raw.integer("SELECT count(*) FROM sqlite_schema WHERE name = 'junk'"), 0LL);
        QCOMPARE(raw.text("PRAGMA journal_mode"), std::string("wal"));
    }

    // The schema table (page 1) damaged, with committed changes still in the
    // -wal: refused with the file's name, and neither the file nor the -wal
    // is changed (no checkpoint into the damaged file, the -wal is kept).
    void damagedSchemaWithWalIsRefusedUntouched() {
        QTemporaryDir dir;
        const fs::path p = makeDb(dir);
        const fs::path wal = p.string() + "-wal";
        {
            Raw raw(p);
            sqlite3_db_config(raw.db, SQLITE_DBCONFIG_NO_CKPT_ON_CLOSE, 1, nullptr);
            QVERIFY(raw.exec("UPDATE machines SET title = 'из журнала' WHERE name = "
                             "'grinder-205'")
                        .empty());
        }
        QVERIFY(fs::exists(wal) && fs::file_size(wal) > 0);
        std::string bytes = fileBytes(p);
        for (std::size_t i = 100; i < 4096; ++i)
            bytes[i] = static_cast<char>(0xA5 ^ i);
        writeBytes(p, bytes);
        const std::string walBytes = fileBytes(wal);
        const std::string e = openError(p, db::ErrorKind::Corrupt);
        QVERIFY2(e.find(p.string()) != std::string::npos, e.c_str());
        QVERIFY2(e.find("cannot be read as a database") != std::string::npos, e.c_str());
        QVERIFY2(e.find("left untouched") != std::string::npos, e.c_str());
        QVERIFY(fileBytes(p) == bytes);
        QVERIFY(fileBytes(wal) == walBytes);
    }

    void nonSqliteFileIsRefused() {
        QTemporaryDir dir;
        const fs::path p = tempPath(dir, "notes.db");
        const std::string text = "[machine]\nformat=1\nname=x\n" + std::string(400, 'x');
        writeBytes(p, text);
        const std::string e = openError(p, db::ErrorKind::Foreign);
        QVERIFY2(e.find("SQLite header") != std::string::npos, e.c_str());
        QVERIFY(fileBytes(p) == text);
        const fs::path tiny = tempPath(dir, "tiny.db");
        writeBytes(tiny, "SQLite");
        const std::string e2 = openError(tiny, db::ErrorKind::Foreign);
        QVERIFY2(e2.find("only 6 bytes") != std::string::npos, e2.c_str());
        QVERIFY(fileBytes(tiny) == "SQLite");
    }

    void garbledFileIsRefusedUntouched() {
        QTemporaryDir dir;
        const fs::path p = makeDb(dir);
        std::string bytes = fileBytes(p);
        const std::size_t pageSize = 4096;
        QVERIFY(bytes.size() > 8 * pageSize);
        // Overwrite the middle of several b-tree pages.
        for (std::size_t page = 2; page * pageSize < bytes.size(); page += 5)
            for (std::size_t i = 0; i < 300; ++i)
                bytes[page * pageSize + 100 + i] = static_cast<char>(0xA5 ^ i);
        writeBytes(p, bytes);
        const std::string e = openError(p, db::ErrorKind::Corrupt);
        QVERIFY2(e.find("damaged") != std::string::npos ||
                     e.find("cannot be read") != std::string::npos,
                 e.c_str());
        QVERIFY2(e.find("left untouched") != std::string::npos, e.c_str());
        QVERIFY(fileBytes(p) == bytes);
        QVERIFY(!fs::exists(p.string() + "-wal"));
        QVERIFY(!fs::exists(p.string() + "-shm"));
    }

    void truncatedFileIsRefusedUntouched() {
        QTemporaryDir dir;
        const fs::path p = makeDb(dir);
        std::string bytes = fileBytes(p);
        bytes.resize(bytes.size() / 2 / 4096 * 4096);
        writeBytes(p, bytes);
        const std::string e = openError(p, db::ErrorKind::Corrupt);
        QVERIFY2(!e.empty(), "a truncated database opened");
        QVERIFY(fileBytes(p) == bytes);
        // A truncated header.
        writeBytes(p, bytes.substr(0, 50));
        QVERIFY(!openError(p, db::ErrorKind::Foreign).empty());
        QCOMPARE(fileBytes(p).size(), std::size_t(50));
    }

    void newerSchemaIsRefusedUntouched() {
        QTemporaryDir dir;
        const fs::path p = makeDb(dir);
        const std::string newer = std::to_string(db::latestSchemaVersion() + 1);
        {
            Raw raw(p);
            QVERIFY(raw.exec("PRAGMA user_version = " + newer).empty());
        }
        const std::string bytes = fileBytes(p);
        const std::string e = openError(p, db::ErrorKind::TooNew);
        QVERIFY2(e.find("schema version " + newer) != std::string::npos, e.c_str());
        QVERIFY2(e.find("newer K528 Studio") != std::string::npos, e.c_str());
        QVERIFY(fileBytes(p) == bytes);
    }

    // The schema itself refuses values outside their definitions, for people
    // who edit the file with other tools.
    void schemaGuardsValues() {
        QTemporaryDir dir;
        const fs::path p = makeDb(dir);
        Raw raw(p);
        raw.exec("PRAGMA foreign_keys = ON");
        QCOMPARE(raw.exec("UPDATE c_values SET value = 40000 WHERE number = 22"),
                 std::string("C-parameter value outside the range of its definition"));
        QVERIFY(raw.exec("INSERT INTO c_values (machine_id, number, value) VALUES (1, 153, 0)") !=
                "");
        QVERIFY(raw.exec("INSERT INTO r_values (machine_id, number, value) VALUES (1, 240, 5)")
                    .find("CHECK") != std::string::npos);
        QVERIFY(raw.exec("INSERT INTO plc_messages (machine_id, grp, number, text) VALUES "
                         "(1, 'S', 17, 'x')")
                    .find("CHECK") != std::string::npos);
        QVERIFY(raw.exec("INSERT INTO messages (machine_id, number, text) VALUES (99, 1, 'x')")
                    .find("FOREIGN KEY") != std::string::npos);
        QCOMPARE(raw.integer("SELECT value FROM c_values WHERE number = 22 AND machine_id = "
                             "(SELECT id FROM machines WHERE name = 'grinder-205')"),
                 2000LL);
    }

    // Definitions edited outside are restored from the catalog on open.
    void definitionsFollowTheCatalog() {
        QTemporaryDir dir;
        const fs::path p = makeDb(dir);
        {
            Raw raw(p);
            QVERIFY(raw.exec("UPDATE c_definitions SET name = 'XXX' WHERE number = 22;"
                             "UPDATE meta SET value = 'old' WHERE key = 'catalog_sha256'")
                        .empty());
        }
        {
            db::Database d = db::Database::open(p, testOptions());
            QVERIFY(d.openReport().definitionsUpdated);
            QCOMPARE(d.audit(1).front().action, std::string("definitions"));
        }
        Raw raw(p);
        QCOMPARE(raw.text("SELECT name FROM c_definitions WHERE number = 22"),
                 std::string("УСКОРЕНИЕ 1"));
    }

    void timestampsAreUtc() {
        QCOMPARE(db::formatTimestamp(0), std::string("1970-01-01T00:00:00Z"));
        QCOMPARE(db::formatTimestamp(1715934600), std::string("2024-05-17T08:30:00Z"));
        QCOMPARE(db::formatTimestamp(951782400), std::string("2000-02-29T00:00:00Z"));
        QCOMPARE(db::formatTimestamp(4102444799), std::string("2099-12-31T23:59:59Z"));
        QCOMPARE(db::formatTimestamp(-1), std::string("1969-12-31T23:59:59Z"));
    }
};

QTEST_APPLESS_MAIN(TestSchema)
#include "test_schema.moc"
