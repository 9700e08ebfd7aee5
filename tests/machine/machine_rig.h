// A simulated machine (machine::Simulation) for the tests: a built-in
// profile with its machine description, an operator's helpers at the
// machine's panel and the K923, waiting, and the PLC's messages.
#pragma once

#include "engine/load_programs.h"
#include "machine/run.h"
#include "machine/simulation.h"
#include "profile/builtin.h"
#include "program/parser.h"

#include <QtTest>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace mrig {

using namespace k528;
using engine::AxisId;
using engine::Mode;
using engine::ProgramState;
using machine::Button;
using machine::Fault;
using machine::FaultSpec;

inline constexpr AxisId X = AxisId::X;
inline constexpr AxisId Z = AxisId::Z;

struct Rig {
    profile::MachineProfile prof;
    std::unique_ptr<machine::Simulation> sim;

    explicit Rig(std::string_view name = "training-lathe",
                 const std::function<void(profile::MachineProfile&)>& tweak = {}) {
        prof = profile::builtin(name);
        if (tweak)
            tweak(prof);
        sim = std::make_unique<machine::Simulation>(prof);
        sim->powerOn();
        sim->advance(20);
    }

    machine::Simulation& s() { return *sim; }
    engine::Controller& c() { return sim->controller(); }
    const engine::InterfaceWords& w() { return sim->controller().words(); }
    bool bit(engine::ZBit b) { return w().bit(b); }
    std::optional<bool> plc(std::string_view name) { return sim->plc().signal(name); }

    void tick() { sim->tick(); }
    void advance(std::int64_t ms) { sim->advance(ms); }
    bool until(const std::function<bool()>& done, std::int64_t maxMs) {
        return sim->runUntil(done, maxMs);
    }
    // A push of the operator's hand (100 ms) and time for the PLC to see it.
    void push(Button b, std::int64_t holdMs = 100) {
        sim->pressFor(b, holdMs);
        advance(holdMs + 30);
    }

    // «Включение приводов»: true once every present axis has its loop closed.
    bool drivesOn() {
        sim->pressFor(Button::DrivesOn, 100);
        return until(
            [&] {
                for (AxisId a : {X, Z}) {
                    const engine::AxisView v = c().axisView(a);
                    if (v.present && !(v.loopClosed && v.regulatorOn))
                        return false;
                }
                return !sim->buttonDown(Button::DrivesOn);
            },
            5000);
    }

    // ПБТ with the jog buttons, X first, as `k528 run` does
    // (engine::homeAxes over the simulated machine). False on failure.
    bool home() {
        machine::SimulationRunMachine run(*sim);
        return engine::homeAxes(run).status == engine::RunStatus::Completed;
    }

    void load(const std::string& text) {
        const program::ParseResult r = program::parse(text);
        QVERIFY2(!r.hasErrors(),
                 r.diagnostics.empty() ? "parse error" : r.diagnostics.front().messageEn.c_str());
        QVERIFY(engine::loadPrograms(c(), r.store).ok());
    }

    // АВТОМАТ, program n, «Пуск» on the machine's panel, until it started.
    bool start(int n) {
        c().selectMode(Mode::Auto);
        c().selectProgram(n);
        sim->pressFor(Button::CycleStart, 100);
        return until(
                   [&] {
                       return engine::programActive(c().state()) ||
                              c().state() == ProgramState::Alarm;
                   },
                   1000) &&
               c().state() != ProgramState::Alarm;
    }
    bool untilState(ProgramState st, std::int64_t maxMs) {
        return until([&] { return c().state() == st; }, maxMs);
    }
    bool runToEnd(std::int64_t maxMs = 600000) {
        return until(
            [&] {
                const ProgramState st = c().state();
                return st == ProgramState::Ended || st == ProgramState::Alarm ||
                       st == ProgramState::Idle;
            },
            maxMs);
    }

    bool hasAlarm(int n) { return c().alarmRegistry().latched(n); }
    std::vector<int> alarms() {
        std::vector<int> v;
        for (const auto& a : c().alarms())
            v.push_back(a.number);
        return v;
    }
    bool plcAlarm(int k) { return (c().plcMessages().alarms >> (k - 1)) & 1u; }
    bool plcAlarmPresent(int k) { return (c().plcMessages().alarmsPresent >> (k - 1)) & 1u; }
    bool work(int k) { return (c().plcMessages().work >> (k - 1)) & 1u; }
    bool system(int k) { return (c().plcMessages().system >> (k - 1)) & 1u; }
    bool lamp(std::string_view id) {
        for (const auto& [name, on] : sim->view().lamps)
            if (name == id)
                return on;
        return false;
    }
    double rpm(std::string_view name) {
        for (const auto& sp : sim->view().spindles)
            if (sp.name == name)
                return sp.rpm;
        return 0;
    }
    double mm(AxisId a) {
        return units::discToMm(c().axisView(a).currentDisc, c().axisView(a).scale);
    }
    std::string alarmList() {
        std::string s;
        for (const auto& a : c().alarms())
            s += " " + std::to_string(a.number);
        const auto pm = c().plcMessages();
        for (int k = 1; k <= 32; ++k)
            if ((pm.alarms >> (k - 1)) & 1u)
                s += " A" + std::to_string(k);
        return s;
    }
};

} // namespace mrig
