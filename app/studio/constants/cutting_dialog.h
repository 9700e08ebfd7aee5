// The cutting-data calculator beside the C-constant one (profile/cutting.h):
// the spindle speed from a cutting speed and a diameter, the feed per minute
// from a feed per revolution, the grinding wheel's surface speed from its
// diameter R207 (the controller's value, else the machine's preset) and its
// speed. Recomputed as the values change.
#pragma once

#include "profile/profile.h"

#include <QDialog>

class QDoubleSpinBox;
class QLabel;

namespace k528::studio {

class Controller;

class CuttingDataDialog : public QDialog {
    Q_OBJECT
public:
    // `machine`: its X discrete (R207) and preset R207; `controller` (may be
    // null): the R207 it holds now.
    CuttingDataDialog(const profile::MachineProfile& machine, const Controller* controller,
                      QWidget* parent = nullptr);

    QDoubleSpinBox* cuttingSpeed() const { return v_; }
    QDoubleSpinBox* diameter() const { return d_; }
    QDoubleSpinBox* feedPerRev() const { return f_; }
    QDoubleSpinBox* r207() const { return r207_; }
    QDoubleSpinBox* wheelRpm() const { return wheelN_; }
    QLabel* spindleResult() const { return n_; }
    QLabel* feedResult() const { return feed_; }
    QLabel* wheelResult() const { return wheel_; }
    void recalculate();

private:
    profile::MachineProfile machine_;
    QDoubleSpinBox *v_, *d_, *f_, *r207_, *wheelN_;
    QLabel *n_, *feed_, *wheel_;
};

} // namespace k528::studio
