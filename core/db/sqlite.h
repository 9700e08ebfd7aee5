// Thin RAII wrappers over the sqlite3 C API, used inside core/db only: the
// SQLite side of the SQL seam (sql.h). Every failure throws db::Error with
// SQLite's message and what we were doing.
#pragma once

#include "db/error.h"
#include "db/sql.h"

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

struct sqlite3;
struct sqlite3_stmt;

namespace k528::db::sql {

// Throws the db::Error for SQLite result code `rc` ("<what>: <sqlite message>").
[[noreturn]] void fail(sqlite3* db, int rc, std::string_view what);
// The same with SQLite's message given.
[[noreturn]] void failWith(int rc, std::string_view what, const std::string& message);

class Stmt final : public Query {
public:
    Stmt(sqlite3* db, std::string_view sql);
    ~Stmt() override;
    Stmt(const Stmt&) = delete;
    Stmt& operator=(const Stmt&) = delete;

    using Query::bind;
    Query& bind(int i, std::int64_t v) override;
    Query& bind(int i, std::string_view v) override;
    Query& bindNull(int i) override;
    bool step() override;
    void reset() override;
    std::int64_t changes() const override;
    int columns() const override;
    std::int64_t i64(int col) const override;
    std::string text(int col) const override;
    bool isNull(int col) const override;
    Value value(int col) const override;

private:
    sqlite3* db_;
    sqlite3_stmt* st_ = nullptr;
    std::string sql_;
};

// An SQLite connection (not owned) as the SQL seam sees it, with its
// prepared statements kept for the life of the connection, found by their text.
class SqliteConnection final : public Connection {
public:
    explicit SqliteConnection(sqlite3* db = nullptr) : db_(db) {}
    // Forgets every statement (before the connection closes) and uses `db`.
    void reset(sqlite3* db);
    sqlite3* handle() const { return db_; }

    Dialect dialect() const override { return Dialect::Sqlite; }
    Stmt& operator()(std::string_view text) override;
    void exec(std::string_view text) override;

private:
    sqlite3* db_;
    std::map<std::string, std::unique_ptr<Stmt>, std::less<>> cache_;
};

// Resets statements left mid-iteration (an exception inside a loop), so no
// read snapshot outlives the call that made it (before COMMIT or ROLLBACK).
void resetBusyStatements(sqlite3* db);

// Runs SQL without results (may hold several statements).
void exec(sqlite3* db, std::string_view sqlText);
// The single integer a query returns (e.g. PRAGMA user_version).
std::int64_t queryInt(sqlite3* db, std::string_view sqlText);

} // namespace k528::db::sql
