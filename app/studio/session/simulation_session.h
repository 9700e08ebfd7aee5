// One simulated machine on the desktop: owns a machine::Simulation (the
// positioner, the PLC and the plant of core/machine) and advances it by the
// real time elapsed, measured here (core never reads a clock). A timer
// catches up in whole ticks; a frame never advances by more than
// kMaxFrameMs of real time, so a stalled window does not make the machine
// leap. A trainer may pause it or run it faster (1×, 2×, 10× ... 100×), or
// as fast as the host allows («fastest»: each frame ticks for up to
// kFastestBudgetMs of real time, so the window stays responsive).
//
// The frame rate follows what the machine does (the machine's time does
// not: every frame ticks the real time elapsed since the last, so the
// simulated machine keeps real time and its ticks stay the same whatever
// the rate): kFrameIntervalMs (30 Hz) while what the views show changes,
// kIdleIntervalMs (10 Hz) once nothing has changed for kSettleMs — an idle
// studio then costs almost nothing. A key, a click or a wheel turn in the
// application (wake(), an event filter on the application) takes the next
// frame at once and the fast rate again, so an input is seen without delay.
//
// Every view of the workstation redraws on advanced() when what it shows
// changed. The session also owns the K923 panel model (panel::Panel) over
// controller(): the desktop K923 widget shows its display and hands it the
// keys, as the PC link will.
#pragma once

#include "engine/interface_words.h"
#include "machine/simulation.h"
#include "panel/display.h"
#include "panel/panel.h"
#include "profile/profile.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <array>
#include <memory>

namespace k528::studio {

class SimulationSession : public QObject {
    Q_OBJECT
public:
    static constexpr int kFrameIntervalMs = 33;  // ~30 Hz while something changes
    static constexpr int kIdleIntervalMs = 100;  // 10 Hz while nothing does
    static constexpr int kSettleMs = 600;        // unchanged this long: the idle rate
    static constexpr int kFastestIntervalMs = 16; // «fastest»: a frame every 16 ms ...
    static constexpr int kFastestBudgetMs = 12;  // ... that ticks for 12 ms of real time
    static constexpr int kMaxFrameMs = 250;      // real time a frame may catch up

    // Builds the machine of `profile` and switches the controller on (its
    // self-test); the drives stay off until the operator switches them on.
    // Throws plc::DescriptionError for a bad machine description.
    explicit SimulationSession(const profile::MachineProfile& profile, QObject* parent = nullptr);
    ~SimulationSession() override;

    machine::Simulation& simulation() { return *sim_; }
    const machine::Simulation& simulation() const { return *sim_; }
    engine::Positioner& controller() { return sim_->controller(); }
    // The K923 of this machine.
    panel::Panel& panel() { return *panel_; }

    bool isRunning() const { return running_; }
    double speed() const { return speed_; }
    bool isFastest() const { return fastest_; }
    // Simulated milliseconds since the session started.
    std::int64_t timeMs() const { return sim_->timeMs(); }
    // The frame timer's interval now (kFrameIntervalMs, kIdleIntervalMs or
    // kFastestIntervalMs); 0 while paused.
    int frameIntervalMs() const { return running_ ? timer_.interval() : 0; }
    // Nothing the views show has changed for kSettleMs: the idle rate.
    bool isIdle() const { return running_ && !fastest_ && timer_.interval() == kIdleIntervalMs; }

    // Watches the application's input (keys, buttons, wheel) and wakes the
    // session on each (the main window installs it).
    void watchInput();

public slots:
    void setRunning(bool running); // pause / resume with real time
    void setSpeed(double factor);  // 0.1 .. 100
    void setFastest(bool on);      // as fast as the host allows (speed() is kept for off)
    // Advances the machine by `ms` of simulated time now (whole ticks) and
    // emits advanced(): for stepping while paused, and for tests.
    void advance(std::int64_t ms);
    // An input is coming: the next frame now (the machine catches up to
    // this moment first) and the fast rate until things settle again.
    void wake();

signals:
    void advanced();
    void runningChanged(bool running);
    void speedChanged(double factor);
    void fastestChanged(bool on);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private slots:
    void frame();

private:
    // The views' moment: the K923's state follows the machine, then advanced().
    void advancedTo();
    // What the views show, cheaply: changed since the last frame?
    bool somethingChanged();
    void setInterval(int ms);

private:
    std::unique_ptr<machine::Simulation> sim_;
    std::unique_ptr<panel::Panel> panel_;
    QTimer timer_;
    QElapsedTimer clock_;
    QElapsedTimer unchanged_; // real time since what the views show last changed
    double owedMs_ = 0; // simulated time not yet advanced (less than a tick)
    double speed_ = 1.0;
    bool running_ = false;
    bool fastest_ = false;
    bool watching_ = false;
    // The last frame's look of the machine (somethingChanged()).
    struct Look {
        engine::InterfaceWords words;
        panel::Display display;
        std::array<std::int64_t, 8> axes{}; // per axis: current, machine, DAC, error (rounded)
        std::int64_t frames = 0;
        int state = 0, program = 0, frame = 0;
        std::size_t alarms = 0;
        bool operator==(const Look&) const = default;
    };
    Look look_;
};

} // namespace k528::studio
