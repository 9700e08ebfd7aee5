// A machine's time in each state (run, idle, alarm, offline) per local day,
// counted from the polls of its line and kept in the shop's database
// (db::addStateTimes, db/state_times.h; docs/shop.md): the poller adds what it
// counted since its last write — once a minute, when a machine's state
// changes, and when it stops — never at every poll.
//
//   shop::StateTally tally;
//   tally.poll("m01", before, lastPollMs, r.atMs);   // after Tracker::update
//   if (tally.due(now)) db::addStateTimes(d, rowsOf(tally.take(now)));
#pragma once

#include "shop/state.h"

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace k528::shop {

// A Unix time in ms as the PC's local time, in a strftime `format` ("%H:%M:%S"):
// the one conversion of the shop's times into what its people read.
std::string localTimeText(std::int64_t unixMs, const char* format);

// The local day (YYYY-MM-DD) of a Unix time in ms, as the pollers' PC sees it.
std::string localDay(std::int64_t unixMs);

// The state a time counts for: "run", "idle", "alarm", "offline" (activityName).
class StateTally {
public:
    explicit StateTally(std::int64_t flushEveryMs = 60000) : every_(flushEveryMs) {}

    // `ms` of `machine` in `a` on `day`, not yet written.
    void add(const std::string& machine, const std::string& day, Activity a, std::int64_t ms);
    // A machine's state changed: what is counted is written at the next due().
    void changed() { changed_ = true; }

    // Whether to write now: something counted and a state changed or a minute
    // (flushEveryMs) passed since the last take().
    bool due(std::int64_t nowMs) const;
    bool empty() const { return pending_.empty(); }

    struct Row {
        std::string machine, day, state;
        std::int64_t ms = 0;
    };
    // What is counted, by machine, day and state; cleared. The first call
    // starts the minute.
    std::vector<Row> take(std::int64_t nowMs);
    // Counted again (a write that failed): added back to what is pending.
    void putBack(const std::vector<Row>& rows);

private:
    std::int64_t every_;
    mutable std::int64_t lastMs_ = -1; // the last take(); the first due() starts the minute
    bool changed_ = false;
    std::map<std::pair<std::string, std::string>, std::array<std::int64_t, 4>> pending_; // (machine, day)
};

} // namespace k528::shop
