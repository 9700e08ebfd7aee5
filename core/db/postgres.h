// libpq under the SQL seam (sql.h), used inside core/db only: a connection
// to a PostgreSQL database and its prepared queries. A query's `?N` becomes
// `$N`; every value goes and comes as text (integers parsed exactly); each
// query text is prepared once per session. Failures are db::Error by the
// server's SQLSTATE: Busy (lock timeout, serialization, deadlock), Denied
// (insufficient privilege), Invalid (a constraint), Io (the connection),
// ReadOnly (a read-only server), Sql (anything else).
#pragma once

#include "db/sql.h"

#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

struct pg_conn;
struct pg_result;

namespace k528::db::sql {

class PgConnection;

class PgQuery final : public Query {
public:
    PgQuery(PgConnection& c, std::string name, std::string text, int params);
    ~PgQuery() override;
    PgQuery(const PgQuery&) = delete;
    PgQuery& operator=(const PgQuery&) = delete;

    using Query::bind;
    Query& bind(int i, std::int64_t v) override;
    Query& bind(int i, std::string_view v) override;
    Query& bindNull(int i) override;
    bool step() override;
    void reset() override;
    // Runs the bound query now (its rows then read by step(), or by PgPart).
    void runNow();
    std::int64_t changes() const override { return changes_; }
    int columns() const override;
    std::int64_t i64(int col) const override;
    std::string text(int col) const override;
    bool isNull(int col) const override;
    Value value(int col) const override;

private:
    friend class PgConnection;
    friend class PgPart;
    void execute();
    // Sends the execution into the connection's pipeline (false: not sent).
    bool send();
    // Takes `r`, the successful result of its execution.
    void adopt(pg_result* r);
    std::string what() const;
    PgConnection& c_;
    std::string name_, text_;
    std::vector<std::optional<std::string>> params_;
    pg_result* result_ = nullptr;
    bool executed_ = false;
    int row_ = -1;
    std::int64_t changes_ = 0;
};

// The rows of one part of a query's result that a UNION ALL of several
// tables returns in one statement: the first column tags each row with its
// part (an integer), the part's own columns follow, counted from 0 here.
// Read with step() as a query of its own; it binds nothing. The query
// must have run (PgQuery::runNow) and stay as it is while its parts are read.
class PgPart final : public Query {
public:
    PgPart(const PgQuery& q, int tag);
    Query& bind(int i, std::int64_t v) override;
    Query& bind(int i, std::string_view v) override;
    Query& bindNull(int i) override;
    bool step() override;
    void reset() override;
    std::int64_t changes() const override { return 0; }
    int columns() const override;
    std::int64_t i64(int col) const override;
    std::string text(int col) const override;
    bool isNull(int col) const override;
    Value value(int col) const override;

private:
    pg_result* result_;
    std::string tag_;
    int rows_ = 0;
    int row_ = -1;
};

class PgConnection final : public Connection {
public:
    // Connects to `uri` (a libpq URI; `postgresql://` alone: the PG*
    // variables). `where` names the database in messages. Throws Error(Io).
    PgConnection(const std::string& uri, std::string where);
    ~PgConnection() override;
    PgConnection(const PgConnection&) = delete;
    PgConnection& operator=(const PgConnection&) = delete;

    Dialect dialect() const override { return Dialect::Postgres; }
    PgQuery& operator()(std::string_view text) override;
    void exec(std::string_view text) override;
    void runTogether(std::span<Query* const> queries) override;
    void runLater(Query& query) override;

    // Opens a transaction with `begin` (a BEGIN statement), sent with the
    // next statement in the same round trip; when none follows before the
    // end (commitReadOnly, or exec of COMMIT or ROLLBACK), nothing is sent.
    void beginWithNext(std::string begin);
    // Ends a read-only transaction: its COMMIT is sent, and its answer read
    // when the connection is next used (a read-only COMMIT has nothing to
    // report).
    void commitReadOnly() noexcept;
    // Whether the connection to the server is lost.
    bool lost() const;

    pg_conn* handle() const { return conn_; }
    const std::string& where() const { return where_; }
    // Whether a transaction is open (or failed and not yet rolled back).
    bool inTransaction();
    // A lost connection is made again (its prepared queries forgotten);
    // false when the server still does not answer.
    bool reconnectIfLost();
    // Notifications received so far, after one round trip (outside a
    // transaction): (channel, payload, whether this session sent it).
    struct Notification {
        std::string channel, payload;
        bool ours = false;
    };
    std::vector<Notification> notifications();

    // Throws the db::Error of a failed result (and clears it).
    [[noreturn]] void fail(pg_result* r, std::string_view what) const;

private:
    friend class PgQuery;
    // Runs `queries` (with the pending BEGIN first) and gives each its result.
    void run(std::span<PgQuery* const> queries);
    // One pipeline: the deferred writes, the pending BEGIN, `queries`, then
    // `statement` (one without parameters; nullptr: none). Throws the first error.
    void pipeline(std::span<PgQuery* const> queries, const std::string* statement);
    // Reads the results of the deferred writes (throws the first error).
    void flush();
    // Reads the answers not waited for (commitReadOnly) and leaves pipeline mode.
    void drain() noexcept;
    // Reads the answers not waited for, staying in pipeline mode.
    void readUnread() noexcept;

    pg_conn* conn_ = nullptr;
    std::string where_;
    std::string begin_; // the BEGIN to send with the next statement
    int unread_ = 0;    // pipelines sent whose answers are not read yet
    std::vector<std::string> deferred_; // writes sent, not synchronised: what each was
    int next_ = 0;
    std::map<std::string, std::unique_ptr<PgQuery>, std::less<>> cache_;
};

// `?1`, `?2`… as `$1`, `$2`… (outside quotes), and the highest number.
std::string postgresParameters(std::string_view text, int& count);

} // namespace k528::db::sql
