#include "db/sqlite.h"

#include <sqlite3.h>

namespace k528::db::sql {

[[noreturn]] void fail(sqlite3* db, int rc, std::string_view what) {
    failWith(rc, what, db ? sqlite3_errmsg(db) : sqlite3_errstr(rc));
}

namespace {

// The kind of error of an SQLite result code.
ErrorKind kindOf(int rc) {
    switch (rc & 0xff) {
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
        return ErrorKind::Busy;
    case SQLITE_CORRUPT:
    case SQLITE_NOTADB:
        return ErrorKind::Corrupt;
    case SQLITE_READONLY:
        return ErrorKind::ReadOnly;
    case SQLITE_IOERR:
    case SQLITE_CANTOPEN:
    case SQLITE_FULL:
    case SQLITE_PERM:
    case SQLITE_NOLFS:
        return ErrorKind::Io;
    case SQLITE_CONSTRAINT:
        return ErrorKind::Invalid;
    default:
        return ErrorKind::Sql;
    }
}

} // namespace

[[noreturn]] void failWith(int rc, std::string_view what, const std::string& msg) {
    const ErrorKind kind = kindOf(rc);
    std::string text = std::string(what) + ": " + msg;
    if (kind == ErrorKind::Busy)
        text += " (another program kept the database locked longer than the busy timeout)";
    throw Error(kind, text, msg);
}

Stmt::Stmt(sqlite3* db, std::string_view sql) : db_(db), sql_(sql) {
    const int rc = sqlite3_prepare_v3(db, sql.data(), static_cast<int>(sql.size()),
                                      SQLITE_PREPARE_PERSISTENT, &st_, nullptr);
    if (rc != SQLITE_OK)
        fail(db, rc, "preparing \"" + sql_ + "\"");
}

Stmt::~Stmt() {
    sqlite3_finalize(st_);
}

Query& Stmt::bind(int i, std::int64_t v) {
    const int rc = sqlite3_bind_int64(st_, i, v);
    if (rc != SQLITE_OK)
        fail(db_, rc, "binding a value");
    return *this;
}

Query& Stmt::bind(int i, std::string_view v) {
    // A null data pointer would bind NULL: an empty text is "".
    const int rc = sqlite3_bind_text64(st_, i, v.data() ? v.data() : "", v.size(), SQLITE_TRANSIENT,
                                       SQLITE_UTF8);
    if (rc != SQLITE_OK)
        fail(db_, rc, "binding a text");
    return *this;
}

Query& Stmt::bindNull(int i) {
    const int rc = sqlite3_bind_null(st_, i);
    if (rc != SQLITE_OK)
        fail(db_, rc, "binding NULL");
    return *this;
}

bool Stmt::step() {
    const int rc = sqlite3_step(st_);
    if (rc == SQLITE_ROW)
        return true;
    if (rc == SQLITE_DONE)
        return false;
    const int code = sqlite3_extended_errcode(db_);
    std::string what = "running \"" + sql_.substr(0, 80) + (sql_.size() > 80 ? "…" : "") + "\"";
    sqlite3_reset(st_);
    fail(db_, code, what);
}

void Stmt::reset() {
    sqlite3_reset(st_);
    sqlite3_clear_bindings(st_);
}

std::int64_t Stmt::i64(int col) const {
    return sqlite3_column_int64(st_, col);
}

std::string Stmt::text(int col) const {
    const auto* p = sqlite3_column_text(st_, col);
    const int n = sqlite3_column_bytes(st_, col);
    return p ? std::string(reinterpret_cast<const char*>(p), static_cast<std::size_t>(n))
             : std::string();
}

bool Stmt::isNull(int col) const {
    return sqlite3_column_type(st_, col) == SQLITE_NULL;
}

std::int64_t Stmt::changes() const {
    return sqlite3_changes64(db_);
}

int Stmt::columns() const {
    return sqlite3_column_count(st_);
}

Value Stmt::value(int col) const {
    switch (sqlite3_column_type(st_, col)) {
    case SQLITE_NULL: return {};
    case SQLITE_INTEGER: return i64(col);
    case SQLITE_TEXT: return text(col);
    default:
        // A value written by another program (SQLite's columns take any
        // type): a real or a blob where we store integers and texts.
        throw Error(ErrorKind::Corrupt,
                    ErrorText{"corrupt.column-type", {sqlite3_column_name(st_, col), sql_.substr(0, 60)}});
    }
}

void SqliteConnection::reset(sqlite3* db) {
    cache_.clear();
    db_ = db;
}

Stmt& SqliteConnection::operator()(std::string_view text) {
    auto it = cache_.find(text);
    if (it == cache_.end())
        it = cache_.emplace(std::string(text), std::make_unique<Stmt>(db_, text)).first;
    it->second->reset();
    return *it->second;
}

void SqliteConnection::exec(std::string_view text) {
    sql::exec(db_, text);
}

void resetBusyStatements(sqlite3* db) {
    for (sqlite3_stmt* s = sqlite3_next_stmt(db, nullptr); s; s = sqlite3_next_stmt(db, s))
        if (sqlite3_stmt_busy(s))
            sqlite3_reset(s);
}

void exec(sqlite3* db, std::string_view sqlText) {
    const std::string s(sqlText);
    char* err = nullptr;
    const int rc = sqlite3_exec(db, s.c_str(), nullptr, nullptr, &err);
    if (rc != SQLITE_OK) {
        const std::string msg = err ? err : sqlite3_errstr(rc);
        sqlite3_free(err);
        const int code = sqlite3_extended_errcode(db);
        failWith(code != SQLITE_OK ? code : rc,
                 "running \"" + s.substr(0, 80) + (s.size() > 80 ? "…" : "") + "\"", msg);
    }
}

std::int64_t queryInt(sqlite3* db, std::string_view sqlText) {
    Stmt st(db, sqlText);
    if (!st.step())
        throw internalError("\"" + std::string(sqlText) + "\" returned no row");
    return st.i64(0);
}

} // namespace k528::db::sql
