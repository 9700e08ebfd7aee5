// A machine of the shop as its poller sees it (docs/shop.md): the state of
// the last poll of its line (online with the live state, or offline with the
// reason), what it is doing (run, idle, alarm, offline) and since when, and
// the alarms raised and cleared between polls. Times are the caller's
// (milliseconds since the Unix epoch): the same polls give the same states.
//
// The JSON objects are the contract of `k528 shop status --json` and of the
// MQTT topics k528/<machine>/state and k528/<machine>/alarms.
#pragma once

#include "link/client.h"
#include "util/json_fwd.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace k528::shop {

enum class Activity { Offline, Alarm, Run, Idle };
const char* activityName(Activity a); // "offline", "alarm", "run", "idle"

struct MachineState {
    std::string machine;
    std::string line; // the line's canonical text (profile/line.h)
    bool online = false;
    bool polled = false; // at least one poll came back (online or not)
    link::LiveState live; // the last answer (kept, stale, while offline)
    bool everOnline = false;
    std::string why;      // why offline
    Activity activity = Activity::Offline;
    std::int64_t sinceMs = 0;  // when this activity began (the first poll that saw it)
    std::int64_t polledMs = 0; // the last poll
    std::int64_t lastSeenMs = 0; // the last answer
};

struct AlarmEvent {
    std::string machine;
    int number = 0;
    bool raised = true; // false: cleared
    std::int64_t atMs = 0;
};

// What the machine does by its live state: an alarm (flag or numbers) first,
// then a program running, else idle.
Activity activityOf(const link::LiveState& s);

// One machine's polls in order.
class Tracker {
public:
    Tracker(std::string machine, std::string line);
    // One poll: `live` is the answer, or nullptr with `why` when the line did
    // not answer. Returns true when the published state changed (online,
    // activity, mode, PC readiness, program, frame, alarms, message; not
    // the axes) and appends the alarms raised and cleared. Going offline
    // raises no alarm event; the alarms of the controller when it answers
    // again are compared with those it had before.
    bool update(const link::LiveState* live, const std::string& why, std::int64_t nowMs,
                std::vector<AlarmEvent>& events);
    const MachineState& state() const { return s_; }

private:
    MachineState s_;
};

// 2026-12-03T14:02:05.123Z
std::string isoTime(std::int64_t unixMs);

// {"machine","line","online","state","since","seconds_in_state", online:
//  "mode","pc_ready","running","program","frame","override","message",
//  "alarms":[numbers],"alarm_texts":[{"number","text_ru","text_en"}];
//  offline: "why","last_seen" (or null)}. `nowMs` gives seconds_in_state.
Json stateJson(const MachineState& s, std::int64_t nowMs);
// {"machine","number","event":"raised"|"cleared","text_ru","text_en","at"}
Json alarmJson(const AlarmEvent& e);

} // namespace k528::shop
