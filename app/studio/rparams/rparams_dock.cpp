#include "rparams/rparams_dock.h"

#include "catalog/rparams.h"
#include "db/notes.h"
#include "session/core_texts.h"
#include "session/shop_database.h"
#include "constants/machine_store.h"
#include "engine/positioner.h"
#include "engine/rparams.h"
#include "rparams/rparams_model.h"
#include "rparams/trial_dialog.h"
#include "controller/controller.h"
#include "database/database_ui.h"
#include "widgets.h"

#include <QComboBox>
#include <QLineEdit>
#include <QPointer>
#include <QMainWindow>
#include <QTableView>
#include <QToolButton>

namespace k528::studio {

RParamsPane::RParamsPane(ViewedController& viewed, const profile::MachineProfile& machine, QWidget* parent)
    : ParameterTablePane(viewed, "rparams", MemoryArea::R,
                         {QT_TR_NOOP("R-parameters"),
                          QT_TR_NOOP("The R-parameters of the controller on the line, all read every 2.5 s."),
                          QT_TR_NOOP("R0..R231 are written to it at once (not R158, R222, R223).")},
                         parent),
      store_(new MachineStore(machine)) {
    model_ = new RParamsModel(viewed, this);
    filter_ = new RParamsFilter(this);
    filter_->setDynamicSortFilter(true);

    show_ = filterChoice(this, "rparams.show", 6, filter_, &RParamsFilter::setShow);

    keep_ = toolButton("keepPreset", QT_TR_NOOP("Keep as preset"),
                       QT_TR_NOOP("The selected parameter's value becomes the machine's preset (a new revision)"));
    remove_ = toolButton("removePreset", QT_TR_NOOP("Remove preset"));
    keepAll_ = toolButton("keepAll", QT_TR_NOOP("Keep all as presets"),
                          QT_TR_NOOP("Every writable R-parameter that is not 0 becomes a preset, as «Keep the "
                                     "controller's memory» does"));
    apply_ = toolButton("applyPresets", QT_TR_NOOP("Load the presets"), QT_TR_NOOP("The machine's presets into the controller"));
    trial_ = toolButton("trialPart", QT_TR_NOOP("Trial part..."),
                        QT_TR_NOOP("The size measured on the trial part against the drawing: the change of the "
                                   "tool's offset R-parameter, kept as the machine's preset"));
    connect(keep_, &QToolButton::clicked, this, [this] { keepSelectedAsPreset(); });
    connect(remove_, &QToolButton::clicked, this, [this] { removeSelectedPreset(); });
    connect(keepAll_, &QToolButton::clicked, this, [this] { keepAllAsPresets(); });
    connect(apply_, &QToolButton::clicked, this, &RParamsPane::applyPresets);
    connect(trial_, &QToolButton::clicked, this, [this] { trialPartDialog()->show(); });
    build(model_, filter_, {show_}, {keep_, remove_, keepAll_, apply_, trial_},
          {4, 8, 14, 30, 7, 7}); // No., access, preset screen, meaning, discretes, mm

    connect(model_, &RParamsModel::refused, this, [this](const QString& why) { say(why, true); });
    try {
        model_->setPresets(store_->current().r);
    } catch (const std::exception& e) {
        say(tr("The machine's presets are not read from the database: %1").arg(databaseErrorText(e)), true);
    }
    // File > Database…: the presets of the machine as the new database holds it.
    connect(DatabaseWatch::instance(), &DatabaseWatch::switched, this, [this](const QString& where) {
        try {
            const MachineStore::Reloaded m = store_->reload();
            model_->setPresets(m.profile.r);
            say(m.revision == 0 ? tr("Database %1 has no machine %2: the presets shown are those the window "
                                     "loaded; the first one kept creates the machine there")
                                      .arg(where, store_->qName())
                                : tr("Database %1: the presets shown are those of revision %2 of %3")
                                      .arg(where)
                                      .arg(m.revision)
                                      .arg(store_->qName()),
                false);
        } catch (const std::exception& e) {
            say(tr("The machine's presets are not read from the database: %1").arg(databaseErrorText(e)), true);
        }
    });
    retranslate();
}

RParamsPane::~RParamsPane() {
    delete store_;
}

void RParamsPane::retranslatePane() {
    searchField()->setPlaceholderText(tr("Search: number or meaning"));
    setItemTexts(show_, {tr("All R0..R299"), tr("User R0..R149"), tr("System (writable)"), tr("Read only R232..R262"),
                         tr("With a preset"), tr("Not zero")});
    note_->setPlaceholderText(tr("why the presets change (kept with the revision)"));
}

void RParamsPane::selectR(int number) {
    selectSource(model_->index(number, RParamsModel::Value));
}

int RParamsPane::keepPresets(const std::map<int, std::optional<std::int64_t>>& presets, const QString& given) {
    if (presets.empty()) {
        say(tr("No preset changes"), false);
        return 0;
    }
    db::Edit e;
    e.r = presets;
    QStringList items;
    for (const auto& [n, v] : presets)
        items << (v ? QStringLiteral("R%1=%2").arg(n).arg(*v) : QStringLiteral("R%1 -").arg(n));
    const QString note = !given.isEmpty()              ? given
                         : note_->text().trimmed().isEmpty()
                             ? QString::fromStdString(db::noteText({"studio.presets", {items.join(QLatin1Char(' ')).toStdString()}}))
                             : note_->text().trimmed();
    const MachineStore::Kept k = store_->keep(e, note);
    if (k.revision == 0) {
        say(tr("The presets were not kept: %1").arg(k.error), true);
        return 0;
    }
    try {
        model_->setPresets(store_->current().r);
    } catch (const std::exception&) {
    }
    note_->clear();
    say(tr("%1 — kept as revision %2 of %3").arg(revisionNoteText(note.toStdString())).arg(k.revision).arg(store_->qName()), false);
    return k.revision;
}

int RParamsPane::keepSelectedAsPreset() {
    const int n = selectedNumber();
    if (n < 0) {
        say(tr("Select an R-parameter first"), true);
        return 0;
    }
    if (engine::rReadOnly(n)) {
        say(tr("R%1 is read only (R232..R262): it cannot be preset").arg(n), true);
        return 0;
    }
    return keepPresets({{n, viewed_.current().rValues()[static_cast<std::size_t>(n)]}});
}

int RParamsPane::removeSelectedPreset() {
    const int n = selectedNumber();
    if (n < 0 || !model_->presets().count(n)) {
        say(tr("The selected R-parameter has no preset"), true);
        return 0;
    }
    return keepPresets({{n, std::nullopt}});
}

int RParamsPane::keepAllAsPresets() {
    std::map<int, std::optional<std::int64_t>> p;
    const auto r = viewed_.current().rValues();
    for (int n = 0; n < engine::kRCount && n < static_cast<int>(r.size()); ++n) {
        if (engine::rReadOnly(n))
            continue;
        const std::int64_t v = r[static_cast<std::size_t>(n)];
        const auto it = model_->presets().find(n);
        if (v != 0 && (it == model_->presets().end() || it->second != v))
            p[n] = v;
        else if (v == 0 && it != model_->presets().end())
            p[n] = std::nullopt;
    }
    return keepPresets(p);
}

TrialPartDialog* RParamsPane::trialPartDialog() {
    auto* d = new TrialPartDialog(store_->current(), this);
    d->setAttribute(Qt::WA_DeleteOnClose);
    connect(d, &TrialPartDialog::keepRequested, this, [this](int r, qint64 value, const QString& note) {
        keepTrialCorrection(r, value, note);
    });
    return d;
}

int RParamsPane::keepTrialCorrection(int r, std::int64_t value, const QString& note) {
    const int revision = keepPresets({{r, value}}, note);
    if (revision == 0)
        return 0;
    QPointer<RParamsPane> self(this);
    model_->setValue(r, value, [self, r, revision](const QString& why) {
        if (self && !why.isEmpty())
            self->say(tr("Kept as revision %1; R%2 not set in the controller: %3").arg(revision).arg(r).arg(why), true);
    });
    return revision;
}

void RParamsPane::applyPresets() {
    std::vector<std::pair<int, std::int64_t>> presets(model_->presets().begin(), model_->presets().end());
    apply_->setEnabled(false);
    applyFrom(std::move(presets), 0);
}

void RParamsPane::applyFrom(std::vector<std::pair<int, std::int64_t>> presets, std::size_t next) {
    // One after another: a controller on the link answers each in turn.
    if (next == presets.size()) {
        apply_->setEnabled(true);
        say(tr("Presets loaded into the controller: %1").arg(presets.size()), false);
        return;
    }
    const auto [n, v] = presets[next];
    QPointer<RParamsPane> self(this);
    model_->setValue(n, v, [self, presets, next](const QString& why) {
        if (!self)
            return;
        if (!why.isEmpty()) {
            self->apply_->setEnabled(true);
            self->say(tr("Presets loaded into the controller: %1 of %2; R%3 not: %4")
                          .arg(next)
                          .arg(presets.size())
                          .arg(presets[next].first)
                          .arg(why),
                      true);
            return;
        }
        self->applyFrom(presets, next + 1);
    });
}

QDockWidget* addRParamsDock(QMainWindow* window, ViewedController& viewed, const profile::MachineProfile& machine) {
    return addParameterTableDock(window, new RParamsPane(viewed, machine));
}

} // namespace k528::studio
