#include "rparams/trial_dialog.h"

#include "db/notes.h"
#include "profile/english.h"
#include "profile/tools.h"
#include "proveout/setup_sheet.h"
#include "session/catalog_texts.h"
#include "session/core_texts.h"
#include "window_language.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

namespace k528::studio {

TrialPartDialog::TrialPartDialog(const profile::MachineProfile& machine, QWidget* parent)
    : QDialog(parent), machine_(machine) {
    setObjectName("rparams.trialDialog");
    setWindowTitle(tr("Trial part: correct a tool's offset"));
    tool_ = new QComboBox(this);
    tool_->setObjectName("trial.tool");
    try {
        for (const profile::Tool& t : profile::tools(machine_)) {
            const QString kind = toolKindText(t.kind);
            // The machine file's name of the tool and its English, as the
            // setup sheet and the prove-out show it.
            const QString name = coreText(profile::toolName(machine_, t, false), profile::toolName(machine_, t, true));
            tool_->addItem(QStringLiteral("T%1 %2 — %3").arg(t.station).arg(kind, name), t.station);
        }
    } catch (const std::exception&) {
    }
    axis_ = new QComboBox(this);
    axis_->setObjectName("trial.axis");
    const bool diameter = profile::axisScale(machine_, catalog::Axis::X).diameter;
    axis_->addItem(tr("X: a diameter"), 0);
    axis_->addItem(tr("Z: a length"), 1);
    const auto spin = [this](const char* name) {
        auto* s = new QDoubleSpinBox(this);
        s->setObjectName(name);
        s->setRange(-100000, 100000);
        s->setDecimals(3);
        s->setSingleStep(0.01);
        connect(s, &QDoubleSpinBox::valueChanged, this, &TrialPartDialog::recalculate);
        return s;
    };
    measured_ = spin("trial.measured");
    drawing_ = spin("trial.drawing");
    result_ = new QLabel(this);
    result_->setObjectName("trial.result");
    result_->setWordWrap(true);
    result_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* explain = new QLabel(
        (diameter ? tr("X of this machine shows a diameter: the offset changes by the diameter's error.")
                  : tr("X of this machine shows a radius: the offset changes by half the diameter's error.")) +
            QLatin1Char(' ') +
            tr("A size that came out larger than the drawing's was cut with too large an offset: the new offset "
               "is the old one minus the error."),
        this);
    explain->setWordWrap(true);
    auto* form = new QFormLayout;
    form->addRow(tr("Tool"), tool_);
    form->addRow(tr("Measured on"), axis_);
    form->addRow(tr("Measured, mm"), measured_);
    form->addRow(tr("Drawing, mm"), drawing_);
    keep_ = new QPushButton(tr("Keep as the preset"), this);
    keep_->setObjectName("trial.keep");
    keep_->setToolTip(tr("The new offset becomes the machine's preset (its next revision in the database, the "
                         "measurement as its note) and goes into the controller"));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(keep_, QDialogButtonBox::AcceptRole);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(keep_, &QPushButton::clicked, this, [this] {
        if (!correction_)
            return;
        emit keepRequested(correction_->rNumber, correction_->newValue, note());
        accept();
    });
    connect(tool_, &QComboBox::currentIndexChanged, this, &TrialPartDialog::recalculate);
    connect(axis_, &QComboBox::currentIndexChanged, this, &TrialPartDialog::recalculate);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(explain);
    layout->addLayout(form);
    layout->addWidget(result_);
    layout->addStretch(1);
    layout->addWidget(buttons);
    resize(520, 360);
    recalculate();
}

void TrialPartDialog::setInputs(int station, bool xAxis, double measuredMm, double drawingMm) {
    tool_->setCurrentIndex(tool_->findData(station));
    axis_->setCurrentIndex(xAxis ? 0 : 1);
    measured_->setValue(measuredMm);
    drawing_->setValue(drawingMm);
    recalculate();
}

QString TrialPartDialog::note() const {
    if (!correction_)
        return {};
    const bool x = axis_->currentData().toInt() == 0;
    // As stored (db/notes.h), said in the reader's language by the history.
    return QString::fromStdString(db::noteText(
        {"trial",
         {std::to_string(tool_->currentData().toInt()), x ? "X" : "Z",
          QString::number(measured_->value(), 'f', 3).toStdString(),
          QString::number(drawing_->value(), 'f', 3).toStdString(), std::to_string(correction_->rNumber),
          std::to_string(correction_->oldValue), std::to_string(correction_->newValue)}}));
}

void TrialPartDialog::recalculate() {
    correction_.reset();
    if (tool_->count() == 0) {
        result_->setText(tr("The machine's tools are not described (tool.N.* of its settings)."));
        keep_->setEnabled(false);
        return;
    }
    if (measured_->value() == 0 && drawing_->value() == 0) {
        // Opened, nothing entered yet: no error of 0 mm against 0 mm.
        result_->setText(tr("Enter the size measured on the trial part and the drawing's size."));
        keep_->setEnabled(false);
        return;
    }
    try {
        const std::optional<profile::Tool> t = profile::toolAt(profile::tools(machine_), tool_->currentData().toInt());
        if (!t)
            throw profile::cutting::CuttingError(profile::problem("cutting.no-tool", {std::to_string(tool_->currentData().toInt())}));
        const bool x = axis_->currentData().toInt() == 0;
        correction_ = profile::cutting::trialCorrection(machine_, *t, x ? catalog::Axis::X : catalog::Axis::Z,
                                                        measured_->value(), drawing_->value());
        const QLocale l;
        result_->setText(tr("Error %1 mm: R%2 %3 → %4 (offset %5 mm)")
                             .arg(l.toString(correction_->errorMm, 'f', 3))
                             .arg(correction_->rNumber)
                             .arg(correction_->oldValue)
                             .arg(correction_->newValue)
                             .arg((correction_->changeMm > 0 ? QStringLiteral("+") : QString()) +
                                  l.toString(correction_->changeMm + 0.0, 'f', 3))); // never «-0.000»
    } catch (const std::exception& e) {
        result_->setText(coreErrorText(e));
    }
    keep_->setEnabled(correction_ && correction_->newValue != correction_->oldValue);
}

} // namespace k528::studio
