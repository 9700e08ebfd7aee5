// A Positioner on the ideal machine, for the engine tests: a built-in
// profile (tweaked by the test), programs loaded from text, helpers to home,
// start and wait. Positions in display discretes unless a name says mm.
#pragma once

#include "engine/ideal_machine.h"
#include "rig/controller_rig.h"

#include <functional>
#include <memory>
#include <string_view>
#include <vector>

namespace k528::testrig {

class EngineRig : public ControllerRig {
public:
    std::unique_ptr<engine::Positioner> ctl;
    std::unique_ptr<engine::IdealMachine> m;

    // `tweak` edits the profile before the controller is built.
    explicit EngineRig(std::string_view name = "training-lathe", const ProfileTweak& tweak = {})
        : ControllerRig(tweakedProfile(name, tweak)),
          ctl(std::make_unique<engine::Positioner>(prof)),
          m(std::make_unique<engine::IdealMachine>(*ctl)) {
        ctl->powerOn();
        m->advance(10);
    }

    engine::Positioner& c() override { return *ctl; }
    const engine::Positioner& c() const override { return *ctl; }
    bool until(const std::function<bool()>& done, std::int64_t maxMs) override {
        return m->runUntil(done, maxMs);
    }
    std::unique_ptr<engine::RunMachine> runMachine() override {
        return std::make_unique<engine::IdealRunMachine>(*ctl, *m);
    }

    engine::InterfaceWords& w() { return ctl->words(); }
    void tick() { m->tick(); }
    void advance(std::int64_t ms) { m->advance(ms); }

    // АВТОМАТ, program n, «Пуск»; ticks until the program started (or refused).
    void start(int n) {
        until([&] { return !ctl->words().bit(engine::z::Start); }, 1000); // a fresh edge
        ctl->selectMode(Mode::Auto);
        ctl->selectProgram(n);
        m->pressStart();
        tick();
        tick();
    }
    // Ticks until the setpoint of `a` has arrived at its target (the
    // trapezoid is over); returns the ms since the program started, -1 if not.
    double setpointArrivalS(AxisId a, std::int64_t maxMs) {
        const auto& s = ctl->servo(a);
        if (!until(
                [&] {
                    return s.setpoint() == s.target() && s.commandVelocity() == 0.0 &&
                           s.target() != 0.0;
                },
                maxMs))
            return -1;
        return static_cast<double>(ctl->timeMs() - ctl->programStartMs()) / 1000.0;
    }

    engine::AxisView x() const { return ctl->axisView(X); }
    engine::AxisView z() const { return ctl->axisView(Z); }
    std::int64_t current(AxisId a) const { return ctl->axisView(a).currentDisc; }
    std::int64_t machine(AxisId a) const { return ctl->axisView(a).machineDisc; }

    const engine::AlarmView* alarm(int n) const {
        static thread_local std::vector<engine::AlarmView> list;
        list = ctl->alarms();
        for (const auto& a : list)
            if (a.number == n)
                return &a;
        return nullptr;
    }
};

} // namespace k528::testrig
