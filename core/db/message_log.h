// The message history (schema version 2): every alarm, machine and work
// message the positioner and the PLC raised, one row an occurrence, kept in
// the database beside the machines — when it came (machine time and time of
// day), its number, source, text, the program and line, when its cause went,
// and when and how it was acknowledged. core/msglog's Recorder watches a
// controller and hands its events here in batches; the desktop's history
// dock reads them page by page.
//
//   db::Database d = db::Database::open(path);
//   db::MessageLog log(d);
//   const auto run = log.beginRun("grinder-205", dayMs);   // one session of a machine
//   log.write(run, recorder.takeEvents());                  // one transaction
//   for (const auto& m : log.page({.machine = "grinder-205"}, 0, 100)) ...  // newest first
//
// Rules: a MessageLog uses its Database's connection (keep the Database alive
// and in place while the log exists; one thread). Each write() is one
// transaction: all its events or none (a bad event: Error(Invalid), nothing
// written). The log is not audited (it is a log itself). Times of day are
// the caller's (Unix milliseconds, UTC): core never reads a clock for them.
#pragma once

#include "db/database.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace k528::db {

enum class MessageSource : std::uint8_t {
    Positioner, // messages 1..64 of appendix М
    PlcAlarm,   // machine alarms A01..A32 (Z1900/Z1901)
    PlcSystem,  // PLC system messages S01..S16 (Z1307)
    PlcWork,    // work messages W01..W32 (Z1902/Z1903)
    Program,    // technological messages #1..99 of a program
};
inline constexpr int kMessageSourceCount = 5;
// "positioner", "plc-alarm", "plc-system", "plc-work", "program".
std::string_view messageSourceName(MessageSource s);
std::optional<MessageSource> messageSourceFromName(std::string_view name);
// The number as the panel and the messages dock show it: "37", "A03", "S01",
// "W12", "#5".
std::string messageCode(MessageSource s, int number);
// "2024-05-17T08:30:00.250Z" (Unix milliseconds, UTC).
std::string formatDayMs(std::int64_t unixMs);

struct MessageRecord {
    std::int64_t id = 0;    // row id (0 before it is written)
    std::int64_t runId = 0; // the session it came in
    std::int64_t seq = 0;   // its occurrence within the run (1, 2, ...)
    std::string machine;
    std::int64_t machineMs = 0; // machine time it came (ms of the run's simulated time)
    std::int64_t dayMs = 0;     // time of day it came (Unix ms, UTC)
    MessageSource source = MessageSource::Positioner;
    int number = 0;     // 1..64, 1..32, 1..16, 1..99
    std::string text;   // as the panel shows it (the positioner's in Russian, the PLC's as written)
    std::string textEn; // English where the catalog has it, else the same as text
    int program = 0;    // the program (and its source line) it came in, 0 if none
    int line = 0;
    std::optional<std::int64_t> clearedMs; // machine time its cause went (or the work message ended)
    std::optional<std::int64_t> ackMs;     // machine time it was acknowledged
    std::optional<std::int64_t> ackDayMs;  // and the time of day
    std::string ackHow;                    // "esc", "z1000.7", "reset", ... ("" if not)
    bool acknowledged() const { return ackMs.has_value(); }
    std::string code() const { return messageCode(source, number); }
};

// What a recorder saw: a message came, its cause went, it was acknowledged.
struct MessageEvent {
    enum class Kind : std::uint8_t { Raised, Cleared, Acknowledged };
    Kind kind = Kind::Raised;
    std::int64_t seq = 0; // the occurrence within its run
    std::int64_t machineMs = 0;
    std::int64_t dayMs = 0; // Raised, Acknowledged
    std::string how;        // Acknowledged
    MessageRecord message;  // Raised: source, number, texts, program, line
};

struct MessageFilter {
    std::string machine; // "" every machine
    // A part of the text (either language) or the code ("A03", "37"); SQLite
    // LIKE: case-insensitive for Latin letters.
    std::string search;
    std::optional<MessageSource> source;
    bool unacknowledgedOnly = false; // acknowledgeable ones not yet acknowledged
    std::optional<std::int64_t> fromDayMs, toDayMs;
    std::int64_t afterId = 0; // only rows with a greater id (newer ones)
};

class MessageLog {
public:
    explicit MessageLog(Database& db);
    ~MessageLog();
    MessageLog(const MessageLog&) = delete;
    MessageLog& operator=(const MessageLog&) = delete;

    // A new session of `machine` starting at `dayMs`: its id for write().
    std::int64_t beginRun(std::string_view machine, std::int64_t dayMs, std::string author = {});
    // Writes a batch in one transaction. Cleared / Acknowledged events update
    // the occurrence `seq` of the run (written before or in this batch).
    // Throws Error(Invalid) for a bad event (nothing written), Busy, Io.
    void write(std::int64_t runId, std::span<const MessageEvent> events);

    std::int64_t count(const MessageFilter& f = {}) const;
    // Newest first: at most `limit` rows with id < beforeId (0: from the newest).
    std::vector<MessageRecord> page(const MessageFilter& f, std::int64_t beforeId, int limit) const;
    // The rows of these ids (in the order given; missing ones left out).
    std::vector<MessageRecord> byIds(std::span<const std::int64_t> ids) const;
    // Every matching row, newest first; `each` returns false to stop.
    void forEach(const MessageFilter& f,
                 const std::function<bool(const MessageRecord&)>& each) const;

    // CSV (RFC 4180, UTF-8): the header and one row of a record.
    static std::string csvHeader();
    static std::string csvRow(const MessageRecord& m);

private:
    struct Impl;
    std::unique_ptr<Impl> d_;
};

} // namespace k528::db
