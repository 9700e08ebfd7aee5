// Thin RAII wrappers over the sqlite3 C API, used inside core/db only.
// Every failure throws db::Error with SQLite's message and what we were doing.
#pragma once

#include "db/error.h"

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

class Stmt {
public:
    Stmt(sqlite3* db, std::string_view sql);
    ~Stmt();
    Stmt(const Stmt&) = delete;
    Stmt& operator=(const Stmt&) = delete;

    // Parameters are 1-based, as in SQLite.
    Stmt& bind(int i, std::int64_t v);
    Stmt& bind(int i, int v) { return bind(i, static_cast<std::int64_t>(v)); }
    Stmt& bind(int i, std::string_view v);
    Stmt& bind(int i, const std::string& v) { return bind(i, std::string_view(v)); }
    Stmt& bind(int i, const char* v) { return bind(i, std::string_view(v)); }
    Stmt& bind(int i, const std::optional<std::string>& v);
    Stmt& bindNull(int i);

    // One step: true when a row is available, false when done.
    bool step();
    // Steps to the end and resets (for statements without rows).
    void run();
    // Resets and clears the bindings, ready for the next use.
    void reset();

    std::int64_t i64(int col) const;
    int i32(int col) const { return static_cast<int>(i64(col)); }
    std::string text(int col) const;
    std::optional<std::string> optText(int col) const;
    bool isNull(int col) const;

private:
    sqlite3* db_;
    sqlite3_stmt* st_ = nullptr;
    std::string sql_;
};

// Prepared statements kept for the life of a connection, found by their text.
class StatementCache {
public:
    explicit StatementCache(sqlite3* db = nullptr) : db_(db) {}
    // Forgets every statement (before the connection closes) and uses `db`.
    void reset(sqlite3* db);
    // The statement of `text`, reset and without bindings.
    Stmt& operator()(std::string_view text);

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
