#include "db/postgres.h"
#include "db/libpq_lazy.h"

#include <charconv>
#include <cstring>
#include <libpq-fe.h>
#include <mutex>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace k528::db::sql {

namespace {

// Type oids of the integers (pg_type.h).
constexpr Oid kInt8 = 20, kInt2 = 21, kInt4 = 23;

ErrorKind kindOf(std::string_view state) {
    if (state == "40001" || state == "40P01" || state == "55P03" || state == "57014")
        return ErrorKind::Busy; // serialization, deadlock, lock or statement timeout
    if (state == "42501")
        return ErrorKind::Denied;
    if (state == "25006")
        return ErrorKind::ReadOnly;
    if (state.substr(0, 2) == "23")
        return ErrorKind::Invalid;
    if (state.substr(0, 2) == "08" || state.substr(0, 2) == "53" || state.substr(0, 2) == "57" ||
        state.substr(0, 2) == "58")
        return ErrorKind::Io;
    return ErrorKind::Sql;
}

// The integer in a text column of `r` (a value of any integer type).
std::int64_t integerAt(PGresult* r, int row, int col) {
    if (PQgetisnull(r, row, col))
        return 0;
    const char* s = PQgetvalue(r, row, col);
    const std::size_t len = static_cast<std::size_t>(PQgetlength(r, row, col));
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(s, s + len, v);
    if (ec != std::errc() || end != s + len)
        throw Error(ErrorKind::Corrupt, ErrorText{"corrupt.column-integer", {PQfname(r, col), std::string(s, len)}});
    return v;
}

std::string trimmed(const char* s) {
    std::string t = s ? s : "";
    while (!t.empty() && (t.back() == '\n' || t.back() == ' '))
        t.pop_back();
    return t;
}

// The server's notices (NOTICE: relation exists, …) are not the user's business.
void quiet(void*, const PGresult*) {}

// libpq keeps each result in memory of its own (a machine's state: ~150 kB
// in ~1000 blocks) and frees it at PQclear. With glibc's default trim
// threshold (128 kB) every free gave that memory back to the system (brk)
// and the next result faulted it in again page by page: on a kept
// connection that was most of the client's time of opening a machine (perf:
// brk, page faults and TLB flushes; 1.1 ms of CPU a load, 0.2 ms without).
// Freed memory up to 16 MB now stays in the process for the next result.
// A setting of the whole process, made here on purpose: only the backend
// knows when a process starts to use libpq (the database is chosen at run
// time), so SQLite-only runs keep glibc's defaults (docs/database.md,
// PostgreSQL: Memory).
void keepFreedMemory() {
#if defined(__GLIBC__)
    static std::once_flag once;
    std::call_once(once, [] { mallopt(M_TRIM_THRESHOLD, 16 * 1024 * 1024); });
#endif
}

} // namespace

std::string postgresParameters(std::string_view text, int& count) {
    std::string out;
    out.reserve(text.size());
    count = 0;
    bool quoted = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\'')
            quoted = !quoted;
        if (!quoted && c == '?' && i + 1 < text.size() && text[i + 1] >= '0' && text[i + 1] <= '9') {
            int n = 0;
            std::size_t j = i + 1;
            while (j < text.size() && text[j] >= '0' && text[j] <= '9')
                n = n * 10 + (text[j++] - '0');
            out += '$';
            out += text.substr(i + 1, j - i - 1);
            count = std::max(count, n);
            i = j - 1;
            continue;
        }
        out += c;
    }
    return out;
}

PgConnection::PgConnection(const std::string& uri, std::string where) : where_(std::move(where)) {
    if (const char* why = libpq::loadError())
        throw Error(ErrorKind::Io, ErrorText{"connect.failed", {where_, why}}, why);
    const char* keys[] = {"dbname", "application_name", "client_encoding", nullptr};
    const char* values[] = {uri.c_str(), "K528 Studio", "UTF8", nullptr};
    conn_ = PQconnectdbParams(keys, values, 1);
    if (!conn_ || PQstatus(conn_) != CONNECTION_OK) {
        const std::string why = conn_ ? trimmed(PQerrorMessage(conn_)) : "out of memory";
        PQfinish(conn_);
        conn_ = nullptr;
        throw Error(ErrorKind::Io, ErrorText{"connect.failed", {where_, why}}, why);
    }
    PQsetNoticeReceiver(conn_, quiet, nullptr);
    keepFreedMemory();
}

PgConnection::~PgConnection() {
    cache_.clear();
    PQfinish(conn_);
}

void PgConnection::fail(PGresult* r, std::string_view what) const {
    // Everything read from the result before PQclear frees it (the SQLSTATE
    // field points into the result's memory).
    const char* state = r ? PQresultErrorField(r, PG_DIAG_SQLSTATE) : nullptr;
    ErrorKind kind = state ? kindOf(state) : ErrorKind::Io;
    std::string message = trimmed(r ? PQresultErrorMessage(r) : nullptr);
    if (message.empty())
        message = trimmed(PQerrorMessage(conn_));
    if (r)
        PQclear(r);
    const std::string said = message; // the server's or libpq's words
    if (PQstatus(conn_) != CONNECTION_OK) {
        kind = ErrorKind::Io;
        message = "the connection to the server was lost (" + message + ")";
    }
    if (message.rfind("ERROR:  ", 0) == 0)
        message = message.substr(8);
    std::string text = std::string(what) + ": " + message;
    if (kind == ErrorKind::Busy)
        text += " (another session kept the database locked longer than the busy timeout)";
    throw Error(kind, text, said);
}

bool PgConnection::inTransaction() {
    if (!begin_.empty() || !deferred_.empty())
        return true;
    if (unread_ > 0) // the last thing sent was a read-only COMMIT
        return false;
    const auto s = PQtransactionStatus(conn_);
    return s == PQTRANS_INTRANS || s == PQTRANS_INERROR || s == PQTRANS_ACTIVE;
}

bool PgConnection::lost() const {
    return PQstatus(conn_) != CONNECTION_OK;
}

bool PgConnection::reconnectIfLost() {
    if (PQstatus(conn_) == CONNECTION_OK)
        return true;
    drain();
    cache_.clear(); // the session's prepared statements went with it
    begin_.clear();
    deferred_.clear();
    PQreset(conn_);
    return PQstatus(conn_) == CONNECTION_OK;
}

PgQuery& PgConnection::operator()(std::string_view text) {
    auto it = cache_.find(text);
    if (it == cache_.end()) {
        flush();
        drain();
        int params = 0;
        const std::string converted = postgresParameters(text, params);
        std::string name = "k528_" + std::to_string(++next_);
        PGresult* r = PQprepare(conn_, name.c_str(), converted.c_str(), params, nullptr);
        if (!r || PQresultStatus(r) != PGRES_COMMAND_OK)
            fail(r, "preparing \"" + converted.substr(0, 80) + "\"");
        PQclear(r);
        it = cache_.emplace(std::string(text),
                            std::make_unique<PgQuery>(*this, std::move(name), converted, params))
                 .first;
    }
    it->second->reset();
    return *it->second;
}

void PgConnection::exec(std::string_view text) {
    if (!deferred_.empty() && text.find(';') == std::string_view::npos) {
        const std::string statement(text); // with the writes sent before: one round trip
        pipeline({}, &statement);
        return;
    }
    flush();
    drain();
    std::string s(text);
    if (!begin_.empty()) {
        // A transaction that ran nothing ends without a word to the server.
        if (text == "COMMIT" || text == "ROLLBACK") {
            begin_.clear();
            return;
        }
        s = begin_ + "; " + s; // one round trip, as one simple query
        begin_.clear();
    }
    PGresult* r = PQexec(conn_, s.c_str());
    const auto st = r ? PQresultStatus(r) : PGRES_FATAL_ERROR;
    if (st != PGRES_COMMAND_OK && st != PGRES_TUPLES_OK)
        fail(r, "running \"" + s.substr(0, 80) + (s.size() > 80 ? "…" : "") + "\"");
    PQclear(r);
}

void PgConnection::beginWithNext(std::string begin) {
    begin_ = std::move(begin);
}

void PgConnection::commitReadOnly() noexcept {
    if (!begin_.empty()) { // nothing was read: no transaction was opened
        begin_.clear();
        return;
    }
    drain();
    if (PQtransactionStatus(conn_) == PQTRANS_IDLE)
        return;
    if (PQenterPipelineMode(conn_) == 1 &&
        PQsendQueryParams(conn_, "COMMIT", 0, nullptr, nullptr, nullptr, nullptr, 0) == 1 &&
        PQpipelineSync(conn_) == 1) {
        ++unread_; // its answer is read before the next one's
        return;
    }
    drain(); // could not be sent: the connection is lost, or the pipeline left as it is
    if (PQpipelineStatus(conn_) == PQ_PIPELINE_OFF && PQstatus(conn_) == CONNECTION_OK)
        PQclear(PQexec(conn_, "COMMIT"));
}

void PgConnection::drain() noexcept {
    if (PQpipelineStatus(conn_) == PQ_PIPELINE_OFF) {
        unread_ = 0;
        return;
    }
    readUnread();
    PQexitPipelineMode(conn_);
}

void PgConnection::readUnread() noexcept {
    // Each pipeline's results up to its synchronisation point; two NULLs in
    // a row: nothing more will come (the connection is lost).
    int nulls = 0;
    while (unread_ > 0) {
        PGresult* r = PQgetResult(conn_);
        if (!r) {
            if (++nulls >= 2)
                break;
            continue;
        }
        nulls = 0;
        if (PQresultStatus(r) == PGRES_PIPELINE_SYNC)
            --unread_;
        PQclear(r);
    }
    unread_ = 0;
}

void PgConnection::runTogether(std::span<Query* const> queries) {
    std::vector<PgQuery*> mine;
    mine.reserve(queries.size());
    for (Query* q : queries)
        mine.push_back(static_cast<PgQuery*>(q)); // this connection's queries
    run(mine);
}

void PgConnection::run(std::span<PgQuery* const> queries) {
    if (queries.empty())
        return;
    if (unread_ == 0 && deferred_.empty() && begin_.empty() && queries.size() == 1) {
        PgQuery& q = *queries[0];
        std::vector<const char*> values(q.params_.size());
        for (std::size_t i = 0; i < q.params_.size(); ++i)
            values[i] = q.params_[i] ? q.params_[i]->c_str() : nullptr;
        PGresult* r = PQexecPrepared(conn_, q.name_.c_str(), static_cast<int>(values.size()),
                                     values.data(), nullptr, nullptr, 0);
        const auto st = r ? PQresultStatus(r) : PGRES_FATAL_ERROR;
        if (st != PGRES_TUPLES_OK && st != PGRES_COMMAND_OK)
            fail(r, q.what());
        q.adopt(r);
        return;
    }
    pipeline(queries, nullptr);
}

void PgConnection::pipeline(std::span<PgQuery* const> queries, const std::string* statement) {
    // One pipeline: the writes sent before without waiting, the pending
    // BEGIN, each query, `statement`, one synchronisation point; after a
    // read-only COMMIT not waited for, in the same pipeline as it (its
    // answer comes first).
    if (PQpipelineStatus(conn_) == PQ_PIPELINE_OFF && PQenterPipelineMode(conn_) != 1)
        fail(nullptr, "entering pipeline mode");
    struct Target {
        PgQuery* query; // nullptr: a statement whose result is only checked
        std::string what;
    };
    std::vector<Target> targets;
    targets.reserve(deferred_.size() + queries.size() + 2);
    for (std::string& w : deferred_)
        targets.push_back(Target{nullptr, std::move(w)});
    deferred_.clear();
    bool sent = true;
    const auto sendStatement = [&](const std::string& text) {
        sent = sent && PQsendQueryParams(conn_, text.c_str(), 0, nullptr, nullptr, nullptr,
                                         nullptr, 0) == 1;
        if (sent)
            targets.push_back(Target{nullptr, "running \"" + text.substr(0, 80) + "\""});
    };
    if (!begin_.empty()) {
        sendStatement(begin_);
        begin_.clear();
    }
    for (PgQuery* q : queries) {
        sent = sent && q->send();
        if (sent)
            targets.push_back(Target{q, {}});
    }
    if (statement)
        sendStatement(*statement);
    if (PQpipelineSync(conn_) != 1)
        sent = false;
    readUnread();
    // The results in the order sent; after a failure the server skips the
    // rest of the pipeline (PGRES_PIPELINE_ABORTED).
    PGresult* error = nullptr;
    std::string what;
    std::size_t index = 0;
    int nulls = 0;
    for (;;) {
        PGresult* r = PQgetResult(conn_);
        if (!r) {
            if (++nulls >= 2)
                break;
            continue;
        }
        nulls = 0;
        const auto st = PQresultStatus(r);
        if (st == PGRES_PIPELINE_SYNC) {
            PQclear(r);
            break;
        }
        Target* t = index < targets.size() ? &targets[index] : nullptr;
        ++index;
        if (st == PGRES_TUPLES_OK || st == PGRES_COMMAND_OK) {
            if (t && t->query)
                t->query->adopt(r);
            else
                PQclear(r);
        } else if (!error && st != PGRES_PIPELINE_ABORTED) {
            error = r;
            what = !t ? "running queries together" : t->query ? t->query->what() : t->what;
        } else {
            PQclear(r);
        }
    }
    PQexitPipelineMode(conn_);
    if (error)
        fail(error, what);
    if (!sent || index < targets.size())
        fail(nullptr, "sending " + std::to_string(targets.size()) + " statements together");
}

void PgConnection::runLater(Query& query) {
    auto& q = static_cast<PgQuery&>(query); // this connection's query
    // Only inside a transaction that has begun (its errors then surface by
    // the COMMIT at the latest, and undo everything).
    const bool inWrite = begin_.empty() && unread_ == 0 &&
                         (!deferred_.empty() || PQtransactionStatus(conn_) == PQTRANS_INTRANS);
    if (!inWrite || (PQpipelineStatus(conn_) == PQ_PIPELINE_OFF && PQenterPipelineMode(conn_) != 1)) {
        q.run();
        return;
    }
    if (!q.send()) {
        pipeline({}, nullptr); // reports what failed
        fail(nullptr, q.what());
    }
    deferred_.push_back(q.what());
    q.reset();
}

void PgConnection::flush() {
    if (!deferred_.empty())
        pipeline({}, nullptr);
}

std::vector<PgConnection::Notification> PgConnection::notifications() {
    flush();
    drain();
    std::vector<Notification> out;
    // One round trip first: a notice of a commit that returned to its
    // session before this call is in its way to us; the server sends it
    // before it answers (it was signalled at that commit).
    if (!inTransaction()) {
        PGresult* r = PQexec(conn_, "SELECT 1");
        PQclear(r);
    }
    if (!PQconsumeInput(conn_))
        return out;
    const int self = PQbackendPID(conn_);
    while (PGnotify* n = PQnotifies(conn_)) {
        out.push_back(Notification{n->relname, n->extra ? n->extra : "", n->be_pid == self});
        PQfreemem(n);
    }
    return out;
}

PgQuery::PgQuery(PgConnection& c, std::string name, std::string text, int params)
    : c_(c), name_(std::move(name)), text_(std::move(text)), params_(static_cast<std::size_t>(params)) {}

// A prepared statement lives as long as its session: nothing to deallocate.
PgQuery::~PgQuery() {
    PQclear(result_);
}

Query& PgQuery::bind(int i, std::int64_t v) {
    params_.at(static_cast<std::size_t>(i - 1)) = std::to_string(v);
    return *this;
}

Query& PgQuery::bind(int i, std::string_view v) {
    params_.at(static_cast<std::size_t>(i - 1)) = std::string(v);
    return *this;
}

Query& PgQuery::bindNull(int i) {
    params_.at(static_cast<std::size_t>(i - 1)).reset();
    return *this;
}

bool PgQuery::send() {
    std::vector<const char*> values(params_.size());
    for (std::size_t i = 0; i < params_.size(); ++i)
        values[i] = params_[i] ? params_[i]->c_str() : nullptr;
    PQclear(result_);
    result_ = nullptr;
    executed_ = false;
    return PQsendQueryPrepared(c_.handle(), name_.c_str(), static_cast<int>(values.size()),
                               values.data(), nullptr, nullptr, 0) == 1;
}

void PgQuery::adopt(PGresult* r) {
    PQclear(result_);
    result_ = r;
    const char* n = PQcmdTuples(result_);
    changes_ = n && *n ? std::strtoll(n, nullptr, 10) : 0;
    executed_ = true;
    row_ = -1;
}

std::string PgQuery::what() const {
    return "running \"" + text_.substr(0, 80) + (text_.size() > 80 ? "…" : "") + "\"";
}

void PgQuery::execute() {
    PQclear(result_);
    result_ = nullptr;
    executed_ = false;
    PgQuery* self = this;
    c_.run(std::span(&self, 1));
}

void PgQuery::runNow() {
    if (!executed_)
        execute();
}

bool PgQuery::step() {
    if (!executed_)
        execute();
    ++row_;
    return row_ < PQntuples(result_);
}

void PgQuery::reset() {
    PQclear(result_);
    result_ = nullptr;
    executed_ = false;
    row_ = -1;
    for (auto& p : params_)
        p.reset();
}

int PgQuery::columns() const {
    return result_ ? PQnfields(result_) : 0;
}

bool PgQuery::isNull(int col) const {
    return PQgetisnull(result_, row_, col) != 0;
}

std::int64_t PgQuery::i64(int col) const {
    return integerAt(result_, row_, col);
}

std::string PgQuery::text(int col) const {
    return std::string(PQgetvalue(result_, row_, col),
                       static_cast<std::size_t>(PQgetlength(result_, row_, col)));
}

Value PgQuery::value(int col) const {
    if (isNull(col))
        return {};
    const Oid t = PQftype(result_, col);
    if (t == kInt8 || t == kInt4 || t == kInt2)
        return i64(col);
    return text(col);
}

PgPart::PgPart(const PgQuery& q, int tag)
    : result_(q.result_), tag_(std::to_string(tag)), rows_(q.result_ ? PQntuples(q.result_) : 0) {}

Query& PgPart::bind(int, std::int64_t) {
    throw internalError("a part of a result takes no parameters");
}

Query& PgPart::bind(int, std::string_view) {
    throw internalError("a part of a result takes no parameters");
}

Query& PgPart::bindNull(int) {
    throw internalError("a part of a result takes no parameters");
}

bool PgPart::step() {
    while (++row_ < rows_) {
        const int len = PQgetlength(result_, row_, 0);
        if (static_cast<std::size_t>(len) == tag_.size() &&
            std::memcmp(PQgetvalue(result_, row_, 0), tag_.data(), tag_.size()) == 0)
            return true;
    }
    row_ = rows_;
    return false;
}

void PgPart::reset() {
    row_ = rows_; // read: nothing more
}

int PgPart::columns() const {
    return result_ ? PQnfields(result_) - 1 : 0;
}

bool PgPart::isNull(int col) const {
    return PQgetisnull(result_, row_, col + 1) != 0;
}

std::int64_t PgPart::i64(int col) const {
    return integerAt(result_, row_, col + 1);
}

std::string PgPart::text(int col) const {
    return std::string(PQgetvalue(result_, row_, col + 1),
                       static_cast<std::size_t>(PQgetlength(result_, row_, col + 1)));
}

Value PgPart::value(int col) const {
    if (isNull(col))
        return {};
    return text(col); // the parts' columns are texts
}

} // namespace k528::db::sql
