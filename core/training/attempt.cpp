#include "training/attempt.h"

#include "catalog/messages.h"
#include "engine/load_programs.h"
#include "engine/rparams.h"
#include "machine/run.h"
#include "machine/simulation.h"
#include "msglog/recorder.h"
#include "panel/panel.h"
#include "profile/builtin.h"
#include "profile/tools.h"
#include "units/units.h"

#include <optional>
#include <algorithm>
#include <cmath>
#include <functional>

namespace k528::training {

namespace {

using engine::AxisId;
using engine::ProgramState;

constexpr std::int64_t kKeyMs = 50;        // an operator's key press on the K923
constexpr std::int64_t kReleaseSeenMs = 30; // the PLC's debounce sees a release
constexpr std::int64_t kStartSeenMs = 1500; // «Пуск» reaches the positioner
constexpr std::int64_t kM0WaitMs = 1000;    // the operator presses «Пуск» again at M00
constexpr double kPathToleranceUm = 1.0;

// The machine time an attempt may take at most.
std::int64_t guardMs(const Exercise& e) {
    const double limit = e.limits.cycleTimeS > 0 ? e.limits.cycleTimeS : 600;
    return static_cast<std::int64_t>(std::llround((4 * limit + 600) * 1000.0));
}

class Session {
public:
    Session(const AttemptInput& in, AttemptRecord& rec)
        : e_(*in.exercise), in_(in), rec_(rec), sim_(in.profile), ctl_(sim_.controller()),
          k923_(ctl_), recorder_(ctl_), decimator_(kPathToleranceUm, rec.path) {}

    void run() {
        sim_.powerOn();
        engine::loadPrograms(ctl_, in_.programs);
        const std::span<const std::int32_t> r0 = ctl_.rValues();
        std::copy(r0.begin(), r0.end(), rec_.rAtBegin.begin());
        // The lathe's path in the program's coordinates of the set-up; the
        // grinder's in the machine's (its ring is placed there).
        for (int i = 0; i < 2; ++i) {
            const engine::AxisView v = ctl_.axisView(engine::axisAt(i));
            offsetMm_[static_cast<std::size_t>(i)] =
                e_.lathe() ? units::discToMm(v.machineDisc - v.currentDisc, v.scale) : 0.0;
        }
        if (e_.lathe() && sim_.equipment().turret) {
            tools_ = profile::tools(in_.profile);
            station_ = startStation_ = sim_.equipment().turret->station();
        }
        if (e_.grinder() && sim_.equipment().grinding) {
            const machine::Grinding& g = *sim_.equipment().grinding;
            const double len = e_.ring->zMaxMm - e_.ring->zMinMm;
            const int cells = std::max(1, static_cast<int>(std::lround(len / rec_.bandMm)));
            rec_.bandMm = len / cells;
            for (int i = 0; i < cells; ++i)
                rec_.bands.push_back({e_.ring->zMinMm + i * rec_.bandMm, g.boreMm(), false, 0, 0, 0});
            lastBore_ = g.boreMm();
            rec_.blankBoreMm = g.boreMm();
        }
        spindle_ = sim_.equipment().spindle(e_.grinder() ? "wheel" : "spindle");
        slideAtFault_.assign(e_.faults.size(), 0.0);
        for (const FaultInjection& f : e_.faults) {
            FaultEvent ev;
            const machine::FaultText t = machine::faultText(f.fault);
            ev.id = t.id;
            ev.args = t.args;
            rec_.faults.push_back(ev);
        }
        guardEndMs_ = sim_.timeMs() + guardMs(e_);
        observer_ = sim_.addTickObserver([this] { observe(); });
        observe();

        for (const ProcedureStep& s : in_.procedure.steps) {
            if (guard())
                break;
            step(s);
        }
        // The machine goes on with a program under way after the last step.
        if (!guard() && engine::executing(ctl_.state()))
            runProgram(nullptr);
        // The slides come to rest before the part and the machine are looked at.
        restTicks_ = 0;
        until([&] { return !moving(); }, 10000);
        // A spindle told to stop coasts down (the wheel for seconds): the
        // operator waits for it before he looks at the machine.
        if (coasting())
            until([&] { return !coasting(); }, 30000);
        finish();
        sim_.removeTickObserver(observer_);
    }

private:
    // --- time ------------------------------------------------------------------
    bool guard() {
        if (sim_.timeMs() >= guardEndMs_)
            rec_.guardHit = true;
        return rec_.guardHit;
    }
    void advance(std::int64_t ms) {
        const std::int64_t end = sim_.timeMs() + ms;
        while (sim_.timeMs() < end && !guard())
            sim_.tick();
    }
    bool until(const std::function<bool()>& done, std::int64_t maxMs) {
        const std::int64_t end = sim_.timeMs() + maxMs;
        while (sim_.timeMs() < end && !guard()) {
            sim_.tick();
            if (done())
                return true;
        }
        return false;
    }
    void note(const ProcedureStep& s, std::string id, std::vector<TextArg> args = {}) {
        rec_.notes.push_back({s.line, s.token, Text{std::move(id), std::move(args)}});
    }

    // --- the procedure ------------------------------------------------------------
    void key(panel::KeyPress k) {
        k923_.press(k);
        k923_.setHealth(sim_.k923Health());
        advance(kKeyMs);
    }
    void key(panel::Key k) { key(panel::KeyPress{k}); }
    void digits(std::int64_t v) {
        if (v < 0)
            key(panel::Key::Minus);
        const std::string s = std::to_string(v < 0 ? -v : v);
        for (char c : s)
            key(static_cast<panel::Key>(static_cast<int>(panel::Key::D0) + (c - '0')));
    }

    void step(const ProcedureStep& s) {
        using K = ProcedureStep::Kind;
        switch (s.kind) {
        case K::Key:
            key(s.key);
            break;
        case K::Push:
        case K::Hold:
            sim_.press(s.button);
            advance(s.ms);
            sim_.release(s.button);
            advance(kReleaseSeenMs);
            break;
        case K::EstopPush:
            sim_.pressEmergencyStop();
            advance(kReleaseSeenMs);
            break;
        case K::EstopPull:
            sim_.releaseEmergencyStop();
            advance(kReleaseSeenMs);
            break;
        case K::Wait:
            advance(s.ms);
            break;
        case K::Home:
            home(s);
            break;
        case K::Run:
            runProgram(&s);
            break;
        case K::Program:
            key(panel::Key::F1);
            key(panel::Key::Ack);
            digits(s.value);
            key(panel::Key::Enter);
            if (ctl_.programView().selectedProgram != s.value)
                note(s, "note.program-refused", {std::to_string(s.value)});
            break;
        case K::Preset:
            preset(s);
            break;
        case K::Handwheel:
            sim_.selectHandwheel(s.value == 0   ? machine::HandwheelAxis::Off
                                 : s.value == 1 ? machine::HandwheelAxis::X
                                                : machine::HandwheelAxis::Z);
            advance(kReleaseSeenMs);
            break;
        case K::HandwheelStep:
            sim_.selectHandwheelMultiplier(static_cast<int>(s.value));
            advance(kReleaseSeenMs);
            break;
        case K::Turn:
            turn(s);
            break;
        case K::Override:
            try {
                machine::SimulationRunMachine m(sim_);
                m.setOverrideCode(units::overridePercentToCode(static_cast<int>(s.value)));
            } catch (const std::invalid_argument&) {
                note(s, "note.override-refused", {std::to_string(s.value)});
            }
            advance(kReleaseSeenMs);
            break;
        case K::NewWheel:
            if (sim_.changeWheel())
                rec_.wheelChanged = true;
            else
                note(s, "note.new-wheel-refused");
            advance(kKeyMs);
            break;
        case K::DoorOpen:
            if (!sim_.openDoor())
                note(s, "note.door-refused");
            advance(kReleaseSeenMs);
            break;
        case K::DoorClose:
            sim_.closeDoor();
            advance(kReleaseSeenMs);
            break;
        }
    }

    void home(const ProcedureStep& s) {
        key(panel::Key::F3);
        machine::SimulationRunMachine m(sim_);
        const engine::HomingResult h = engine::homeAxes(m);
        if (h.status != engine::RunStatus::Completed) {
            std::string why;
            for (const engine::RunBlocker& b : h.blockedBy)
                why += (why.empty() ? "" : "; ") + engine::describeBlocker(b, true);
            std::string whyEn;
            for (const engine::RunBlocker& b : h.blockedBy)
                whyEn += (whyEn.empty() ? "" : "; ") + engine::describeBlocker(b, false);
            note(s, "note.home-failed", {TextArg(why, whyEn)});
        }
    }

    // R<n>=<v> on РУЧ screen 3: F2, MODE until the R-parameters show, PAR,
    // the number, ENTER, the value, ENTER.
    void preset(const ProcedureStep& s) {
        key(panel::Key::F2);
        for (int i = 0; i < 3 && !rScreen(); ++i)
            key(panel::Key::Mode);
        if (!rScreen()) {
            note(s, "note.preset-refused", {"R" + std::to_string(s.r), std::to_string(s.value)});
            return;
        }
        key(panel::Key::Par);
        digits(s.r);
        key(panel::Key::Enter);
        digits(s.value);
        key(panel::Key::Enter);
        if (ctl_.r(s.r) != s.value)
            note(s, "note.preset-refused", {"R" + std::to_string(s.r), std::to_string(s.value)});
    }
    bool rScreen() {
        const panel::Display d = k923_.display();
        for (int i = 1; i < 4; ++i) {
            const std::string& l = d.lcd.lines[static_cast<std::size_t>(i)];
            if (l.size() > 2 && (l[1] == 'R') && l.find('=') != std::string::npos)
                return true;
        }
        return false;
    }

    // The setpoints stand and the slides have come to rest (the following
    // error runs out after the setpoint stops).
    bool moving() {
        bool m = false;
        for (int i = 0; i < 2; ++i) {
            const AxisId a = engine::axisAt(i);
            if (!ctl_.axisPresent(a))
                continue;
            const double p = sim_.slideMm(a);
            m = m || ctl_.axisView(a).moving || std::fabs(p - restPos_[static_cast<std::size_t>(i)]) > 1e-6;
            restPos_[static_cast<std::size_t>(i)] = p;
        }
        restTicks_ = m ? 0 : restTicks_ + 1;
        return restTicks_ < 20;
    }

    // A spindle that runs with no speed set: coasting down after a stop.
    bool coasting() {
        for (const auto& sp : sim_.equipment().spindles)
            if (sp->running() && sp->targetRpm() == 0)
                return true;
        return false;
    }

    void turn(const ProcedureStep& s) {
        sim_.turnHandwheel(s.value);
        advance(100);
        restTicks_ = 0;
        // The slide follows the pulses: wait until it stands again.
        until([&] { return !moving(); }, 600000);
    }

    // RUN: until the program ends, a message stops it, or it is held by
    // «Стоп»; at M00 «Пуск» again after a second.
    void runProgram(const ProcedureStep* s) {
        if (!engine::programActive(ctl_.state())) {
            const bool started =
                until([&] { return engine::programActive(ctl_.state()); }, kStartSeenMs);
            if (!started) {
                rec_.blockedBy = engine::startBlockers(
                    ctl_, {"start", 0, "программа не запущена", "the program did not start"});
                if (s)
                    note(*s, "note.not-started");
                return;
            }
        }
        std::int64_t m0Since = -1;
        while (!guard()) {
            const ProgramState st = ctl_.state();
            if (!engine::programActive(st) || st == ProgramState::Interrupted)
                return;
            if (st == ProgramState::M0) {
                if (m0Since < 0)
                    m0Since = sim_.timeMs();
                if (sim_.timeMs() - m0Since >= kM0WaitMs &&
                    !sim_.buttonDown(machine::Button::CycleStart)) {
                    sim_.pressFor(machine::Button::CycleStart, 100);
                    m0Since = -1;
                }
            } else {
                m0Since = -1;
            }
            sim_.tick();
        }
    }

    // Where the tip of the tool in use stands off the tip of the tool the set-up
    // was made with (the turret's station at the start): the difference of
    // their offsets (the machine's R presets, profile/tools.h). The slide
    // carries the tool; nothing moves the tip onto the programmed point
    // unless the program copies the new tool's offsets into the correction
    // R226/R227 (docs/engine.md "The tool change"), which moves the slide.
    profile::ToolOffsets toolShift() {
        if (tools_.empty())
            return {};
        if (const int st = sim_.equipment().turret->station(); st > 0)
            station_ = st; // between stations: the tool that was locked last
        if (station_ == shiftStation_)
            return shift_;
        shiftStation_ = station_;
        const auto offsetsAt = [&](int station) {
            const std::optional<profile::Tool> tool = profile::toolAt(tools_, station);
            return tool ? profile::toolOffsets(*tool, in_.profile) : profile::ToolOffsets{};
        };
        const profile::ToolOffsets now = offsetsAt(station_), start = offsetsAt(startStation_);
        shift_ = {now.xMm - start.xMm, now.zMm - start.zMm};
        return shift_;
    }

    // --- watching every tick ------------------------------------------------------
    void observe() {
        const double t = static_cast<double>(sim_.timeMs());
        const ProgramState st = ctl_.state();
        const bool active = engine::programActive(st);
        const engine::Interpreter& in = ctl_.interpreter();

        toolpath::ActualSample s;
        s.tMs = t;
        const profile::ToolOffsets shift = toolShift();
        s.x = sim_.machineMm(AxisId::X) - offsetMm_[0] - shift.xMm;
        s.z = sim_.machineMm(AxisId::Z) - offsetMm_[1] - shift.zMm;
        if (active) {
            s.program = in.program();
            s.line = in.line();
            s.n = in.frameNumber();
            s.kind = ctl_.modal().rapid ? toolpath::SegmentKind::Rapid : toolpath::SegmentKind::Feed;
        } else {
            s.manual = true;
            s.kind = sim_.buttonDown(machine::Button::Rapid) ? toolpath::SegmentKind::Rapid
                                                              : toolpath::SegmentKind::Feed;
        }
        decimator_.add(s);

        if (spindle_) {
            const bool running = spindle_->running();
            if (rec_.spindle.empty() || rec_.spindle.back().running != running)
                rec_.spindle.push_back({t, running});
        }

        // The program's starts and ends.
        if (active && !wasActive_) {
            ++rec_.starts;
            if (rec_.firstStartMs < 0) {
                rec_.firstStartMs = t;
                const std::span<const std::int32_t> r = ctl_.rValues();
                std::copy(r.begin(), r.end(), rec_.rAtFirstStart.begin());
                for (int i = 0; i < 2; ++i) {
                    const AxisId a = engine::axisAt(i);
                    rec_.referencedAtFirstStart[static_cast<std::size_t>(i)] =
                        !ctl_.axisPresent(a) || ctl_.referenceOk(a);
                }
            }
        }
        if (st == ProgramState::Ended && lastState_ != ProgramState::Ended)
            rec_.lastEndMs = t;
        wasActive_ = active;
        lastState_ = st;

        faults(t, active);
        messages();
        if (!rec_.bands.empty())
            grind(t, active, s);
    }

    void faults(double t, bool active) {
        const engine::Interpreter& in = ctl_.interpreter();
        for (std::size_t i = 0; i < e_.faults.size(); ++i) {
            const FaultInjection& f = e_.faults[i];
            FaultEvent& ev = rec_.faults[i];
            if (ev.injectedMs < 0) {
                bool due = false;
                if (f.atFrame)
                    due = active && in.program() == f.atFrame->program &&
                          in.frameNumber() == f.atFrame->n;
                else if (f.atS)
                    due = rec_.firstStartMs >= 0 && t - rec_.firstStartMs >= *f.atS * 1000.0;
                if (!due)
                    continue;
                try {
                    sim_.inject(f.fault);
                } catch (const std::invalid_argument&) {
                    ev.injectedMs = -2; // the machine cannot have it: never
                    continue;
                }
                ev.injectedMs = t;
                if (active) {
                    ev.program = in.program();
                    ev.line = in.line();
                    ev.n = in.frameNumber();
                }
                slideAtFault_[i] = sim_.slideMm(f.fault.axis);
                continue;
            }
            if (ev.injectedMs < 0 || ev.clearedMs >= 0)
                continue;
            bool over = false;
            if (f.until == FaultInjection::Until::Time)
                over = t - ev.injectedMs >= f.forS * 1000.0;
            else if (f.until == FaultInjection::Until::MovedOff) {
                // Off the switch: the slide moved away from the side it hit.
                const double moved = sim_.slideMm(f.fault.axis) - slideAtFault_[i];
                over = (f.fault.detail > 0 ? -moved : moved) >= f.moveOffMm;
            }
            if (over) {
                sim_.clear(f.fault);
                ev.clearedMs = t;
            }
        }
    }

    void messages() {
        const engine::AlarmRegistry& reg = ctl_.alarmRegistry();
        const engine::PlcMessagesView pm = ctl_.plcMessages();
        const std::array<std::uint64_t, 6> key{reg.latchedMask(), reg.activeMask(), pm.alarms,
                                               pm.alarmsPresent, pm.system, pm.systemPresent};
        if (key == messageKey_ && messagesSeen_)
            return;
        messageKey_ = key;
        messagesSeen_ = true;
        recorder_.observe();
        for (const db::MessageEvent& ev : recorder_.takeEvents()) {
            const db::MessageSource src = ev.message.source;
            if (src == db::MessageSource::PlcWork || src == db::MessageSource::Program)
                continue;
            if (ev.kind == db::MessageEvent::Kind::Raised) {
                SeenMessage m;
                m.source = src;
                m.number = ev.message.number;
                m.code = db::messageCode(src, m.number);
                m.textRu = ev.message.text;
                m.textEn = ev.message.textEn;
                m.program = ev.message.program;
                m.line = ev.message.line;
                m.tMs = static_cast<double>(ev.machineMs);
                seq_.push_back(ev.seq);
                rec_.messages.push_back(std::move(m));
            } else if (ev.kind == db::MessageEvent::Kind::Acknowledged) {
                for (std::size_t i = 0; i < seq_.size(); ++i)
                    if (seq_[i] == ev.seq)
                        rec_.messages[i].acknowledged = true;
            }
        }
    }

    void grind(double t, bool active, const toolpath::ActualSample& s) {
        (void)t;
        const machine::Grinding& g = *sim_.equipment().grinding;
        const double bore = g.boreMm();
        const double z = sim_.machineMm(AxisId::Z);
        const double edge = g.edgeMm(sim_.machineMm(AxisId::X));
        const Ring& ring = *e_.ring;
        const bool overlap = z < ring.zMaxMm && z + ring.wheelWidthMm > ring.zMinMm;
        if (bore > lastBore_ + 1e-12) {
            for (BandCell& c : rec_.bands) {
                if (c.zMm + rec_.bandMm <= z || c.zMm >= z + ring.wheelWidthMm)
                    continue;
                if (bore > c.boreMm) {
                    c.boreMm = bore;
                    c.ground = true;
                    c.program = s.program;
                    c.line = s.line;
                    c.n = s.n;
                }
            }
        }
        lastBore_ = bore;
        // A motion that pushes the wheel into the ring's wall or face: the
        // prove-out's rule for it (a rapid; a feed with the wheel standing).
        if (active && overlap && edge > bore + 0.01 &&
            (edge > lastEdge_ + 1e-9 || std::fabs(z - lastZ_) > 1e-9)) {
            const proveout::Motion motion = s.manual ? proveout::Motion::Manual
                                            : s.kind == toolpath::SegmentKind::Rapid
                                                ? proveout::Motion::Rapid
                                                : proveout::Motion::Feed;
            const std::optional<proveout::Rule> rule =
                proveout::materialRule(motion, spindle_ && spindle_->running(), true);
            if (rule && (rec_.ringContacts.empty() || rec_.ringContacts.back().line != s.line ||
                         rec_.ringContacts.back().program != s.program))
                rec_.ringContacts.push_back({*rule, s.program, s.line, s.n, edge, bore, z});
        }
        lastEdge_ = edge;
        lastZ_ = z;
    }

    void finish() {
        decimator_.finish();
        rec_.endMs = static_cast<double>(sim_.timeMs());
        rec_.endState = ctl_.state();
        const engine::ProgramView p = ctl_.programView();
        rec_.endProgram = p.program;
        rec_.endLine = p.line;
        rec_.endN = p.frameNumber;
        const std::span<const std::int32_t> r = ctl_.rValues();
        std::copy(r.begin(), r.end(), rec_.rAtEnd.begin());
        for (int i = 0; i < 2; ++i) {
            const AxisId a = engine::axisAt(i);
            const engine::AxisView v = ctl_.axisView(a);
            rec_.referencedAtEnd[static_cast<std::size_t>(i)] = !v.present || v.referenceOk;
            rec_.currentAtEndMm[static_cast<std::size_t>(i)] = units::discToMm(v.currentDisc, v.scale);
        }
        const machine::Equipment& eq = sim_.equipment();
        rec_.spindlesStoppedAtEnd = true;
        for (const auto& sp : eq.spindles)
            rec_.spindlesStoppedAtEnd = rec_.spindlesStoppedAtEnd && !sp->running();
        for (const auto& pu : eq.pumps)
            if (pu->settings().name == "coolant")
                rec_.coolantOffAtEnd = !pu->on();
        rec_.gaugeOutAtEnd = !eq.grinding || !eq.grinding->gaugeIn();
    }

    const Exercise& e_;
    const AttemptInput& in_;
    AttemptRecord& rec_;
    machine::Simulation sim_;
    engine::Positioner& ctl_;
    panel::Panel k923_;
    msglog::Recorder recorder_;
    toolpath::Decimator decimator_;
    int observer_ = 0;
    std::int64_t guardEndMs_ = 0;
    std::array<double, 2> offsetMm_{};
    std::vector<profile::Tool> tools_; // the lathe's turret stations (none: no turret)
    int station_ = 0, startStation_ = 0, shiftStation_ = -1;
    profile::ToolOffsets shift_;
    const machine::Spindle* spindle_ = nullptr;
    bool wasActive_ = false;
    ProgramState lastState_ = ProgramState::Idle;
    std::vector<double> slideAtFault_;
    std::array<std::uint64_t, 6> messageKey_{};
    bool messagesSeen_ = false;
    std::vector<std::int64_t> seq_; // the recorder's occurrence of each rec_.messages entry
    double lastBore_ = 0, lastEdge_ = 0, lastZ_ = 0;
    std::array<double, 2> restPos_{};
    int restTicks_ = 0;
};

} // namespace

profile::MachineProfile exerciseProfile(const Exercise& e) {
    profile::MachineProfile p = profile::builtin(e.machine);
    for (const auto& [n, v] : e.setupR)
        p.r[n] = v;
    return p;
}

AttemptRecord runAttempt(const AttemptInput& in) {
    AttemptRecord rec;
    Session s(in, rec);
    s.run();
    return rec;
}

} // namespace k528::training
