// The logs of both backends: the audit log, the releases and withdrawals of
// programs, the transfers to and from controllers.
#include "db/sql_store.h"

#include <cstdio>

namespace k528::db {

namespace {

// LIMIT for "all rows" that both backends read as a number.
constexpr std::int64_t kAll = 9223372036854775807LL;

} // namespace

void SqlStore::insertAudit(const AuditEntry& e) {
    auto& q = query("INSERT INTO audit (at, author, action, machine, revision, detail) "
                    "VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
    q.bind(1, e.at).bind(2, e.author).bind(3, e.action).bind(4, e.machine).bind(5, e.revision).bind(6, e.detail);
    connection().runLater(q);
}

std::vector<AuditEntry> SqlStore::audit(int limit, std::string_view machine) {
    auto& q = query("SELECT id, at, author, action, machine, revision, detail FROM audit WHERE "
                    "(?1 = '' OR machine = ?1) ORDER BY id DESC LIMIT ?2");
    q.bind(1, machine).bind(2, limit > 0 ? std::int64_t(limit) : kAll);
    std::vector<AuditEntry> out;
    while (q.step())
        out.push_back(AuditEntry{q.i64(0), q.text(1), q.text(2), q.text(3), q.text(4), q.i32(5), q.text(6)});
    return out;
}

void SqlStore::insertProgramState(std::int64_t id, const ReleaseEntry& e) {
    // PostgreSQL records its own user (the column's default, current_user).
    const bool server = connection().dialect() == sql::Dialect::Postgres;
    auto& q = query(server ? "INSERT INTO program_states (machine_id, number, revision, sha256, "
                             "state, at, note) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)"
                           : "INSERT INTO program_states (machine_id, number, revision, sha256, "
                             "state, at, note, author) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)");
    q.bind(1, id).bind(2, e.number).bind(3, e.revision).bind(4, e.sha256)
        .bind(5, e.released ? "released" : "withdrawn").bind(6, e.at).bind(7, e.note);
    if (!server)
        q.bind(8, e.author);
    q.run();
}

std::vector<ReleaseEntry> SqlStore::programStates(std::int64_t id, std::optional<int> number) {
    auto& q = query("SELECT number, revision, sha256, state, at, author, note FROM program_states "
                    "WHERE machine_id = ?1 AND (?2 = 0 OR number = ?2) ORDER BY id DESC");
    q.bind(1, id).bind(2, number.value_or(0));
    std::vector<ReleaseEntry> out;
    while (q.step())
        out.push_back(ReleaseEntry{q.i32(0), q.i32(1), q.text(2), q.text(3) == "released", q.text(4),
                                   q.text(5), q.text(6)});
    return out;
}

std::int64_t SqlStore::insertTransfer(const TransferEntry& t) {
    const bool server = connection().dialect() == sql::Dialect::Postgres;
    auto& q = query(server ? "INSERT INTO transfers (at, host, machine, revision, controller, "
                             "direction, result, detail) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8) "
                             "RETURNING id"
                           : "INSERT INTO transfers (at, host, machine, revision, controller, "
                             "direction, result, detail, db_user) VALUES (?1, ?2, ?3, ?4, ?5, ?6, "
                             "?7, ?8, ?9) RETURNING id");
    q.bind(1, t.at).bind(2, t.host).bind(3, t.machine).bind(4, t.revision).bind(5, t.controller)
        .bind(6, t.direction).bind(7, t.result).bind(8, t.detail);
    if (!server)
        q.bind(9, t.user);
    if (!q.step())
        throw sql::internalError("the transfer's row has no id", path_.string());
    const std::int64_t id = q.i64(0);
    q.reset();
    auto& item = query("INSERT INTO transfer_items (transfer_id, seq, kind, number, crc32, sha256, "
                       "state) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
    int seq = 0;
    for (const TransferItem& i : t.items) {
        item.reset();
        item.bind(1, id).bind(2, seq++).bind(3, i.kind).bind(4, i.number).bind(5, i.crc32)
            .bind(6, i.sha256).bind(7, i.state);
        item.run();
    }
    return id;
}

std::vector<TransferEntry> SqlStore::transfers(const TransferFilter& f) {
    auto& q = query("SELECT id, at, db_user, host, machine, revision, controller, direction, "
                    "result, detail FROM transfers WHERE (?1 = '' OR machine = ?1) AND at >= ?2 "
                    "ORDER BY id DESC LIMIT ?3");
    q.bind(1, f.machine).bind(2, f.since).bind(3, f.limit > 0 ? std::int64_t(f.limit) : kAll);
    std::vector<TransferEntry> out;
    while (q.step())
        out.push_back(TransferEntry{q.i64(0), q.text(1), q.text(2), q.text(3), q.text(4), q.i32(5),
                                    q.text(6), q.text(7), q.text(8), q.text(9), {}});
    q.reset();
    auto& items = query("SELECT kind, number, crc32, sha256, state FROM transfer_items WHERE "
                        "transfer_id = ?1 ORDER BY seq");
    for (TransferEntry& t : out) {
        items.reset();
        items.bind(1, t.id);
        while (items.step())
            t.items.push_back(TransferItem{items.text(0), items.i32(1), items.text(2),
                                           items.optText(3), items.text(4)});
    }
    return out;
}

} // namespace k528::db
