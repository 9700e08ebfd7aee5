// The built-in controller: the simulated K528-05 of this window's
// SimulationSession, its K923 panel model taking the keys.
#pragma once

#include "controller/controller.h"

namespace k528::studio {

class SimulationSession;

class SimulatedController final : public Controller {
    Q_OBJECT
public:
    explicit SimulatedController(SimulationSession& session, QObject* parent = nullptr);

    QString kind() const override { return QStringLiteral("simulation"); }
    QString description() const override;
    const ControllerState& state() const override;
    const program::ProgramStore& programs() const override;
    std::uint64_t programsRevision() const override;
    const profile::MachineProfile& profile() const override;
    bool acceptsKeys() const override { return true; }
    void pressKey(panel::KeyPress k) override;

    SimulationSession& session() const { return session_; }

private:
    SimulationSession& session_;
    mutable ControllerState state_;
    mutable bool dirty_ = true;
};

} // namespace k528::studio
