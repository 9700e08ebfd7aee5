// What every test rig around a simulated K528-05 gives a test: the built-in
// profile it was made from (tweaked by the test), programs loaded from text,
// waiting on a condition in machine time, the reference-point cycles, the
// program's end and the alarms. The machine under the controller is the
// rig's own: the ideal machine (EngineRig, PanelRig) or the simulated
// machine with its PLC (MachineRig).
#pragma once

#include "engine/positioner.h"
#include "engine/load_programs.h"
#include "engine/run.h"
#include "profile/builtin.h"
#include "program/diagnostic_texts.h"
#include "program/parser.h"

#include <QtTest>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace k528::testrig {

using engine::AxisId;
using engine::Mode;
using engine::ProgramState;
using engine::ZBit;

inline constexpr AxisId X = AxisId::X;
inline constexpr AxisId Z = AxisId::Z;

// Edits a profile before the rig builds its controller from it.
using ProfileTweak = std::function<void(profile::MachineProfile&)>;

inline profile::MachineProfile tweakedProfile(std::string_view name, const ProfileTweak& tweak) {
    profile::MachineProfile p = profile::builtin(name);
    if (tweak)
        tweak(p);
    return p;
}

// Profile tweaks: programs run without the reference-point cycles (АВТ.БЕЗ ПБТ = 1).
inline void noHoming(profile::MachineProfile& p) {
    p.setC(8, 1);
    p.setC(60, 1);
}
inline void setC(profile::MachineProfile& p, int n, std::int64_t v) {
    p.setC(n, v);
}

// Tolerance of an axis that ended a move, in display discretes: the frame
// ends inside ДОПУСК ПОЗ (10 internal units = 10 discretes on the diameter
// axis X of the training lathe, 5 on Z).
inline constexpr std::int64_t kRestTol = 10;

class ControllerRig {
public:
    profile::MachineProfile prof;

    virtual ~ControllerRig() = default;
    ControllerRig(const ControllerRig&) = delete;
    ControllerRig& operator=(const ControllerRig&) = delete;

    virtual engine::Positioner& c() = 0;
    virtual const engine::Positioner& c() const = 0;
    // Ticks until `done` holds or `maxMs` of machine time passed; false then.
    virtual bool until(const std::function<bool()>& done, std::int64_t maxMs) = 0;
    // engine/run.h's view of this rig's machine (homing, runs).
    virtual std::unique_ptr<engine::RunMachine> runMachine() = 0;

    bool bit(ZBit b) const { return c().words().bit(b); }

    // Loads programs from text (replacing those with the same numbers).
    void load(const std::string& text) {
        const program::ParseResult r = program::parse(text);
        QVERIFY2(!r.hasErrors(),
                 r.diagnostics.empty() ? "parse error" : program::diagnosticText(r.diagnostics.front(), false).c_str());
        QVERIFY(engine::loadPrograms(c(), r.store).ok());
    }

    // Homes every present axis that needs it, X first, as `k528 run` does
    // (engine::homeAxes). False on failure.
    bool home() {
        const std::unique_ptr<engine::RunMachine> run = runMachine();
        return engine::homeAxes(*run).status == engine::RunStatus::Completed;
    }

    // Ticks until the program ended, stopped with an alarm or went idle.
    bool runToEnd(std::int64_t maxMs = 600000) {
        return until(
            [&] {
                const ProgramState s = c().state();
                return s == ProgramState::Ended || s == ProgramState::Alarm || s == ProgramState::Idle;
            },
            maxMs);
    }
    bool untilState(ProgramState s, std::int64_t maxMs) {
        return until([&] { return c().state() == s; }, maxMs);
    }

    std::vector<int> alarms() const {
        std::vector<int> v;
        for (const auto& a : c().alarms())
            v.push_back(a.number);
        return v;
    }
    bool hasAlarm(int n) const { return c().alarmRegistry().latched(n); }

protected:
    explicit ControllerRig(profile::MachineProfile p) : prof(std::move(p)) {}
};

// "alarms: 12 45", for a failed check's message.
inline QString alarmList(const ControllerRig& r) {
    QString s = "alarms:";
    for (int n : r.alarms())
        s += " " + QString::number(n);
    return s;
}

} // namespace k528::testrig
