// The trial part (handbook 13.8): the size measured on the part against the
// drawing's, for a tool and an axis, gives the change of the tool's offset
// R-parameter (profile/cutting.h: X measured as a diameter). The dialog shows
// the change; «Keep» makes it the machine's preset (its next revision in the
// database, with the measurement as the note) and puts it into the controller.
#pragma once

#include "profile/cutting.h"
#include "profile/profile.h"

#include <QDialog>
#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace k528::studio {

class TrialPartDialog : public QDialog {
    Q_OBJECT
public:
    explicit TrialPartDialog(const profile::MachineProfile& machine, QWidget* parent = nullptr);

    void setInputs(int station, bool xAxis, double measuredMm, double drawingMm); // tests
    // The change the inputs give, nullopt when none (no tools, no offsets).
    const std::optional<profile::cutting::TrialCorrection>& correction() const { return correction_; }
    // The revision's note: the measurement and the change.
    QString note() const;
    QLabel* result() const { return result_; }
    QPushButton* keepButton() const { return keep_; }

signals:
    // «Keep» with a correction: the pane keeps R`r` = `value` with `note`.
    void keepRequested(int r, qint64 value, const QString& note);

private:
    void recalculate();
    profile::MachineProfile machine_;
    QComboBox* tool_;
    QComboBox* axis_;
    QDoubleSpinBox* measured_;
    QDoubleSpinBox* drawing_;
    QLabel* result_;
    QPushButton* keep_;
    std::optional<profile::cutting::TrialCorrection> correction_;
};

} // namespace k528::studio
