// `k528 run` on the simulated machine: the run of engine/run.h driven through
// machine::Simulation — the operator switches the drives on at the machine's
// panel, homes with the jog buttons in ПБТ, sets the override selector and
// presses «Пуск»; the PLC runs the machine description (spindle, coolant,
// turret, gauge ...). Same result type and statuses as engine::runProgram.
#pragma once

#include "engine/run.h"
#include "machine/simulation.h"

#include <map>
#include <optional>
#include <stdexcept>

namespace k528::machine {

// A RunMachine over a Simulation (also for tests and the benchmark).
class SimulationRunMachine final : public engine::RunMachine {
public:
    explicit SimulationRunMachine(Simulation& sim) : sim_(sim) {}
    engine::Positioner& controller() override { return sim_.controller(); }
    void tick() override { sim_.tick(); }
    bool switchOn(std::int64_t maxMs) override;
    // The override selector, or the K923 L key of that code when the machine
    // has no selector; std::invalid_argument when neither gives it.
    void setOverrideCode(int code) override;
    void startReferenceCycle(engine::AxisId a, int dir) override;
    void pressStart() override { sim_.pressFor(Button::CycleStart, kPressMs); }
    bool startHeld() const override { return sim_.buttonDown(Button::CycleStart); }
    std::vector<int> mFunctions() const override { return sim_.mCodes(); }

    static constexpr std::int64_t kPressMs = 100; // an operator's push

private:
    Simulation& sim_;
};

// Runs program `number` on the simulated machine of `profile` (its machine
// description as Simulation finds it). Throws plc::DescriptionError for a
// bad description, std::invalid_argument for an override the machine cannot
// set.
engine::RunResult runProgram(const profile::MachineProfile& profile,
                             const program::ProgramStore& programs, int number,
                             const engine::RunOptions& options);

// The cycle time of program `number` on the simulated machine of `profile`:
// the program run as `k528 run` runs it (homed first where the machine needs
// it, override 100 %, an M00 continued by a push at once — no waiting operator), from
// «Пуск» to its end: the servos' acceleration and lag, the feeds, the dwells
// and the PLC's answers to the M functions as this machine has them. No
// estimate beside the simulation: the same deterministic run, so the figure
// is the one `k528 run` reports. `seconds` is empty when the run did not
// complete (an alarm, the time limit, a start that was blocked); `run` says
// why.
struct CycleTime {
    std::optional<double> seconds;
    engine::RunResult run;
};
CycleTime cycleTime(const profile::MachineProfile& profile, const program::ProgramStore& programs,
                    int number, const std::map<int, std::int64_t>& rPresets,
                    double maxSeconds = 3600);

} // namespace k528::machine
