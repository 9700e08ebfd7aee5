// The SQL seam of core/db's backends (internal to core/db): a prepared query
// and a connection, implemented over SQLite (sqlite.h) and PostgreSQL
// (postgres.h). The rows code (sql_store.h), the message history and the
// copy of a whole database are written once against these, in the SQL both
// speak: parameters are `?1`, `?2`… (PostgreSQL's connection turns them into
// `$1`, `$2`…), ids come back with RETURNING, upserts are ON CONFLICT.
// Every failure throws db::Error with the backend's message and what we were
// doing.
#pragma once

#include "db/error.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

namespace k528::db::sql {

// A column's value as stored: NULL, an integer or a text.
using Value = std::variant<std::monostate, std::int64_t, std::string>;

enum class Dialect { Sqlite, Postgres };

// An error of core/db's own code, not of the database or its data: a query
// that always returns a row returned none, a packed row asked to bind, no
// schema migrations given. Kind Sql, the catalog's "internal" in the
// reader's language around `what` — our English for the bug report, kept as
// written, as PostgreSQL keeps its "cannot happen" messages untranslated:
// the words are for whoever fixes it, the sentence around them for the user.
// `at`: the database it concerns, "" if none.
Error internalError(std::string what, std::string at = {});

class Query {
public:
    virtual ~Query() = default;

    // Parameters are 1-based (?1 is 1).
    virtual Query& bind(int i, std::int64_t v) = 0;
    virtual Query& bind(int i, std::string_view v) = 0;
    virtual Query& bindNull(int i) = 0;
    Query& bind(int i, int v) { return bind(i, static_cast<std::int64_t>(v)); }
    Query& bind(int i, const std::string& v) { return bind(i, std::string_view(v)); }
    Query& bind(int i, const char* v) { return bind(i, std::string_view(v)); }
    Query& bind(int i, const std::optional<std::string>& v) {
        return v ? bind(i, std::string_view(*v)) : bindNull(i);
    }
    Query& bind(int i, const Value& v);

    // One step: true when a row is available, false when done.
    virtual bool step() = 0;
    // Steps to the end and resets (for statements without rows).
    void run() {
        while (step()) {
        }
        reset();
    }
    // Resets and clears the bindings, ready for the next use.
    virtual void reset() = 0;
    // Rows changed by the last run of an INSERT/UPDATE/DELETE.
    virtual std::int64_t changes() const = 0;

    virtual int columns() const = 0;
    virtual std::int64_t i64(int col) const = 0;
    int i32(int col) const { return static_cast<int>(i64(col)); }
    virtual std::string text(int col) const = 0;
    virtual bool isNull(int col) const = 0;
    std::optional<std::string> optText(int col) const {
        if (isNull(col))
            return std::nullopt;
        return text(col);
    }
    // The value with its stored type (for copying rows between backends).
    virtual Value value(int col) const = 0;
};

// The rows of a table of two integer columns packed by the server into one
// text, "n v n v …" (string_agg): one row of the result instead of one a
// pair. Read with step() as a query of its own; it binds nothing. A text
// that is not such pairs is Corrupt, said by the database's catalog:
// `idStem` + ".pairs" (its `args` and the text found) or ".odd" (a number
// without its value, its `args`).
class IntegerPairs final : public Query {
public:
    IntegerPairs(std::string packed, std::string idStem, std::vector<std::string> args);
    Query& bind(int i, std::int64_t v) override;
    Query& bind(int i, std::string_view v) override;
    Query& bindNull(int i) override;
    bool step() override;
    void reset() override { at_ = packed_.size(); }
    std::int64_t changes() const override { return 0; }
    int columns() const override { return 2; }
    std::int64_t i64(int col) const override { return col == 0 ? first_ : second_; }
    std::string text(int col) const override { return std::to_string(i64(col)); }
    bool isNull(int) const override { return false; }
    Value value(int col) const override { return i64(col); }

private:
    std::int64_t next();
    std::string packed_, idStem_;
    std::vector<std::string> args_;
    std::size_t at_ = 0;
    std::int64_t first_ = 0, second_ = 0;
};

class Connection {
public:
    virtual ~Connection() = default;
    virtual Dialect dialect() const = 0;
    // The prepared query of `text`, kept for the life of the connection,
    // reset and without bindings.
    virtual Query& operator()(std::string_view text) = 0;
    // Runs SQL without results (may hold several statements).
    virtual void exec(std::string_view text) = 0;
    // Runs the bound `queries` now, all in one round trip where the server
    // is across a network (PostgreSQL: one pipeline); their rows are then
    // read with step() as usual. For reads that do not depend on each other.
    // SQLite: nothing to do (each query runs at its first step).
    virtual void runTogether(std::span<Query* const> /*queries*/) {}
    // Runs `query` (bound; a write without rows) inside an open transaction;
    // PostgreSQL sends it and reads its result with the transaction's next
    // query or its COMMIT (a failure is thrown there, and the transaction
    // is rolled back as with any failure). SQLite: run() now.
    virtual void runLater(Query& query) { query.run(); }
    // The single integer a query returns.
    std::int64_t queryInt(std::string_view text);
};

} // namespace k528::db::sql
