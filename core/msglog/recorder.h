// The message recorder: watches a controller after every tick and turns what
// its message lists do into events for the message history (db/message_log.h):
//   - a message came (the positioner's 1..64 latch, a PLC alarm or system bit
//     is remembered, a work message or a program's technological message
//     shows) -> Raised, with its number, texts, program and line;
//   - its cause went (the condition ended, the PLC bit dropped, the work or
//     technological message went out) -> Cleared;
//   - it was acknowledged (unlatched / erased) -> Acknowledged, with how:
//     "z1000.7" (the machine's acknowledge signal), "reset" (Z1000.5 «Сброс»)
//     or "esc" (ESC: the K923 or the desktop), unless the caller said how
//     (noteAcknowledgement, e.g. "esc-dock" before it calls escape()).
// Deterministic: events carry the controller's machine time; the time of day
// comes from the caller (stampDayTime), core never reads a clock.
//
//   msglog::Recorder rec(sim.controller());
//   sim.addTickObserver([&] { rec.observe(); });
//   ... sim.advance(16); rec.stampDayTime(nowUnixMs);
//   log.write(run, rec.takeEvents());
#pragma once

#include "db/message_log.h"
#include "engine/positioner.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace k528::msglog {

// One message the recorder saw come and not yet go away for good
// (acknowledged, or ended for work and technological messages).
struct OpenMessage {
    std::int64_t seq = 0;
    db::MessageSource source = db::MessageSource::Positioner;
    int number = 0;
    bool causePresent = false;
};

// What the recorder looks at, from any controller's views: a real K528-05
// read over the link gives its latched messages, the PLC's message words,
// the program shown and Z1000 (its time is the PC's: ms since the
// recording began).
struct Observation {
    std::int64_t timeMs = 0;
    std::uint16_t z1000 = 0;
    std::vector<engine::AlarmView> alarms; // the positioner's messages shown (latched)
    engine::PlcMessagesView plc;
    engine::ProgramView program;
};

class Recorder {
public:
    // Starts with what the controller shows now: messages already present
    // are recorded as raised at this moment on the first observe().
    explicit Recorder(const engine::Positioner& ctl);
    // Without an engine controller: observe(Observation) only; `machine`
    // gives the PLC messages' texts (it must outlive the recorder).
    Recorder(const profile::MachineProfile& machine, std::uint16_t z1000);

    // Looks at the controller now (after each tick; again after an ESC
    // between ticks).
    void observe();
    // Looks at what another controller shows now.
    void observe(const Observation& o);
    // The acknowledgements the next observe() sees were made this way.
    void noteAcknowledgement(std::string how) { note_ = std::move(how); }
    // The time of day (Unix ms) of the machine time of the last observe():
    // events not yet stamped get dayNowMs - (that - their machine time) /
    // speed. (Does not touch the controller.)
    void stampDayTime(std::int64_t dayNowMs, double speed = 1.0);

    // Events seen and not yet taken, in the order seen (unstamped: dayMs 0).
    const std::vector<db::MessageEvent>& pending() const { return events_; }
    std::vector<db::MessageEvent> takeEvents();
    // Messages raised and not yet acknowledged or ended.
    std::vector<OpenMessage> open() const;
    // Occurrences seen so far (the last seq).
    std::int64_t raisedCount() const { return seq_; }

private:
    struct Track {
        std::int64_t seq = 0; // open occurrence, 0 none
        bool cause = false;   // its cause present (as last seen)
        std::uint32_t order = 0;
    };
    std::int64_t raise(db::MessageSource s, int number, std::string text, std::string textEn,
                       int program, int line);
    void cleared(Track& t);
    void acknowledged(Track& t, const std::string& how);
    void bits(db::MessageSource s, std::uint32_t shown, std::uint32_t present, int count,
              Track* tracks, bool acknowledgeable, const std::string& how, int program, int line);
    std::string plcText(db::MessageSource s, int k, bool english) const;
    template <class EntryOf>
    void step(std::int64_t now, std::uint16_t z1000, EntryOf&& entryOf, const engine::PlcMessagesView& pm,
              const engine::ProgramView& pv);

    const engine::Positioner* ctl_ = nullptr;
    const profile::MachineProfile* machine_ = nullptr;
    std::int64_t seq_ = 0;
    std::int64_t now_ = 0;
    std::array<Track, 65> positioner_{};
    std::array<Track, 33> plcAlarm_{}, plcWork_{};
    std::array<Track, 17> plcSystem_{};
    Track program_{};
    int programMessage_ = 0;
    std::uint16_t lastZ1000_ = 0;
    std::string note_;
    std::vector<db::MessageEvent> events_;
    std::size_t stamped_ = 0;
};

} // namespace k528::msglog
