// The PostgreSQL backend: opening (connect, the checks, create or migrate in
// one transaction), transactions, notices of revisions, roles.
#include "db/postgres_store.h"

#include <algorithm>
#include <optional>
#include <libpq-fe.h>

namespace k528::db {

namespace {

// The advisory lock every write holds: one writer at a time ("K528").
constexpr std::int64_t kWriteLock = 0x4B353238;
constexpr std::string_view kApplication = "K528 Studio";

struct Found {
    bool empty = false;
    std::int64_t version = 0;
};

// `t` said of `where` ("WHERE: …").
ErrorText at(const std::string& where, ErrorText t) {
    t.at = where;
    return t;
}

// What is at the location: nothing (empty), ours (its version), or refused.
Found inspect(sql::Connection& c, const std::string& where, int latest) {
    Found f;
    auto& q = c("SELECT (SELECT count(*) FROM pg_class k JOIN pg_namespace n ON n.oid = "
                "k.relnamespace WHERE n.nspname = current_schema() AND k.relkind IN ('r', 'v', "
                "'m', 'p', 'f')), to_regclass('k528_schema') IS NOT NULL, current_schema() IS NULL");
    q.step();
    const std::int64_t objects = q.i64(0);
    const bool marked = q.text(1) == "t";
    const bool noSchema = q.text(2) == "t";
    q.reset();
    if (noSchema)
        throw Error(ErrorKind::Io, at(where, ErrorText{"pg.no-schema"}));
    if (!marked) {
        if (objects != 0)
            throw Error(ErrorKind::Foreign, at(where, ErrorText{"pg.foreign-tables", {std::to_string(objects)}}));
        f.empty = true;
        return f;
    }
    auto& m = c("SELECT application, version FROM k528_schema");
    if (!m.step())
        throw Error(ErrorKind::Corrupt, at(where, ErrorText{"pg.schema-empty"}));
    const std::string app = m.text(0);
    f.version = m.i64(1);
    m.reset();
    if (app != kApplication)
        throw Error(ErrorKind::Foreign, at(where, ErrorText{"pg.foreign-application", {app}}));
    if (f.version > latest)
        throw Error(ErrorKind::TooNew,
                    at(where, ErrorText{"open.too-new", {std::to_string(f.version), std::to_string(latest)}}));
    return f;
}

} // namespace

std::unique_ptr<PostgresStore> PostgresStore::open(const Location& where,
                                                   const OpenOptions& options, const Fill& fill) {
    const auto& migrations = options.migrations;
    if (migrations.empty())
        throw sql::internalError("no schema migrations given");
    const int latest = migrations.back().version;
    std::unique_ptr<PostgresStore> s(new PostgresStore);
    s->uri_ = where.uri();
    s->path_ = where.text();
    s->clock_ = options.clock ? options.clock : systemClock();
    s->busyTimeoutMs_ = options.busyTimeoutMs;
    s->conn_ = std::make_unique<sql::PgConnection>(where.uri(), where.text());
    sql::Connection& c = *s->conn_;
    {
        auto& v = c("SELECT current_setting('server_version_num')::int, current_setting("
                    "'server_encoding'), current_user");
        v.step();
        const std::int64_t version = v.i64(0);
        const std::string encoding = v.text(1);
        s->user_ = v.text(2);
        v.reset();
        if (version < 110000)
            throw Error(ErrorKind::Io, at(where.text(), ErrorText{"pg.old-server", {std::to_string(version / 10000)}}));
        if (encoding != "UTF8" && encoding != "SQL_ASCII")
            throw Error(ErrorKind::Io, at(where.text(), ErrorText{"pg.encoding", {encoding}}));
    }
    c.exec("SET lock_timeout = " + std::to_string(std::max(1, options.busyTimeoutMs)));
    const std::string author = options.author.empty() ? s->user_ : options.author;

    Found found = inspect(c, where.text(), latest);
    if (options.requireEmpty && !found.empty)
        throw Error(ErrorKind::Invalid, ErrorText{"pg.not-empty", {where.text(), std::to_string(found.version)}});
    if (found.empty && (!options.create || options.readOnly))
        throw Error(ErrorKind::Io, ErrorText{"pg.no-database", {where.text()}});
    s->report_.created = found.empty;
    s->report_.fromVersion = static_cast<int>(found.version);
    if (options.readOnly) {
        s->readOnly_ = ReadOnlyReason::Requested;
        s->report_.version = static_cast<int>(found.version);
    } else {
        if (found.empty || found.version < latest) {
            WriteTransaction tx(*s);
            // Another session may have created or migrated it meanwhile.
            found = inspect(c, where.text(), latest);
            if (found.empty) {
                try {
                    c.exec("CREATE TABLE k528_schema (application TEXT NOT NULL, version BIGINT "
                           "NOT NULL)");
                    auto& q = c("INSERT INTO k528_schema (application, version) VALUES (?1, 0)");
                    q.bind(1, kApplication);
                    q.run();
                } catch (const Error& e) {
                    if (e.kind() != ErrorKind::Denied)
                        throw;
                    throw DeniedError(s->path_.string(), DeniedAction::CreateTables, DeniedHolder::DatabaseOwner,
                                      s->user_, s->rolesOfUser(), e.what());
                }
            }
            if (found.version < latest)
                s->upgrade(migrations, found.version, author, fill);
            tx.commit();
            if (!found.empty && found.version < latest)
                s->vacuumChanges();
        }
        s->report_.version = latest;
        // Reference data from the catalog, when this user may write it.
        if (!s->definitionsCurrent() &&
            c.queryInt("SELECT has_table_privilege('c_definitions', 'UPDATE')::int") == 1) {
            WriteTransaction tx(*s);
            s->syncDefinitions(author);
            tx.commit();
        }
    }
    return s;
}

void PostgresStore::vacuumChanges() {
    // The history reads changes_history alone (an index-only scan) where the
    // table's visibility map marks a page all-visible; after an upgrade (a
    // new index, rows rewritten) VACUUM marks them now, not when autovacuum
    // next comes by, and ANALYZE gives the planner the new index's figures.
    // Outside the upgrade's transaction (VACUUM cannot run in one): the
    // upgrade stands if it fails, and autovacuum does it later.
    try {
        conn_->exec("VACUUM (ANALYZE) changes");
    } catch (const Error&) {
    }
}

void PostgresStore::stampSchema(int version) {
    auto& q = query("UPDATE k528_schema SET version = ?1");
    q.bind(1, version);
    q.run();
}

int PostgresStore::schemaVersion() {
    return static_cast<int>(conn_->queryInt("SELECT version FROM k528_schema"));
}

std::vector<IntegrityProblem> PostgresStore::checkIntegrity() {
    // The server keeps its pages and keys; what it cannot know is ours.
    return checkRows();
}

void PostgresStore::reconnect() {
    // The session's settings and LISTEN are made again only on a new session.
    const bool wasLost = conn_->lost();
    if (conn_->reconnectIfLost()) {
        if (!wasLost)
            return;
        if (watching_) {
            watching_ = false;
            listen();
        }
        conn_->exec("SET lock_timeout = " + std::to_string(std::max(1, busyTimeoutMs_)));
        return;
    }
    throw Error(ErrorKind::Io, at(path_.string(), ErrorText{"connect.lost"}));
}

bool PostgresStore::beginRead() {
    if (conn_->inTransaction())
        return false;
    reconnect();
    conn_->beginWithNext("BEGIN ISOLATION LEVEL REPEATABLE READ, READ ONLY");
    return true;
}

void PostgresStore::endRead() noexcept {
    conn_->commitReadOnly();
}

void PostgresStore::beginWrite() {
    if (readOnly_ != ReadOnlyReason::None)
        throw ReadOnlyError(path_, readOnly_);
    reconnect();
    conn_->beginWithNext("BEGIN"); // sent with the lock's query
    try {
        auto& q = query("SELECT pg_advisory_xact_lock(?1)");
        q.bind(1, kWriteLock);
        q.run();
    } catch (const Error& e) {
        rollback();
        if (e.kind() != ErrorKind::Busy)
            throw;
        throw Error(ErrorKind::Busy, ErrorText{"busy.write.session", {path_.string()}});
    }
}

void PostgresStore::commit() {
    conn_->exec("COMMIT");
}

void PostgresStore::rollback() noexcept {
    try {
        conn_->exec("ROLLBACK");
    } catch (...) {
    }
}

void PostgresStore::notifyChange(std::string_view machine, int revision) {
    auto& q = query("SELECT pg_notify(?1, ?2)");
    q.bind(1, kRevisionChannel).bind(2, std::string(machine) + " " + std::to_string(revision));
    conn_->runLater(q);
}

void PostgresStore::listen() {
    if (watching_)
        return;
    conn_->exec("LISTEN " + std::string(kRevisionChannel));
    watching_ = true;
}

bool PostgresStore::changedElsewhere(std::vector<std::string>& machines) {
    if (!watching_) {
        reconnect();
        listen();
        return false;
    }
    bool changed = false;
    for (const auto& n : conn_->notifications()) {
        if (n.ours || n.channel != kRevisionChannel)
            continue;
        changed = true;
        const std::string name = n.payload.substr(0, n.payload.rfind(' '));
        if (std::find(machines.begin(), machines.end(), name) == machines.end())
            machines.push_back(name);
    }
    return changed;
}

void PostgresStore::afterCopy() {
    // The identity columns continue after the ids copied in.
    for (const char* table : {"machines", "program_revisions", "audit", "message_runs",
                              "message_history", "program_states", "transfers", "training_attempts"}) {
        const std::string t = table;
        conn_->exec("SELECT setval(pg_get_serial_sequence('" + t + "', 'id'), (SELECT coalesce("
                    "max(id), 0) + 1 FROM " + t + "), false)");
    }
    // Statistics for the planner now, not when autovacuum next comes by: a
    // freshly filled table looks empty to it, and the first opens of a copied
    // shop read whole tables instead of one machine's rows by the index.
    conn_->exec("ANALYZE");
}

bool PostgresStore::mayActAs(std::string_view role) {
    auto& q = query("SELECT (SELECT rolsuper FROM pg_roles WHERE rolname = current_user) OR "
                    "EXISTS (SELECT 1 FROM pg_tables WHERE schemaname = current_schema() AND "
                    "tablename = 'machines' AND tableowner = current_user) OR EXISTS (SELECT 1 "
                    "FROM pg_roles WHERE rolname = ?1 AND pg_has_role(current_user, oid, 'MEMBER'))");
    q.bind(1, role);
    q.step();
    const bool may = q.text(0) == "t";
    q.reset();
    return may;
}

std::string PostgresStore::rolesOfUser() {
    auto& q = query("SELECT coalesce(string_agg(rolname, ', ' ORDER BY rolname), '') FROM pg_roles "
                    "WHERE rolname LIKE 'k528\\_%' AND pg_has_role(current_user, oid, 'MEMBER')");
    q.step();
    std::string roles = q.text(0);
    q.reset();
    return roles;
}

} // namespace k528::db

namespace k528::db {

namespace {

struct RoleDef {
    std::string_view name, may, member; // member: the role it includes
};
constexpr RoleDef kRoles[] = {
    {"k528_viewer", "read machines, programs, history, messages and transfers", ""},
    {"k528_operator", "a viewer's; record transfers and messages; push released programs",
     "k528_viewer"},
    {"k528_technologist",
     "an operator's; change machines, release and withdraw programs, push drafts where the "
     "machine allows",
     "k528_operator"},
    {"k528_trainer",
     "a technologist's; lock and unlock the machine constants for a class (constants.lock), record "
     "and read the class's training attempts",
     "k528_technologist"},
};

std::string identifier(std::string_view ident) {
    std::string q = "\"";
    for (char c : ident) {
        if (c == '"')
            q += '"';
        q += c;
    }
    return q + "\"";
}

} // namespace

std::vector<RoleInfo> PostgresStore::roles(bool setUp) {
    if (setUp) {
        // The refusal is named after the rollback: the failed transaction
        // answers nothing more.
        std::optional<Error> denied;
        try {
            WriteTransaction tx(*this);
            for (const RoleDef& r : kRoles) {
                auto& exists = query("SELECT count(*) FROM pg_roles WHERE rolname = ?1");
                exists.bind(1, r.name);
                exists.step();
                const bool have = exists.i64(0) != 0;
                exists.reset();
                if (!have)
                    conn_->exec("CREATE ROLE " + std::string(r.name) + " NOLOGIN");
                if (!r.member.empty())
                    conn_->exec("GRANT " + std::string(r.member) + " TO " + std::string(r.name));
            }
            const std::string schema =
                identifier([&] {
                    auto& q = query("SELECT current_schema()");
                    q.step();
                    std::string s = q.text(0);
                    q.reset();
                    return s;
                }());
            conn_->exec("GRANT USAGE ON SCHEMA " + schema + " TO k528_viewer;"
                        "GRANT SELECT ON ALL TABLES IN SCHEMA " + schema + " TO k528_viewer;"
                        "GRANT INSERT ON transfers, transfer_items, message_runs, message_history, "
                        "training_attempts TO k528_operator;"
                        "GRANT INSERT, UPDATE ON state_times TO k528_operator;"
                        "GRANT UPDATE (cleared_ms, ack_ms, ack_day_ms, ack_how) ON message_history "
                        "TO k528_operator;"
                        "GRANT USAGE ON ALL SEQUENCES IN SCHEMA " + schema + " TO k528_operator;"
                        "GRANT INSERT, UPDATE, DELETE ON machines, c_values, r_values, messages, "
                        "plc_messages, settings, revisions, changes, item_history, program_revisions, "
                        "program_states, audit TO k528_technologist;");
            tx.commit();
        } catch (const Error& e) {
            if (e.kind() != ErrorKind::Denied)
                throw;
            denied = e;
        }
        if (denied)
            throw DeniedError(path_.string(), DeniedAction::SetUpRoles, DeniedHolder::TablesCreator, user_,
                              rolesOfUser(), denied->what());
    }
    std::vector<RoleInfo> out;
    for (const RoleDef& r : kRoles) {
        RoleInfo info{std::string(r.name), std::string(r.may), {}};
        auto& q = query("SELECT m.rolname FROM pg_auth_members a JOIN pg_roles g ON g.oid = "
                        "a.roleid JOIN pg_roles m ON m.oid = a.member WHERE g.rolname = ?1 AND "
                        "m.rolname NOT LIKE 'k528\\_%' ORDER BY m.rolname");
        q.bind(1, r.name);
        while (q.step())
            info.members.push_back(q.text(0));
        q.reset();
        out.push_back(std::move(info));
    }
    return out;
}

void PostgresStore::grantRole(const std::string& user, const std::string& role) {
    const std::string name = role.rfind("k528_", 0) == 0 ? role : "k528_" + role;
    bool known = false;
    for (const RoleDef& r : kRoles)
        known = known || r.name == name;
    if (!known)
        throw Error(ErrorKind::Invalid, ErrorText{"role.unknown", {role}});
    try {
        conn_->exec("GRANT " + name + " TO " + identifier(user));
    } catch (const Error& e) {
        if (e.kind() != ErrorKind::Denied)
            throw;
        throw DeniedError(path_.string(), DeniedAction::GrantRole, DeniedHolder::RoleAdmin, user_,
                          rolesOfUser(), e.what());
    }
}

} // namespace k528::db
