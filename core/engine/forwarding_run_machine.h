// A RunMachine that is another in every respect: the base of a decorator
// that overrides tick() to watch a run tick by tick (toolpath's
// SamplingRunMachine, the test rigs' WatchedSimulationRun, the benchmarks').
#pragma once

#include "engine/run.h"

#include <cstdint>
#include <vector>

namespace k528::engine {

class ForwardingRunMachine : public RunMachine {
public:
    explicit ForwardingRunMachine(RunMachine& inner) : inner_(inner) {}
    Positioner& controller() override { return inner_.controller(); }
    void tick() override { inner_.tick(); }
    bool switchOn(std::int64_t maxMs) override { return inner_.switchOn(maxMs); }
    void setOverrideCode(int code) override { inner_.setOverrideCode(code); }
    void startReferenceCycle(AxisId a, int dir) override { inner_.startReferenceCycle(a, dir); }
    void pressStart() override { inner_.pressStart(); }
    bool startHeld() const override { return inner_.startHeld(); }
    std::vector<int> mFunctions() const override { return inner_.mFunctions(); }

private:
    RunMachine& inner_;
};

} // namespace k528::engine
