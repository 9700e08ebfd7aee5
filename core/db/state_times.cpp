// The shop's time in each state (db/state_times.h): rows added to, never
// one per poll.
#include "db/state_times.h"

#include "db/database_impl.h"

namespace k528::db {

namespace {

constexpr std::string_view kWhat = "state-times"; // the time in each state of the shop's machines

} // namespace

void addStateTimes(Database& d, const std::vector<StateTime>& rows) {
    Store& s = d.store();
    d.requireWritable();
    requireSchema(s, 5, kWhat);
    for (const StateTime& r : rows) {
        const bool known = r.state == "run" || r.state == "idle" || r.state == "alarm" || r.state == "offline";
        if (r.machine.empty() || r.day.size() != 10 || !known || r.ms < 0)
            throw Error(ErrorKind::Invalid,
                        ErrorText{"state-time.invalid", {r.machine, r.day, r.state, std::to_string(r.ms)}});
    }
    if (rows.empty())
        return;
    const std::string at = formatTimestamp(systemClock()());
    asRole(s, DeniedAction::RecordStateTimes, kOperator, [&] {
        WriteTransaction tx(s);
        auto& q = s.connection()(
            "INSERT INTO state_times (machine, day, source, state, ms, changed_at) VALUES (?1, ?2, ?3, ?4, ?5, ?6) "
            "ON CONFLICT (machine, day, source, state) DO UPDATE SET ms = state_times.ms + excluded.ms, "
            "changed_at = excluded.changed_at");
        for (const StateTime& r : rows) {
            q.reset();
            q.bind(1, r.machine).bind(2, r.day).bind(3, r.source).bind(4, r.state).bind(5, r.ms).bind(6, at);
            q.run();
        }
        q.reset();
        tx.commit();
    });
}

std::vector<StateTime> stateTimes(const Database& d, const std::string& day, const std::string& source) {
    Store& s = d.store();
    requireSchema(s, 5, kWhat);
    ReadSnapshot tx(s);
    auto& q = s.connection()("SELECT machine, day, source, state, ms, changed_at FROM state_times WHERE (?1 = '' OR "
                             "day = ?1) AND (?2 = '' OR source = ?2) ORDER BY machine, day, source, state");
    q.bind(1, day).bind(2, source);
    std::vector<StateTime> out;
    while (q.step())
        out.push_back({q.text(0), q.text(1), q.text(2), q.text(3), q.i64(4), q.text(5)});
    q.reset();
    return out;
}

} // namespace k528::db
