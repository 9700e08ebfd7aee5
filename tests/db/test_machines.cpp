// Machines in the database: writes with validation, per-value history (who,
// when, old -> new), revisions rebuilt exactly, renames, conflicts, deletion,
// the audit log, explanations of values, and the engine's profile hook.
#include "catalog/cparams.h"
#include "db/database.h"
#include "db/db_texts.h"
#include "db/explain.h"
#include "db/location.h"
#include "db/sha256.h"
#include "db_test_util.h"
#include "profile/builtin.h"
#include "profile/diff.h"
#include "profile/text_format.h"
#include "profile/validate.h"
#include "random_machine.h"

#include <QtTest>
#include <sqlite3.h>
#include <algorithm>
#include <cstdlib>
#include <functional>
#include <map>
#include <random>

using namespace k528;
using namespace k528::testing;
namespace fs = std::filesystem;
using profile::MachineProfile;

namespace {

// A clock the test sets.
struct ManualClock {
    std::shared_ptr<std::int64_t> t = std::make_shared<std::int64_t>(1715934600);
    db::Clock clock() const {
        auto p = t;
        return [p] { return *p; };
    }
};

db::Edit editC(int n, std::int64_t v) {
    db::Edit e;
    e.c[n] = v;
    return e;
}

template <typename F> db::ErrorKind errorKind(F f) {
    try {
        f();
    } catch (const db::Error& e) {
        return e.kind();
    }
    return db::ErrorKind::Sql; // "no error": never expected below
}

// A random change of a profile: constants without error cross-checks, R,
// programs, messages, PLC texts, settings (values, new keys, order), title.
void mutate(MachineProfile& p, std::mt19937& rng) {
    const int kind = static_cast<int>(rng() % 9);
    switch (kind) {
    case 0: {
        static const int free[] = {21, 22, 23, 30, 32, 36, 40, 41, 42, 74, 75, 92, 139, 140};
        const int n = free[rng() % std::size(free)];
        const auto& d = catalog::cParam(n);
        p.setC(n, std::uniform_int_distribution<std::int64_t>(d.min, d.max)(rng));
        break;
    }
    case 1:
        p.r[static_cast<int>(rng() % 150)] = static_cast<std::int32_t>(rng());
        break;
    case 2:
        if (!p.r.empty())
            p.r.erase(std::next(p.r.begin(), static_cast<long>(rng() % p.r.size())));
        break;
    case 3: {
        const int n = static_cast<int>(rng() % 20) + 20;
        p.programs[n] = randomProgram(rng, n, static_cast<int>(rng() % 10) + 2);
        break;
    }
    case 4:
        for (auto it = p.programs.begin(); it != p.programs.end(); ++it)
            if (it->first >= 20) {
                p.programs.erase(it);
                break;
            }
        break;
    case 5:
        if (rng() % 2)
            p.messages[static_cast<int>(rng() % 99) + 1] = randomWord(rng, 20);
        else if (!p.messages.empty())
            p.messages.erase(p.messages.begin());
        break;
    case 6:
        p.plcTexts(catalog::PlcGroup::Work)[static_cast<int>(rng() % 32) + 1] = randomWord(rng, 40);
        break;
    case 7: {
        // Settings: a new key, a removed one, or the same keys in another order.
        const int what = static_cast<int>(rng() % 3);
        if (what == 0) {
            p.simulation.set("custom.k" + std::to_string(rng() % 5), std::to_string(rng() % 100));
        } else if (what == 1 && !p.simulation.empty()) {
            p.simulation.erase(p.simulation.entries().front().first);
        } else {
            auto entries = p.simulation.entries();
            std::shuffle(entries.begin(), entries.end(), rng);
            p.simulation.clear();
            for (const auto& [k, v] : entries)
                p.simulation.set(k, v);
        }
        break;
    }
    default:
        p.title = "Станок " + randomWord(rng, 20);
        break;
    }
}

// What psql prints for `sql` on a PostgreSQL database (unaligned, tuples
// only), or what it said on failure.
std::string psqlOutput(const db::Location& where, const std::string& sql) {
    QProcess p;
    p.start("psql", {"-XAtq", "-v", "ON_ERROR_STOP=1", QString::fromStdString(where.uri()), "-c",
                     QString::fromStdString(sql)});
    if (!p.waitForFinished(60000) || p.exitCode() != 0)
        return "psql failed: " + p.readAllStandardError().toStdString();
    return p.readAllStandardOutput().toStdString();
}

// `n` random characters of four UTF-8 bytes each (CJK extension B).
std::string wideText(std::mt19937& rng, int n) {
    std::string s;
    for (int i = 0; i < n; ++i) {
        const std::uint32_t cp = 0x20000 + rng() % 0xA6D0;
        s += static_cast<char>(0xF0 | (cp >> 18));
        s += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        s += static_cast<char>(0x80 | (cp & 0x3F));
    }
    return s;
}

bool sameHistory(const std::vector<db::HistoryEntry>& a, const std::vector<db::HistoryEntry>& b) {
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].revision != b[i].revision || a[i].author != b[i].author || a[i].at != b[i].at ||
            !(a[i].change == b[i].change))
            return false;
    return true;
}

// The names of the indexes on changes and revisions, sorted, space-separated:
// SQLite's own (sqlite_schema: not the automatic ones of the keys), or
// PostgreSQL's (pg_indexes, through psql).
std::string indexesOf(const db::Location& where) {
    std::string out;
    if (onPostgres()) {
        QProcess p;
        p.start("psql", {"-XAtq", QString::fromStdString(where.uri()), "-c",
                         "SELECT string_agg(indexname, ' ' ORDER BY indexname) FROM pg_indexes "
                         "WHERE tablename IN ('changes', 'revisions')"});
        if (!p.waitForFinished(60000) || p.exitCode() != 0)
            return "psql failed: " + p.readAllStandardError().toStdString();
        out = p.readAllStandardOutput().trimmed().toStdString();
        return out;
    }
    sqlite3* db = nullptr;
    if (sqlite3_open_v2(where.file().c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK)
        return "cannot open";
    sqlite3_stmt* st = nullptr;
    sqlite3_prepare_v2(db,
                       "SELECT name FROM sqlite_schema WHERE type = 'index' AND tbl_name IN "
                       "('changes', 'revisions') AND sql IS NOT NULL ORDER BY name",
                       -1, &st, nullptr);
    while (st && sqlite3_step(st) == SQLITE_ROW)
        out += (out.empty() ? "" : " ") + std::string(reinterpret_cast<const char*>(sqlite3_column_text(st, 0)));
    sqlite3_finalize(st);
    sqlite3_close(db);
    return out;
}

// A database of an older schema `version` (only its first migrations run,
// as an older program left it) where grinder-205 has `edits` revisions
// more: C022 = 1000 + i and R<i> = i, by `authorOf(i)`.
db::Database databaseOfVersion(const db::Location& where, int version, int edits,
                               const std::function<std::string(int)>& authorOf) {
    auto o = testOptions();
    o.migrations = db::schemaMigrations().subspan(0, static_cast<std::size_t>(version));
    db::Database d = db::Database::open(where, o);
    for (int i = 0; i < edits; ++i) {
        db::Edit e;
        e.c[22] = 1000 + i;
        e.r[i] = i;
        d.applyEdit("grinder-205", e, by(authorOf(i)));
    }
    return d;
}

} // namespace

class TestMachines : public QObject {
    Q_OBJECT
private slots:
    void historyOfEachChange() {
        QTemporaryDir dir;
        ManualClock clk;
        db::Database d = db::Database::open(testLocation(dir, "h.db"), testOptions(clk.clock()));
        *clk.t = 1715940000; // 2024-05-17T10:00:00Z
        db::Edit e;
        e.c[22] = 2133;
        e.r[12] = 5;
        e.messages[9] = "ПРОВЕРКА";
        e.plc[{catalog::PlcGroup::Alarm, 10}] = "Нет воздуха";
        e.simulation["x.kv"] = "1.5";
        const auto r1 = d.applyEdit("grinder-205", e, by("Иванов И.И."));
        QVERIFY(r1.changed);
        QCOMPARE(r1.revision, 2);
        QCOMPARE(r1.changes.size(), std::size_t(5));
        *clk.t = 1716026400; // 2024-05-18T10:00:00Z
        db::Edit e2;
        e2.c[22] = 2000;
        e2.r[12] = std::nullopt;
        const auto r2 = d.applyEdit("grinder-205", e2, by("Петров"));
        QCOMPARE(r2.revision, 3);

        const auto h = d.history("grinder-205", std::string("C022"));
        QCOMPARE(h.size(), std::size_t(3));
        QCOMPARE(h[0].revision, 3);
        QCOMPARE(h[0].author, std::string("Петров"));
        QCOMPARE(h[0].at, std::string("2024-05-18T10:00:00Z"));
        QCOMPARE(*h[0].change.before, std::string("2133"));
        QCOMPARE(*h[0].change.after, std::string("2000"));
        QCOMPARE(h[0].change.label, std::string("УСКОРЕНИЕ 1"));
        QCOMPARE(h[0].change.key, std::string("C022"));
        QVERIFY(h[0].change.section == profile::DiffSection::C);
        QCOMPARE(h[1].author, std::string("Иванов И.И."));
        QCOMPARE(h[1].at, std::string("2024-05-17T10:00:00Z"));
        QCOMPARE(*h[1].change.before, std::string("2000"));
        QCOMPARE(*h[1].change.after, std::string("2133"));
        QCOMPARE(h[2].revision, 1);
        QVERIFY(!h[2].change.before); // as first stored
        QCOMPARE(h[2].author, std::string("tester"));

        const auto hr = d.history("grinder-205", std::string("R12"));
        QCOMPARE(hr.size(), std::size_t(2));
        QVERIFY(!hr[0].change.after); // removed
        QCOMPARE(*hr[0].change.before, std::string("5"));
        QVERIFY(!hr[1].change.before); // added
        QCOMPARE(d.history("grinder-205", std::string("#9")).size(), std::size_t(1));
        QCOMPARE(*d.history("grinder-205", std::string("A10")).front().change.after,
                 std::string("Нет воздуха"));
        const auto hs = d.history("grinder-205", std::string("x.kv"));
        QCOMPARE(hs.size(), std::size_t(2));
        QCOMPARE(*hs[0].change.before, std::string("1"));
        QCOMPARE(*hs[0].change.after, std::string("1.5"));

        // No such item: none; no such machine: said (PostgreSQL answers both
        // with no rows of its one statement and asks again).
        QVERIFY(d.history("grinder-205", std::string("R299")).empty());
        QVERIFY_THROWS_EXCEPTION(db::Error, d.history("no-such-machine", std::string("C022")));

        const auto revs = d.revisions("grinder-205");
        QCOMPARE(revs.size(), std::size_t(3));
        QCOMPARE(revs[0].revision, 3);
        QCOMPARE(revs[0].changeCount, 2);
        QCOMPARE(revs[0].summary, std::string("set C022 R12"));
        QCOMPARE(revs[1].author, std::string("Иванов И.И."));
        // The newest revision only.
        const auto last = d.history("grinder-205", std::nullopt, 1);
        QCOMPARE(last.size(), std::size_t(2));
        QCOMPARE(last[0].change.key, std::string("C022"));
        QCOMPARE(last[1].change.key, std::string("R12"));
        QVERIFY(last[1].change.section == profile::DiffSection::R);
        // One item of the newest revisions; of the whole history, every
        // item of every revision, newest first.
        const auto c022 = d.history("grinder-205", std::string("C022"), 2);
        QCOMPARE(c022.size(), std::size_t(2));
        QCOMPARE(c022[1].revision, 2);
        QCOMPARE(c022[1].change.key, std::string("C022"));
        QCOMPARE(*c022[1].change.after, std::string("2133"));
        QVERIFY(d.history("grinder-205", std::string("x.kv"), 1).empty());
        QCOMPARE(d.history("grinder-205", std::string("x.kv"), 2).size(), std::size_t(1));
        const auto all = d.history("grinder-205");
        QCOMPARE(all.size() - last.size() - r1.changes.size(),
                 static_cast<std::size_t>(std::count_if(all.begin(), all.end(), [](const auto& x) {
                     return x.revision == 1;
                 })));
        QCOMPARE(all[0].change.key, std::string("C022"));
        QCOMPARE(all[2].revision, 2);
        QCOMPARE(all.back().revision, 1);
        // The machine row follows.
        const auto m = *d.machine("grinder-205");
        QCOMPARE(m.revision, 3);
        QCOMPARE(m.changedBy, std::string("Петров"));
        QCOMPARE(m.changedAt, std::string("2024-05-18T10:00:00Z"));
        // The audit log has both writes.
        const auto audit = d.audit(2);
        QCOMPARE(audit[0].action, std::string("set"));
        QCOMPARE(audit[0].author, std::string("Петров"));
        QCOMPARE(audit[0].revision, 3);
        QCOMPARE(audit[0].at, std::string("2024-05-18T10:00:00Z"));
        QCOMPARE(audit[0].machine, std::string("grinder-205"));
        QCOMPARE(audit[1].author, std::string("Иванов И.И."));
        QCOMPARE(d.audit(0, "training-lathe").size(), std::size_t(1)); // its seeding
    }

    // A database of schema version 5 opened by this program: upgraded to the
    // history's index (changes_history; version 6 on PostgreSQL also had
    // revisions_authors, which version 7 drops with the history's join),
    // every revision and change kept, the history read as before.
    void historyIndexFromVersion5() {
        QTemporaryDir dir;
        const db::Location where = testLocation(dir, "v5.db");
        std::vector<db::HistoryEntry> before;
        std::size_t lastTwo = 0;
        {
            db::Database d = databaseOfVersion(where, 5, 30, [](int i) { return i % 2 ? "Петров" : "Иванов"; });
            QCOMPARE(d.schemaVersion(), 5);
            before = d.history("grinder-205", std::string("C022"));
            QCOMPARE(before.size(), std::size_t(31));
            lastTwo = d.history("grinder-205", std::nullopt, 2).size();
            QCOMPARE(indexesOf(where), std::string(onPostgres() ? "changes_by_key changes_pkey revisions_pkey"
                                                                : "changes_by_key"));
        }
        db::Database d = db::Database::open(where, testOptions());
        QCOMPARE(d.openReport().fromVersion, 5);
        QCOMPARE(d.schemaVersion(), db::latestSchemaVersion());
        QCOMPARE(d.audit(1).front().detail,
                 "schema version 5 -> " + std::to_string(db::latestSchemaVersion()));
        QCOMPARE(indexesOf(where), std::string(onPostgres()
                                                   ? "changes_history changes_pkey revisions_pkey"
                                                   : "changes_history"));
        QCOMPARE(d.revisions("grinder-205").size(), std::size_t(31));
        const auto after = d.history("grinder-205", std::string("C022"));
        QCOMPARE(after.size(), before.size());
        for (std::size_t i = 0; i < after.size(); ++i) {
            QCOMPARE(after[i].revision, before[i].revision);
            QCOMPARE(after[i].author, before[i].author);
            QCOMPARE(after[i].at, before[i].at);
            QCOMPARE(after[i].change.after, before[i].change.after);
        }
        QCOMPARE(after[0].revision, 31);
        QVERIFY(lastTwo >= 2);
        QCOMPARE(d.history("grinder-205", std::nullopt, 2).size(), lastTwo);
        QCOMPARE(d.loadMachine("grinder-205", 12).cValue(22), std::int64_t(1010));
        QVERIFY(d.checkIntegrity().empty());
        // The author is a name: one too long for the authors' index is refused whole.
        db::Edit e;
        e.c[22] = 1500;
        QVERIFY_THROWS_EXCEPTION(db::Error, d.applyEdit("grinder-205", e, by(std::string(300, 'a'))));
        QCOMPARE(d.machine("grinder-205")->revision, 31);
    }

    // A database of schema version 6 opened by this program: each recorded
    // change takes its revision's author and time (version 7), every
    // revision kept; the history (of one constant, of the last revisions,
    // whole, of every machine) and the export of every revision are the same
    // as before. A change whose author SQL altered apart from its revision's
    // is found by the integrity check.
    void historyAuthorsFromVersion6() {
        QTemporaryDir dir;
        const db::Location where = testLocation(dir, "v6.db");
        std::vector<std::string> names;
        std::map<std::string, std::vector<db::HistoryEntry>> whole;
        std::map<std::string, std::vector<std::string>> exports;
        std::vector<db::HistoryEntry> ofKey, lastThree;
        std::vector<db::RevisionInfo> revisions;
        {
            db::Database d = databaseOfVersion(where, 6, 25, [](int i) { return i % 3 ? "Петров" : "Иванов И.И."; });
            QCOMPARE(d.schemaVersion(), 6);
            ofKey = d.history("grinder-205", std::string("C022"));
            QCOMPARE(ofKey.size(), std::size_t(26));
            QVERIFY(ofKey[0].at != ofKey[1].at); // the stepping clock: each revision its time
            lastThree = d.history("grinder-205", std::nullopt, 3);
            revisions = d.revisions("grinder-205");
            for (const db::MachineInfo& m : d.machines()) {
                names.push_back(m.name);
                whole[m.name] = d.history(m.name);
                for (int r = 1; r <= m.revision; ++r)
                    exports[m.name].push_back(
                        profile::writeMachineText(d.loadMachine(m.name, r)));
            }
            QVERIFY(names.size() >= 2);
        }
        {
            // Read as it is (read-only: not upgraded), the history is the same.
            auto o = testOptions();
            o.readOnly = true;
            const db::Database d = db::Database::open(where, o);
            QCOMPARE(d.schemaVersion(), 6);
            QVERIFY(sameHistory(d.history("grinder-205", std::string("C022")), ofKey));
            QVERIFY(sameHistory(d.history("grinder-205", std::nullopt, 3), lastThree));
        }
        db::Database d = db::Database::open(where, testOptions());
        QCOMPARE(d.openReport().fromVersion, 6);
        QCOMPARE(d.schemaVersion(), db::latestSchemaVersion());
        QCOMPARE(d.audit(1).front().detail,
                 "schema version 6 -> " + std::to_string(db::latestSchemaVersion()));
        QCOMPARE(indexesOf(where), std::string(onPostgres() ? "changes_history changes_pkey revisions_pkey"
                                                            : "changes_history"));
        QVERIFY(sameHistory(d.history("grinder-205", std::string("C022")), ofKey));
        QVERIFY(sameHistory(d.history("grinder-205", std::nullopt, 3), lastThree));
        const auto revisionsNow = d.revisions("grinder-205");
        QCOMPARE(revisionsNow.size(), revisions.size());
        for (std::size_t i = 0; i < revisions.size(); ++i) {
            QCOMPARE(revisionsNow[i].revision, revisions[i].revision);
            QCOMPARE(revisionsNow[i].author, revisions[i].author);
            QCOMPARE(revisionsNow[i].at, revisions[i].at);
            QCOMPARE(revisionsNow[i].summary, revisions[i].summary);
            QCOMPARE(revisionsNow[i].changeCount, revisions[i].changeCount);
        }
        for (const std::string& name : names) {
            QVERIFY2(sameHistory(d.history(name), whole[name]), name.c_str());
            const int last = d.machine(name)->revision;
            QCOMPARE(static_cast<std::size_t>(last), exports[name].size());
            for (int r = 1; r <= last; ++r)
                QCOMPARE(profile::writeMachineText(d.loadMachine(name, r)),
                         exports[name][static_cast<std::size_t>(r - 1)]);
        }
        QVERIFY(d.checkIntegrity().empty());
        // A new revision writes its author and time into its changes.
        db::Edit e;
        e.c[22] = 1500;
        d.applyEdit("grinder-205", e, by("Сидоров"));
        const auto now = d.history("grinder-205", std::string("C022"));
        QCOMPARE(now.size(), ofKey.size() + 1);
        QCOMPARE(now[0].revision, 27);
        QCOMPARE(now[0].author, std::string("Сидоров"));
        QCOMPARE(now[0].at, d.revisions("grinder-205").front().at);
        QVERIFY(sameHistory(std::vector(now.begin() + 1, now.end()), ofKey));
        QVERIFY(d.checkIntegrity().empty());
        QCOMPARE(runSql(where, "UPDATE changes SET author = 'X' WHERE revision = 5 AND key = 'C022' "
                               "AND machine_id = (SELECT id FROM machines WHERE name = 'grinder-205')"),
                 std::string());
        using K = db::IntegrityProblem::Kind;
        const auto problems = d.checkIntegrity();
        QVERIFY(std::ranges::find(problems, db::IntegrityProblem{K::ChangeAuthors, {"grinder-205", "5", "1"}}) !=
                problems.end());
    }

    // A database of schema version 7 opened by this program: upgraded to
    // version 8, the history (of one constant, of the last revisions, whole)
    // the same as before and a new revision in it. On PostgreSQL the
    // history's index then holds every column the history reads and the
    // upgrade has vacuumed the table: the history of one constant can be
    // read from the index alone, no table page (an index-only scan with no
    // heap fetches; the planner is kept from a sequential or bitmap scan,
    // which it would choose for so small a table).
    void historyFromItsIndexFromVersion7() {
        QTemporaryDir dir;
        const db::Location where = testLocation(dir, "v7.db");
        std::vector<db::HistoryEntry> ofKey, lastThree, whole;
        {
            db::Database d = databaseOfVersion(where, 7, 20, [](int i) { return i % 2 ? "Петров" : "Иванов И.И."; });
            QCOMPARE(d.schemaVersion(), 7);
            ofKey = d.history("grinder-205", std::string("C022"));
            QCOMPARE(ofKey.size(), std::size_t(21));
            lastThree = d.history("grinder-205", std::nullopt, 3);
            whole = d.history("grinder-205");
        }
        const int latest = db::latestSchemaVersion();
        QVERIFY(latest >= 8);
        db::Database d = db::Database::open(where, testOptions());
        QCOMPARE(d.openReport().fromVersion, 7);
        QCOMPARE(d.schemaVersion(), latest);
        QCOMPARE(d.audit(1).front().detail, "schema version 7 -> " + std::to_string(latest));
        QCOMPARE(indexesOf(where), std::string(onPostgres() ? "changes_history changes_pkey revisions_pkey"
                                                            : "changes_history"));
        QVERIFY(sameHistory(d.history("grinder-205", std::string("C022")), ofKey));
        QVERIFY(sameHistory(d.history("grinder-205", std::nullopt, 3), lastThree));
        QVERIFY(sameHistory(d.history("grinder-205"), whole));
        QVERIFY(d.checkIntegrity().empty());
        if (onPostgres()) {
            const std::string def = psqlOutput(
                where, "SELECT indexdef FROM pg_indexes WHERE indexname = 'changes_history'");
            QVERIFY2(def.find("(machine_id, key, revision DESC, seq) INCLUDE (section, label, before, "
                              "after, author, at)") != std::string::npos,
                     def.c_str());
            const std::string plan = psqlOutput(
                where,
                "SET enable_seqscan = off; SET enable_bitmapscan = off; EXPLAIN (ANALYZE, COSTS OFF, "
                "TIMING OFF, SUMMARY OFF) SELECT c.revision, c.author, c.at, c.section, c.key, "
                "c.label, c.before, c.after FROM changes c WHERE c.machine_id = (SELECT id FROM "
                "machines WHERE name = 'grinder-205') AND c.revision > 0 AND c.key = 'C022' ORDER "
                "BY c.revision DESC, c.seq");
            QVERIFY2(plan.find("Index Only Scan using changes_history on changes") != std::string::npos,
                     plan.c_str());
            QVERIFY2(plan.find("Heap Fetches: 0") != std::string::npos, plan.c_str());
            QVERIFY2(plan.find("Sort") == std::string::npos, plan.c_str());
            // Autovacuum keeps the newest changes all-visible too: after
            // every 1000 written (PostgreSQL 13 on), not after a fifth of
            // the table.
            const std::string options = psqlOutput(
                where, "SELECT current_setting('server_version_num')::int >= 130000, "
                       "coalesce(array_to_string(reloptions, ' '), '') FROM pg_class WHERE "
                       "relname = 'changes'");
            QVERIFY2(options.rfind("f|", 0) == 0 ||
                         options == "t|autovacuum_vacuum_insert_threshold=1000 "
                                    "autovacuum_vacuum_insert_scale_factor=0\n",
                     options.c_str());
        }
        db::Edit e;
        e.c[22] = 1500;
        d.applyEdit("grinder-205", e, by("Сидоров"));
        const auto now = d.history("grinder-205", std::string("C022"));
        QCOMPARE(now.size(), ofKey.size() + 1);
        QCOMPARE(now[0].author, std::string("Сидоров"));
        QCOMPARE(*now[0].change.after, std::string("1500"));
        QVERIFY(sameHistory(std::vector(now.begin() + 1, now.end()), ofKey));
    }

    // A database of schema version 8 opened by this program: upgraded to
    // version 9, each item's whole history built into its row of
    // item_history from the recorded changes by the upgrade's SQL — Cyrillic
    // authors and labels, counted in bytes as the program counts them — so
    // the history of every item, of the last revisions and whole, reads as
    // before; a new revision is appended to its items' rows. The integrity
    // check compares those rows with the changes: a row altered by SQL is
    // named; a row no longer in its form, or gone, leaves the history of its
    // item read from the changes themselves (PostgreSQL reads the history of
    // one item from its row).
    void itemHistoryFromVersion8() {
        QTemporaryDir dir;
        const db::Location where = testLocation(dir, "v8.db");
        std::map<std::string, std::vector<db::HistoryEntry>> items;
        std::vector<db::HistoryEntry> lastThree, whole;
        {
            db::Database d = databaseOfVersion(where, 8, 20, [](int i) { return i % 2 ? "Петров" : "Иванов И.И."; });
            QCOMPARE(d.schemaVersion(), 8);
            whole = d.history("grinder-205");
            lastThree = d.history("grinder-205", std::nullopt, 3);
            for (const db::HistoryEntry& e : whole)
                items[e.change.key];
            for (auto& [key, h] : items)
                h = d.history("grinder-205", key);
        }
        QVERIFY(items.size() >= 21); // C022 and R0 … R19 at least
        QCOMPARE(items.at("C022").size(), std::size_t(21));
        const int latest = db::latestSchemaVersion();
        QVERIFY(latest >= 9);
        db::Database d = db::Database::open(where, testOptions());
        QCOMPARE(d.openReport().fromVersion, 8);
        QCOMPARE(d.audit(1).front().detail, "schema version 8 -> " + std::to_string(latest));
        for (const auto& [key, h] : items)
            QVERIFY2(sameHistory(d.history("grinder-205", key), h), key.c_str());
        QVERIFY(sameHistory(d.history("grinder-205", std::nullopt, 3), lastThree));
        QVERIFY(sameHistory(d.history("grinder-205"), whole));
        QVERIFY(d.checkIntegrity().empty());

        db::Edit e;
        e.c[22] = 1500;
        d.applyEdit("grinder-205", e, by("Сидоров"));
        const auto now = d.history("grinder-205", std::string("C022"));
        QCOMPARE(now.size(), items.at("C022").size() + 1);
        QCOMPARE(now[0].author, std::string("Сидоров"));
        QCOMPARE(*now[0].change.after, std::string("1500"));
        QVERIFY(sameHistory(std::vector(now.begin() + 1, now.end()), items.at("C022")));
        QVERIFY(d.checkIntegrity().empty());

        // An entry of C022 cut off by SQL.
        QCOMPARE(runSql(where, "UPDATE item_history SET entries = substr(entries, 1, 10) WHERE key "
                               "= 'C022'"),
                 std::string());
        using K = db::IntegrityProblem::Kind;
        // (Both machines' rows of C022: the SQL names no machine.)
        QCOMPARE(d.checkIntegrity(),
                 std::vector<db::IntegrityProblem>({{K::ItemHistoryDiffers, {"grinder-205", "C022"}},
                                                    {K::ItemHistoryDiffers, {"training-lathe", "C022"}}}));
        QVERIFY(sameHistory(d.history("grinder-205", std::string("C022")), now));
        // The row of R3 gone: named as missing.
        QCOMPARE(runSql(where, "DELETE FROM item_history WHERE key = 'R3'"), std::string());
        const auto problems = d.checkIntegrity();
        QVERIFY2(std::ranges::find(problems, db::IntegrityProblem{K::ItemHistoryMissing, {"grinder-205", "R3"}}) !=
                     problems.end(),
                 integrityText(problems).c_str());
        QVERIFY(std::ranges::find(problems, db::IntegrityProblem{K::ItemHistoryDiffers, {"grinder-205", "R3"}}) ==
                problems.end());
        QVERIFY(sameHistory(d.history("grinder-205", std::string("R3")), items.at("R3")));
    }

    // The longest texts one change can carry — a setting's key of 64
    // characters, its values of 200 characters of four UTF-8 bytes each
    // before and after, an author of 256 bytes; a title of 120 such
    // characters — are written and read back as they were: on PostgreSQL
    // the history's index keeps them beside its key (schema version 8)
    // within its row limit.
    void longestChangeIsKept() {
        QTemporaryDir dir;
        db::Database d = db::Database::open(testLocation(dir, "long.db"), testOptions());
        std::mt19937 rng(8);
        const std::string key = "x" + std::string(63, 'k');
        const std::string first = wideText(rng, 200), second = wideText(rng, 200);
        const std::string title = wideText(rng, 120);
        std::string author;
        for (int i = 0; i < 128; ++i)
            author += "Ж";
        QCOMPARE(author.size(), std::size_t(256));
        db::Edit e;
        e.simulation[key] = first;
        d.applyEdit("grinder-205", e, by(author));
        e.simulation[key] = second;
        e.title = title;
        d.applyEdit("grinder-205", e, by(author));
        const auto h = d.history("grinder-205", key);
        QCOMPARE(h.size(), std::size_t(2));
        QCOMPARE(h[0].author, author);
        QCOMPARE(h[0].change.before, std::optional(first));
        QCOMPARE(h[0].change.after, std::optional(second));
        QVERIFY(!h[1].change.before);
        QCOMPARE(h[1].change.after, std::optional(first));
        const auto t = d.history("grinder-205", std::string("title"));
        QVERIFY(!t.empty());
        QCOMPARE(t[0].author, author);
        QCOMPARE(t[0].change.after, std::optional(title));
        const MachineProfile p = d.loadMachine("grinder-205");
        QCOMPARE(p.title, title);
        QCOMPARE(p.simulation.find(key), std::optional(second));
        QVERIFY(d.checkIntegrity().empty());
    }

    // A program's text changed outside K528 Studio (SQL) no longer matches
    // its SHA-256: loading says so, on either backend (PostgreSQL compares
    // them on the server, over the text's UTF-8 bytes as the client hashes).
    void alteredProgramIsDetected() {
        QTemporaryDir dir;
        const db::Location where = testLocation(dir, "altered.db");
        { db::Database d = db::Database::open(where, testOptions()); }
        // Written consistently (text and digest): loaded as it is, Cyrillic too.
        const std::string text = "% Проверка\nN1 G01 X10\n";
        QCOMPARE(runSql(where, "UPDATE program_revisions SET text = '" + text + "', sha256 = '" +
                                   db::sha256Hex(text) + "' WHERE number = 11"),
                 std::string());
        {
            db::Database d = db::Database::open(where, testOptions());
            QCOMPARE(d.loadMachine("grinder-205").programs.at(11), text);
        }
        QCOMPARE(runSql(where, "UPDATE program_revisions SET text = replace(text, 'X10', 'X11') "
                               "WHERE number = 11"),
                 std::string());
        db::Database d = db::Database::open(where, testOptions());
        try {
            d.loadMachine("grinder-205");
            QFAIL("an altered program was loaded");
        } catch (const db::Error& e) {
            QCOMPARE(e.kind(), db::ErrorKind::Corrupt);
            QVERIFY2(std::string(e.what()).find("program L11") != std::string::npos, e.what());
            QVERIFY2(std::string(e.what()).find("SHA-256") != std::string::npos, e.what());
        }
        QVERIFY(d.loadMachine("training-lathe") == profile::builtin("training-lathe"));
    }

    // A write the machine's rules reject is said by the database's catalog
    // in either language, the machine named once; the findings follow a line
    // each, said by their own ids.
    void rejectionsAreSaidByTheCatalog() {
        QTemporaryDir dir;
        db::Database d = db::Database::open(testLocation(dir, "rejected.db"), testOptions());
        try {
            d.applyEdit("grinder-205", editC(69, 1), by("x")); // both encoders on channel 1
            QFAIL("a cross-check error was written");
        } catch (const db::ValidationError& v) {
            QCOMPARE(v.textId(), std::string("rejected.error"));
            QCOMPARE(v.head(db::Lang::En), std::string("machine grinder-205: rejected, nothing was written (1 error):"));
            QCOMPARE(v.head(db::Lang::Ru), std::string("станок grinder-205: отклонено, ничего не записано (ошибок: 1):"));
            QCOMPARE(v.findings().at(0).problem.id, std::string("check.encoders-channel"));
            const std::string ru = v.text(db::Lang::Ru);
            QVERIFY2(ru.find("\n  error [M37] C017,C069: Оба ДОС подключены к одному каналу 1") != std::string::npos,
                     ru.c_str());
            QVERIFY2(!hasEnglishSentence(QString::fromStdString(ru), false), ru.c_str());
            QCOMPARE(std::string(v.what()), v.text(db::Lang::En));
        }
        db::Edit e;
        e.simulation["Tilte"] = "oops"; // not a key at all
        try {
            d.applyEdit("training-lathe", e, by("x"));
            QFAIL("a bad simulation key was kept");
        } catch (const db::ValidationError& v) {
            QVERIFY(v.findings().empty());
            QCOMPARE(v.textId(), std::string("rejected.problem"));
            const QString ru = QString::fromStdString(v.text(db::Lang::Ru));
            const QString en = QString::fromStdString(v.text(db::Lang::En));
            QVERIFY2(ru.startsWith(QStringLiteral("станок training-lathe: отклонено, ничего не записано: ")) &&
                         ru.count(QStringLiteral("станок")) == 1 && !hasEnglishSentence(ru, false),
                     qPrintable(ru));
            QVERIFY2(en.startsWith("machine training-lathe: rejected, nothing was written: ") &&
                         en.count("machine") == 1 && en.contains("Tilte"),
                     qPrintable(en));
            QCOMPARE(en, QString::fromUtf8(v.what()));
        }
        QCOMPARE(d.machine("grinder-205")->revision, 1);
        QCOMPARE(d.machine("training-lathe")->revision, 1);
    }

    // A write to a database this process may only read, and a role refusal,
    // are said by the catalog: the refusal's id holding the reason's (the
    // action's and the role's), whole in either language; the server's words
    // stay out of the texts (what() keeps them for a log).
    void refusalsAreSaidByTheCatalog() {
        QTemporaryDir dir;
        const db::Location where = testLocation(dir, "read-only.db");
        const std::string path = where.text();
        { db::Database::open(where, testOptions()); }
        db::OpenOptions o = testOptions();
        o.readOnly = true;
        db::Database d = db::Database::open(where, o);
        try {
            d.applyEdit("grinder-205", editC(22, 2133), by("x"));
            QFAIL("a read-only database was written");
        } catch (const db::ReadOnlyError& e) {
            QCOMPARE(e.textId(), std::string("read-only.write"));
            QCOMPARE(e.catalogText().within.size(), std::size_t(1));
            QCOMPARE(e.catalogText().within[0].id, std::string("read-only.requested"));
            QCOMPARE(e.text(db::Lang::Ru),
                     "база данных доступна только для чтения: " + path + " (открыта только для чтения); ничего не записано");
            QCOMPARE(e.text(db::Lang::En), "the database is read-only: " + path + " (opened read-only); nothing was written");
            QCOMPARE(std::string(e.what()), e.text(db::Lang::En));
        }
        QCOMPARE(db::readOnlyReasonText(db::ReadOnlyReason::Folder, db::Lang::Ru),
                 std::string("нет права создавать файлы в её папке"));
        // Every action and holder a refusal can name is a text of the catalog.
        const util::TextCatalog catalog = db::dbTexts();
        for (int a = 0; a <= int(db::DeniedAction::RecordStateTimes); ++a)
            for (int h = 0; h <= int(db::DeniedHolder::RoleAdmin); ++h)
                for (const std::string roles : {"k528_operator", ""}) {
                    const auto holder = db::DeniedHolder(h);
                    const db::DeniedError e =
                        holder == db::DeniedHolder::Role
                            ? db::DeniedError("postgresql:///shop", db::DeniedAction(a), "k528_technologist", "ivanov",
                                              roles, "permission denied for table machines")
                            : db::DeniedError("postgresql:///shop", db::DeniedAction(a), holder, "ivanov", roles,
                                              "permission denied for table machines");
                    QCOMPARE(e.kind(), db::ErrorKind::Denied);
                    for (const db::ErrorText& part : e.catalogText().within)
                        QVERIFY2(catalog.find(part.id), part.id.c_str());
                    const QString ru = QString::fromStdString(e.text(db::Lang::Ru));
                    const std::string en = e.text(db::Lang::En);
                    QVERIFY2(ru.startsWith(QStringLiteral("база данных postgresql:///shop отказала пользователю ivanov: "
                                                          "для действия «")) &&
                                 ru.endsWith(QStringLiteral("; ничего не записано")) && !hasEnglishSentence(ru, false),
                             qPrintable(ru));
                    QVERIFY2(en.find("the database postgresql:///shop refused the user ivanov: ") == 0 &&
                                 en.find("for table") == std::string::npos,
                             en.c_str());
                    QCOMPARE(std::string(e.what()), en + " (the server said: permission denied for table machines)");
                    QCOMPARE(e.detail(), std::string("permission denied for table machines"));
                }
        const db::DeniedError release("postgresql:///shop", db::DeniedAction::ReleaseProgram, "k528_technologist",
                                      "ivanov", "k528_operator", "");
        QCOMPARE(release.role(), std::string("k528_technologist"));
        QCOMPARE(release.text(db::Lang::Ru),
                 std::string("база данных postgresql:///shop отказала пользователю ivanov: для действия «выпуск "
                             "программы» требуется роль k528_technologist; у пользователя: k528_operator; ничего не "
                             "записано"));
        QCOMPARE(release.text(db::Lang::En),
                 std::string("the database postgresql:///shop refused the user ivanov: releasing a program needs the "
                             "role k528_technologist; the user has k528_operator; nothing was written"));
        const db::DeniedError grant("postgresql:///shop", db::DeniedAction::GrantRole, db::DeniedHolder::RoleAdmin,
                                    "ivanov", "", "");
        QCOMPARE(grant.role(), std::string());
        QCOMPARE(grant.text(db::Lang::En),
                 std::string("the database postgresql:///shop refused the user ivanov: granting a role needs the role's "
                             "admin (its creator, or CREATEROLE); the user has no K528 Studio role; nothing was written"));
    }

    // Stored rows that break their own rules (another program's SQL): said
    // by the catalog, the machine and the file first.
    void storedRowsThatBreakTheirRulesAreSaid() {
        QTemporaryDir dir;
        const db::Location where = testLocation(dir, "rows.db");
        { db::Database d = db::Database::open(where, testOptions()); }
        QCOMPARE(runSql(where, "DELETE FROM c_values WHERE number = 22 AND machine_id = "
                               "(SELECT id FROM machines WHERE name = 'grinder-205')"),
                 std::string());
        db::Database d = db::Database::open(where, testOptions());
        try {
            d.loadMachine("grinder-205");
            QFAIL("a machine with 151 C values was loaded");
        } catch (const db::Error& e) {
            QCOMPARE(e.kind(), db::ErrorKind::Corrupt);
            QCOMPARE(e.textId(), std::string("corrupt.c-count"));
            const QString ru = QString::fromStdString(e.text(db::Lang::Ru));
            QVERIFY2(ru.startsWith(QStringLiteral("станок grinder-205 в ")) &&
                         ru.endsWith(QStringLiteral(": хранится значений C-параметров: 151 из 152")) &&
                         !hasEnglishSentence(ru, false),
                     qPrintable(ru));
            QVERIFY2(std::string(e.what()).ends_with(": 151 of the 152 C-parameter values are stored"), e.what());
        }
        QVERIFY(d.loadMachine("training-lathe") == profile::builtin("training-lathe"));
    }

    void equalProfileWritesNothing() {
        QTemporaryDir dir;
        db::Database d = db::Database::open(testLocation(dir, "n.db"), testOptions());
        const auto auditBefore = d.audit().size();
        const auto r = d.saveMachine("grinder-205", d.loadMachine("grinder-205"), by("x"));
        QVERIFY(!r.changed);
        QCOMPARE(r.revision, 1);
        QCOMPARE(d.machine("grinder-205")->revision, 1);
        QCOMPARE(d.audit().size(), auditBefore);
        const auto r2 = d.applyEdit("grinder-205", editC(22, 2000), by("x"));
        QVERIFY(!r2.changed);
    }

    void saveWholeProfile() {
        QTemporaryDir dir;
        db::Database d = db::Database::open(testLocation(dir, "s.db"), testOptions());
        const MachineProfile old = d.loadMachine("training-lathe");
        MachineProfile p = randomMachine(7, "training-lathe");
        const auto r = d.saveMachine("training-lathe", p, by("техн."));
        QVERIFY(r.changed);
        QCOMPARE(r.revision, 2);
        std::vector<profile::Change> expected = profile::diff(old, p);
        // Programs are compared in full; the order row may follow.
        QVERIFY(r.changes.size() >= expected.size());
        for (std::size_t i = 0; i < expected.size(); ++i)
            QVERIFY(r.changes[i] == expected[i]);
        QVERIFY(d.loadMachine("training-lathe") == p);
        QVERIFY(d.loadMachine("training-lathe", 1) == old);
        QVERIFY(d.loadMachine("training-lathe", 2) == p);
    }

    void validationRejectsWholeAndWritesNothing() {
        QTemporaryDir dir;
        db::Database d = db::Database::open(testLocation(dir, "v.db"), testOptions());
        const auto auditBefore = d.audit().size();
        // A value outside its definition: never, even with allowErrors.
        db::WriteOptions allow = by("x");
        allow.allowErrors = true;
        for (bool allowErrors : {false, true}) {
            db::Edit e;
            e.c[22] = 2133;  // fine
            e.c[20] = 40000; // outside 1..32767
            db::WriteOptions o = by("x");
            o.allowErrors = allowErrors;
            try {
                d.applyEdit("grinder-205", e, o);
                QFAIL("an out-of-range value was written");
            } catch (const db::ValidationError& v) {
                QCOMPARE(v.findings().size(), std::size_t(1));
                QCOMPARE(*v.findings()[0].message, 13); // L/N of X
                QCOMPARE(v.findings()[0].subject, std::string("C020"));
                QVERIFY(std::string(v.what()).find("nothing was written") != std::string::npos);
            }
        }
        // A cross-check error: message 37, both encoders on one channel.
        try {
            d.applyEdit("grinder-205", editC(69, 1), by("x"));
            QFAIL("a cross-check error was written");
        } catch (const db::ValidationError& v) {
            QCOMPARE(v.findings().size(), std::size_t(1));
            QCOMPARE(*v.findings()[0].message, 37);
            QCOMPARE(v.findings()[0].cParams, (std::vector<int>{17, 69}));
        }
        // DAC limit below DAC max: message 6 (X).
        try {
            d.applyEdit("grinder-205", editC(28, 2000), by("x"));
            QFAIL("ПРЕДЕЛ ЦАП < МАКС.ЦАП was written");
        } catch (const db::ValidationError& v) {
            QCOMPARE(*v.findings()[0].message, 6);
        }
        // R232..R262 are read only; PLC texts at most 40 characters.
        db::Edit bad;
        bad.r[240] = 1;
        bad.plc[{catalog::PlcGroup::System, 1}] = std::string(41, 'x');
        QCOMPARE(errorKind([&] { d.applyEdit("grinder-205", bad, allow); }),
                 db::ErrorKind::Invalid);
        QCOMPARE(d.machine("grinder-205")->revision, 1);
        QCOMPARE(d.audit().size(), auditBefore);
        QVERIFY(d.loadMachine("grinder-205") == profile::builtin("grinder-205"));

        // Allowed on purpose (a training machine with a fault) ...
        const auto r = d.applyEdit("grinder-205", editC(69, 1), allow);
        QCOMPARE(r.revision, 2);
        QVERIFY(profile::hasErrors(r.findings));
        // ... after which other changes are not blocked by the known error,
        const auto r2 = d.applyEdit("grinder-205", editC(22, 2133), by("x"));
        QCOMPARE(r2.revision, 3);
        // but a new error still is.
        QCOMPARE(errorKind([&] { d.applyEdit("grinder-205", editC(70, 1), by("x")); }),
                 db::ErrorKind::Invalid);
        // Fixing the error is accepted.
        const auto r3 = d.applyEdit("grinder-205", editC(69, 3), by("x"));
        QVERIFY(!profile::hasErrors(r3.findings));
    }

    void createRenameRemove() {
        QTemporaryDir dir;
        db::Database d = db::Database::open(testLocation(dir, "c.db"), testOptions());
        MachineProfile p = profile::builtin("grinder-205");
        QCOMPARE(errorKind([&] { d.createMachine(p); }), db::ErrorKind::MachineExists);
        p.name = "Bad Name";
        QCOMPARE(errorKind([&] { d.createMachine(p); }), db::ErrorKind::Invalid);
        p.name = "grinder-2";
        const auto r = d.createMachine(p, by("Сидоров"));
        QCOMPARE(r.revision, 1);
        QCOMPARE(d.audit(1).front().action, std::string("create"));
        QVERIFY(d.loadMachine("grinder-2") == p);

        // Rename: history goes with the machine.
        d.applyEdit("grinder-2", editC(22, 2100), by("x"));
        MachineProfile q = d.loadMachine("grinder-2");
        q.name = "grinder-3";
        QCOMPARE(errorKind([&] {
                     MachineProfile clash = q;
                     clash.name = "training-lathe";
                     d.saveMachine("grinder-2", clash);
                 }),
                 db::ErrorKind::MachineExists);
        d.saveMachine("grinder-2", q, by("x"));
        QVERIFY(!d.hasMachine("grinder-2"));
        QCOMPARE(d.machine("grinder-3")->revision, 3);
        QCOMPARE(d.loadMachine("grinder-3", 1).name, std::string("grinder-2"));
        QCOMPARE(d.loadMachine("grinder-3", 3).name, std::string("grinder-3"));
        QCOMPARE(d.history("grinder-3", std::string("C022")).size(), std::size_t(2));

        d.removeMachine("grinder-3", by("x"));
        QVERIFY(!d.hasMachine("grinder-3"));
        QCOMPARE(d.audit(1).front().action, std::string("delete"));
        QCOMPARE(d.audit(1).front().machine, std::string("grinder-3"));
        try {
            d.loadMachine("grinder-3");
            QFAIL("a deleted machine loaded");
        } catch (const db::Error& e) {
            QCOMPARE(e.kind(), db::ErrorKind::NoMachine);
            QVERIFY2(std::string(e.what()).find("grinder-205, training-lathe") != std::string::npos,
                     e.what());
        }
        QVERIFY(d.checkIntegrity().empty());
    }

    // A bug of the database code itself, provoked from outside: another
    // program's trigger that skips every new machine row, so INSERT …
    // RETURNING id returns none. Said as the catalog's "internal" in either
    // language, our English detail kept for the report; nothing is written.
    void internalErrorIsSaidInBothLanguages() {
        QTemporaryDir dir;
        const db::Location where = testLocation(dir, "internal.db");
        db::Database d = db::Database::open(where, testOptions());
        const std::string skip =
            onPostgres() ? "CREATE FUNCTION skip_row() RETURNS trigger LANGUAGE plpgsql AS $$ BEGIN RETURN NULL; END $$; "
                           "CREATE TRIGGER skip_new BEFORE INSERT ON machines FOR EACH ROW EXECUTE FUNCTION skip_row();"
                         : "CREATE TRIGGER skip_new BEFORE INSERT ON machines BEGIN SELECT RAISE(IGNORE); END;";
        QCOMPARE(runSql(where, skip), std::string());
        MachineProfile p = profile::builtin("grinder-205");
        p.name = "grinder-2";
        try {
            d.createMachine(p, by("x"));
            QFAIL("a machine was created without its row");
        } catch (const db::Error& e) {
            QCOMPARE(e.kind(), db::ErrorKind::Sql);
            QCOMPARE(e.textId(), std::string("internal"));
            const QString ru = QString::fromStdString(e.text(db::Lang::Ru));
            const QString en = QString::fromStdString(e.text(db::Lang::En));
            QVERIFY2(ru.endsWith(QStringLiteral(
                         ": непредвиденная ошибка базы данных (пожалуйста, сообщите о ней): «the new machine's row has no id»")) &&
                         !hasEnglishSentence(ru, false),
                     qPrintable(ru));
            QVERIFY2(en.endsWith(": an unexpected database error (please report it): the new machine's row has no id"),
                     qPrintable(en));
            QCOMPARE(en, QString::fromUtf8(e.what()));
            QVERIFY2(!e.at().empty() && en.startsWith(QString::fromStdString(e.at() + ": ")), qPrintable(en));
        }
        QVERIFY(!d.hasMachine("grinder-2"));
        QCOMPARE(d.machines().size(), std::size_t(2));
    }

    // What another program left in a database, said by the catalog in either
    // language with no English sentence of ours in the Russian: a value of a
    // type we never store — SQLite's columns take any (a blob where the meta
    // table keeps texts, met by a copy of the database), PostgreSQL's only
    // after their type was changed (a text where the revision belongs, met
    // by reading the machines) — and, SQLite only, a file whose header
    // SQLite cannot read (its bytes after the magic overwritten in a copy).
    void corruptDataIsSaidInBothLanguages() {
        QTemporaryDir dir;
        const db::Location where = testLocation(dir, "corrupt.db");
        db::Database d = db::Database::open(where, testOptions());
        const auto check = [](const db::Error& e, const char* id, const QString& ru, const QString& en) {
            QCOMPARE(e.kind(), db::ErrorKind::Corrupt);
            QCOMPARE(e.textId(), std::string(id));
            const QString saidRu = QString::fromStdString(e.text(db::Lang::Ru));
            const QString saidEn = QString::fromStdString(e.text(db::Lang::En));
            QVERIFY2(saidRu.contains(ru) && !hasEnglishSentence(saidRu, false), qPrintable(saidRu));
            QVERIFY2(saidEn.contains(en), qPrintable(saidEn));
            QCOMPARE(saidEn, QString::fromUtf8(e.what()));
        };
        if (onPostgres()) {
            QCOMPARE(runSql(where, "ALTER TABLE machines DROP CONSTRAINT machines_revision_check; "
                                   "ALTER TABLE machines ALTER COLUMN revision TYPE text USING 'first'"),
                     std::string());
            try {
                // A new connection: the old one's prepared statements keep the old type.
                db::Database::open(where, testOptions()).machines();
                QFAIL("a revision that is no number was read");
            } catch (const db::Error& e) {
                check(e, "corrupt.column-integer",
                      QStringLiteral("столбец revision содержит значение там, где должно быть целое число: «first»"),
                      QStringLiteral("column revision holds a value where an integer belongs: first"));
            }
            return;
        }
        QCOMPARE(runSql(where, "UPDATE meta SET value = x'00ff' WHERE key = 'created_at'"), std::string());
        try {
            d.copyTo(testLocation(dir, "copy.db"));
            QFAIL("a blob was copied");
        } catch (const db::Error& e) {
            check(e, "corrupt.column-type",
                  QStringLiteral("столбец value содержит значение, которое не является ни целым числом, ни текстом "
                                 "(запрос «SELECT * FROM meta ORDER BY "),
                  QStringLiteral("column value holds a value that is neither an integer nor a text (query: "
                                 "SELECT * FROM meta ORDER BY "));
        }

        std::string bytes = fileBytes(where.file());
        for (std::size_t i = 16; i < 24; ++i)
            bytes[i] = '\xa5'; // page size, format versions, reserved space: none SQLite accepts
        const fs::path header = tempPath(dir, "header.db");
        writeBytes(header, bytes);
        try {
            db::Database::open(db::Location(header), testOptions());
            QFAIL("a file with a broken header was opened");
        } catch (const db::Error& e) {
            check(e, "open.not-database", QStringLiteral("файл не читается как база данных (SQLite: «"),
                  QStringLiteral("cannot be read as a database ("));
        }
        QVERIFY(fileBytes(header) == bytes);
    }

    void staleWriterIsRefused() {
        QTemporaryDir dir;
        db::Database d = db::Database::open(testLocation(dir, "x.db"), testOptions());
        db::WriteOptions o = by("desk");
        o.expectedRevision = 1;
        MachineProfile p = d.loadMachine("grinder-205");
        d.applyEdit("grinder-205", editC(22, 2100), by("other"));
        p.setC(23, 4100);
        QCOMPARE(errorKind([&] { d.saveMachine("grinder-205", p, o); }), db::ErrorKind::Conflict);
        o.expectedRevision = 2;
        p = d.loadMachine("grinder-205");
        p.setC(23, 4100);
        QCOMPARE(d.saveMachine("grinder-205", p, o).revision, 3);
    }

    // Every revision of a long random history is rebuilt exactly, and diffs of
    // revisions are the diffs of what was saved.
    void revisionsRebuildExactly() {
        QTemporaryDir dir;
        db::Database d = db::Database::open(testLocation(dir, "r.db"), testOptions());
        std::mt19937 rng(2024);
        MachineProfile p = randomMachine(3, "lathe-7");
        for (int n = 20; n < 40; ++n)
            p.programs.erase(n);
        std::vector<MachineProfile> saved{MachineProfile{}, p};
        d.createMachine(p, by("a"));
        for (int i = 0; i < 60; ++i) {
            const int steps = 1 + static_cast<int>(rng() % 3);
            for (int s = 0; s < steps; ++s)
                mutate(p, rng);
            if (i == 30) {
                p.name = "lathe-8"; // renamed half way
                d.saveMachine("lathe-7", p, by("b"));
            } else {
                const auto r = d.saveMachine(p.name, p, by("b"));
                if (!r.changed)
                    continue;
            }
            saved.push_back(p);
        }
        const int last = static_cast<int>(saved.size()) - 1;
        QCOMPARE(d.machine("lathe-8")->revision, last);
        QVERIFY(last > 50);
        for (int r = 1; r <= last; ++r) {
            const MachineProfile got = d.loadMachine("lathe-8", r);
            if (!(got == saved[static_cast<std::size_t>(r)]))
                QFAIL(("revision " + std::to_string(r) + " differs:\n" +
                       profile::formatDiff(profile::diff(saved[static_cast<std::size_t>(r)], got)))
                          .c_str());
        }
        QVERIFY(d.loadMachine("lathe-8") == saved.back());
        // A reorder of the settings is recorded, not lost.
        bool reorderSeen = false;
        for (const auto& h : d.history("lathe-8"))
            reorderSeen = reorderSeen || h.change.key == "(order)";
        QVERIFY(reorderSeen);
        for (int a : {1, 10, 31}) {
            const auto changes =
                profile::diff(d.loadMachine("lathe-8", a), d.loadMachine("lathe-8", last));
            QVERIFY(changes == profile::diff(saved[static_cast<std::size_t>(a)], saved.back()));
        }
        QCOMPARE(errorKind([&] { d.loadMachine("lathe-8", 0); }), db::ErrorKind::NoRevision);
        QCOMPARE(errorKind([&] { d.loadMachine("lathe-8", last + 1); }), db::ErrorKind::NoRevision);
    }

    void programRevisionsAndChecksums() {
        QTemporaryDir dir;
        db::Database d = db::Database::open(testLocation(dir, "p.db"), testOptions());
        MachineProfile p = d.loadMachine("grinder-205");
        const std::string v1 = p.programs.at(11);
        p.programs[11] = v1 + "N4 M30\n";
        d.saveMachine("grinder-205", p, by("a"));
        p.programs.erase(11);
        d.saveMachine("grinder-205", p, by("a"));
        const auto h = d.programHistory("grinder-205", 11);
        QCOMPARE(h.size(), std::size_t(3));
        QCOMPARE(h[0].revision, 3);
        QVERIFY(!h[0].text && !h[0].sha256); // deleted
        QCOMPARE(*h[1].text, v1 + "N4 M30\n");
        QCOMPARE(*h[1].sha256, db::sha256Hex(v1 + "N4 M30\n"));
        QCOMPARE(*h[2].text, v1);
        QCOMPARE(*d.programText("grinder-205", 11, 1), v1);
        QVERIFY(!d.programText("grinder-205", 11, 3));
        // The change rows of programs carry the checksums.
        const auto hc = d.history("grinder-205", std::string("L11"));
        QCOMPARE(*hc[1].change.before, db::sha256Hex(v1));
        QCOMPARE(*hc[1].change.after, db::sha256Hex(v1 + "N4 M30\n"));
        // C143 names L11, which is gone: a warning (message 45), accepted.
        QVERIFY(!profile::hasErrors(profile::validate(d.loadMachine("grinder-205"))));
    }

    void explanations() {
        const MachineProfile g = profile::builtin("grinder-205");
        using db::Lang;
        QCOMPARE(db::explainCValue(g, 40, Lang::Ru), std::string("= 5000 мм/мин"));
        QCOMPARE(db::explainCValue(g, 40, Lang::En), std::string("= 5000 mm/min"));
        QCOMPARE(db::explainCValue(g, 29, Lang::Ru), std::string("= 10 В"));
        QCOMPARE(db::explainCValue(g, 28, Lang::En), std::string("= 11.7 V"));
        QCOMPARE(db::explainCValue(g, 17, Lang::Ru), std::string("1-й модуль СР34.23, канал 1"));
        QCOMPARE(db::explainCValue(g, 69, Lang::En), std::string("CP34.23 module 2, channel 1"));
        QCOMPARE(db::explainCValue(g, 70, Lang::Ru), std::string("канал 2 модуля СМ32.03"));
        QCOMPARE(db::explainCValue(g, 143, Lang::Ru), std::string("L11 (ВЫХОД В ИСХОДНОЕ)"));
        QCOMPARE(db::explainCValue(g, 144, Lang::Ru), std::string("цикл не задан"));
        QCOMPARE(db::explainCValue(g, 107, Lang::Ru), std::string("Готовность привода оси"));
        QCOMPARE(db::explainCValue(g, 114, Lang::Ru),
                 std::string("Стирание остатка пути – сигнал 4 (от ПАК «размер»)"));
        QCOMPARE(db::explainCValue(g, 119, Lang::En), std::string("input not used"));
        QCOMPARE(db::explainCValue(g, 47, Lang::Ru), std::string("= 40.000 мм на диаметр"));
        QCOMPARE(db::explainCValue(g, 99, Lang::Ru), std::string("= 200.000 мм"));
        QCOMPARE(db::explainCValue(g, 19, Lang::Ru),
                 std::string("L/N = 1/2: 0.0005 мм на импульс ДОС"));
        QCOMPARE(db::explainCValue(g, 30, Lang::Ru), std::string("= 0.5 мм"));
        QCOMPARE(db::explainCValue(g, 141, Lang::Ru), std::string("= 50 %"));
        QCOMPARE(db::explainCValue(g, 21, Lang::En), std::string("= 2.5 s"));
        QCOMPARE(db::explainCValue(g, 1, Lang::Ru), std::string("да"));
        // УСКОРЕНИЕ 1 of Ж: 2000 = 0.078 m/s², 1.07 s to 5000 mm/min.
        QCOMPARE(db::explainCValue(g, 22, Lang::En),
                 std::string("= 0.0781 m/s²; run-up to F AUTO RAPID in 1067 ms"));
        MachineProfile h = g;
        h.programs.erase(11);
        QCOMPARE(db::explainCValue(h, 143, Lang::Ru),
                 std::string("L11: программы нет (сообщение 45)"));
        QCOMPARE(db::programTitle("%L14 (ПРАВКА КРУГА)\nN1 G0\n"), std::string("ПРАВКА КРУГА"));
        QCOMPARE(db::programTitle("N1 G0 (x)\n"), std::string());
    }

    void defaultLocation() {
        const QByteArray oldDb = qgetenv("K528_DB"), oldXdg = qgetenv("XDG_DATA_HOME"),
                         oldHome = qgetenv("HOME");
        qputenv("K528_DB", "/data/shop.db");
        QCOMPARE(db::defaultDatabasePath(), fs::path("/data/shop.db"));
        qunsetenv("K528_DB");
        qputenv("XDG_DATA_HOME", "/xdg");
        QCOMPARE(db::defaultDatabasePath(), fs::path("/xdg/k528studio/k528.db"));
        qunsetenv("XDG_DATA_HOME");
        qputenv("HOME", "/home/ivan");
        QCOMPARE(db::defaultDatabasePath(), fs::path("/home/ivan/.local/share/k528studio/k528.db"));
        qputenv("XDG_DATA_HOME", "relative/path"); // not absolute: ignored (XDG spec)
        QCOMPARE(db::defaultDatabasePath(), fs::path("/home/ivan/.local/share/k528studio/k528.db"));
        oldDb.isNull() ? qunsetenv("K528_DB") : qputenv("K528_DB", oldDb);
        oldXdg.isNull() ? qunsetenv("XDG_DATA_HOME") : qputenv("XDG_DATA_HOME", oldXdg);
        oldHome.isNull() ? qunsetenv("HOME") : qputenv("HOME", oldHome);
    }

    // A location is a path, sqlite:PATH or a libpq URI; never a password.
    void locations() {
        using db::Location;
        QVERIFY(Location::parse("/srv/k528.db") == Location(fs::path("/srv/k528.db")));
        QVERIFY(Location::parse("sqlite:/srv/k528.db") == Location(fs::path("/srv/k528.db")));
        QVERIFY(Location::parse("sqlite:///srv/k528.db") == Location(fs::path("/srv/k528.db")));
        QVERIFY(Location::parse("shop.db").isFile());
        const Location pg = Location::parse("postgresql://k528@db.shop/k528?sslmode=require");
        QCOMPARE(pg.backend(), db::Backend::Postgres);
        QCOMPARE(pg.text(), std::string("postgresql://k528@db.shop/k528?sslmode=require"));
        QCOMPARE(Location::parse("postgresql://").backend(), db::Backend::Postgres);
        QCOMPARE(Location::parse("postgres://host/db").backend(), db::Backend::Postgres);
        for (const char* bad : {"postgresql://k528:secret@db.shop/k528",
                                "postgresql://db.shop/k528?sslmode=require&password=secret",
                                "mysql://db.shop/k528", "", "sqlite:"}) {
            try {
                Location::parse(bad);
                QFAIL(bad);
            } catch (const db::Error& e) {
                QCOMPARE(e.kind(), db::ErrorKind::Invalid);
                if (std::string(bad).find("secret") != std::string::npos)
                    QVERIFY2(std::string(e.what()).find(".pgpass") != std::string::npos, e.what());
            }
        }
        const QByteArray oldDb = qgetenv("K528_DB");
        qputenv("K528_DB", "postgresql:///shop");
        QCOMPARE(db::defaultDatabaseLocation().backend(), db::Backend::Postgres);
        QVERIFY_THROWS_EXCEPTION(db::Error, db::defaultDatabasePath());
        oldDb.isNull() ? qunsetenv("K528_DB") : qputenv("K528_DB", oldDb);
    }

    // The engine's hook reads a server's machine as it reads a file's.
    void engineProfileHookOnTheServer() {
        if (!onPostgres())
            QSKIP("PostgreSQL only (SQLite: engineProfileHook)");
        QTemporaryDir dir;
        const db::Location where = testLocation(dir, "engine.db");
        QVERIFY_THROWS_EXCEPTION(db::Error, db::loadProfile("grinder-205", where)); // empty: no tables
        {
            db::Database d = db::Database::open(where, testOptions());
            d.applyEdit("grinder-205", editC(22, 2133), by("x"));
        }
        QCOMPARE(db::loadProfile("grinder-205", where).cValue(22), std::int64_t(2133));
        QVERIFY(db::loadProfile("training-lathe", where) == profile::builtin("training-lathe"));
    }

    // The engine's profile: the database's machine when it has one, else the
    // built-in or the file; a missing database is not created.
    void engineProfileHook() {
        K528_SQLITE_ONLY();
        QTemporaryDir dir;
        const fs::path p = tempPath(dir, "engine.db");
        QVERIFY(db::loadProfile("grinder-205", p) == profile::builtin("grinder-205"));
        QVERIFY(!fs::exists(p));
        {
            db::Database d = db::Database::open(p, testOptions());
            d.applyEdit("grinder-205", editC(22, 2133), by("x"));
            MachineProfile mine = profile::builtin("training-lathe");
            mine.name = "lathe-3";
            d.createMachine(mine, by("x"));
        }
        QCOMPARE(db::loadProfile("grinder-205", p).cValue(22), std::int64_t(2133));
        QCOMPARE(db::loadProfile("lathe-3", p).name, std::string("lathe-3"));
        const fs::path file = tempPath(dir, "m.k528m");
        profile::writeMachineFile(file, profile::builtin("training-lathe"));
        QVERIFY(db::loadProfile(file.string(), p) == profile::builtin("training-lathe"));
        QVERIFY_THROWS_EXCEPTION(profile::FileError, db::loadProfile("no-such-machine", p));
        // A damaged database is an error, not a silent fallback.
        std::string bytes = fileBytes(p);
        for (std::size_t i = 4096 * 2; i < bytes.size(); i += 4096)
            for (std::size_t j = 50; j < 400; ++j)
                bytes[i + j] = 'Z';
        writeBytes(p, bytes);
        QVERIFY_THROWS_EXCEPTION(db::Error, db::loadProfile("grinder-205", p));
    }
};

QTEST_APPLESS_MAIN(TestMachines)
#include "test_machines.moc"
