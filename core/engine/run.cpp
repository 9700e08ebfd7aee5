#include "engine/run.h"

#include "catalog/messages.h"
#include "engine/positioner.h"
#include "engine/ideal_machine.h"
#include "engine/load_programs.h"
#include "profile/english.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace k528::engine {

std::string_view runStatusName(RunStatus s) {
    switch (s) {
    case RunStatus::Completed:
        return "completed";
    case RunStatus::Alarm:
        return "alarm";
    case RunStatus::Timeout:
        return "timeout";
    case RunStatus::Blocked:
        return "blocked";
    }
    return "";
}

std::string describeBlocker(const RunBlocker& b, bool russian) {
    const std::string& text = russian ? b.textRu : b.textEn;
    if (b.number == 0)
        return text;
    const char letter = b.source == "plc_alarm" ? 'A' : b.source == "plc_work" ? 'W' : 'S';
    std::string k = std::to_string(b.number);
    if (k.size() < 2)
        k = "0" + k;
    return std::string(1, letter) + k + (text.empty() ? "" : " " + text);
}

namespace {

constexpr std::int64_t kSwitchOnMs = 10000;
// After «Пуск» is let go: the PLC's debounce and scans have passed it on.
constexpr std::int64_t kStartSeenMs = 1000;
// An operator's hand between two pushes of «Пуск»: released this long
// before the next push, so that the PLC sees the release. Pressed again at
// the very tick of the release, the button never looks released and the
// press is never taken (an M00 with --m0-wait 0 then waited for ever).
constexpr std::int64_t kReleasedBeforePushMs = 100;

void collect(RunMachine& machine, RunResult& res) {
    const Positioner& ctl = machine.controller();
    res.alarms = ctl.alarms();
    res.frames = ctl.framesExecuted();
    for (int i = 0; i < kAxisCount; ++i) {
        const AxisView v = ctl.axisView(axisAt(i));
        RunAxis& a = res.axes[static_cast<std::size_t>(i)];
        a.present = v.present;
        a.scale = v.scale;
        a.currentDisc = v.currentDisc;
        a.machineDisc = v.machineDisc;
    }
    const std::span<const std::int32_t> r = ctl.r().values();
    std::copy(r.begin(), r.end(), res.r.begin());
    const ProgramView p = ctl.programView();
    res.state = p.state;
    res.program = p.program;
    res.frameNumber = p.frameNumber;
    res.line = p.line;
    res.messageNumber = p.messageNumber;
    res.messageText = p.messageText;
    res.mFunctions = machine.mFunctions();
    res.modal = ctl.modal();
}

bool runUntil(RunMachine& m, const std::function<bool()>& done, std::int64_t maxMs) {
    Positioner& ctl = m.controller();
    const std::int64_t end = ctl.timeMs() + maxMs;
    while (ctl.timeMs() < end) {
        m.tick();
        if (done())
            return true;
    }
    return false;
}

// An owning ideal machine for runProgram(profile, ...).
struct OwnedIdealMachine {
    explicit OwnedIdealMachine(const profile::MachineProfile& p) : ctl(p), m(ctl), run(ctl, m) {}
    Positioner ctl;
    IdealMachine m;
    IdealRunMachine run;
};

} // namespace

std::vector<RunBlocker> startBlockers(const Positioner& ctl, RunBlocker what) {
    std::vector<RunBlocker> out;
    const InterfaceWords& w = ctl.words();
    if (!w.bit(z::EmergencyStopOk))
        out.push_back({"emergency_stop", 0, "Z1000.0 «Аварийный стоп» = 0",
                       "Z1000.0 emergency stop = 0"});
    if (!w.bit(z::StartEnable))
        out.push_back({"start_enable", 0, "Z1000.2 «Деблокировка пуска программы» = 0",
                       "Z1000.2 program start enable = 0"});
    const unsigned code = (w.word(z::ModeCodeWord) >> z::ModeCodeFirst) & 7u;
    if (code != 0 && code != static_cast<unsigned>(Mode::Auto))
        out.push_back({"mode", 0,
                       "Z1000.8-10: ПЛК задает режим " + std::to_string(code),
                       "Z1000.8-10: the PLC imposes mode " + std::to_string(code)});
    const PlcMessagesView m = ctl.plcMessages();
    const auto add = [&](catalog::PlcGroup g, std::uint32_t bits, const char* source) {
        const auto& texts = ctl.profile().plcTexts(g);
        for (int k = 1; k <= catalog::plcMessageCount(g); ++k)
            if ((bits >> (k - 1)) & 1u) {
                const auto t = texts.find(k);
                const std::string text = t == texts.end() ? std::string() : t->second;
                // The machine file's English beside its Russian, when it gives one.
                const std::string en = t == texts.end() ? std::string() : profile::plcText(ctl.profile(), g, k, true);
                out.push_back({source, k, text, en});
            }
    };
    add(catalog::PlcGroup::Alarm, m.alarms, "plc_alarm");
    add(catalog::PlcGroup::System, m.system, "plc_system");
    add(catalog::PlcGroup::Work, m.work, "plc_work");
    out.push_back(std::move(what));
    return out;
}

void IdealRunMachine::tick() {
    m_.tick();
}
bool IdealRunMachine::switchOn(std::int64_t) {
    m_.advance(10); // the PLC's first scans: regulators enabled, loops closed
    return true;
}
void IdealRunMachine::setOverrideCode(int code) {
    m_.setOverrideCode(code);
}
void IdealRunMachine::startReferenceCycle(AxisId a, int dir) {
    m_.setJog(a, dir);
    m_.tick();
    m_.setJog(a, 0);
}
void IdealRunMachine::pressStart() {
    m_.pressStart();
}
bool IdealRunMachine::startHeld() const {
    return ctl_.words().bit(z::Start);
}
std::vector<int> IdealRunMachine::mFunctions() const {
    return m_.mLog();
}

HomingResult homeAxes(RunMachine& machine) {
    HomingResult res;
    Positioner& ctl = machine.controller();
    const std::int64_t t0 = ctl.timeMs();
    const auto elapsed = [&] { return static_cast<double>(ctl.timeMs() - t0) / 1000.0; };
    const std::uint64_t latchedBefore = ctl.alarmRegistry().latchedMask();
    const auto newAlarm = [&] { return (ctl.alarmRegistry().latchedMask() & ~latchedBefore) != 0; };
    ctl.selectMode(Mode::Reference);
    for (int i = 0; i < kAxisCount; ++i) {
        const AxisId a = axisAt(i);
        if (!ctl.axisPresent(a) || ctl.referenceOk(a))
            continue;
        const bool negative = ctl.c()[c::ofAxis(c::HomeNegativeX, i)] != 0;
        machine.startReferenceCycle(a, negative ? -1 : 1);
        // The cycle starts once the PLC has passed the button on.
        const bool started = runUntil(
            machine, [&] { return ctl.homing(a) || ctl.referenced(a) || newAlarm(); },
            kHomingStartMs);
        if (!started) {
            const std::string ax = a == AxisId::X ? "X" : "Z";
            res.status = RunStatus::Blocked;
            res.timeS = elapsed();
            res.blockedBy = startBlockers(
                ctl, {"homing", 0, "привязка к базовой точке по " + ax + " не началась",
                      "the reference-point cycle of " + ax + " did not start"});
            return res;
        }
        const bool done = runUntil(
            machine, [&] { return ctl.referenced(a) || !ctl.homing(a) || newAlarm(); },
            kHomingGuardMs);
        res.timeS = elapsed();
        if (newAlarm()) {
            res.status = RunStatus::Alarm;
            return res;
        }
        if (!done || !ctl.referenced(a)) {
            res.status = RunStatus::Timeout;
            return res;
        }
    }
    res.timeS = elapsed();
    return res;
}

RunResult runProgram(RunMachine& machine, const program::ProgramStore& programs, int number,
                     const RunOptions& options) {
    RunResult res;
    Positioner& ctl = machine.controller();
    ctl.powerOn();
    loadPrograms(ctl, programs); // a fresh controller: no program runs
    for (const auto& [n, v] : options.rPresets)
        ctl.setR(n, v);
    // The operator homes at 100 % and sets the program's override before
    // «Пуск»: --override is the program's, not the reference-point cycle's.
    constexpr int kFullOverrideCode = 10;
    const int code = units::overridePercentToCode(options.overridePercent);
    machine.setOverrideCode(kFullOverrideCode);
    const std::int64_t limitMs =
        static_cast<std::int64_t>(std::llround(options.maxSeconds * 1000.0));

    const auto finish = [&](RunStatus s) {
        res.status = s;
        collect(machine, res);
        return res;
    };
    if (ctl.alarmRegistry().anyLatched())
        return finish(RunStatus::Alarm); // the power-on test found something
    const bool ready = machine.switchOn(kSwitchOnMs);
    if (ctl.alarmRegistry().anyLatched())
        return finish(RunStatus::Alarm);
    if (!ready) {
        res.blockedBy = startBlockers(
            ctl, {"drives", 0, "станок не готов (приводы не включены)", "the machine is not ready (drives off)"});
        return finish(RunStatus::Blocked);
    }

    if (options.home) {
        HomingResult h = homeAxes(machine);
        res.homeTimeS = h.timeS;
        if (h.status != RunStatus::Completed) {
            res.blockedBy = std::move(h.blockedBy);
            return finish(h.status);
        }
    }

    machine.setOverrideCode(code >= 0 ? code : kFullOverrideCode);
    ctl.selectMode(Mode::Auto);
    ctl.selectProgram(number);
    if (options.from)
        ctl.setStartPoint(options.from);
    machine.pressStart();
    const std::int64_t pressed = ctl.timeMs();
    const std::int64_t m0WaitMs = static_cast<std::int64_t>(std::llround(options.m0WaitS * 1000.0));
    std::int64_t m0Since = -1;
    std::int64_t upSince = -1;    // «Пуск» released since then
    std::int64_t releasedMs = -1; // the first «Пуск» let go
    RunStatus status = RunStatus::Timeout;
    // The limit counts from the moment the positioner saw «Пуск» (the PLC's
    // debounce lies between the press and that moment).
    const auto since = [&] {
        return ctl.programStartMs() >= pressed ? ctl.programStartMs() : pressed;
    };
    // The axes' presence and scale stay while a program runs (C-parameters
    // are edited in another mode): read once, not a view each tick.
    std::array<bool, kAxisCount> present{};
    std::array<units::AxisScale, kAxisCount> scale{};
    for (int i = 0; i < kAxisCount; ++i) {
        const AxisView v = ctl.axisView(axisAt(i));
        present[static_cast<std::size_t>(i)] = v.present;
        scale[static_cast<std::size_t>(i)] = v.scale;
    }
    while (ctl.timeMs() - since() < limitMs) {
        machine.tick();
        for (int i = 0; i < kAxisCount; ++i) {
            const std::size_t k = static_cast<std::size_t>(i);
            double& peak = res.axes[k].maxFollowingErrorDisc;
            if (present[k])
                peak = std::max(peak, std::fabs(units::internalToDisc(
                                          ctl.servo(axisAt(i)).followingError(), scale[k])));
        }
        const ProgramState s = ctl.state();
        if (s == ProgramState::Ended) {
            status = RunStatus::Completed;
            break;
        }
        if (s == ProgramState::Alarm || (ctl.alarmRegistry().anyLatched() && !programActive(s))) {
            status = RunStatus::Alarm;
            break;
        }
        if (ctl.programStartMs() < pressed && !programActive(s)) {
            // «Пуск» not taken: once the press is over and the PLC has had
            // time to pass it on, the run is blocked; say by what.
            if (releasedMs < 0 && !machine.startHeld())
                releasedMs = ctl.timeMs();
            if (releasedMs >= 0 && ctl.timeMs() - releasedMs >= kStartSeenMs) {
                res.blockedBy = startBlockers(ctl, {"start", 0, "«Пуск» не принят позиционером",
                                                    "«Пуск» was not taken by the positioner"});
                status = RunStatus::Blocked;
                break;
            }
        }
        if (machine.startHeld())
            upSince = -1;
        else if (upSince < 0)
            upSince = ctl.timeMs();
        if (s == ProgramState::M0) {
            if (m0Since < 0)
                m0Since = ctl.timeMs();
            if (ctl.timeMs() - m0Since >= m0WaitMs && upSince >= 0 &&
                ctl.timeMs() - upSince >= kReleasedBeforePushMs) {
                machine.pressStart();
                m0Since = -1;
                upSince = -1;
            }
        }
    }
    const std::int64_t start = ctl.programStartMs() >= 0 ? ctl.programStartMs() : ctl.timeMs();
    res.timeS = static_cast<double>(ctl.timeMs() - start) / 1000.0;
    return finish(status);
}

RunResult runProgram(const profile::MachineProfile& profile, const program::ProgramStore& programs,
                     int number, const RunOptions& options) {
    OwnedIdealMachine machine(profile);
    return runProgram(machine.run, programs, number, options);
}

} // namespace k528::engine
