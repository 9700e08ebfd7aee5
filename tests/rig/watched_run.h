// Runs watched tick by tick: the simulated machine as engine/run.h drives
// it calling `afterTick` after every tick (WatchedSimulationRun, a
// decorator over engine::ForwardingRunMachine): a test or a benchmark that
// watches a whole run (a trace, a live path flushed every UI frame, the
// session's time).
#pragma once

#include "engine/forwarding_run_machine.h"
#include "machine/run.h"

#include <functional>
#include <utility>

namespace k528::testrig {

namespace detail {
// Owns the machine's run before the forwarding base is given it.
struct OwnedSimulationRun {
    explicit OwnedSimulationRun(machine::Simulation& sim) : simulationRun(sim) {}
    machine::SimulationRunMachine simulationRun;
};
} // namespace detail

class WatchedSimulationRun final : private detail::OwnedSimulationRun, public engine::ForwardingRunMachine {
public:
    WatchedSimulationRun(machine::Simulation& sim, std::function<void()> afterTick)
        : OwnedSimulationRun(sim), ForwardingRunMachine(simulationRun), afterTick_(std::move(afterTick)) {}
    void tick() override {
        ForwardingRunMachine::tick();
        afterTick_();
    }

private:
    std::function<void()> afterTick_;
};

} // namespace k528::testrig
