// The SQLite backend's audit log and the whole-file integrity check.
#include "db/sqlite_store.h"

namespace k528::db {

void SqliteStore::insertAudit(const AuditEntry& e) {
    auto& q = st_("INSERT INTO audit (at, author, action, machine, revision, detail) "
                  "VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
    q.bind(1, e.at).bind(2, e.author).bind(3, e.action).bind(4, e.machine).bind(5, e.revision).bind(6, e.detail);
    q.run();
}

std::vector<AuditEntry> SqliteStore::audit(int limit, std::string_view machine) {
    auto& q = st_("SELECT id, at, author, action, machine, revision, detail FROM audit WHERE "
                  "(?1 = '' OR machine = ?1) ORDER BY id DESC LIMIT ?2");
    q.bind(1, machine).bind(2, limit > 0 ? limit : -1);
    std::vector<AuditEntry> out;
    while (q.step())
        out.push_back(AuditEntry{q.i64(0), q.text(1), q.text(2), q.text(3), q.text(4), q.i32(5), q.text(6)});
    return out;
}

std::string SqliteStore::checkIntegrity() {
    std::string problems;
    sql::Stmt ic(db_, "PRAGMA integrity_check");
    while (ic.step())
        if (const std::string line = ic.text(0); line != "ok")
            problems += (problems.empty() ? "" : "; ") + line;
    try {
        sql::Stmt fk(db_, "PRAGMA foreign_key_check");
        while (fk.step())
            problems += (problems.empty() ? "" : "; ") + std::string("foreign key: ") + fk.text(0) +
                        " row " + std::to_string(fk.i64(1));
    } catch (const Error& e) {
        // Damage the integrity check listed can stop the key check: say it.
        if (e.kind() == ErrorKind::Busy)
            throw;
        problems += (problems.empty() ? "" : "; ") + std::string(e.what());
    }
    return problems;
}

} // namespace k528::db
