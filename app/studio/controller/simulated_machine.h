// The training-only side of the simulated controller: the machine of the
// window's SimulationSession as the views that need more than a
// controller's state reach it — every servo tick (the oscilloscope's trace,
// the history and the live path sampled per tick), its speed, ESC from the
// history dock. A real controller has none of it (Controller::simulated()
// is nullptr), so a view says what it cannot give instead.
#pragma once

#include <QObject>

namespace k528::machine {
class Simulation;
}

namespace k528::studio {

class SimulatedMachine {
public:
    virtual ~SimulatedMachine() = default;
    // Its ticks (addTickObserver, setAfterTick), its engine controller.
    virtual machine::Simulation& simulation() = 0;
    virtual double speed() const = 0;
    // A change made between frames (ESC, a setting) shown by every view now.
    virtual void showNow() = 0;
    // Emits destroyed() when the simulation goes (before the views that
    // observe its ticks): they stop touching it.
    virtual QObject* lifetime() = 0;
};

} // namespace k528::studio
