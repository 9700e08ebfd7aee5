// The shop's database, on SQLite and (db.shop.postgresql) on PostgreSQL:
// programs released and withdrawn, the transfer log, other sessions'
// revisions seen, a stale change refused naming who and when, the message
// history, a whole database copied between backends and back with identical
// exports, the same schema on both, PostgreSQL's roles refusing what they
// must; and the commands `k528 db release/withdraw/log/copy/roles`.
#include "cli_runner.h"
#include "db/database.h"
#include "db/message_log.h"
#include "db/sql.h"
#include "db/state_times.h"
#include "db/store.h"
#include "db_test_util.h"
#include "profile/builtin.h"
#include "profile/text_format.h"
#include "random_machine.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>
#include <random>

using namespace k528;
using namespace k528::testing;
namespace fs = std::filesystem;
using profile::MachineProfile;

namespace {

db::Edit editC(int n, std::int64_t v) {
    db::Edit e;
    e.c[n] = v;
    return e;
}

const db::ProgramRelease& releaseOf(const std::vector<db::ProgramRelease>& all, int number) {
    for (const auto& p : all)
        if (p.number == number)
            return p;
    qFatal("no program L%d", number);
}

// The author a write records: the one given, except where the server says
// who it is (a release's author on PostgreSQL).
std::string releaseAuthor(const db::Database& d, const std::string& given) {
    return d.backend() == db::Backend::Postgres ? d.sessionUser() : given;
}

db::TransferEntry pushEntry(const std::string& machine, int revision, const std::string& result) {
    db::TransferEntry t;
    t.machine = machine;
    t.revision = revision;
    t.controller = "/dev/ttyUSB0 address 1 (K528-05, id 5)";
    t.direction = "push";
    t.result = result;
    t.detail = result == "ok" ? "written and verified: C-parameters, program 11"
                              : "push stopped: new: C-parameters; as they were: program 11";
    t.items = {{"c", 0, "0badc0de", std::nullopt, "new"},
               {"program", 11, "1a2b3c4d", std::string(64, 'e'), result == "ok" ? "new" : "as-it-was"}};
    return t;
}

// Every machine at every revision as its machine file, the logs as text:
// what a copy must keep exactly.
std::string everything(const db::Database& d) {
    std::string s;
    for (const db::MachineInfo& m : d.machines()) {
        s += "== " + m.name + " " + m.createdAt + " " + m.changedAt + " " + m.changedBy + "\n";
        for (int r = 1; r <= m.revision; ++r)
            s += profile::writeMachineText(d.loadMachine(m.name, r));
        for (const db::RevisionInfo& r : d.revisions(m.name))
            s += std::to_string(r.revision) + " " + r.author + " " + r.at + " " + r.summary + "\n";
        for (const db::ProgramRelease& p : d.programReleases(m.name))
            for (const db::ReleaseEntry& e : d.releaseHistory(m.name, p.number))
                s += "release L" + std::to_string(e.number) + " " + std::to_string(e.revision) + " " +
                     e.author + " " + e.at + " " + e.note + (e.released ? " +" : " -") + "\n";
    }
    for (const db::AuditEntry& a : d.audit())
        s += std::to_string(a.id) + " " + a.at + " " + a.author + " " + a.action + " " + a.machine +
             " " + a.detail + "\n";
    for (const db::TransferEntry& t : d.transfers()) {
        s += std::to_string(t.id) + " " + t.at + " " + t.user + " " + t.host + " " + t.machine + " " +
             t.direction + " " + t.result + " " + t.detail + "\n";
        for (const db::TransferItem& i : t.items)
            s += "  " + i.kind + std::to_string(i.number) + " " + i.crc32 + " " + i.state + "\n";
    }
    db::Database& w = const_cast<db::Database&>(d);
    db::MessageLog log(w);
    log.forEach({}, [&](const db::MessageRecord& m) {
        s += db::MessageLog::csvRow(m) + "\n";
        return true;
    });
    return s;
}

// The connection of a Database, for what only SQL can show.
db::sql::Connection& sqlOf(const db::Database& d) {
    return d.store().connection();
}

} // namespace

class TestShop : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        qputenv("K528_DB", QDir::temp().filePath("k528-shop-must-not-be-used.db").toUtf8());
    }

    void releaseAndWithdraw() {
        QTemporaryDir dir;
        db::Database d = db::Database::open(testLocation(dir, "r.db"), testOptions());
        auto all = d.programReleases("grinder-205");
        QCOMPARE(all.size(), std::size_t(3)); // L1, L11, L14
        for (const auto& p : all) {
            QCOMPARE(p.state, db::ProgramState::Draft);
            QVERIFY(!p.releasedRevision);
        }
        const std::size_t auditBefore = d.audit().size();
        const db::ReleaseEntry e = d.releaseProgram("grinder-205", 11, "проверена на станке", by("Петров"));
        QCOMPARE(e.number, 11);
        QCOMPARE(e.revision, 1);
        QVERIFY(e.released);
        QCOMPARE(e.note, std::string("проверена на станке"));
        QCOMPARE(e.author, releaseAuthor(d, "Петров"));
        QCOMPARE(e.sha256.size(), std::size_t(64));
        QCOMPARE(releaseOf(d.programReleases("grinder-205"), 11).state, db::ProgramState::Released);
        QCOMPARE(d.audit().size(), auditBefore + 1);
        QCOMPARE(d.audit(1).front().action, std::string("release"));
        // Released again: the same entry, nothing written.
        QVERIFY(d.releaseProgram("grinder-205", 11, "again", by("Петров")) == e);
        QCOMPARE(d.audit().size(), auditBefore + 1);

        // A change of the program makes a draft; the released version stays what a push takes.
        MachineProfile p = d.loadMachine("grinder-205");
        p.programs[11] += "N99 M02\n";
        QCOMPARE(d.saveMachine("grinder-205", p, by("Сидоров")).revision, 2);
        auto now = releaseOf(d.programReleases("grinder-205"), 11);
        QCOMPARE(now.state, db::ProgramState::Draft);
        QCOMPARE(now.revision, 2);
        QCOMPARE(*now.releasedRevision, 1);
        QCOMPARE(*now.releasedSha256, e.sha256);
        QCOMPARE(d.releaseProgram("grinder-205", 11, "", by("Петров")).revision, 2);
        QCOMPARE(releaseOf(d.programReleases("grinder-205"), 11).state, db::ProgramState::Released);

        const db::ReleaseEntry w = d.withdrawProgram("grinder-205", 11, "ошибка в N5", by("Петров"));
        QVERIFY(!w.released);
        QCOMPARE(w.revision, 2);
        now = releaseOf(d.programReleases("grinder-205"), 11);
        QCOMPARE(now.state, db::ProgramState::Withdrawn);
        QVERIFY(!now.releasedRevision);
        QCOMPARE(d.releaseHistory("grinder-205", 11).size(), std::size_t(3));
        QCOMPARE(d.audit(1).front().action, std::string("withdraw"));

        try {
            d.withdrawProgram("grinder-205", 11, "", by("Петров"));
            QFAIL("withdrawn twice");
        } catch (const db::Error& err) {
            QCOMPARE(err.kind(), db::ErrorKind::Invalid);
            QVERIFY2(std::string(err.what()).find("withdrawn already") != std::string::npos, err.what());
        }
        try {
            d.releaseProgram("grinder-205", 55, "", by("Петров"));
            QFAIL("released a program that does not exist");
        } catch (const db::Error& err) {
            QCOMPARE(err.kind(), db::ErrorKind::NoRevision);
            QVERIFY2(std::string(err.what()).find("no program L55") != std::string::npos, err.what());
        }
        // A released program deleted from the machine is no longer released.
        d.releaseProgram("grinder-205", 14, "", by("Петров"));
        p = d.loadMachine("grinder-205");
        p.programs.erase(14);
        d.saveMachine("grinder-205", p, by("Сидоров"));
        now = releaseOf(d.programReleases("grinder-205"), 14);
        QCOMPARE(now.revision, 0);
        QCOMPARE(now.state, db::ProgramState::Withdrawn);
        QVERIFY(!now.releasedRevision);
        QCOMPARE(integrityText(d), std::string());
    }

    void transferLog() {
        QTemporaryDir dir;
        auto o = testOptions();
        db::Database d = db::Database::open(testLocation(dir, "t.db"), o);
        db::TransferEntry a = pushEntry("grinder-205", 1, "ok");
        a.user = "someone-else"; // PostgreSQL records its own user instead
        const db::TransferEntry stored = d.recordTransfer(a);
        QVERIFY(stored.id > 0);
        QCOMPARE(stored.user, d.backend() == db::Backend::Postgres ? d.sessionUser() : std::string("someone-else"));
        QVERIFY(!stored.host.empty());
        QVERIFY(!stored.at.empty());
        QCOMPARE(stored.items, a.items);
        QCOMPARE(stored.detail, a.detail);
        db::TransferEntry b = pushEntry("training-lathe", 1, "partial");
        b.at = "2030-01-02T03:04:05Z";
        d.recordTransfer(b);
        db::TransferEntry c;
        c.direction = "pull";
        c.result = "failed";
        c.machine = "grinder-205";
        c.controller = "tcp://10.0.0.5:502/1";
        c.detail = "the line does not answer";
        d.recordTransfer(c);
        QCOMPARE(d.transfers().size(), std::size_t(3));
        QCOMPARE(d.transfers().front().direction, std::string("pull")); // newest first
        db::TransferFilter f;
        f.machine = "grinder-205";
        QCOMPARE(d.transfers(f).size(), std::size_t(2));
        f = {};
        f.since = "2030-01-01";
        QCOMPARE(d.transfers(f).size(), std::size_t(1));
        QCOMPARE(d.transfers(f).front().machine, std::string("training-lathe"));
        f = {};
        f.limit = 1;
        QCOMPARE(d.transfers(f).size(), std::size_t(1));
        db::TransferEntry bad = pushEntry("grinder-205", 1, "ok");
        bad.direction = "sideways";
        QVERIFY_THROWS_EXCEPTION(db::Error, d.recordTransfer(bad));
        QCOMPARE(d.transfers().size(), std::size_t(3));
    }

    // Two connections (two PCs): a change of one is seen by the other
    // without reading anything (PostgreSQL's NOTIFY names the machine;
    // SQLite's data_version says that something changed).
    void otherSessionsChangesAreSeen() {
        QTemporaryDir dir;
        const db::Location where = testLocation(dir, "n.db");
        db::Database a = db::Database::open(where, testOptions());
        db::Database b = db::Database::open(where, testOptions());
        std::vector<std::string> names;
        QVERIFY(!b.changedElsewhere(&names)); // starts watching
        QVERIFY(!a.changedElsewhere(&names));
        a.applyEdit("grinder-205", editC(22, 2133), by("Петров"));
        QVERIFY(!a.changedElsewhere(&names)); // its own change
        QVERIFY(b.changedElsewhere(&names));
        if (onPostgres())
            QCOMPARE(names, std::vector<std::string>{"grinder-205"});
        QVERIFY(!b.changedElsewhere(&names)); // once
        b.releaseProgram("training-lathe", 1, "", by("Иванов"));
        QVERIFY(a.changedElsewhere(&names));
        QVERIFY(!b.changedElsewhere(&names));
        QCOMPARE(b.machine("grinder-205")->revision, 2);
    }

    // A change based on an older revision than the current one is refused,
    // naming who made the newer one and when.
    void staleChangeNamesWhoAndWhen() {
        QTemporaryDir dir;
        const db::Location where = testLocation(dir, "s.db");
        db::Database a = db::Database::open(where, testOptions());
        db::Database b = db::Database::open(where, testOptions());
        MachineProfile mine = a.loadMachine("grinder-205");
        const int read = a.machine("grinder-205")->revision;
        b.applyEdit("grinder-205", editC(23, 1500), by("Сидоров"));
        const std::string at = b.machine("grinder-205")->changedAt;
        mine.setC(22, 2133);
        db::WriteOptions o = by("Петров");
        o.expectedRevision = read;
        try {
            a.saveMachine("grinder-205", mine, o);
            QFAIL("a stale change was written");
        } catch (const db::Error& e) {
            QCOMPARE(e.kind(), db::ErrorKind::Conflict);
            const std::string m = e.what();
            QVERIFY2(m.find("Сидоров") != std::string::npos && m.find(at) != std::string::npos, m.c_str());
        }
        QCOMPARE(a.loadMachine("grinder-205").cValue(22), profile::builtin("grinder-205").cValue(22));
        QCOMPARE(a.machine("grinder-205")->revision, 2);
    }

    // The message history on this backend: a run, raised, cleared and
    // acknowledged messages, search by code and by text in either case.
    void messageHistory() {
        QTemporaryDir dir;
        db::Database d = db::Database::open(testLocation(dir, "m.db"), testOptions());
        db::MessageLog log(d);
        const std::int64_t run = log.beginRun("grinder-205", 1715934600000, "Петров");
        std::vector<db::MessageEvent> ev;
        for (int i = 1; i <= 12; ++i) {
            db::MessageEvent e;
            e.seq = i;
            e.machineMs = i * 100;
            e.dayMs = 1715934600000 + i;
            e.message.source = i % 2 ? db::MessageSource::PlcAlarm : db::MessageSource::Positioner;
            e.message.number = i;
            e.message.text = i % 2 ? "Нет давления СОЖ" : "ПРЕВЫШЕНИЕ ОШИБКИ ПО ОСИ X";
            e.message.textEn = i % 2 ? "No coolant pressure" : "Following error X";
            ev.push_back(e);
        }
        db::MessageEvent cleared;
        cleared.kind = db::MessageEvent::Kind::Cleared;
        cleared.seq = 3;
        cleared.machineMs = 450;
        ev.push_back(cleared);
        db::MessageEvent ack;
        ack.kind = db::MessageEvent::Kind::Acknowledged;
        ack.seq = 3;
        ack.machineMs = 500;
        ack.dayMs = 1715934601000;
        ack.how = "esc";
        ev.push_back(ack);
        log.write(run, ev);
        QCOMPARE(log.count(), std::int64_t(12));
        db::MessageFilter f;
        f.search = "A03";
        QCOMPARE(log.count(f), std::int64_t(1));
        f.search = "a0";
        QCOMPARE(log.count(f), std::int64_t(5)); // A01, A03, A05, A07, A09
        f.search = "coolant";
        QCOMPARE(log.count(f), std::int64_t(6));
        f.search = "COOLANT";
        QCOMPARE(log.count(f), std::int64_t(6));
        f = {};
        f.unacknowledgedOnly = true;
        QCOMPARE(log.count(f), std::int64_t(11));
        const auto page = log.page({}, 0, 5);
        QCOMPARE(page.size(), std::size_t(5));
        QCOMPARE(page.front().seq, std::int64_t(12));
        const auto rest = log.page({}, page.back().id, 100); // the 7 older ones
        QCOMPARE(rest.size(), std::size_t(7));
        QCOMPARE(rest.front().seq, std::int64_t(7));
        const db::MessageRecord three = rest[4];
        QCOMPARE(three.seq, std::int64_t(3));
        QCOMPARE(*three.clearedMs, std::int64_t(450));
        QCOMPARE(three.ackHow, std::string("esc"));
        // A bad batch writes nothing.
        db::MessageEvent stray;
        stray.kind = db::MessageEvent::Kind::Cleared;
        stray.seq = 99;
        QVERIFY_THROWS_EXCEPTION(db::Error, log.write(run, std::vector<db::MessageEvent>{ev[0], stray}));
        QCOMPARE(log.count(), std::int64_t(12));
    }

    // SQLite -> this backend -> SQLite: every machine at every revision, the
    // releases, the audit log, the transfers and the message history are the
    // same; a second copy into a database that is not empty is refused and
    // changes nothing.
    void copyRoundTrip() {
        QTemporaryDir dir;
        const db::Location first(fs::path(dir.filePath("first.db").toStdString()));
        {
            db::Database d = db::Database::open(first, testOptions());
            std::mt19937 rng(528);
            d.createMachine(randomMachine(7, "big"), by("Иванов"));
            for (int i = 0; i < 20; ++i)
                d.applyEdit(i % 2 ? "big" : "grinder-205", editC(22, 1000 + i), by(i % 3 ? "Петров" : "Сидоров"));
            d.releaseProgram("grinder-205", 11, "в работу", by("Петров"));
            d.withdrawProgram("grinder-205", 11, "", by("Петров"));
            d.releaseProgram("big", 5, "", by("Петров"));
            d.recordTransfer(pushEntry("grinder-205", 21, "ok"));
            d.recordTransfer(pushEntry("big", 11, "partial"));
            db::MessageLog log(d);
            const auto run = log.beginRun("big", 1715934600000, "Петров");
            std::vector<db::MessageEvent> ev(3);
            for (int i = 0; i < 3; ++i) {
                ev[static_cast<std::size_t>(i)].seq = i + 1;
                ev[static_cast<std::size_t>(i)].message.number = i + 1;
                ev[static_cast<std::size_t>(i)].message.text = "Сообщение " + std::to_string(i);
            }
            log.write(run, ev);
        }
        const db::Location middle = onPostgres() ? testLocation(dir, "middle")
                                                 : db::Location(fs::path(dir.filePath("middle.db").toStdString()));
        const db::Location last(fs::path(dir.filePath("last.db").toStdString()));
        std::string before;
        {
            db::Database d = db::Database::open(first, testOptions());
            before = everything(d);
            const db::CopyReport r = d.copyTo(middle, testOptions());
            QCOMPARE(r.machines, std::int64_t(3));
            QCOMPARE(r.revisions, std::int64_t(23));
            QCOMPARE(r.releases, std::int64_t(3));
            QCOMPARE(r.transfers, std::int64_t(2));
            QCOMPARE(r.messages, std::int64_t(3));
        }
        if (onPostgres()) {
            // The copy leaves the planner its statistics: a copied shop's first
            // opens read one machine's rows by the index, not whole tables.
            const std::string text = middle.text();
            QProcess psql;
            psql.start("psql", {"-X", "-At", "-d", QString::fromStdString(text.substr(text.rfind('/') + 1)),
                                "-c", "SELECT count(*) FROM pg_class WHERE relname IN "
                                      "('c_values', 'r_values', 'changes', 'program_revisions') "
                                      "AND reltuples >= 0"}); // -1: never analysed
            QVERIFY(psql.waitForFinished(60000));
            QCOMPARE(QString::fromUtf8(psql.readAllStandardOutput()).trimmed(), QStringLiteral("4"));
        }
        {
            db::Database d = db::Database::open(middle, testOptions());
            QCOMPARE(everything(d), before);
            QCOMPARE(integrityText(d), std::string());
            d.copyTo(last, testOptions());
            // Writes go on after a copy: the ids continue.
            d.applyEdit("big", editC(22, 2222), by("Петров"));
            QVERIFY(d.recordTransfer(pushEntry("big", 12, "ok")).id > 2);
        }
        {
            db::Database d = db::Database::open(last, testOptions());
            QCOMPARE(everything(d), before);
            QCOMPARE(integrityText(d), std::string());
        }
        // Not into a database that holds something.
        db::Database d = db::Database::open(first, testOptions());
        const std::string middleNow = everything(db::Database::open(middle, testOptions()));
        try {
            d.copyTo(middle, testOptions());
            QFAIL("copied into a database that is not empty");
        } catch (const db::Error& e) {
            QCOMPARE(e.kind(), db::ErrorKind::Invalid);
            QVERIFY2(std::string(e.what()).find("not an empty database") != std::string::npos, e.what());
        }
        QCOMPARE(everything(db::Database::open(middle, testOptions())), middleNow);
    }

    // One schema: the same tables with the same columns in the same order on
    // both backends.
    void sameSchemaOnBothBackends() {
        if (!onPostgres())
            QSKIP("PostgreSQL only");
        QTemporaryDir dir;
        db::Database lite = db::Database::open(fs::path(dir.filePath("l.db").toStdString()), testOptions());
        db::Database pg = db::Database::open(testLocation(dir, "p"), testOptions());
        const auto columnsOf = [](db::sql::Connection& c, const std::string& sql) {
            std::vector<std::string> out;
            auto& q = c(sql);
            while (q.step())
                out.push_back(q.text(0) + "." + q.text(1));
            q.reset();
            return out;
        };
        const auto a = columnsOf(sqlOf(lite), "SELECT m.name, p.name FROM sqlite_schema m, pragma_table_info(m.name) p "
                                              "WHERE m.type IN ('table', 'view') AND m.name NOT LIKE 'sqlite%' "
                                              "ORDER BY m.name, p.cid");
        const auto b = columnsOf(sqlOf(pg), "SELECT table_name, column_name FROM information_schema.columns "
                                            "WHERE table_schema = current_schema() AND table_name <> 'k528_schema' "
                                            "ORDER BY table_name COLLATE \"C\", ordinal_position");
        QCOMPARE(b, a);
        QVERIFY(a.size() > 100);
    }

    // Roles set up on a database of schema version 8: after the upgrade to 9
    // (each item's history in a row of item_history, a new table) a
    // technologist still changes a machine — the upgrade gives the roles
    // the new table's rights — and a viewer reads the history from it.
    void rolesSetUpBeforeVersion9KeepTheirRights() {
        if (!onPostgres())
            QSKIP("PostgreSQL only");
        QTemporaryDir dir;
        const db::Location where = testLocation(dir, "roles8");
        const std::string dbName = where.uri().substr(where.uri().rfind('/') + 1);
        {
            auto o = testOptions();
            o.migrations = db::schemaMigrations().subspan(0, 8);
            db::Database owner = db::Database::open(where, o);
            QCOMPARE(owner.schemaVersion(), 8);
            // The roles as the program of version 8 set them up, its grants
            // without item_history: this program's name it, so a stand-in
            // table takes its grant and goes.
            sqlOf(owner).exec("CREATE TABLE item_history (stand_in INTEGER)");
            owner.setUpRoles();
            sqlOf(owner).exec("DROP TABLE item_history");
            const std::string password = qgetenv("PGPASSWORD").toStdString();
            for (const char* user : {"tech8", "view8"})
                sqlOf(owner).exec("DO $$ BEGIN IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = '" +
                                  std::string(user) + "') THEN CREATE ROLE " + user + " LOGIN PASSWORD '" +
                                  password + "'; END IF; END $$");
            owner.grantRole("tech8", "technologist");
            owner.grantRole("view8", "k528_viewer");
        }
        // Roles are the cluster's: the other tests' members lists stay as
        // they expect them, whatever this test ends with.
        struct Leave {
            db::Location where;
            ~Leave() {
                try {
                    db::Database owner = db::Database::open(where, testOptions());
                    sqlOf(owner).exec("REVOKE k528_technologist FROM tech8; REVOKE k528_viewer FROM view8");
                } catch (const db::Error&) {
                }
            }
        } leave{where};
        {
            db::Database owner = db::Database::open(where, testOptions());
            QCOMPARE(owner.openReport().fromVersion, 8);
            QVERIFY(owner.schemaVersion() >= 9);
        }
        const auto as = [&](const char* user) {
            return db::Database::open(db::Location::parse("postgresql://" + std::string(user) + "@/" + dbName),
                                      testOptions());
        };
        db::Database tech = as("tech8");
        const auto before = tech.history("grinder-205", std::string("C022"));
        QCOMPARE(tech.applyEdit("grinder-205", editC(22, 2133)).revision, 2);
        db::Database view = as("view8");
        const auto h = view.history("grinder-205", std::string("C022"));
        QCOMPARE(h.size(), before.size() + 1);
        QCOMPARE(h.front().author, std::string("tech8"));
        QCOMPARE(h.front().change.after, std::optional<std::string>("2133"));
        QCOMPARE(integrityText(view), std::string());
    }

    // PostgreSQL's roles: each may what it must and is refused the rest, with
    // a message naming the role needed; the transfer log's user is the
    // server's, whatever a client says.
    void rolesRefuseWhatTheyMust() {
        if (!onPostgres())
            QSKIP("PostgreSQL only");
        QTemporaryDir dir;
        const db::Location where = testLocation(dir, "roles");
        const std::string dbName = where.uri().substr(where.uri().rfind('/') + 1);
        db::Database owner = db::Database::open(where, testOptions());
        const auto roles = owner.setUpRoles();
        QCOMPARE(roles.size(), std::size_t(4));
        QCOMPARE(roles[3].role, std::string("k528_trainer"));
        const std::string password = qgetenv("PGPASSWORD").toStdString();
        for (const char* user : {"tech1", "oper1", "view1", "train1"})
            sqlOf(owner).exec("DO $$ BEGIN IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = '" +
                              std::string(user) + "') THEN CREATE ROLE " + user + " LOGIN PASSWORD '" +
                              password + "'; END IF; END $$");
        owner.grantRole("tech1", "technologist");
        owner.grantRole("oper1", "operator");
        owner.grantRole("view1", "k528_viewer");
        owner.grantRole("train1", "trainer");
        QCOMPARE(owner.roles()[2].members, std::vector<std::string>{"tech1"});
        const auto as = [&](const char* user) {
            return db::Database::open(db::Location::parse("postgresql://" + std::string(user) + "@/" + dbName),
                                      testOptions());
        };
        // The role a refusal names, and its message ("" when nothing was refused).
        const auto refusal = [](auto f) -> std::pair<std::string, std::string> {
            try {
                f();
            } catch (const db::DeniedError& e) {
                return {e.role(), e.what()};
            }
            return {};
        };
#define DENIED_FOR(call, needed)                                                                   \
    do {                                                                                           \
        const auto [role, message] = refusal([&] { call; });                                      \
        QVERIFY2(role == (needed) && message.find(needed) != std::string::npos,                     \
                 (role + ": " + message).c_str());                                                 \
    } while (false)
        {
            db::Database op = as("oper1");
            QCOMPARE(op.sessionUser(), std::string("oper1"));
            QVERIFY(op.mayActAs("k528_operator"));
            QVERIFY(!op.mayActAs("k528_technologist"));
            QVERIFY(op.loadMachine("grinder-205") == owner.loadMachine("grinder-205"));
            DENIED_FOR(op.applyEdit("grinder-205", editC(22, 2133), by("oper1")), "k528_technologist");
            {
                const auto [role, message] = refusal([&] { op.releaseProgram("grinder-205", 11); });
                // The refusal says which roles the user has.
                QVERIFY2(message.find("refused the user oper1: releasing a program needs the role "
                                      "k528_technologist; the user has k528_operator") != std::string::npos &&
                             message.find("; nothing was written (the server said: ") != std::string::npos,
                         message.c_str());
            }
            DENIED_FOR(op.releaseProgram("grinder-205", 11), "k528_technologist");
            DENIED_FOR(op.removeMachine("grinder-205"), "k528_technologist");
            {
                // The command line says the refusal in its language: the
                // action, the role it needs, the user's roles.
                const QString asOper = QString::fromStdString("postgresql://oper1@/" + dbName);
                CliResult r = runK528({"db", "set", "grinder-205", "C022=2133", "--db", asOper});
                QCOMPARE(r.exitCode, 2);
                QVERIFY2(r.err.contains(QStringLiteral("отказала пользователю oper1: для действия «изменение "
                                                       "станка» требуется роль k528_technologist; у пользователя: "
                                                       "k528_operator")) &&
                             r.err.contains(QStringLiteral("; ничего не записано")) &&
                             !hasEnglishSentence(r.err),
                         qPrintable(r.err));
                r = runK528({"db", "set", "grinder-205", "C022=2133", "--db", asOper, "--lang", "en"});
                QCOMPARE(r.exitCode, 2);
                QVERIFY2(r.err.contains("refused the user oper1: changing a machine needs the role "
                                        "k528_technologist; the user has k528_operator") &&
                             r.err.contains("; nothing was written") && !r.err.contains("the server said"),
                         qPrintable(r.err));
            }
            db::TransferEntry t = pushEntry("grinder-205", 1, "ok");
            t.user = "tech1"; // not a text anyone can type
            QCOMPARE(op.recordTransfer(t).user, std::string("oper1"));
            // Not even in SQL: row security keeps the server's user.
            try {
                sqlOf(op).exec("INSERT INTO transfers (at, db_user, host, machine, revision, controller, "
                               "direction, result, detail) VALUES ('x', 'tech1', 'h', 'm', 0, 'c', 'push', "
                               "'ok', '')");
                QFAIL("an operator wrote another user's transfer");
            } catch (const db::Error& e) {
                QCOMPARE(e.kind(), db::ErrorKind::Denied);
            }
            db::MessageLog log(op);
            const auto run = log.beginRun("grinder-205", 1715934600000);
            db::MessageEvent e;
            e.seq = 1;
            e.message.number = 5;
            e.message.text = "x";
            log.write(run, std::vector<db::MessageEvent>{e});
            QCOMPARE(log.count(), std::int64_t(1));
            // An operator's shop page keeps the machines' time in each state.
            db::addStateTimes(op, {{"grinder-205", "2026-12-06", "studio@pc1", "idle", 60000, {}}});
        }
        {
            db::Database view = as("view1");
            QVERIFY(!view.mayActAs("k528_operator"));
            QCOMPARE(view.transfers().size(), std::size_t(1));
            DENIED_FOR(view.recordTransfer(pushEntry("grinder-205", 1, "ok")), "k528_operator");
            DENIED_FOR(db::MessageLog(view).beginRun("grinder-205", 0), "k528_operator");
            DENIED_FOR(view.applyEdit("grinder-205", editC(22, 2133)), "k528_technologist");
            QCOMPARE(db::stateTimes(view, "2026-12-06").size(), std::size_t(1));
            DENIED_FOR(db::addStateTimes(view, {{"grinder-205", "2026-12-06", "studio@pc2", "idle", 1, {}}}),
                       "k528_operator");
        }
        {
            db::Database tech = as("tech1");
            QVERIFY(tech.mayActAs("k528_operator"));
            QCOMPARE(tech.applyEdit("grinder-205", editC(22, 2133)).revision, 2);
            QCOMPARE(tech.revisions("grinder-205").front().author, std::string("tech1"));
            QCOMPARE(tech.releaseProgram("grinder-205", 11, "", by("someone")).author, std::string("tech1"));
            QCOMPARE(tech.recordTransfer(pushEntry("grinder-205", 2, "ok")).user, std::string("tech1"));
            try {
                tech.setUpRoles();
                QFAIL("a technologist set up the roles");
            } catch (const db::DeniedError& e) {
                // Who may do it is no role's name: the catalog says who.
                QCOMPARE(e.holder(), db::DeniedHolder::TablesCreator);
                QCOMPARE(e.role(), std::string());
                QVERIFY2(std::string(e.what()).find("setting up the roles needs the owner of the database's tables "
                                                    "with CREATEROLE; the user has ") != std::string::npos,
                         e.what());
            }
        }
        {
            // The trainer's lock of the constants: only a trainer sets and
            // clears it; while set, nobody changes a constant.
            db::Edit lock;
            lock.simulation["constants.lock"] = "TM-21";
            db::Database tech = as("tech1");
            QVERIFY(!tech.mayActAs("k528_trainer"));
            DENIED_FOR(tech.applyEdit("grinder-205", lock), "k528_trainer");
            db::Database trainer = as("train1");
            QVERIFY(trainer.mayActAs("k528_technologist"));
            QVERIFY(trainer.mayActAs("k528_trainer"));
            const int locked = trainer.applyEdit("grinder-205", lock).revision;
            try {
                tech.applyEdit("grinder-205", editC(22, 2000));
                QFAIL("a constant changed while locked");
            } catch (const db::ValidationError& e) {
                QVERIFY2(std::string(e.what()).find("«TM-21»") != std::string::npos, e.what());
            }
            QCOMPARE(tech.machine("grinder-205")->revision, locked);
            db::Edit unlock;
            unlock.simulation["constants.lock"] = std::nullopt;
            DENIED_FOR(tech.applyEdit("grinder-205", unlock), "k528_trainer");
            QCOMPARE(trainer.applyEdit("grinder-205", unlock).revision, locked + 1);
            QCOMPARE(tech.applyEdit("grinder-205", editC(22, 2000)).revision, locked + 2);
        }
        QCOMPARE(integrityText(owner), std::string());
#undef DENIED_FOR
    }

    // The trainer's lock of the constants (setting constants.lock) holds for
    // `k528 db set` and `import` as for the studio: a constant is refused
    // naming the lock and the class, nothing written; other items may change;
    // unlocked, the constant is taken.
    void constantsLockRefusesDbSet() {
        QTemporaryDir dir;
        const QString where = QString::fromStdString(testLocation(dir, "lock.db").text());
        const auto db = [&](QStringList args) {
            args.prepend("db");
            args << "--db" << where;
            return runK528(args);
        };
        QCOMPARE(db({"init"}).exitCode, 0);
        auto r = db({"set", "grinder-205", "constants.lock=TM-21", "--author", "trainer"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString before = db({"export", "grinder-205"}).out;
        r = db({"set", "grinder-205", "C022=2133", "--lang", "en"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("locked by the trainer for the class «TM-21»")) &&
                     r.err.contains("constants.lock") && r.err.contains("C022") && r.err.contains("nothing was written"),
                 qPrintable(r.err));
        r = db({"set", "grinder-205", "C022=2133"}); // Russian by default
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("заблокированы преподавателем для группы «TM-21»")) &&
                     r.err.contains("constants.lock") && r.err.contains("C022") && r.err.contains("ничего не записано"),
                 qPrintable(r.err));
        r = db({"set", "grinder-205", "C022=2133", "--allow-errors"});
        QCOMPARE(r.exitCode, 1);
        // An import that changes a constant is refused the same way.
        const QString file = dir.filePath("g.k528m");
        {
            QFile f(file);
            QVERIFY(f.open(QIODevice::WriteOnly));
            QString changed = before;
            QVERIFY2(changed.contains("\nC022=2000 "), qPrintable(before.left(400)));
            changed.replace("\nC022=2000 ", "\nC022=2133 ");
            f.write(changed.toUtf8());
        }
        r = db({"import", file, "--replace"});
        QVERIFY2(r.exitCode != 0 && r.err.contains(QStringLiteral("«TM-21»")), qPrintable(r.out + r.err));
        QCOMPARE(db({"export", "grinder-205"}).out, before);
        // The K923 of `k528 panel` refuses F5 (РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ) as the studio's.
        r = runK528({"panel", "--profile", "grinder-205", "--db", where, "--keys", "F5", "--lang", "en"});
        QVERIFY2(r.exitCode == 0 && r.err.contains(QStringLiteral("key F5 refused")) &&
                     r.err.contains(QStringLiteral("«TM-21»")),
                 qPrintable(r.out + r.err));
        // In Russian, as the other commands (--lang ru, the default).
        r = runK528({"panel", "--profile", "grinder-205", "--db", where, "--keys", "F5"});
        QVERIFY2(r.exitCode == 0 && r.err.contains(QStringLiteral("клавиша F5 не принята")) &&
                     r.err.contains(QStringLiteral("«TM-21»")),
                 qPrintable(r.out + r.err));
        QCOMPARE(runK528({"panel", "--lang", "de"}).exitCode, 2);
        // What is not a constant may change.
        r = db({"set", "grinder-205", "R12=5"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = db({"set", "grinder-205", "constants.lock="});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = db({"set", "grinder-205", "C022=2133"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    }

    // The shop's time in each state: a poller's rows add up across
    // connections (a restarted studio continues its day), each source apart.
    void stateTimesAddUp() {
        QTemporaryDir dir;
        const db::Location where = testLocation(dir, "times");
        {
            db::Database d = db::Database::open(where, testOptions());
            db::addStateTimes(d, {{"m01", "2026-12-06", "studio@pc1", "run", 60000, {}},
                             {"m01", "2026-12-06", "studio@pc1", "idle", 1000, {}}});
        }
        db::Database d = db::Database::open(where, testOptions());
        db::addStateTimes(d, {{"m01", "2026-12-06", "studio@pc1", "run", 500, {}},
                         {"m01", "2026-12-06", "shop@pc2", "alarm", 42, {}}});
        const auto rows = db::stateTimes(d, "2026-12-06", "studio@pc1");
        QCOMPARE(rows.size(), std::size_t(2));
        QCOMPARE(rows[0].state, std::string("idle"));
        QCOMPARE(rows[1].state, std::string("run"));
        QCOMPARE(rows[1].ms, std::int64_t(60500));
        QCOMPARE(db::stateTimes(d, "2026-12-06").size(), std::size_t(3));
        QVERIFY(db::stateTimes(d, "2026-12-05").empty());
        QCOMPARE(integrityText(d), std::string());
    }

    // The commands: release and withdraw, the log, a copy, the roles.
    void commands() {
        QTemporaryDir dir;
        const QString where = QString::fromStdString(testLocation(dir, "c.db").text());
        const auto db = [&](QStringList args) {
            args.prepend("db");
            args << "--db" << where;
            return runK528(args);
        };
        QCOMPARE(db({"init"}).exitCode, 0);
        auto r = db({"release", "grinder-205", "L11", "--note", "проверена", "--author", "Петров"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        // What the commands report is in their language (Russian unless --lang en).
        QVERIFY2(r.out.startsWith(QStringLiteral("выпущена    grinder-205 L11 в ревизии 1 (SHA-256 ")) &&
                     r.out.contains(QStringLiteral("…): ")) && !hasEnglishSentence(r.out),
                 qPrintable(r.out));
        QVERIFY(r.out.contains(": проверена"));
        r = db({"show", "grinder-205", "--programs"});
        QVERIFY2(r.out.contains(QStringLiteral("выпущена — выпустил ")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("черновик")) && !hasEnglishSentence(r.out), qPrintable(r.out));
        r = db({"show", "grinder-205", "--programs", "--lang", "en"});
        QVERIFY2(r.out.contains("released by ") && r.out.contains("draft"), qPrintable(r.out));
        r = db({"withdraw", "grinder-205", "11", "--lang", "en"});
        QVERIFY2(r.exitCode == 0 && r.out.startsWith("withdrawn grinder-205 L11 as of revision 1"),
                 qPrintable(r.out + r.err));
        r = db({"withdraw", "grinder-205", "L11"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("программа L11 станка grinder-205 уже отозвана; ничего не записано")), qPrintable(r.err));
        QCOMPARE(db({"release", "grinder-205", "L100"}).exitCode, 2);
        QCOMPARE(db({"release", "no-such-machine", "L1"}).exitCode, 2);

        r = db({"log"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out, QStringLiteral("передач в журнале нет\n"));
        QCOMPARE(db({"log", "--lang", "en"}).out, QString("no transfers on record\n"));
        {
            db::Database d = db::Database::open(testLocation(dir, "c.db"), testOptions());
            d.recordTransfer(pushEntry("grinder-205", 1, "ok"));
            d.recordTransfer(pushEntry("training-lathe", 1, "partial"));
        }
        r = db({"log", "grinder-205", "--lang", "en"});
        QVERIFY2(r.out.contains("push  ok") && r.out.contains("L11 1a2b3c4d new") &&
                     !r.out.contains("training-lathe"),
                 qPrintable(r.out));
        r = db({"log", "grinder-205"});
        QVERIFY2(r.out.contains(QStringLiteral("в станок   успешно ")) && r.out.contains("L11 1a2b3c4d new") &&
                     !r.out.contains("push"),
                 qPrintable(r.out));
        r = db({"log", "training-lathe"});
        QVERIFY2(r.out.contains(QStringLiteral("в станок   частично")), qPrintable(r.out));
        r = db({"log", "--json"});
        const QJsonArray log = QJsonDocument::fromJson(r.out.toUtf8()).object()["transfers"].toArray();
        QCOMPARE(log.size(), 2);
        QCOMPARE(log[0].toObject()["machine"].toString(), QString("training-lathe"));
        QCOMPARE(log[1].toObject()["items"].toArray()[1].toObject()["crc32"].toString(), QString("1a2b3c4d"));
        QCOMPARE(db({"log", "--since", "yesterday"}).exitCode, 2);
        QCOMPARE(db({"log", "--since", "2999-01-01", "--lang", "en"}).out, QString("no transfers on record\n"));
        QCOMPARE(db({"log", "no-such", "--since", "2999-01-01"}).out, QStringLiteral("передач станка no-such в журнале нет\n"));

        const QString copy = dir.filePath("copy.db");
        r = db({"copy", "--to", copy});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("станков     2, ревизий 2, версий программ 6, выпусков 2")) &&
                     r.out.contains(QStringLiteral(" в одной транзакции")) && !hasEnglishSentence(r.out),
                 qPrintable(r.out));
        const QString copyEn = dir.filePath("copy-en.db");
        r = db({"copy", "--to", copyEn, "--lang", "en"});
        QVERIFY2(r.out.contains("machines  2, revisions 2, program versions 6, releases 2") &&
                     r.out.contains("in one transaction"),
                 qPrintable(r.out + r.err));
        QCOMPARE(runK528({"db", "export", "grinder-205", "--db", copy}).out,
                 db({"export", "grinder-205"}).out);
        r = db({"copy", "--to", copy});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("база данных не пуста (версия схемы")), qPrintable(r.err));
        QCOMPARE(db({"copy", "--to", "postgresql://u:secret@h/db"}).exitCode, 2);

        r = db({"roles"});
        QCOMPARE(r.exitCode, 0);
        if (onPostgres()) {
            // Roles are the cluster's: members granted by other tests may show.
            QVERIFY2(r.out.contains("k528_technologist") && r.out.contains("k528_operator") &&
                         r.out.contains("k528_viewer") && r.out.contains(QStringLiteral("члены: ")) &&
                         r.out.contains(QStringLiteral("читать станки, программы")) && !hasEnglishSentence(r.out),
                     qPrintable(r.out));
            r = db({"roles", "--lang", "en"});
            QVERIFY2(r.out.contains("members: ") && r.out.contains("read machines, programs, history"), qPrintable(r.out));
            QVERIFY(!r.out.contains("cmd_oper"));
            sqlOf(db::Database::open(testLocation(dir, "c.db"), testOptions()))
                .exec("DO $$ BEGIN IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'cmd_oper') "
                      "THEN CREATE ROLE cmd_oper LOGIN; END IF; END $$");
            r = db({"roles", "grant", "cmd_oper", "operator"});
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            const qsizetype op = r.out.indexOf("k528_operator"), tech = r.out.indexOf("k528_technologist");
            const qsizetype member = r.out.indexOf("cmd_oper");
            QVERIFY2(op >= 0 && member > op && (tech < op || member < tech), qPrintable(r.out));
            r = db({"roles", "grant", "cmd_oper", "boss", "--lang", "en"});
            QVERIFY2(r.exitCode != 0 && r.err.contains("technologist, operator and viewer"), qPrintable(r.err));
            r = db({"roles", "grant", "cmd_oper", "boss"});
            QVERIFY2(r.exitCode != 0 && r.err.contains(QStringLiteral("нет роли «boss»: роли — trainer, technologist, operator и viewer")) &&
                         !hasEnglishSentence(r.err),
                     qPrintable(r.err));
        } else {
            QVERIFY2(r.out.contains(QStringLiteral("один пользователь, которому можно всё")) && !hasEnglishSentence(r.out),
                     qPrintable(r.out));
            QVERIFY2(db({"roles", "--lang", "en"}).out.contains("one user, who may do everything"), qPrintable(r.out));
        }
    }
};

QTEST_APPLESS_MAIN(TestShop)
#include "test_shop.moc"
