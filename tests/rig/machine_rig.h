// A simulated machine (machine::Simulation) for the tests: a built-in
// profile with its machine description, an operator's helpers at the
// machine's panel and the K923, waiting, and the PLC's messages.
#pragma once

#include "machine/run.h"
#include "machine/simulation.h"
#include "units/units.h"
#include "rig/controller_rig.h"
#include "rig/watched_run.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace k528::testrig {

using machine::Button;
using machine::Fault;
using machine::FaultSpec;

class MachineRig : public ControllerRig {
public:
    std::unique_ptr<machine::Simulation> sim;

    explicit MachineRig(std::string_view name = "training-lathe", const ProfileTweak& tweak = {})
        : ControllerRig(tweakedProfile(name, tweak)), sim(std::make_unique<machine::Simulation>(prof)) {
        sim->powerOn();
        sim->advance(20);
    }

    engine::Positioner& c() override { return sim->controller(); }
    const engine::Positioner& c() const override { return sim->controller(); }
    bool until(const std::function<bool()>& done, std::int64_t maxMs) override {
        return sim->runUntil(done, maxMs);
    }
    // ПБТ with the jog buttons, as `k528 run` does over the simulated machine.
    std::unique_ptr<engine::RunMachine> runMachine() override {
        return std::make_unique<machine::SimulationRunMachine>(*sim);
    }

    machine::Simulation& s() { return *sim; }
    const engine::InterfaceWords& w() { return sim->controller().words(); }
    std::optional<bool> plc(std::string_view name) { return sim->plc().signal(name); }

    void tick() { sim->tick(); }
    void advance(std::int64_t ms) { sim->advance(ms); }
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
    // The positioner's alarms and the PLC's («A3»), for a failed check's message.
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

} // namespace k528::testrig
