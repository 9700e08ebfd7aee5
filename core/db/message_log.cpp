#include "db/message_log.h"

#include "db/database_impl.h"
#include "db/db_texts.h"
#include "db/sql.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace k528::db {

std::string_view messageSourceName(MessageSource s) {
    switch (s) {
    case MessageSource::Positioner: return "positioner";
    case MessageSource::PlcAlarm: return "plc-alarm";
    case MessageSource::PlcSystem: return "plc-system";
    case MessageSource::PlcWork: return "plc-work";
    case MessageSource::Program: return "program";
    }
    return "";
}

std::optional<MessageSource> messageSourceFromName(std::string_view name) {
    for (int i = 0; i < kMessageSourceCount; ++i)
        if (messageSourceName(static_cast<MessageSource>(i)) == name)
            return static_cast<MessageSource>(i);
    return std::nullopt;
}

std::string messageCode(MessageSource s, int number) {
    char buf[16];
    switch (s) {
    case MessageSource::Positioner: std::snprintf(buf, sizeof buf, "%d", number); break;
    case MessageSource::PlcAlarm: std::snprintf(buf, sizeof buf, "A%02d", number); break;
    case MessageSource::PlcSystem: std::snprintf(buf, sizeof buf, "S%02d", number); break;
    case MessageSource::PlcWork: std::snprintf(buf, sizeof buf, "W%02d", number); break;
    case MessageSource::Program: std::snprintf(buf, sizeof buf, "#%d", number); break;
    }
    return buf;
}

std::string formatDayMs(std::int64_t unixMs) {
    const std::int64_t s = unixMs >= 0 ? unixMs / 1000 : -((-unixMs + 999) / 1000);
    const std::int64_t ms = unixMs - s * 1000;
    std::string t = formatTimestamp(s); // "...T08:30:00Z"
    char frac[8];
    std::snprintf(frac, sizeof frac, ".%03lld", static_cast<long long>(ms));
    t.insert(t.size() - 1, frac);
    return t;
}

namespace {

// `t` said of the database's file ("PATH: …").
ErrorText said(const Database& db, ErrorText t) {
    t.at = db.path().string();
    return t;
}

// The code as SQL computes it, for searching (in the SQL both backends speak).
constexpr std::string_view kCodeSql =
    "(CASE source WHEN 'plc-alarm' THEN 'A' WHEN 'plc-system' THEN 'S' WHEN 'plc-work' THEN 'W' "
    "WHEN 'program' THEN '#' ELSE '' END || CASE WHEN source IN ('plc-alarm', 'plc-system', "
    "'plc-work') AND number < 10 THEN '0' ELSE '' END || CAST(number AS TEXT))";

constexpr std::string_view kColumns =
    "id, run_id, seq, machine, machine_ms, day_ms, source, number, text, text_en, program, line, "
    "cleared_ms, ack_ms, ack_day_ms, ack_how";

std::optional<std::int64_t> optInt(const sql::Query& q, int col) {
    if (q.isNull(col))
        return std::nullopt;
    return q.i64(col);
}

MessageRecord readRecord(const sql::Query& q) {
    MessageRecord m;
    m.id = q.i64(0);
    m.runId = q.i64(1);
    m.seq = q.i64(2);
    m.machine = q.text(3);
    m.machineMs = q.i64(4);
    m.dayMs = q.i64(5);
    const std::string source = q.text(6);
    const auto s = messageSourceFromName(source);
    if (!s)
        throw Error(ErrorKind::Corrupt, ErrorText{"messages.bad-source", {std::to_string(m.id), source}});
    m.source = *s;
    m.number = q.i32(7);
    m.text = q.text(8);
    m.textEn = q.text(9);
    m.program = q.i32(10);
    m.line = q.i32(11);
    m.clearedMs = optInt(q, 12);
    m.ackMs = optInt(q, 13);
    m.ackDayMs = optInt(q, 14);
    m.ackHow = q.isNull(15) ? std::string() : q.text(15);
    return m;
}

std::string likePattern(const std::string& s) {
    std::string p = "%";
    for (char c : s) {
        if (c == '%' || c == '_' || c == '\\')
            p += '\\';
        p += c;
    }
    return p + "%";
}

// WHERE clause and its bindings (?1.. in order).
struct Where {
    std::string sql;
    std::vector<std::string> texts; // bound as text, then ints
    std::vector<std::int64_t> ints;
    std::vector<bool> isText;       // per parameter, in order
};

Where makeWhere(const MessageFilter& f, std::int64_t beforeId) {
    Where w;
    std::vector<std::string> parts;
    int n = 0;
    const auto text = [&](const std::string& v) {
        w.texts.push_back(v);
        w.isText.push_back(true);
        return "?" + std::to_string(++n);
    };
    const auto integer = [&](std::int64_t v) {
        w.ints.push_back(v);
        w.isText.push_back(false);
        return "?" + std::to_string(++n);
    };
    if (!f.machine.empty())
        parts.push_back("machine = " + text(f.machine));
    if (beforeId > 0)
        parts.push_back("id < " + integer(beforeId));
    if (f.afterId > 0)
        parts.push_back("id > " + integer(f.afterId));
    if (f.source)
        parts.push_back("source = " + text(std::string(messageSourceName(*f.source))));
    if (f.unacknowledgedOnly)
        parts.push_back("ack_ms IS NULL AND source IN ('positioner', 'plc-alarm', 'plc-system')");
    if (f.fromDayMs)
        parts.push_back("day_ms >= " + integer(*f.fromDayMs));
    if (f.toDayMs)
        parts.push_back("day_ms <= " + integer(*f.toDayMs));
    if (!f.search.empty()) {
        // lower() on both sides: case-insensitive as SQLite's LIKE is, on
        // PostgreSQL too (whose LIKE is not).
        const std::string p = "lower(" + text(likePattern(f.search)) + ")";
        parts.push_back("(lower(text) LIKE " + p + " ESCAPE '\\' OR lower(text_en) LIKE " + p +
                        " ESCAPE '\\' OR lower(" + std::string(kCodeSql) + ") LIKE " + p +
                        " ESCAPE '\\')");
    }
    for (std::size_t i = 0; i < parts.size(); ++i)
        w.sql += (i == 0 ? " WHERE " : " AND ") + parts[i];
    return w;
}

void bindWhere(sql::Query& q, const Where& w) {
    std::size_t t = 0, k = 0;
    for (std::size_t i = 0; i < w.isText.size(); ++i) {
        if (w.isText[i])
            q.bind(static_cast<int>(i + 1), w.texts[t++]);
        else
            q.bind(static_cast<int>(i + 1), w.ints[k++]);
    }
}

std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"\r\n") == std::string::npos)
        return s;
    std::string out = "\"";
    for (char c : s) {
        if (c == '"')
            out += '"';
        out += c;
    }
    return out + "\"";
}

std::string optField(const std::optional<std::int64_t>& v) {
    return v ? std::to_string(*v) : std::string();
}

} // namespace

struct MessageLog::Impl {
    Database& db;
    Store& store;
    explicit Impl(Database& d) : db(d), store(d.store()) {}
    sql::Query& st(std::string_view text) { return store.connection()(text); }
};

MessageLog::MessageLog(Database& db) : d_(std::make_unique<Impl>(db)) {
    requireSchema(d_->store, 2, "messages");
}

MessageLog::~MessageLog() = default;

std::int64_t MessageLog::beginRun(std::string_view machine, std::int64_t dayMs,
                                  std::string author) {
    d_->db.requireWritable();
    Store& s = d_->store;
    return asRole(s, DeniedAction::RecordMessages, kOperator, [&] {
        auto& q = d_->st("INSERT INTO message_runs (machine, started_at, started_ms, author) "
                         "VALUES (?1, ?2, ?3, ?4) RETURNING id");
        q.bind(1, machine)
            .bind(2, formatDayMs(dayMs))
            .bind(3, dayMs)
            .bind(4, authorOf(s, author));
        if (!q.step())
            throw Error(ErrorKind::Sql, said(d_->db, ErrorText{"messages.no-run-id"}));
        const std::int64_t id = q.i64(0);
        q.reset();
        return id;
    });
}

void MessageLog::write(std::int64_t runId, std::span<const MessageEvent> events) {
    if (events.empty())
        return;
    d_->db.requireWritable();
    Store& s = d_->store;
    auto& run = d_->st("SELECT machine FROM message_runs WHERE id = ?1");
    run.bind(1, runId);
    if (!run.step())
        throw Error(ErrorKind::Invalid, said(d_->db, ErrorText{"messages.no-run", {std::to_string(runId)}}));
    const std::string machine = run.text(0);
    run.reset();
    asRole(s, DeniedAction::RecordMessages, kOperator, [&] {
        try {
            s.beginWrite();
        } catch (const Error& e) {
            if (e.kind() != ErrorKind::Busy)
                throw;
            throw Error(ErrorKind::Busy, said(d_->db, ErrorText{"messages.busy"}));
        }
        try {
            for (const MessageEvent& e : events) {
                const std::vector<std::string> which = {std::to_string(e.seq), std::to_string(runId)};
                if (e.kind == MessageEvent::Kind::Raised) {
                    const MessageRecord& m = e.message;
                    auto& q = d_->st("INSERT INTO message_history (run_id, seq, machine, machine_ms, "
                                     "day_ms, source, number, text, text_en, program, line) VALUES "
                                     "(?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11)");
                    q.bind(1, runId)
                        .bind(2, e.seq)
                        .bind(3, machine)
                        .bind(4, e.machineMs)
                        .bind(5, e.dayMs)
                        .bind(6, messageSourceName(m.source))
                        .bind(7, m.number)
                        .bind(8, m.text)
                        .bind(9, m.textEn.empty() ? m.text : m.textEn)
                        .bind(10, m.program)
                        .bind(11, m.line);
                    q.run();
                    continue;
                }
                const bool cleared = e.kind == MessageEvent::Kind::Cleared;
                auto& q = cleared ? d_->st("UPDATE message_history SET cleared_ms = ?3 WHERE "
                                           "run_id = ?1 AND seq = ?2 AND cleared_ms IS NULL")
                                  : d_->st("UPDATE message_history SET ack_ms = ?3, ack_day_ms = ?4, "
                                           "ack_how = ?5 WHERE run_id = ?1 AND seq = ?2 AND "
                                           "ack_ms IS NULL");
                q.bind(1, runId).bind(2, e.seq).bind(3, e.machineMs);
                if (!cleared) {
                    if (e.how.empty())
                        throw Error(ErrorKind::Invalid, ErrorText{"messages.no-how", which});
                    q.bind(4, e.dayMs).bind(5, e.how);
                }
                q.step();
                const std::int64_t changed = q.changes();
                q.reset();
                if (changed == 0) {
                    auto& known = d_->st("SELECT 1 FROM message_history WHERE run_id = ?1 AND seq = ?2");
                    known.bind(1, runId).bind(2, e.seq);
                    const bool exists = known.step();
                    known.reset();
                    if (!exists)
                        throw Error(ErrorKind::Invalid, ErrorText{"messages.not-raised", which});
                }
            }
            s.commit();
        } catch (const Error& e) {
            s.rollback();
            if (e.kind() == ErrorKind::Denied)
                throw;
            // The error as it was said, of this database, and that the
            // batch was not written.
            ErrorText text = e.catalogText();
            // Said of this database's file, unless the text names it.
            if (text.at.empty() && (e.textId().empty() || e.textId().rfind("messages.", 0) == 0))
                text.at = d_->db.path().string();
            text.tail = "messages.none-written";
            text.tailArgs = {std::to_string(events.size())};
            if (e.textId().empty())
                throw Error(e.kind(), d_->db.path().string() + ": " + e.what() +
                                          dbText(text.tail, text.tailArgs, false),
                            e.detail(), std::move(text));
            throw Error(e.kind(), std::move(text), e.detail());
        }
    });
}

std::int64_t MessageLog::count(const MessageFilter& f) const {
    const Where w = makeWhere(f, 0);
    auto& q = d_->st("SELECT count(*) FROM message_history" + w.sql);
    bindWhere(q, w);
    const std::int64_t n = q.step() ? q.i64(0) : 0;
    q.reset();
    return n;
}

std::vector<MessageRecord> MessageLog::page(const MessageFilter& f, std::int64_t beforeId,
                                            int limit) const {
    const Where w = makeWhere(f, beforeId);
    auto& q = d_->st("SELECT " + std::string(kColumns) + " FROM message_history" + w.sql +
                     " ORDER BY id DESC LIMIT " + std::to_string(std::max(limit, 0)));
    bindWhere(q, w);
    std::vector<MessageRecord> out;
    out.reserve(static_cast<std::size_t>(std::max(limit, 0)));
    while (q.step())
        out.push_back(readRecord(q));
    q.reset();
    return out;
}

std::vector<MessageRecord> MessageLog::byIds(std::span<const std::int64_t> ids) const {
    std::vector<MessageRecord> out;
    auto& q = d_->st("SELECT " + std::string(kColumns) + " FROM message_history WHERE id = ?1");
    for (std::int64_t id : ids) {
        q.reset();
        q.bind(1, id);
        if (q.step())
            out.push_back(readRecord(q));
    }
    q.reset();
    return out;
}

void MessageLog::forEach(const MessageFilter& f,
                         const std::function<bool(const MessageRecord&)>& each) const {
    // A page at a time (keyset), so that no statement stays open across the
    // caller's work and PostgreSQL does not hold every row at once.
    constexpr int kPage = 1000;
    std::int64_t before = 0;
    for (;;) {
        const auto rows = page(f, before, kPage);
        for (const MessageRecord& m : rows)
            if (!each(m))
                return;
        if (rows.size() < static_cast<std::size_t>(kPage))
            return;
        before = rows.back().id;
    }
}

std::string MessageLog::csvHeader() {
    return "id,machine,run,seq,machine_time_ms,time,source,code,text,text_en,program,line,"
           "cleared_machine_time_ms,acknowledged_machine_time_ms,acknowledged_time,"
           "acknowledged_how";
}

std::string MessageLog::csvRow(const MessageRecord& m) {
    std::string s;
    const auto add = [&](const std::string& v) {
        if (!s.empty())
            s += ',';
        s += csvField(v);
    };
    s = std::to_string(m.id);
    add(m.machine);
    add(std::to_string(m.runId));
    add(std::to_string(m.seq));
    add(std::to_string(m.machineMs));
    add(formatDayMs(m.dayMs));
    add(std::string(messageSourceName(m.source)));
    add(m.code());
    add(m.text);
    add(m.textEn);
    add(std::to_string(m.program));
    add(std::to_string(m.line));
    add(optField(m.clearedMs));
    add(optField(m.ackMs));
    add(m.ackDayMs ? formatDayMs(*m.ackDayMs) : std::string());
    add(m.ackHow);
    return s;
}

} // namespace k528::db
