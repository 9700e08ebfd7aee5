// db::Database's record of the training course's graded attempts (schema
// version 4, docs/database.md): one row an attempt, appended, never changed.
#include "db/database.h"
#include "db/database_impl.h"
#include "db/sha256.h"

namespace k528::db {

namespace {

constexpr std::string_view kColumns = "id, at, recorded_by, host, student, exercise, file, program, "
                                      "sha256, score, passed, status, cycle_time_ms, grade";

AttemptEntry readAttempt(sql::Query& q) {
    AttemptEntry a;
    a.id = q.i64(0);
    a.at = q.text(1);
    a.recordedBy = q.text(2);
    a.host = q.text(3);
    a.student = q.text(4);
    a.exercise = q.text(5);
    a.file = q.text(6);
    a.program = q.text(7);
    a.sha256 = q.text(8);
    a.score = q.i32(9);
    a.passed = q.i64(10) != 0;
    a.status = q.text(11);
    a.cycleTimeMs = q.i64(12);
    a.grade = q.text(13);
    return a;
}

void requireAttempts(Store& s) {
    requireSchema(s, 4, "attempts");
}

} // namespace

AttemptEntry Database::recordAttempt(AttemptEntry entry) {
    Store& s = *d_->store;
    requireWritable();
    requireAttempts(s);
    if (entry.student.empty())
        throw Error(ErrorKind::Invalid, ErrorText{"attempt.no-student", {}});
    if (entry.exercise.empty())
        throw Error(ErrorKind::Invalid, ErrorText{"attempt.no-exercise", {}});
    if (entry.score < 0 || entry.score > 100)
        throw Error(ErrorKind::Invalid,
                    ErrorText{"attempt.score", {entry.student, entry.exercise, std::to_string(entry.score)}});
    if (entry.cycleTimeMs < 0)
        throw Error(ErrorKind::Invalid, ErrorText{"attempt.cycle-time", {entry.student, entry.exercise}});
    if (entry.at.empty())
        entry.at = formatTimestamp(d_->clock());
    const bool server = s.connection().dialect() == sql::Dialect::Postgres;
    if (server)
        entry.recordedBy = s.sessionUser(); // row security: the session's user only
    else if (entry.recordedBy.empty())
        entry.recordedBy = authorOf(s, {});
    if (entry.host.empty())
        entry.host = hostName();
    entry.sha256 = sha256Hex(entry.program);
    return asRole(s, DeniedAction::RecordAttempt, kOperator, [&] {
        WriteTransaction tx(s);
        auto& q = s.connection()(
            "INSERT INTO training_attempts (at, recorded_by, host, student, exercise, file, program, "
            "sha256, score, passed, status, cycle_time_ms, grade) VALUES (?1, ?2, ?3, ?4, ?5, ?6, "
            "?7, ?8, ?9, ?10, ?11, ?12, ?13) RETURNING id");
        q.bind(1, entry.at)
            .bind(2, entry.recordedBy)
            .bind(3, entry.host)
            .bind(4, entry.student)
            .bind(5, entry.exercise)
            .bind(6, entry.file)
            .bind(7, entry.program)
            .bind(8, entry.sha256)
            .bind(9, entry.score)
            .bind(10, entry.passed ? 1 : 0)
            .bind(11, entry.status)
            .bind(12, entry.cycleTimeMs)
            .bind(13, entry.grade);
        if (!q.step())
            throw sql::internalError("the attempt of \"" + entry.student + "\" at \"" + entry.exercise + "\" has no id",
                                     path().string());
        entry.id = q.i64(0);
        q.reset();
        tx.commit();
        return entry;
    });
}

std::vector<AttemptEntry> Database::attempts(const AttemptFilter& f) const {
    Store& s = *d_->store;
    requireAttempts(s);
    ReadSnapshot tx(s);
    auto& q = s.connection()("SELECT " + std::string(kColumns) +
                             " FROM training_attempts WHERE (?1 = '' OR student = ?1) AND (?2 = '' OR "
                             "exercise = ?2) AND id > ?3 ORDER BY id DESC LIMIT ?4");
    q.bind(1, f.student).bind(2, f.exercise).bind(3, f.afterId)
        .bind(4, f.limit > 0 ? std::int64_t(f.limit) : std::int64_t(1) << 62);
    std::vector<AttemptEntry> out;
    while (q.step())
        out.push_back(readAttempt(q));
    q.reset();
    return out;
}

} // namespace k528::db
