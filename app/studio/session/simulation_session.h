// One simulated machine on the desktop: owns a machine::Simulation (the
// positioner, the PLC and the plant of core/machine) and advances it by the
// real time elapsed, measured here (core never reads a clock). A 60 Hz timer
// catches up in whole ticks; a frame never advances by more than
// kMaxFrameMs of real time, so a stalled window does not make the machine
// leap. A trainer may pause it or run it faster (1×, 2×, 10× ... 100×), or
// as fast as the host allows («fastest»: each frame ticks for up to
// kFastestBudgetMs of real time, so the window stays responsive).
//
// Every view of the workstation redraws on advanced(). The session also owns
// the K923 panel model (panel::Panel) over controller(): the desktop K923
// widget shows its display and hands it the keys, as the PC link will.
#pragma once

#include "machine/simulation.h"
#include "panel/panel.h"
#include "profile/profile.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <memory>

namespace k528::studio {

class SimulationSession : public QObject {
    Q_OBJECT
public:
    static constexpr int kFrameIntervalMs = 16; // ~60 Hz
    static constexpr int kMaxFrameMs = 100;     // real time a frame may catch up
    static constexpr int kFastestBudgetMs = 12; // real time a «fastest» frame ticks

    // Builds the machine of `profile` and switches the controller on (its
    // self-test); the drives stay off until the operator switches them on.
    // Throws plc::DescriptionError for a bad machine description.
    explicit SimulationSession(const profile::MachineProfile& profile, QObject* parent = nullptr);
    ~SimulationSession() override;

    machine::Simulation& simulation() { return *sim_; }
    const machine::Simulation& simulation() const { return *sim_; }
    engine::Controller& controller() { return sim_->controller(); }
    // The K923 of this machine.
    panel::Panel& panel() { return *panel_; }

    bool isRunning() const { return running_; }
    double speed() const { return speed_; }
    bool isFastest() const { return fastest_; }
    // Simulated milliseconds since the session started.
    std::int64_t timeMs() const { return sim_->timeMs(); }

public slots:
    void setRunning(bool running); // pause / resume with real time
    void setSpeed(double factor);  // 0.1 .. 100
    void setFastest(bool on);      // as fast as the host allows (speed() is kept for off)
    // Advances the machine by `ms` of simulated time now (whole ticks) and
    // emits advanced(): for stepping while paused, and for tests.
    void advance(std::int64_t ms);

signals:
    void advanced();
    void runningChanged(bool running);
    void speedChanged(double factor);
    void fastestChanged(bool on);

private slots:
    void frame();

private:
    // The views' moment: the K923's state follows the machine, then advanced().
    void advancedTo();

private:
    std::unique_ptr<machine::Simulation> sim_;
    std::unique_ptr<panel::Panel> panel_;
    QTimer timer_;
    QElapsedTimer clock_;
    double owedMs_ = 0; // simulated time not yet advanced (less than a tick)
    double speed_ = 1.0;
    bool running_ = false;
    bool fastest_ = false;
};

} // namespace k528::studio
