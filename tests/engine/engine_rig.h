// A Controller on the ideal machine, for the engine tests: a built-in
// profile (tweaked by the test), programs loaded from text, helpers to home,
// start and wait. Positions in display discretes unless a name says mm.
#pragma once

#include "engine/controller.h"
#include "engine/ideal_machine.h"
#include "engine/load_programs.h"
#include "engine/run.h"
#include "profile/builtin.h"
#include "program/parser.h"

#include <QtTest>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace rig {

using namespace k528;
using engine::AxisId;
using engine::Mode;
using engine::ProgramState;
using engine::ZBit;

inline constexpr AxisId X = AxisId::X;
inline constexpr AxisId Z = AxisId::Z;

struct Rig {
    profile::MachineProfile prof;
    std::unique_ptr<engine::Controller> ctl;
    std::unique_ptr<engine::IdealMachine> m;

    // `tweak` edits the profile before the controller is built.
    explicit Rig(std::string_view name = "training-lathe",
                 const std::function<void(profile::MachineProfile&)>& tweak = {}) {
        prof = profile::builtin(name);
        if (tweak)
            tweak(prof);
        ctl = std::make_unique<engine::Controller>(prof);
        m = std::make_unique<engine::IdealMachine>(*ctl);
        ctl->powerOn();
        m->advance(10);
    }

    engine::Controller& c() { return *ctl; }
    engine::InterfaceWords& w() { return ctl->words(); }
    bool bit(engine::ZBit b) const { return ctl->words().bit(b); }

    // Loads programs from text (replacing those with the same numbers).
    void load(const std::string& text) {
        const program::ParseResult r = program::parse(text);
        QVERIFY2(!r.hasErrors(),
                 r.diagnostics.empty() ? "parse error" : r.diagnostics.front().messageEn.c_str());
        QVERIFY(engine::loadPrograms(*ctl, r.store).ok());
    }

    void tick() { m->tick(); }
    void advance(std::int64_t ms) { m->advance(ms); }
    bool until(const std::function<bool()>& done, std::int64_t maxMs) {
        return m->runUntil(done, maxMs);
    }

    // Homes every present axis that needs it, X first, as `k528 run` does
    // (engine::homeAxes). False on failure.
    bool home() {
        engine::IdealRunMachine run(*ctl, *m);
        return engine::homeAxes(run).status == engine::RunStatus::Completed;
    }

    // АВТОМАТ, program n, «Пуск»; ticks until the program started (or refused).
    void start(int n) {
        until([&] { return !ctl->words().bit(engine::z::Start); }, 1000); // a fresh edge
        ctl->selectMode(Mode::Auto);
        ctl->selectProgram(n);
        m->pressStart();
        tick();
        tick();
    }
    // Ticks until the program ended or stopped with an alarm.
    bool runToEnd(std::int64_t maxMs = 600000) {
        return until(
            [&] {
                const ProgramState s = ctl->state();
                return s == ProgramState::Ended || s == ProgramState::Alarm ||
                       s == ProgramState::Idle;
            },
            maxMs);
    }
    // Ticks until the setpoint of `a` has arrived at its target (the
    // trapezoid is over); returns the ms since the program started, -1 if not.
    double setpointArrivalS(AxisId a, std::int64_t maxMs) {
        const auto& s = ctl->servo(a);
        if (!until(
                [&] {
                    return s.setpoint() == s.target() && s.commandVelocity() == 0.0 &&
                           s.target() != 0.0;
                },
                maxMs))
            return -1;
        return static_cast<double>(ctl->timeMs() - ctl->programStartMs()) / 1000.0;
    }
    bool untilState(ProgramState s, std::int64_t maxMs) {
        return until([&] { return ctl->state() == s; }, maxMs);
    }

    engine::AxisView x() const { return ctl->axisView(X); }
    engine::AxisView z() const { return ctl->axisView(Z); }
    std::int64_t current(AxisId a) const { return ctl->axisView(a).currentDisc; }
    std::int64_t machine(AxisId a) const { return ctl->axisView(a).machineDisc; }

    std::vector<int> alarms() const {
        std::vector<int> v;
        for (const auto& a : ctl->alarms())
            v.push_back(a.number);
        return v;
    }
    bool hasAlarm(int n) const { return ctl->alarmRegistry().latched(n); }
    const engine::AlarmView* alarm(int n) const {
        static thread_local std::vector<engine::AlarmView> list;
        list = ctl->alarms();
        for (const auto& a : list)
            if (a.number == n)
                return &a;
        return nullptr;
    }
};

// Profile tweaks.
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

inline QString alarmList(const Rig& r) {
    QString s = "alarms:";
    for (int n : r.alarms())
        s += " " + QString::number(n);
    return s;
}

} // namespace rig
