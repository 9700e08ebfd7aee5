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
#include "controller/view_notice.h"
#include "database/database_ui.h"
#include "widgets.h"
#include "workspace/flow_layout.h"
#include "workspace/screen_fit.h"
#include "workspace/pane_dock.h"

#include <QComboBox>
#include <QDockWidget>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPointer>
#include <QLineEdit>
#include <QMainWindow>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

namespace k528::studio {

namespace {

class RParamsDock : public PaneDock {
public:
    RParamsDock(QMainWindow* window, ViewedController& viewed, const profile::MachineProfile& machine)
        : PaneDock(window, "rparams") {
        auto* notice = new ViewNotice(new RParamsPane(viewed, machine), this);
        notice->follow(viewed, [](Controller& c) -> std::pair<ViewNotice::Level, QString> {
            if (c.simulated())
                return {ViewNotice::Level::None, {}};
            const QString why = c.whyNotWritable(MemoryArea::R);
            return {ViewNotice::Level::Info,
                    why.isEmpty() ? RParamsPane::tr("The R-parameters of the controller on the line, all read every 2.5 s. "
                                                    "R0..R231 are written to it at once (not R158, R222, R223).")
                                  : RParamsPane::tr("The R-parameters of the controller on the line, all read every 2.5 s. "
                                                    "They cannot be changed now: %1.")
                                        .arg(why)};
        });
        setWidget(notice);
        retranslate();
    }

private:
    void retranslate() override { setWindowTitle(RParamsPane::tr("R-parameters")); }
};

QToolButton* button(QWidget* parent, const char* name) {
    auto* b = new QToolButton(parent);
    b->setObjectName(name);
    b->setAutoRaise(true);
    return b;
}

} // namespace

RParamsPane::RParamsPane(ViewedController& viewed, const profile::MachineProfile& machine, QWidget* parent)
    : QWidget(parent), viewed_(viewed), store_(new MachineStore(machine)) {
    setObjectName("rparamsPane");
    model_ = new RParamsModel(viewed, this);
    filter_ = new RParamsFilter(this);
    filter_->setSourceModel(model_);
    filter_->setDynamicSortFilter(true);

    search_ = new QLineEdit(this);
    search_->setObjectName("rparams.search");
    search_->setClearButtonEnabled(true);
    show_ = new QComboBox(this);
    show_->setObjectName("rparams.show");
    for (int i = 0; i < 6; ++i)
        show_->addItem(QString());
    auto* top = new QHBoxLayout;
    top->addWidget(search_, 1);
    top->addWidget(show_);

    keep_ = button(this, "rparams.keepPreset");
    remove_ = button(this, "rparams.removePreset");
    keepAll_ = button(this, "rparams.keepAll");
    apply_ = button(this, "rparams.applyPresets");
    trial_ = button(this, "rparams.trialPart");
    noteLabel_ = new QLabel(this);
    note_ = new QLineEdit(this);
    note_->setObjectName("rparams.note");
    note_->setMinimumWidth(180);
    auto* tools = new FlowLayout; // wraps in a narrow dock: every button in reach
    for (QToolButton* b : {keep_, remove_, keepAll_, apply_, trial_})
        tools->addWidget(b);
    tools->addGroup({noteLabel_, note_});
    connect(keep_, &QToolButton::clicked, this, [this] { keepSelectedAsPreset(); });
    connect(remove_, &QToolButton::clicked, this, [this] { removeSelectedPreset(); });
    connect(keepAll_, &QToolButton::clicked, this, [this] { keepAllAsPresets(); });
    connect(apply_, &QToolButton::clicked, this, &RParamsPane::applyPresets);
    connect(trial_, &QToolButton::clicked, this, [this] { trialPartDialog()->show(); });

    table_ = new QTableView(this);
    table_->setObjectName("rparams.table");
    table_->setModel(filter_);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                            QAbstractItemView::AnyKeyPressed);
    table_->setAlternatingRowColors(true);
    table_->setWordWrap(false);
    table_->verticalHeader()->hide();
    table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);
    table_->horizontalHeader()->setStretchLastSection(true);
    const int em = fontMetrics().horizontalAdvance(QLatin1Char('M'));
    table_->setColumnWidth(RParamsModel::Number, 4 * em);
    table_->setColumnWidth(RParamsModel::Access, 8 * em);
    table_->setColumnWidth(RParamsModel::Group, 14 * em);
    table_->setColumnWidth(RParamsModel::Meaning, 30 * em);
    table_->setColumnWidth(RParamsModel::Value, 7 * em);
    table_->setColumnWidth(RParamsModel::Mm, 7 * em);

    status_ = new QLabel(this);
    status_->setObjectName("rparams.status");
    status_->setWordWrap(true);
    status_->setProperty(kKeptInView, true); // in view below the table when the dock scrolls
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(top);
    layout->addLayout(tools);
    layout->addWidget(table_, 1);
    layout->addWidget(status_);

    connect(search_, &QLineEdit::textChanged, filter_, &RParamsFilter::setSearch);
    connect(show_, &QComboBox::currentIndexChanged, this,
            [this](int i) { filter_->setShow(static_cast<RParamsFilter::Show>(i)); });
    const auto follow = [this] {
        disconnect(updates_);
        updates_ = connect(&viewed_.current(), &Controller::updated, model_, &RParamsModel::refresh);
        model_->refresh();
    };
    connect(&viewed_, &ViewedController::changed, this, follow);
    follow();
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

void RParamsPane::retranslate() {
    search_->setPlaceholderText(tr("Search: number or meaning"));
    show_->setItemText(0, tr("All R0..R299"));
    show_->setItemText(1, tr("User R0..R149"));
    show_->setItemText(2, tr("System (writable)"));
    show_->setItemText(3, tr("Read only R232..R262"));
    show_->setItemText(4, tr("With a preset"));
    show_->setItemText(5, tr("Not zero"));
    keep_->setText(tr("Keep as preset"));
    keep_->setToolTip(tr("The selected parameter's value becomes the machine's preset (a new revision)"));
    remove_->setText(tr("Remove preset"));
    keepAll_->setText(tr("Keep all as presets"));
    keepAll_->setToolTip(tr("Every writable R-parameter that is not 0 becomes a preset, as «Keep the controller's memory» does"));
    apply_->setText(tr("Load the presets"));
    apply_->setToolTip(tr("The machine's presets into the controller"));
    trial_->setText(tr("Trial part..."));
    trial_->setToolTip(tr("The size measured on the trial part against the drawing: the change of the tool's "
                          "offset R-parameter, kept as the machine's preset"));
    noteLabel_->setText(tr("Note:"));
    note_->setPlaceholderText(tr("why the presets change (kept with the revision)"));
    model_->retranslate();
}

void RParamsPane::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(e);
}

void RParamsPane::say(const QString& text, bool bad) {
    showStatus(status_, text, bad);
}

QString RParamsPane::statusText() const {
    return status_->text();
}

int RParamsPane::selected() const {
    const QModelIndex i = table_->currentIndex();
    return i.isValid() ? i.data(RParamsModel::NumberRole).toInt() : -1;
}

void RParamsPane::selectR(int number) {
    const QModelIndex i = filter_->mapFromSource(model_->index(number, RParamsModel::Value));
    if (i.isValid()) {
        table_->setCurrentIndex(i);
        table_->scrollTo(i);
    }
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
    const int n = selected();
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
    const int n = selected();
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
    auto* dock = new RParamsDock(window, viewed, machine);
    window->addDockWidget(Qt::LeftDockWidgetArea, dock);
    dock->hide(); // shown from the View menu; the workspaces place it
    return dock;
}

} // namespace k528::studio
