// The shop's time in each state per machine and day (schema version 5,
// docs/shop.md, *Time in each state*), on a Database's connection as the
// message log is: the pollers (the studio's Shop page, `k528 shop publish`,
// `status --watch`) add what they counted; the Shop page reads its own back.
//
//   db::addStateTimes(d, {{"m01", "2026-12-06", "studio@pc1", "idle", 60000, {}}});
//   for (const db::StateTime& t : db::stateTimes(d, "2026-12-06", "studio@pc1")) ...
#pragma once

#include "db/database.h"

#include <cstdint>
#include <string>
#include <vector>

namespace k528::db {

// A machine's time in one state on one day as one poller counted it: each
// poller its own `source` ("studio@HOST", "shop@HOST"), so two pollers of one
// machine never count its time twice.
struct StateTime {
    std::string machine;
    std::string day;    // the poller's local day, YYYY-MM-DD
    std::string source; // who polled
    std::string state;  // "run", "idle", "alarm", "offline"
    std::int64_t ms = 0;
    std::string changedAt; // when last added to (UTC); filled by the write
    friend bool operator==(const StateTime&, const StateTime&) = default;
};

// Adds each row's ms to what is kept for its (machine, day, source, state),
// all in one transaction (PostgreSQL: the role k528_operator); a row that is
// not one (no machine, a day not YYYY-MM-DD, another state, a negative time)
// refuses the whole write.
void addStateTimes(Database& d, const std::vector<StateTime>& rows);
// The rows of `day` ("" every day) and `source` ("" every source), by
// machine, day, source and state.
std::vector<StateTime> stateTimes(const Database& d, const std::string& day, const std::string& source = {});

} // namespace k528::db
