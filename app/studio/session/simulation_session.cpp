#include "session/simulation_session.h"

#include <algorithm>
#include <cmath>

namespace k528::studio {

SimulationSession::SimulationSession(const profile::MachineProfile& profile, QObject* parent)
    : QObject(parent), sim_(std::make_unique<machine::Simulation>(profile)) {
    sim_->powerOn();
    panel_ = std::make_unique<panel::Panel>(sim_->controller());
    timer_.setTimerType(Qt::PreciseTimer);
    timer_.setInterval(kFrameIntervalMs);
    connect(&timer_, &QTimer::timeout, this, &SimulationSession::frame);
    setRunning(true);
}

SimulationSession::~SimulationSession() = default;

void SimulationSession::setRunning(bool running) {
    if (running == running_)
        return;
    running_ = running;
    if (running) {
        clock_.start();
        owedMs_ = 0;
        timer_.start();
    } else {
        timer_.stop();
    }
    emit runningChanged(running);
}

void SimulationSession::setSpeed(double factor) {
    factor = std::clamp(factor, 0.1, 100.0);
    if (factor == speed_)
        return;
    speed_ = factor;
    emit speedChanged(factor);
}

void SimulationSession::setFastest(bool on) {
    if (on == fastest_)
        return;
    fastest_ = on;
    owedMs_ = 0;
    emit fastestChanged(on);
}

void SimulationSession::advance(std::int64_t ms) {
    if (ms > 0)
        sim_->advance(ms);
    advancedTo();
}

void SimulationSession::advancedTo() {
    panel_->setHealth(sim_->k923Health()); // a fault may have changed the K923
    emit advanced();
}

void SimulationSession::frame() {
    const double realMs = std::min<double>(static_cast<double>(clock_.restart()), kMaxFrameMs);
    if (fastest_) {
        // Whole ticks for a slice of real time, checked every few ticks.
        QElapsedTimer budget;
        budget.start();
        do {
            for (int i = 0; i < 64; ++i)
                sim_->tick();
        } while (budget.elapsed() < kFastestBudgetMs);
        clock_.restart();
        advancedTo();
        return;
    }
    owedMs_ += realMs * speed_;
    const double tick = static_cast<double>(sim_->tickMs());
    const auto ticks = static_cast<std::int64_t>(std::floor(owedMs_ / tick));
    owedMs_ -= static_cast<double>(ticks) * tick;
    for (std::int64_t i = 0; i < ticks; ++i)
        sim_->tick();
    advancedTo();
}

} // namespace k528::studio
