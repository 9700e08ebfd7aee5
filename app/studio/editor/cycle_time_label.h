// The cycle time of the current file's first program, in the editor's status
// line beside the count of problems («Время цикла L1: 3 мин 32.2 с
// (Учебный токарный станок…)»): the program run on the simulated machine the file is
// checked for, as `k528 path` gives it (machine::cycleTime: the same
// deterministic run as `k528 run` — servo acceleration and lag, feeds,
// dwells, the PLC's M-function answers). Measured on a worker thread after
// the file has been validated and has no errors, a moment after the last
// key (a run costs up to a few tenths of a second); a result outdated by a
// newer text is dropped. Nothing runs while the file does not change.
#pragma once

#include "profile/profile.h"
#include "workspace/elided_label.h"

#include <QTimer>
#include <cstdint>
#include <memory>
#include <optional>

namespace k528::studio {

class ProgramEditor;

class CycleTimeLabel : public ElidedLabel {
    Q_OBJECT
public:
    explicit CycleTimeLabel(QWidget* parent = nullptr);
    ~CycleTimeLabel() override;

    // The file of `ed` changed, was validated, or became the current one
    // (nullptr: no file).
    void follow(const ProgramEditor* ed);
    // The last figure measured for the current text (seconds), if any.
    std::optional<double> seconds() const { return seconds_; }

    // "49.5 с", "3 мин 32.2 с" (ru) / "49.5 s", "3 min 32.2 s" (en).
    static QString durationText(double seconds);

signals:
    void measured(); // seconds() and the text are new

protected:
    void changeEvent(QEvent* e) override;

private:
    void start();
    void retranslate();

    QTimer debounce_;
    const ProgramEditor* editor_ = nullptr;
    std::uint64_t generation_ = 0;
    bool running_ = false;
    std::optional<double> seconds_;
    // What the text says, kept to be said again in the other language.
    enum class State { None, Errors, NoMachine, Measuring, Measured, NotCompleted } state_ = State::None;
    int program_ = 0;
    QString runStatus_;
    // The machine measured on, named by its title in either language.
    std::shared_ptr<const profile::MachineProfile> machine_;
    std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
};

} // namespace k528::studio
