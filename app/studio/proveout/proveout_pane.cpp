#include "proveout/proveout_pane.h"
#include "session/core_texts.h"

#include "editor/editor_tab.h"
#include "editor/program_editor.h"
#include "language.h"
#include "plc/description.h"
#include "profile/english.h"
#include "profile/tools.h"
#include "session/translated_texts.h"
#include "stock/stock.h"
#include "window_language.h"
#include "workspace/pane_dock.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QDockWidget>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QPointer>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QThreadPool>
#include <QVBoxLayout>

#include <optional>

namespace k528::studio {

// What a proof reads: copies, so that the worker owns them.
struct ProveoutPane::Input {
    profile::MachineProfile machine;
    program::ProgramStore store;
    QByteArray text;     // the file's, for its own blank (NC-200 UCG comment)
    QString blankField;  // the pane's blank, "" = the file's
};

struct ProveoutPane::Output {
    std::uint64_t generation = 0;
    proveout::Result result;
    QString error; // the blank or the machine's data could not be read
    bool blankFromFile = false;
};

namespace {

// core/stock/stock.cpp's catalog of a UCG line's errors, each text marked
// for the translators.
const TranslatedText kUcgErrors[] = {
    {"expected", QT_TRANSLATE_NOOP("k528::studio::ProveoutPane", "expected UCG")},
    {"type", QT_TRANSLATE_NOOP("k528::studio::ProveoutPane", "expected the type N after UCG,")},
    {"z", QT_TRANSLATE_NOOP("k528::studio::ProveoutPane", "expected Z<outer length>Z<bore length>")},
    {"x", QT_TRANSLATE_NOOP("k528::studio::ProveoutPane", "expected X<outer diameter>X<bore diameter>")},
    {"s", QT_TRANSLATE_NOOP("k528::studio::ProveoutPane", "expected S<outer angle>S<bore angle>")},
    {"direction", QT_TRANSLATE_NOOP("k528::studio::ProveoutPane", "the direction is 0 or 1")},
    {"detail", QT_TRANSLATE_NOOP("k528::studio::ProveoutPane", "the detail is -1..-5")},
    {"small", QT_TRANSLATE_NOOP("k528::studio::ProveoutPane", "the blank is smaller than 0.01 mm")},
    {"bore-sign", QT_TRANSLATE_NOOP("k528::studio::ProveoutPane", "the bore length has the sign of the outer length")},
    {"bore-long", QT_TRANSLATE_NOOP("k528::studio::ProveoutPane", "the bore is longer than the blank")},
    {"bore-diameter", QT_TRANSLATE_NOOP("k528::studio::ProveoutPane", "the bore diameter is 0..the outer diameter")},
    {"cone", QT_TRANSLATE_NOOP("k528::studio::ProveoutPane", "cone angles are within ±90°")},
    {"none", QT_TRANSLATE_NOOP("k528::studio::ProveoutPane", "no UCG in the file")},
};

const TranslatedTexts kUcgTexts("k528::studio::ProveoutPane", kUcgErrors);

ProveoutPane::Output proveInput(const ProveoutPane::Input& in) {
    ProveoutPane::Output out;
    std::optional<stock::Blank> blank;
    std::string error, id;
    if (!in.blankField.trimmed().isEmpty()) {
        blank = stock::parseUcg(in.blankField.trimmed().toStdString(), &error, &id);
        if (!blank) {
            out.error = QCoreApplication::translate("k528::studio::ProveoutPane", "The blank: %1").arg(ucgErrorText(id));
            return out;
        }
    } else if (in.text.contains("UCG")) {
        const std::string_view t(in.text.constData(), static_cast<std::size_t>(in.text.size()));
        blank = stock::findUcg(t, &error, &id);
        if (!blank && id != stock::kNoUcg) {
            out.error = QCoreApplication::translate("k528::studio::ProveoutPane", "The file's blank: %1")
                            .arg(ucgErrorText(id));
            return out;
        }
        out.blankFromFile = blank.has_value();
    }
    engine::PreviewOptions po;
    po.fromReferencePoint = true; // as a run starts, after homing (`k528 check --profile`)
    try {
        out.result = proveout::proveStore(in.machine, in.store, po, blank);
    } catch (const plc::DescriptionError& e) {
        out.error = QCoreApplication::translate("k528::studio::ProveoutPane", "The machine's description: %1")
                        .arg(descriptionErrorText(e));
    } catch (const profile::ToolError& e) {
        out.error = QCoreApplication::translate("k528::studio::ProveoutPane", "The machine's tools: %1")
                        .arg(problemText(e.problem()));
    }
    return out;
}

QString mm(double v) { return QString::number(v, 'f', 3); }

static_assert(ProveoutPane::kIndicator == ProgramEditor::kProveoutIndicator);

} // namespace

bool hasUcgText(std::string_view id) { return kUcgTexts.has(id); }

QString ucgErrorText(std::string_view id) {
    if (!kUcgTexts.has(id)) // an id without a translation
        return coreText(stock::ucgErrorText(id, {}, true), stock::ucgErrorText(id, {}, false));
    return QString::fromStdString(stock::ucgErrorText(kUcgTexts.pattern(id).toStdString()));
}

ProveoutPane::ProveoutPane(EditorTab* editor, QWidget* parent)
    : QWidget(parent), editor_(editor), alive_(std::make_shared<bool>(true)) {
    setObjectName("proveout.pane");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    auto* row = new QHBoxLayout;
    blankLabel_ = new QLabel(this);
    blank_ = new QLineEdit(this);
    blank_->setObjectName("proveout.blank");
    proveButton_ = new QPushButton(this);
    proveButton_->setObjectName("proveout.prove");
    auto_ = new QCheckBox(this);
    auto_->setObjectName("proveout.auto");
    auto_->setChecked(true);
    row->addWidget(blankLabel_);
    row->addWidget(blank_, 1);
    row->addWidget(proveButton_);
    layout->addLayout(row);
    layout->addWidget(auto_);
    summary_ = new QLabel(this);
    summary_->setObjectName("proveout.summary");
    summary_->setWordWrap(true);
    layout->addWidget(summary_);
    table_ = new QTableWidget(0, 5, this);
    table_->setObjectName("proveout.findings");
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->verticalHeader()->hide();
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->setWordWrap(true); // a finding's text wraps in its row
    layout->addWidget(table_, 3);
    toolsTitle_ = new QLabel(this);
    layout->addWidget(toolsTitle_);
    tools_ = new QTableWidget(0, 8, this);
    tools_->setObjectName("proveout.tools");
    tools_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    tools_->verticalHeader()->hide();
    tools_->horizontalHeader()->setStretchLastSection(true);
    layout->addWidget(tools_, 2);

    connect(proveButton_, &QPushButton::clicked, this, [this] { schedule(); });
    connect(blank_, &QLineEdit::editingFinished, this, [this] {
        if (auto_->isChecked())
            schedule();
    });
    connect(table_, &QTableWidget::cellActivated, this, [this](int r, int) { activate(r); });
    connect(table_, &QTableWidget::cellDoubleClicked, this, [this](int r, int) { activate(r); });
    if (editor_)
        // After each validation of the current file, and on a switch of tab.
        connect(editor_, &EditorTab::problemCountChanged, this, [this] {
            if (auto_->isChecked())
                schedule();
        });
    retranslate();
    schedule();
}

ProveoutPane::~ProveoutPane() { *alive_ = false; }

bool ProveoutPane::input(Input& in, QString& why) const {
    ProgramEditor* ed = editor_ ? editor_->currentEditor() : nullptr;
    if (!ed) {
        why = tr("Open a program file in the editor: it is proved on the machine it is checked for.");
        return false;
    }
    if (!ed->machine()) {
        why = tr("The file is checked for no machine: choose one (Editor menu) to prove it.");
        return false;
    }
    if (program::hasErrors(ed->diagnostics())) {
        why = tr("The file has errors (Problems): it is proved once they are fixed.");
        return false;
    }
    in.machine = *ed->machine();
    in.store = ed->store();
    in.text = ed->text().toUtf8();
    in.blankField = blank_->text();
    return true;
}

void ProveoutPane::schedule() {
    ++generation_;
    if (busy_) {
        again_ = true;
        return;
    }
    auto in = std::make_shared<Input>();
    QString why;
    if (!input(*in, why)) {
        showNothing(why);
        return;
    }
    showTools(in.get());
    busy_ = true;
    const std::uint64_t gen = generation_;
    std::weak_ptr<bool> alive = alive_;
    QPointer<ProveoutPane> self(this);
    QThreadPool::globalInstance()->start([in, gen, self, alive] {
        auto out = std::make_shared<Output>(proveInput(*in));
        out->generation = gen;
        if (alive.expired())
            return;
        QMetaObject::invokeMethod(
            QCoreApplication::instance(), [self, out] {
                if (!self)
                    return;
                self->busy_ = false;
                if (out->generation == self->generation_ && !self->again_)
                    self->show(*out);
                if (self->again_) {
                    self->again_ = false;
                    self->schedule();
                }
            },
            Qt::QueuedConnection);
    });
}

void ProveoutPane::showNothing(const QString& why) {
    showTools(nullptr);
    Output none;
    none.error = why; // the summary says it, no finding is left shown
    show(none);
}

void ProveoutPane::proveNow() {
    ++generation_;
    Input in;
    QString why;
    if (!input(in, why)) {
        showNothing(why);
        return;
    }
    showTools(&in);
    Output out = proveInput(in);
    out.generation = generation_;
    show(out);
}

void ProveoutPane::show(const Output& out) {
    why_ = out.error;
    findings_ = out.result.findings;
    materialRan_ = out.result.material;
    chuckRan_ = out.result.chuck;
    blankFromFile_ = out.blankFromFile;
    fillFindings();
    markEditor();
    refreshSummary();
    ++proofs_;
    emit proved();
}

void ProveoutPane::markEditor() {
    ProgramEditor* ed = editor_ ? editor_->currentEditor() : nullptr;
    if (marked_ && marked_ != ed)
        editor_->setProveoutFindings(marked_, {});
    marked_ = ed;
    if (ed) // boxed on their lines, listed in the Problems
        editor_->setProveoutFindings(ed, findings_);
}

void ProveoutPane::fillFindings() {
    table_->setRowCount(static_cast<int>(findings_.size()));
    for (int r = 0; r < table_->rowCount(); ++r) {
        const proveout::Finding& f = findings_[static_cast<std::size_t>(r)];
        auto* sev = new QTableWidgetItem(f.isError() ? tr("Error") : tr("Warning"));
        sev->setData(kRuleRole, QString::fromUtf8(proveout::ruleId(f.rule).data(),
                                                  static_cast<qsizetype>(proveout::ruleId(f.rule).size())));
        sev->setForeground(f.isError() ? QColor(200, 30, 30) : QColor(170, 110, 0));
        table_->setItem(r, 0, sev);
        table_->setItem(r, 1, new QTableWidgetItem(QStringLiteral("L%1").arg(f.program)));
        table_->setItem(r, 2, new QTableWidgetItem(QStringLiteral("N%1").arg(f.n)));
        auto* line = new QTableWidgetItem(QString::number(f.line));
        line->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        table_->setItem(r, 3, line);
        QString text = findingText(f);
        if (f.occurrences > 1)
            text += QStringLiteral(" (×%1)").arg(f.occurrences);
        auto* msg = new QTableWidgetItem(text);
        msg->setToolTip(text);
        table_->setItem(r, 4, msg);
    }
    for (int col = 0; col < 4; ++col)
        table_->resizeColumnToContents(col);
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->resizeRowsToContents();
}

void ProveoutPane::showTools(const Input* in) {
    tools_->setRowCount(0);
    if (!in)
        return;
    std::vector<profile::Tool> tools;
    try {
        tools = profile::tools(in->machine);
    } catch (const profile::ToolError&) {
        return; // the proof says why
    }
    tools_->setRowCount(static_cast<int>(tools.size()));
    for (int r = 0; r < tools_->rowCount(); ++r) {
        const profile::Tool& t = tools[static_cast<std::size_t>(r)];
        const profile::ToolOffsets o = profile::toolOffsets(t, in->machine);
        QString kind;
        switch (t.kind) {
        case profile::ToolKind::Turning: kind = tr("turning"); break;
        case profile::ToolKind::Facing: kind = tr("facing"); break;
        case profile::ToolKind::Grooving: kind = tr("grooving"); break;
        case profile::ToolKind::Boring: kind = tr("boring bar"); break;
        case profile::ToolKind::Drill: kind = tr("drill"); break;
        case profile::ToolKind::Threading: kind = tr("threading"); break;
        }
        const QStringList cells = {
            QString::number(t.station),
            kind,
            mm(t.tipRadiusMm),
            mm(o.xMm),
            mm(o.zMm),
            t.offsetR >= 0 ? QStringLiteral("R%1, R%2").arg(t.offsetR).arg(t.offsetR + 1) : QString(),
            t.maxDepthMm > 0 ? mm(t.maxDepthMm) : QStringLiteral("—"),
            // The machine's name for it in the window's language (its Russian when it gives no English).
            coreText(profile::toolName(in->machine, t, false), profile::toolName(in->machine, t, true)),
        };
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            if (c != 1 && c != 7)
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            tools_->setItem(r, c, item);
        }
    }
    tools_->resizeColumnsToContents();
    tools_->horizontalHeader()->setStretchLastSection(true);
}

void ProveoutPane::refreshSummary() {
    if (!why_.isEmpty()) {
        summary_->setText(why_);
        return;
    }
    std::size_t errors = 0;
    for (const proveout::Finding& f : findings_)
        errors += f.isError() ? 1 : 0;
    QString s = findings_.empty() ? tr("Nothing found.")
                                  : tr("Errors: %1, warnings: %2.").arg(errors).arg(findings_.size() - errors);
    QStringList ran;
    if (materialRan_)
        ran << (blankFromFile_ ? tr("the blank of the file (UCG)") : tr("the blank"));
    if (chuckRan_)
        ran << tr("the chuck and the turret");
    ran << tr("the spindles");
    s += QLatin1Char(' ') + tr("Proved against: %1.").arg(ran.join(QStringLiteral(", ")));
    if (!materialRan_)
        s += QLatin1Char(' ') + tr("No blank: give one (UCG) to check the rapids against the material.");
    summary_->setText(s);
}

void ProveoutPane::activate(int row) {
    if (row < 0 || row >= static_cast<int>(findings_.size()) || !editor_)
        return;
    const proveout::Finding& f = findings_[static_cast<std::size_t>(row)];
    if (editor_->showLine(f.program, f.line))
        emit lineShown(f.program, f.line);
}

void ProveoutPane::retranslate() {
    blankLabel_->setText(tr("Blank (UCG)"));
    blank_->setPlaceholderText(tr("the file's own"));
    blank_->setToolTip(tr("The blank as a UCG line (NC-200); empty: the UCG comment of the file"));
    proveButton_->setText(tr("Prove"));
    proveButton_->setToolTip(tr("Run the file's programs in preview against the blank, the chuck, "
                                "the turret and the tools of the machine"));
    auto_->setText(tr("Prove after each change"));
    toolsTitle_->setText(tr("The machine's tools"));
    table_->setHorizontalHeaderLabels({tr("Severity"), tr("Program"), tr("Frame"), tr("Line"), tr("Text")});
    tools_->setHorizontalHeaderLabels({tr("Station"), tr("Kind"), tr("Radius, mm"), tr("Offset X, mm"),
                                       tr("Offset Z, mm"), tr("Offsets in"), tr("Max depth, mm"), tr("Tool")});
    tools_->horizontalHeaderItem(2)->setToolTip(tr("The tool's nose radius"));
    tools_->horizontalHeaderItem(6)->setToolTip(tr("The deepest cut the tool takes (its cutting edge)"));
    fillFindings(); // the findings' texts in the new language
    refreshSummary();
}

void ProveoutPane::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) {
        retranslate();
        // The tools' kinds and names in the new language.
        Input in;
        QString why;
        showTools(input(in, why) ? &in : nullptr);
    }
    QWidget::changeEvent(e);
}

QDockWidget* addProveoutDock(QMainWindow* w, EditorTab* editor, QTabWidget* workArea) {
    auto* dock = new PaneDock(w, "proveout", [] { return ProveoutPane::tr("Prove-out"); });
    auto* pane = new ProveoutPane(editor, dock);
    dock->setWidget(pane);
    if (workArea && editor)
        QObject::connect(pane, &ProveoutPane::lineShown, workArea,
                         [workArea, editor] { workArea->setCurrentWidget(editor); });
    w->addDockWidget(Qt::RightDockWidgetArea, dock);
    return dock;
}

} // namespace k528::studio
