#include "msglog/recorder.h"

#include "catalog/messages.h"
#include "profile/english.h"

#include <cmath>

namespace k528::msglog {

using db::MessageEvent;
using db::MessageSource;

Recorder::Recorder(const engine::Positioner& ctl) : ctl_(&ctl), machine_(&ctl.profile()) {
    lastZ1000_ = ctl.words().word(1000);
}

Recorder::Recorder(const profile::MachineProfile& machine, std::uint16_t z1000) : machine_(&machine) {
    lastZ1000_ = z1000;
}

std::int64_t Recorder::raise(MessageSource s, int number, std::string text, std::string textEn,
                             int program, int line) {
    MessageEvent e;
    e.kind = MessageEvent::Kind::Raised;
    e.seq = ++seq_;
    e.machineMs = now_;
    e.message.source = s;
    e.message.number = number;
    e.message.text = std::move(text);
    e.message.textEn = textEn.empty() ? e.message.text : std::move(textEn);
    e.message.program = program;
    e.message.line = line;
    events_.push_back(std::move(e));
    return seq_;
}

void Recorder::cleared(Track& t) {
    MessageEvent e;
    e.kind = MessageEvent::Kind::Cleared;
    e.seq = t.seq;
    e.machineMs = now_;
    events_.push_back(std::move(e));
    t.cause = false;
}

void Recorder::acknowledged(Track& t, const std::string& how) {
    if (t.cause)
        cleared(t);
    MessageEvent e;
    e.kind = MessageEvent::Kind::Acknowledged;
    e.seq = t.seq;
    e.machineMs = now_;
    e.how = how;
    events_.push_back(std::move(e));
    t.seq = 0;
}

std::string Recorder::plcText(MessageSource s, int k, bool english) const {
    const profile::MachineProfile& p = *machine_;
    const catalog::PlcGroup g = s == MessageSource::PlcAlarm    ? catalog::PlcGroup::Alarm
                                : s == MessageSource::PlcSystem ? catalog::PlcGroup::System
                                                                : catalog::PlcGroup::Work;
    if (p.plcTexts(g).contains(k))
        return profile::plcText(p, g, k, english); // the English when the machine file gives one
    return catalog::plcMessageAddress(g, k);
}

void Recorder::bits(MessageSource s, std::uint32_t shown, std::uint32_t present, int count,
                    Track* tracks, bool acknowledgeable, const std::string& how, int program,
                    int line) {
    for (int k = 1; k <= count; ++k) {
        Track& t = tracks[k];
        const bool on = (shown >> (k - 1)) & 1u;
        const bool cause = acknowledgeable ? ((present >> (k - 1)) & 1u) != 0 : on;
        if (t.seq == 0) {
            if (on) {
                t.seq = raise(s, k, plcText(s, k, false), plcText(s, k, true), program, line);
                t.cause = cause;
                if (!cause)
                    cleared(t);
            }
            continue;
        }
        if (t.cause && !cause)
            cleared(t);
        else if (!t.cause && cause)
            t.cause = true; // back while still shown: the same occurrence
        if (!on) {
            if (acknowledgeable)
                acknowledged(t, how);
            else
                t.seq = 0; // a work message ends when its bit drops
        }
    }
}

void Recorder::observe() {
    if (!ctl_)
        return;
    const engine::AlarmRegistry& reg = ctl_->alarmRegistry();
    step(ctl_->timeMs(), ctl_->words().word(1000), [&reg](int n) -> const engine::AlarmEntry& { return reg.entry(n); },
         ctl_->plcMessages(), ctl_->programView());
}

void Recorder::observe(const Observation& o) {
    // The messages shown, as the registry would hold them: latched, active
    // as told (a controller on the link shows only what is latched).
    std::array<engine::AlarmEntry, engine::kMessageCount + 1> entries{};
    for (const engine::AlarmView& a : o.alarms) {
        if (a.number < 1 || a.number > engine::kMessageCount)
            continue;
        engine::AlarmEntry& e = entries[static_cast<std::size_t>(a.number)];
        e.latched = true;
        e.active = a.active;
        e.program = a.program;
        e.line = a.line;
        e.order = 1;
    }
    step(o.timeMs, o.z1000, [&entries](int n) -> const engine::AlarmEntry& { return entries[static_cast<std::size_t>(n)]; },
         o.plc, o.program);
}

template <class EntryOf>
void Recorder::step(std::int64_t now, std::uint16_t z1000, EntryOf&& entryOf, const engine::PlcMessagesView& pm,
                    const engine::ProgramView& pv) {
    now_ = now;
    std::string how = note_;
    if (how.empty()) {
        if ((z1000 >> 7) & 1u)
            how = "z1000.7";
        else if (((z1000 & ~lastZ1000_) >> 5) & 1u)
            how = "reset";
        else
            how = "esc";
    }
    lastZ1000_ = z1000;
    note_.clear();

    const bool running = engine::programActive(pv.state);
    const int curProgram = running ? pv.program : 0, curLine = running ? pv.line : 0;

    // The positioner's messages 1..64.
    for (int n = 1; n <= engine::kMessageCount; ++n) {
        Track& t = positioner_[static_cast<std::size_t>(n)];
        const engine::AlarmEntry& e = entryOf(n);
        if (!e.latched && t.seq == 0)
            continue;
        if (t.seq != 0 && (!e.latched || e.order != t.order)) {
            acknowledged(t, how); // unlatched (or unlatched and latched again)
        }
        if (e.latched && t.seq == 0) {
            const catalog::PositionerMessage* m = catalog::findPositionerMessage(n);
            const bool own = e.program > 0;
            t.seq = raise(MessageSource::Positioner, n, m ? std::string(m->textRu) : std::string(),
                          m ? std::string(m->textEn) : std::string(),
                          own ? e.program : curProgram, own ? e.line : curLine);
            t.order = e.order;
            t.cause = e.active;
            if (!e.active)
                cleared(t); // an event: its cause is over when it latches
            continue;
        }
        if (t.seq != 0) {
            if (t.cause && !e.active)
                cleared(t);
            else if (!t.cause && e.active)
                t.cause = true;
        }
    }

    // The PLC's messages as the positioner remembers them.
    bits(MessageSource::PlcSystem, pm.system, pm.systemPresent, 16, plcSystem_.data(), true, how,
         curProgram, curLine);
    bits(MessageSource::PlcAlarm, pm.alarms, pm.alarmsPresent, 32, plcAlarm_.data(), true, how,
         curProgram, curLine);
    bits(MessageSource::PlcWork, pm.work, pm.work, 32, plcWork_.data(), false, how, curProgram,
         curLine);

    // The technological message of the program (#1..99).
    if (pv.messageNumber != programMessage_) {
        if (program_.seq != 0) {
            cleared(program_);
            program_.seq = 0;
        }
        programMessage_ = pv.messageNumber;
        if (pv.messageNumber > 0) {
            program_.seq = raise(MessageSource::Program, pv.messageNumber, pv.messageText,
                                 engine::programMessageText(pv, *machine_, true), curProgram, curLine);
            program_.cause = true;
        }
    }
}

void Recorder::stampDayTime(std::int64_t dayNowMs, double speed) {
    if (!(speed > 0))
        speed = 1.0;
    const std::int64_t now = now_;
    for (; stamped_ < events_.size(); ++stamped_) {
        MessageEvent& e = events_[stamped_];
        e.dayMs = dayNowMs - std::llround(static_cast<double>(now - e.machineMs) / speed);
    }
}

std::vector<MessageEvent> Recorder::takeEvents() {
    std::vector<MessageEvent> out;
    out.swap(events_);
    stamped_ = 0;
    return out;
}

std::vector<OpenMessage> Recorder::open() const {
    std::vector<OpenMessage> out;
    const auto add = [&](MessageSource s, const auto& tracks) {
        for (std::size_t k = 1; k < tracks.size(); ++k)
            if (tracks[k].seq != 0)
                out.push_back({tracks[k].seq, s, static_cast<int>(k), tracks[k].cause});
    };
    add(MessageSource::Positioner, positioner_);
    add(MessageSource::PlcSystem, plcSystem_);
    add(MessageSource::PlcAlarm, plcAlarm_);
    add(MessageSource::PlcWork, plcWork_);
    if (program_.seq != 0)
        out.push_back({program_.seq, MessageSource::Program, programMessage_, true});
    return out;
}

} // namespace k528::msglog
