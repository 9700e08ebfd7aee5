// Runs watched tick by tick: a RunMachine that is another in every respect
// (ForwardingRunMachine, the base of a decorator that overrides tick()), and
// the simulated machine as engine/run.h drives it calling `afterTick` after
// every tick (WatchedSimulationRun): a test or a benchmark that watches a
// whole run (a trace, a live path flushed every UI frame, the session's time).
#pragma once

#include "engine/run.h"
#include "machine/run.h"

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace k528::testrig {

class ForwardingRunMachine : public engine::RunMachine {
public:
    explicit ForwardingRunMachine(engine::RunMachine& inner) : inner_(inner) {}
    engine::Positioner& controller() override { return inner_.controller(); }
    void tick() override { inner_.tick(); }
    bool switchOn(std::int64_t maxMs) override { return inner_.switchOn(maxMs); }
    void setOverrideCode(int code) override { inner_.setOverrideCode(code); }
    void startReferenceCycle(engine::AxisId a, int dir) override { inner_.startReferenceCycle(a, dir); }
    void pressStart() override { inner_.pressStart(); }
    bool startHeld() const override { return inner_.startHeld(); }
    std::vector<int> mFunctions() const override { return inner_.mFunctions(); }

private:
    engine::RunMachine& inner_;
};

namespace detail {
// Owns the machine's run before the forwarding base is given it.
struct OwnedSimulationRun {
    explicit OwnedSimulationRun(machine::Simulation& sim) : simulationRun(sim) {}
    machine::SimulationRunMachine simulationRun;
};
} // namespace detail

class WatchedSimulationRun final : private detail::OwnedSimulationRun, public ForwardingRunMachine {
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
