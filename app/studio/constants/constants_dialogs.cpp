#include "constants/constants_dialogs.h"
#include "session/core_texts.h"

#include "catalog/cparams.h"
#include "session/shop_database.h"
#include "constants/constants_dock.h"
#include "constants/constants_editor.h"
#include "constants/machine_store.h"
#include "engine/positioner.h"
#include "profile/calculator.h"
#include "controller/controller.h"

#include <QComboBox>
#include <QDateTime>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QFutureWatcher>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTextBrowser>
#include <QVBoxLayout>
#include <map>

namespace k528::studio {

namespace {
QString fromStd(const std::string& s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}
} // namespace

// --- history --------------------------------------------------------------

HistoryDialog::HistoryDialog(const MachineStore& store, int number, QWidget* parent) : QDialog(parent) {
    setObjectName("constants.historyDialog");
    const catalog::CParamDef& d = catalog::cParam(number);
    setWindowTitle(tr("History of %1 %2 — %3").arg(fromStd(d.key()), fromStd(std::string(d.name)), store.qName()));
    table_ = new QTableWidget(this);
    table_->setColumnCount(6);
    table_->setHorizontalHeaderLabels(
        {tr("Revision"), tr("When"), tr("Who"), tr("Before"), tr("After"), tr("Note")});
    table_->verticalHeader()->hide();
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    auto* info = new QLabel(this);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(info);
    layout->addWidget(table_, 1);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    try {
        std::map<int, std::string> notes;
        for (const db::RevisionInfo& r : store.revisions())
            notes[r.revision] = r.summary;
        const std::vector<db::HistoryEntry> h = store.history(d.key());
        table_->setRowCount(static_cast<int>(h.size()));
        for (int i = 0; i < static_cast<int>(h.size()); ++i) {
            const db::HistoryEntry& e = h[static_cast<std::size_t>(i)];
            // The time in the PC's own zone (the database keeps UTC, "…T…Z").
            const QDateTime at = QDateTime::fromString(fromStd(e.at), Qt::ISODate);
            const QStringList cells{QString::number(e.revision),
                                    at.isValid() ? at.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"))
                                                 : fromStd(e.at),
                                    fromStd(e.author),
                                    e.change.before ? fromStd(*e.change.before) : tr("(none)"),
                                    e.change.after ? fromStd(*e.change.after) : tr("(none)"),
                                    revisionNoteText(notes[e.revision])};
            for (int c = 0; c < cells.size(); ++c)
                table_->setItem(i, c, new QTableWidgetItem(cells[c]));
        }
        info->setText(h.empty() ? tr("No revision of %1 changed this constant.").arg(store.qName())
                                : tr("Revisions that changed this constant: %1 (newest first).").arg(h.size()));
    } catch (const std::exception& e) {
        info->setText(tr("The history cannot be read: %1").arg(databaseErrorText(e)));
    }
    table_->resizeColumnsToContents();
    resize(760, 360);
}

// --- diff -----------------------------------------------------------------

DiffDialog::DiffDialog(ConstantsPane& pane, QWidget* parent) : QDialog(parent), pane_(pane) {
    setObjectName("constants.diffDialog");
    setWindowTitle(tr("Compare revisions — %1").arg(pane.editor().store().qName()));
    int current = 0;
    try {
        const auto revs = pane.editor().store().revisions();
        current = revs.empty() ? 0 : revs.front().revision;
    } catch (const std::exception&) {
    }
    a_ = new QSpinBox(this);
    b_ = new QSpinBox(this);
    for (QSpinBox* s : {a_, b_}) {
        s->setRange(0, std::max(current, 0));
        s->setSpecialValueText(tr("the controller now"));
    }
    a_->setValue(std::max(current - 1, current > 0 ? 1 : 0));
    b_->setValue(current);
    go_ = new QPushButton(tr("Compare"), this);
    progress_ = new QProgressBar(this);
    progress_->hide();
    summary_ = new QLabel(this);
    text_ = new QPlainTextEdit(this);
    text_->setReadOnly(true);
    text_->setLineWrapMode(QPlainTextEdit::NoWrap);
    auto* row = new QHBoxLayout;
    row->addWidget(new QLabel(tr("Revision"), this));
    row->addWidget(a_);
    row->addWidget(new QLabel(QStringLiteral("→"), this));
    row->addWidget(b_);
    row->addWidget(go_);
    row->addWidget(progress_, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(row);
    layout->addWidget(summary_);
    layout->addWidget(text_, 1);
    connect(go_, &QPushButton::clicked, this, &DiffDialog::compare);
    resize(720, 480);
}

void DiffDialog::compare() {
    go_->setEnabled(false);
    progress_->show();
    auto* w = new QFutureWatcher<LongResult>(this);
    connect(w, &QFutureWatcher<LongResult>::progressRangeChanged, progress_, &QProgressBar::setRange);
    connect(w, &QFutureWatcher<LongResult>::progressValueChanged, progress_, &QProgressBar::setValue);
    connect(w, &QFutureWatcher<LongResult>::finished, this, [this, w] {
        const LongResult r = w->result();
        w->deleteLater();
        go_->setEnabled(true);
        progress_->hide();
        if (!r.error.isEmpty()) {
            summary_->setText(tr("The revisions cannot be compared: %1").arg(r.error));
            text_->clear();
            return;
        }
        summary_->setText(r.message);
        text_->setPlainText(r.text.isEmpty() ? tr("(no difference)") : r.text);
    });
    w->setFuture(pane_.diffRevisions(a_->value(), b_->value()));
}

void DiffDialog::compareRevisions(int a, int b) {
    a_->setMaximum(std::max({a_->maximum(), a, b}));
    b_->setMaximum(a_->maximum());
    a_->setValue(a);
    b_->setValue(b);
    compare();
}

// --- calculator -------------------------------------------------------------

CalculatorDialog::CalculatorDialog(ConstantsEditor& editor, QWidget* parent)
    : QDialog(parent), editor_(editor) {
    setObjectName("constants.calculatorDialog");
    setWindowTitle(tr("C-constant calculator: acceleration (parameter 22)"));
    axis_ = new QComboBox(this);
    axis_->addItems({tr("Axis X (C22)"), tr("Axis Z (C74)")});
    formula_ = new QComboBox(this);
    formula_->addItems({tr("Formula 1: run-up from 0 to Vmax in Tacc"),
                        tr("Formula 2: braking from Vmax over S"), tr("Formula 3: acceleration A")});
    const auto spin = [this](double lo, double hi, double v, int dec) {
        auto* s = new QDoubleSpinBox(this);
        s->setRange(lo, hi);
        s->setDecimals(dec);
        s->setValue(v);
        connect(s, &QDoubleSpinBox::valueChanged, this, &CalculatorDialog::recalculate);
        return s;
    };
    v_ = spin(1, 1e6, 5000, 1);
    t_ = spin(1, 1e6, 2000, 0);
    s_ = spin(0.001, 1e5, 10, 3);
    a_ = spin(0.0001, 100, 0.5, 4);
    vLabel_ = new QLabel(tr("Vmax, mm/min"), this);
    tLabel_ = new QLabel(tr("Tacc, ms"), this);
    sLabel_ = new QLabel(tr("S, mm of braking"), this);
    aLabel_ = new QLabel(tr("A, m/s²"), this);
    auto* form = new QFormLayout;
    form->addRow(tr("Axis"), axis_);
    form->addRow(tr("Formula"), formula_);
    form->addRow(vLabel_, v_);
    form->addRow(tLabel_, t_);
    form->addRow(sLabel_, s_);
    form->addRow(aLabel_, a_);
    explain_ = new QTextBrowser(this);
    explain_->setObjectName("constants.calculatorExplanation");
    apply_ = new QPushButton(this);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(apply_, QDialogButtonBox::ApplyRole);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(apply_, &QPushButton::clicked, this, &CalculatorDialog::applyToAccel1);
    connect(axis_, &QComboBox::currentIndexChanged, this, &CalculatorDialog::recalculate);
    connect(formula_, &QComboBox::currentIndexChanged, this, &CalculatorDialog::recalculate);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(explain_, 1);
    layout->addWidget(buttons);
    resize(640, 560);
    recalculate();
}

void CalculatorDialog::setInputs(int formula, double a, double b) {
    formula_->setCurrentIndex(formula - 1);
    if (formula == 1) {
        v_->setValue(a);
        t_->setValue(b);
    } else if (formula == 2) {
        v_->setValue(a);
        s_->setValue(b);
    } else {
        a_->setValue(a);
    }
    recalculate();
}

void CalculatorDialog::recalculate() {
    const int f = formula_->currentIndex() + 1;
    const catalog::Axis axis = axis_->currentIndex() == 0 ? catalog::Axis::X : catalog::Axis::Z;
    const int number = catalog::axisParam(catalog::c::kAccel1, axis);
    for (QWidget* w : {static_cast<QWidget*>(v_), static_cast<QWidget*>(vLabel_)})
        w->setVisible(f != 3);
    for (QWidget* w : {static_cast<QWidget*>(t_), static_cast<QWidget*>(tLabel_)})
        w->setVisible(f == 1);
    for (QWidget* w : {static_cast<QWidget*>(s_), static_cast<QWidget*>(sLabel_)})
        w->setVisible(f == 2);
    for (QWidget* w : {static_cast<QWidget*>(a_), static_cast<QWidget*>(aLabel_)})
        w->setVisible(f == 3);
    const units::AxisScale s = profile::axisScale(editor_.controller().profile(), axis);
    const double perMm = static_cast<double>(s.discretesPerMm());
    QString html;
    try {
        profile::calc::AccelResult r;
        QString formula;
        if (f == 1) {
            r = profile::calc::accelByRunUp(v_->value() * perMm, t_->value(), s);
            formula = tr("Formula 1 as printed: C = 0.8533 · Vmax / Tacc, Vmax in discretes/min, Tacc in ms: "
                         "0.8533 · %1 / %2 = %3.")
                          .arg(v_->value() * perMm, 0, 'f', 0)
                          .arg(t_->value(), 0, 'f', 0)
                          .arg(r.printedRaw, 0, 'f', 2);
        } else if (f == 2) {
            r = profile::calc::accelByBraking(v_->value() * perMm, s_->value() * perMm, s);
            formula = tr("Formula 2 as printed: C = 3.556·10⁻⁶ · Vmax² / S, Vmax in discretes/min, S in discretes: "
                         "3.556·10⁻⁶ · %1² / %2 = %3.")
                          .arg(v_->value() * perMm, 0, 'f', 0)
                          .arg(s_->value() * perMm, 0, 'f', 0)
                          .arg(r.printedRaw, 0, 'f', 2);
        } else {
            r = profile::calc::accelByValue(a_->value(), s);
            formula = tr("Formula 3: C = 25600 · A / Kd, A in m/s², Kd = %1 (the discrete in µm): "
                         "25600 · %2 / %1 = %3.")
                          .arg(s.kd())
                          .arg(a_->value())
                          .arg(r.printedRaw, 0, 'f', 2);
        }
        consistent_ = r.consistentValue;
        html += QStringLiteral("<p>%1</p>").arg(formula.toHtmlEscaped());
        html += QStringLiteral("<p>%1</p>")
                    .arg(tr("The motion described: A = %1 m/s². The value as printed: <b>%2</b>, which means "
                            "%3 m/s² in K528 Studio's unit (factor %4).")
                             .arg(r.describedMPerS2, 0, 'g', 5)
                             .arg(r.printedValue)
                             .arg(r.printedMPerS2, 0, 'g', 5)
                             .arg(r.printedFactor(), 0, 'f', 2));
        html += QStringLiteral("<p>%1</p>")
                    .arg(tr("The value that gives this motion: <b>%1</b> (25600 · A / Kd = %2, integer part). "
                            "Enter this one in C%3.")
                             .arg(r.consistentValue)
                             .arg(r.consistentRaw, 0, 'f', 2)
                             .arg(number, 3, 10, QChar('0')));
        apply_->setEnabled(true);
    } catch (const std::exception& e) {
        consistent_ = 0;
        html += QStringLiteral("<p style='color:#b00000'>%1</p>").arg(coreErrorText(e).toHtmlEscaped());
        apply_->setEnabled(false);
    }
    html += QStringLiteral("<hr><p><b>%1</b></p><p>%2</p><p>%3</p>")
                .arg(tr("Why formula 1 gives twice the value"),
                     tr("Table E.1 prints three formulas for parameter 22. Formula 3 defines the unit: C = 25600·A/Kd. "
                        "Braking from V to 0 over S needs A = V²/(2S); put into formula 3 this is "
                        "25600/7200·10⁻⁶·V²/S = 3.5556·10⁻⁶·V²/S — formula 2's 3.556 rounded. A run-up from 0 to V in T "
                        "needs A = V/T, that is 25600/60000·V/T = 0.4267·V/T; formula 1 prints 0.8533, twice as much."),
                     tr("Two formulas against one: K528 Studio takes the unit of formulas 2 and 3 (docs/machine-constants.md). "
                        "A value computed by formula 1 as printed makes the axis accelerate twice as fast as described "
                        "(appendix Zh's 2000 for «2 s to 5000 mm/min» runs up in 1.07 s here). Apply the consistent value."));
    explain_->setHtml(html);
    apply_->setText(tr("Set C%1 to %2").arg(number, 3, 10, QChar('0')).arg(consistent_));
}

bool CalculatorDialog::applyToAccel1() {
    const catalog::Axis axis = axis_->currentIndex() == 0 ? catalog::Axis::X : catalog::Axis::Z;
    const int number = catalog::axisParam(catalog::c::kAccel1, axis);
    return editor_.set(number, consistent_,
                       tr("calculator: %1 → C%2 = %3")
                           .arg(formula_->currentText())
                           .arg(number, 3, 10, QChar('0'))
                           .arg(consistent_));
}

} // namespace k528::studio
