// The built-in controller: the simulated K528-05 of this window's
// SimulationSession, its K923 panel model taking the keys. Memory writes
// follow the desktop's rules of the panel: a constant is set as in
// РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ (F5 for the moment of the change), all of
// them and a clear as in УПРАВЛЕНИЕ ДАННЫМИ (F7), never while a program is
// under way or an axis moves; an R-parameter as on РУЧНОЙ screen 3.
// It is also the SimulatedMachine of the training-only views.
#pragma once

#include "controller/controller.h"
#include "controller/simulated_machine.h"

#include <vector>

namespace k528::engine {
class Positioner;
}

namespace k528::studio {

class SimulationSession;

// Sets C`number` on the controller as the K923 does (F5 for the moment of
// the change); "" when done, otherwise why not (English from the engine).
QString applyCToController(engine::Positioner& controller, int number, std::int64_t value);

class SimulatedController final : public Controller, public SimulatedMachine {
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
    Capabilities capabilities() const override;
    SimulatedMachine* simulated() override { return this; }

    std::span<const std::int64_t> cValues() const override;
    std::span<const std::int32_t> rValues() const override;
    std::uint64_t memoryRevision() const override;
    QString whyNotWritable(MemoryArea area, int number = -1) const override;
    void setC(int number, std::int64_t value, Done done) override;
    void setAllC(std::vector<std::int64_t> c, Done done) override;
    void setR(int number, std::int64_t value, Done done) override;
    void clear(MemoryArea area, Done done) override;
    void loadPrograms(const std::string& text, const QString& source, Done done) override;
    void readMemory(MemoryDone done) override;

    // SimulatedMachine
    machine::Simulation& simulation() override;
    double speed() const override;
    void showNow() override;
    QObject* lifetime() override;

    SimulationSession& session() const { return session_; }

private:
    void written(const QString& why, const Done& done);
    SimulationSession& session_;
    mutable ControllerState state_;
    mutable bool dirty_ = true;
    mutable std::vector<std::int64_t> seenC_;
    mutable std::vector<std::int32_t> seenR_;
    mutable std::uint64_t memoryRevision_ = 0;
};

} // namespace k528::studio
