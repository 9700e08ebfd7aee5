#include "machine/run.h"

#include "units/units.h"

#include <string>

namespace k528::machine {

bool SimulationRunMachine::switchOn(std::int64_t maxMs) {
    sim_.releaseEmergencyStop();
    sim_.pressFor(Button::DrivesOn, kPressMs);
    engine::Positioner& ctl = sim_.controller();
    // Ready to move: the positioner is ready and every present axis has its
    // loop closed with the regulator enabled (the PLC did its part).
    return sim_.runUntil(
        [&] {
            if (!ctl.words().bit(engine::z::Ready))
                return false;
            for (AxisId a : {AxisId::X, AxisId::Z}) {
                const engine::AxisView v = ctl.axisView(a);
                if (v.present && !(v.loopClosed && v.regulatorOn))
                    return false;
            }
            return !sim_.buttonDown(Button::DrivesOn);
        },
        maxMs);
}

void SimulationRunMachine::setOverrideCode(int code) {
    if (sim_.hasOverrideSwitch()) {
        sim_.setOverrideSwitch(code);
        return;
    }
    if (code == 10 && sim_.controller().programView().overridePercent == 100)
        return; // 100 % at power-on
    engine::Positioner& ctl = sim_.controller();
    for (int l = 1; l <= 4; ++l)
        if (ctl.c()[engine::c::overrideKey(l)] == code) {
            ctl.pressOverrideKey(l);
            return;
        }
    throw std::invalid_argument("machine " + sim_.description().name +
                                " has no override selector and no L key for " +
                                std::to_string(units::overrideCodeToPercent(code)) + " %");
}

void SimulationRunMachine::startReferenceCycle(engine::AxisId a, int dir) {
    const Button b = a == AxisId::X ? (dir > 0 ? Button::JogXPlus : Button::JogXMinus)
                                    : (dir > 0 ? Button::JogZPlus : Button::JogZMinus);
    sim_.pressFor(b, kPressMs);
}

engine::RunResult runProgram(const profile::MachineProfile& profile,
                             const program::ProgramStore& programs, int number,
                             const engine::RunOptions& options) {
    Simulation sim(profile);
    SimulationRunMachine machine(sim);
    return engine::runProgram(machine, programs, number, options);
}

CycleTime cycleTime(const profile::MachineProfile& profile, const program::ProgramStore& programs,
                    int number, const std::map<int, std::int64_t>& rPresets, double maxSeconds) {
    engine::RunOptions options;
    options.rPresets = rPresets;
    options.maxSeconds = maxSeconds;
    options.m0WaitS = 0;
    CycleTime t;
    t.run = machine::runProgram(profile, programs, number, options);
    if (t.run.status == engine::RunStatus::Completed)
        t.seconds = t.run.timeS;
    return t;
}

} // namespace k528::machine
