#include "constants/cutting_dialog.h"

#include "controller/controller.h"
#include "profile/cutting.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLocale>
#include <QVBoxLayout>

#include <cmath>

namespace k528::studio {

CuttingDataDialog::CuttingDataDialog(const profile::MachineProfile& machine, const Controller* controller,
                                     QWidget* parent)
    : QDialog(parent), machine_(machine) {
    setObjectName("constants.cuttingDialog");
    setWindowTitle(tr("Cutting data"));
    const auto spin = [this](double lo, double hi, double v, int dec, const QString& name) {
        auto* s = new QDoubleSpinBox(this);
        s->setObjectName(name);
        s->setRange(lo, hi);
        s->setDecimals(dec);
        s->setValue(v);
        connect(s, &QDoubleSpinBox::valueChanged, this, &CuttingDataDialog::recalculate);
        return s;
    };
    const auto result = [this](const QString& name) {
        auto* l = new QLabel(this);
        l->setObjectName(name);
        l->setTextInteractionFlags(Qt::TextSelectableByMouse);
        QFont f = l->font();
        f.setBold(true);
        l->setFont(f);
        return l;
    };
    v_ = spin(0.1, 10000, 120, 1, "cutting.v");
    d_ = spin(0.1, 10000, 40, 3, "cutting.d");
    n_ = result("cutting.n");
    f_ = spin(0.001, 100, 0.2, 3, "cutting.f");
    feed_ = result("cutting.feed");
    // R207: the controller's value, else the machine's preset, in discretes of X.
    double r207 = 0;
    if (controller) {
        const auto r = controller->rValues();
        if (r.size() > 207)
            r207 = r[207];
    }
    if (r207 <= 0)
        if (const auto it = machine_.r.find(207); it != machine_.r.end())
            r207 = static_cast<double>(it->second);
    r207_ = spin(0, 2147483647, r207, 0, "cutting.r207");
    wheelN_ = spin(1, 200000, 30000, 0, "cutting.wheelRpm");
    wheel_ = result("cutting.wheel");

    auto* spindle = new QGroupBox(tr("Spindle speed: n = 1000·v / (π·D)"), this);
    auto* sf = new QFormLayout(spindle);
    sf->addRow(tr("Cutting speed v, m/min"), v_);
    sf->addRow(tr("Diameter D, mm"), d_);
    sf->addRow(tr("Spindle speed n"), n_);
    auto* feed = new QGroupBox(tr("Feed per minute: F = f·n"), this);
    auto* ff = new QFormLayout(feed);
    ff->addRow(tr("Feed per revolution f, mm/rev"), f_);
    ff->addRow(tr("Feed F"), feed_);
    auto* wheel = new QGroupBox(tr("Grinding wheel: v = π·D·n / 60000"), this);
    auto* wf = new QFormLayout(wheel);
    wf->addRow(tr("R207 wheel diameter, discretes of X"), r207_);
    wf->addRow(tr("Wheel speed, rev/min"), wheelN_);
    wf->addRow(tr("Surface speed"), wheel_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(spindle);
    layout->addWidget(feed);
    layout->addWidget(wheel);
    layout->addStretch(1);
    layout->addWidget(buttons);
    recalculate();
}

void CuttingDataDialog::recalculate() {
    namespace cut = profile::cutting;
    const QLocale l;
    double n = 0;
    try {
        n = cut::spindleSpeedRpm(v_->value(), d_->value());
        n_->setText(tr("%1 rev/min").arg(l.toString(n, 'f', 0)));
    } catch (const cut::CuttingError&) {
        n_->setText(QStringLiteral("—"));
    }
    try {
        feed_->setText(tr("%1 mm/min at n = %2 rev/min")
                           .arg(l.toString(cut::feedPerMinute(f_->value(), std::round(n)), 'f', 1),
                                l.toString(std::round(n), 'f', 0)));
    } catch (const cut::CuttingError&) {
        feed_->setText(QStringLiteral("—"));
    }
    try {
        const double dMm = cut::wheelDiameterMm(machine_, static_cast<std::int64_t>(r207_->value()));
        wheel_->setText(tr("%1 m/s (wheel Ø%2 mm)")
                            .arg(l.toString(cut::wheelSurfaceSpeedMPerS(dMm, wheelN_->value()), 'f', 2),
                                 l.toString(dMm, 'f', 3)));
    } catch (const cut::CuttingError&) {
        wheel_->setText(tr("— (no wheel diameter in R207)"));
    }
}

} // namespace k528::studio
