// db::Database::copyTo: a whole database into an empty one — SQLite to
// PostgreSQL and back — row for row, ids kept, in one transaction of the
// target (the one that creates its schema): all or nothing.
#include "db/database.h"
#include "db/database_impl.h"
#include "db/postgres_store.h"
#include "db/sqlite_store.h"

namespace k528::db {

namespace {

// Every table of the schema, parents before children (foreign keys).
constexpr std::string_view kTables[] = {
    "meta",          "c_definitions", "machines",       "revisions",         "c_values",
    "r_values",      "messages",      "plc_messages",   "settings",          "program_revisions",
    "changes",       "item_history", "audit",         "message_runs",   "message_history",   "program_states",
    "transfers",     "transfer_items", "training_attempts", "state_times",
};

// The key that orders a table's rows (the same order on both backends).
// The recorded changes come in the history's order (changes_history's
// key): PostgreSQL fills that index as the rows come, so in its own order
// its leaf pages are filled whole one after the other and each item's
// entries lie together in a few of them, which is all the history of one
// item reads (schema version 8: the index holds what the history shows).
std::string_view orderOf(std::string_view table) {
    if (table == "meta")
        return "key";
    if (table == "c_definitions")
        return "number";
    if (table == "revisions")
        return "machine_id, revision";
    if (table == "c_values" || table == "r_values" || table == "messages")
        return "machine_id, number";
    if (table == "plc_messages")
        return "machine_id, grp, number";
    if (table == "settings")
        return "machine_id, position";
    if (table == "changes")
        return "machine_id, key, revision DESC, seq";
    if (table == "item_history")
        return "machine_id, key";
    if (table == "transfer_items")
        return "transfer_id, seq";
    if (table == "state_times")
        return "machine, day, source, state";
    return "id";
}

} // namespace

CopyReport Database::copyTo(const Location& target, const OpenOptions& targetOptions) const {
    Store& src = *d_->store;
    const int latest = latestSchemaVersion();
    if (src.schemaVersion() != latest)
        throw Error(ErrorKind::Invalid, ErrorText{"copy.schema", {path().string(), std::to_string(src.schemaVersion()),
                                                                  std::to_string(latest)}});
    if (target == location())
        throw Error(ErrorKind::Invalid, ErrorText{"copy.itself", {}});
    CopyReport report;
    report.target = target.text();
    OpenOptions o = targetOptions;
    o.requireEmpty = true;
    o.seedBuiltins = false;
    o.create = true;
    o.readOnly = false;
    o.migrations = schemaMigrations();
    ReadSnapshot snapshot(src); // one state of the source for the whole copy
    const Fill copyRows = [&](Store& dst) {
        sql::Connection& from = src.connection();
        sql::Connection& to = dst.connection();
        // The new database's first rows (created_at, the definitions, its
        // audit entry) give way to the source's.
        for (auto t = std::rbegin(kTables); t != std::rend(kTables); ++t)
            to.exec("DELETE FROM " + std::string(*t));
        for (const std::string_view table : kTables) {
            auto& q = from("SELECT * FROM " + std::string(table) + " ORDER BY " +
                           std::string(orderOf(table)));
            sql::Query* insert = nullptr;
            std::int64_t n = 0;
            while (q.step()) {
                if (!insert) {
                    std::string values;
                    for (int i = 1; i <= q.columns(); ++i)
                        values += (i > 1 ? ", ?" : "?") + std::to_string(i);
                    insert = &to("INSERT INTO " + std::string(table) + " VALUES (" + values + ")");
                }
                insert->reset();
                for (int i = 0; i < q.columns(); ++i)
                    insert->bind(i + 1, q.value(i));
                insert->run();
                ++n;
            }
            q.reset();
            report.rows += n;
            if (table == "machines")
                report.machines = n;
            else if (table == "revisions")
                report.revisions = n;
            else if (table == "program_revisions")
                report.programVersions = n;
            else if (table == "program_states")
                report.releases = n;
            else if (table == "message_history")
                report.messages = n;
            else if (table == "audit")
                report.audit = n;
            else if (table == "transfers")
                report.transfers = n;
            else if (table == "training_attempts")
                report.attempts = n;
        }
        dst.afterCopy();
        return std::vector<std::string>{};
    };
    if (target.backend() != Backend::Postgres) {
        SqliteStore::open(target.file(), o, copyRows);
        return report;
    }
    const auto dst = PostgresStore::open(target, o, copyRows);
    // Committed. VACUUM (outside any transaction) marks the new rows visible
    // to all in the tables' visibility maps, so the history's index-only
    // scans read no table rows from the first call — what autovacuum would
    // do a minute or more later. Not part of the copy: if it fails, the
    // copy stands and autovacuum does it.
    try {
        dst->connection().exec("VACUUM");
    } catch (const Error&) {
    }
    return report;
}

} // namespace k528::db
