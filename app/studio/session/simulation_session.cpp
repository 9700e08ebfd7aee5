#include "session/simulation_session.h"

#include <QCoreApplication>
#include <QEvent>

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
    unchanged_.start();
    setRunning(true);
}

SimulationSession::~SimulationSession() {
    if (watching_ && QCoreApplication::instance())
        QCoreApplication::instance()->removeEventFilter(this);
}

void SimulationSession::watchInput() {
    if (watching_ || !QCoreApplication::instance())
        return;
    watching_ = true;
    QCoreApplication::instance()->installEventFilter(this);
}

bool SimulationSession::eventFilter(QObject* watched, QEvent* event) {
    switch (event->type()) {
    case QEvent::KeyPress:
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonDblClick:
    case QEvent::Wheel:
    case QEvent::TouchBegin:
        // Seen once per input (the application's filter gets each event
        // for every receiver on its way; the first wakes, the rest find
        // the fast rate on).
        if (running_ && !fastest_ && timer_.interval() != kFrameIntervalMs)
            wake();
        break;
    default:
        break;
    }
    return QObject::eventFilter(watched, event);
}

void SimulationSession::setInterval(int ms) {
    if (timer_.interval() != ms)
        timer_.setInterval(ms); // an active timer restarts with it
}

void SimulationSession::setRunning(bool running) {
    if (running == running_)
        return;
    running_ = running;
    if (running) {
        clock_.start();
        owedMs_ = 0;
        unchanged_.restart();
        setInterval(fastest_ ? kFastestIntervalMs : kFrameIntervalMs);
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
    unchanged_.restart();
    setInterval(on ? kFastestIntervalMs : kFrameIntervalMs);
    emit fastestChanged(on);
}

void SimulationSession::wake() {
    unchanged_.restart();
    if (!running_ || fastest_)
        return;
    setInterval(kFrameIntervalMs);
    timer_.start(); // the next frame a full fast interval from now ...
    frame();        // ... and this one now: the machine catches up to the input's moment
}

void SimulationSession::advance(std::int64_t ms) {
    if (ms > 0)
        sim_->advance(ms);
    unchanged_.restart(); // an operator's change or a test's step: views at the fast rate
    advancedTo();
}

void SimulationSession::advancedTo() {
    panel_->setHealth(sim_->k923Health()); // a fault may have changed the K923
    emit advanced();
}

bool SimulationSession::somethingChanged() {
    Look now;
    const engine::Positioner& c = sim_->controller();
    now.words = c.words();
    now.display = panel_->display();
    for (int i = 0; i < 2; ++i) {
        const engine::AxisView v = c.axisView(engine::axisAt(i));
        now.axes[static_cast<std::size_t>(4 * i)] = v.currentDisc;
        now.axes[static_cast<std::size_t>(4 * i + 1)] = v.machineDisc;
        now.axes[static_cast<std::size_t>(4 * i + 2)] = v.dac;
        // The following error as the axes view shows it (0.1 µm is far below it).
        now.axes[static_cast<std::size_t>(4 * i + 3)] = std::llround(v.errorInternal * 16);
    }
    now.frames = c.framesExecuted();
    const engine::ProgramView p = c.programView();
    now.state = static_cast<int>(p.state);
    now.program = p.program;
    now.frame = p.frameIndex;
    now.alarms = c.alarms().size();
    if (now == look_)
        return false;
    look_ = std::move(now);
    return true;
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
    // The rate for the next frames: fast while what the views show changes.
    if (somethingChanged())
        unchanged_.restart();
    setInterval(unchanged_.elapsed() >= kSettleMs ? kIdleIntervalMs : kFrameIntervalMs);
    advancedTo();
}

} // namespace k528::studio
