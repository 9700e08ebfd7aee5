#include "editor/debug_panel.h"

#include "catalog/rparams.h"
#include "engine/preview_run.h"
#include "engine/rparams.h"
#include "editor/debug_session.h"
#include "editor/editor_tab.h"
#include "editor/program_editor.h"
#include "window_language.h"
#include "session/core_texts.h"
#include "session/program_loader.h"
#include "session/simulation_session.h"

#include <QAction>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QPushButton>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QShortcut>
#include <QToolBar>
#include <QTreeWidget>
#include <QPointer>
#include <QVBoxLayout>

#include <algorithm>

namespace k528::studio {

namespace {

// Real time, ×2…×100, fastest (0).
constexpr double kSpeeds[] = {1, 2, 5, 10, 20, 50, 100, 0};

void setTextIfChanged(QTreeWidgetItem* it, int col, const QString& t) {
    if (it->text(col) != t)
        it->setText(col, t);
}

} // namespace

DebugPanel::DebugPanel(EditorTab* tab, SimulationSession* session, QWidget* parent)
    : QWidget(parent), tab_(tab), session_(session), debug_(new DebugSession(session, this)) {
    setObjectName("debug.panel");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 0, 2, 0);
    toolbar_ = new QToolBar(this);
    toolbar_->setObjectName("debug.toolbar");
    toolbar_->setToolButtonStyle(Qt::ToolButtonTextOnly);
    layout->addWidget(toolbar_);
    runAction_ = toolbar_->addAction(QString(), this, [this] { run(); });
    runAction_->setObjectName("debug.run");
    runAction_->setShortcut(Qt::Key_F5);
    holdAction_ = toolbar_->addAction(QString(), this, &DebugPanel::hold);
    holdAction_->setObjectName("debug.hold");
    resumeAction_ = toolbar_->addAction(QString(), this, &DebugPanel::resume);
    resumeAction_->setObjectName("debug.resume");
    stepAction_ = toolbar_->addAction(QString());
    stepAction_->setObjectName("debug.singleFrame");
    stepAction_->setCheckable(true);
    connect(stepAction_, &QAction::toggled, this, &DebugPanel::setSingleFrame);
    cursorAction_ = toolbar_->addAction(QString(), this, [this] { runToCursor(); });
    cursorAction_->setObjectName("debug.runToCursor");
    cursorAction_->setShortcut(Qt::CTRL | Qt::Key_F10);
    startHereAction_ = toolbar_->addAction(QString(), this, [this] { startHere(); });
    startHereAction_->setObjectName("debug.startHere");
    startHereAction_->setShortcut(Qt::CTRL | Qt::SHIFT | Qt::Key_F10);
    stopAction_ = toolbar_->addAction(QString(), this, &DebugPanel::stop);
    stopAction_->setObjectName("debug.stop");
    resetAction_ = toolbar_->addAction(QString(), this, &DebugPanel::reset);
    resetAction_->setObjectName("debug.reset");
    // F5 and Ctrl+F10 work in the whole window while the debugger is shown.

    auto* speedRow = new QHBoxLayout;
    speedLabel_ = new QLabel(this);
    speed_ = new QComboBox(this);
    speed_->setObjectName("debug.speed");
    for (double f : kSpeeds)
        speed_->addItem(QString(), f);
    speedRow->addWidget(speedLabel_);
    speedRow->addWidget(speed_, 1);
    layout->addLayout(speedRow);
    connect(speed_, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (!session_ || i < 0)
            return;
        const double f = speed_->itemData(i).toDouble();
        session_->setFastest(f == 0);
        if (f > 0)
            session_->setSpeed(f);
    });

    status_ = new QLabel(this);
    status_->setObjectName("debug.status");
    status_->setWordWrap(true);
    layout->addWidget(status_);

    stackLabel_ = new QLabel(this);
    layout->addWidget(stackLabel_);
    stack_ = new QTreeWidget(this);
    stack_->setObjectName("debug.callStack");
    stack_->setColumnCount(4);
    stack_->setRootIsDecorated(false);
    stack_->header()->setStretchLastSection(true);
    layout->addWidget(stack_, 1);

    watchLabel_ = new QLabel(this);
    layout->addWidget(watchLabel_);
    watchAdd_ = new QLineEdit(this);
    watchAdd_->setObjectName("debug.watchAdd");
    layout->addWidget(watchAdd_);
    watch_ = new QTreeWidget(this);
    watch_->setObjectName("debug.watch");
    watch_->setColumnCount(3);
    watch_->setRootIsDecorated(false);
    watch_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    watch_->header()->setStretchLastSection(true);
    layout->addWidget(watch_, 2);

    connect(watchAdd_, &QLineEdit::returnPressed, this, [this] {
        QString t = watchAdd_->text().trimmed();
        if (t.startsWith('R', Qt::CaseInsensitive))
            t = t.mid(1);
        bool ok = false;
        const int n = t.toInt(&ok);
        if (ok && addWatch(n))
            watchAdd_->clear();
        else if (!ok)
            emit statusMessage(tr("Type an R-parameter number, R0..R299."));
    });
    connect(watch_, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem* it, int col) {
        if (it && col == 1)
            watch_->editItem(it, 1);
    });
    connect(watch_, &QTreeWidget::itemChanged, this, &DebugPanel::watchEdited);
    auto* del = new QShortcut(QKeySequence::Delete, watch_, nullptr, nullptr, Qt::WidgetShortcut);
    connect(del, &QShortcut::activated, this, [this] {
        if (QTreeWidgetItem* it = watch_->currentItem())
            removeWatch(it->data(0, Qt::UserRole).toInt());
    });
    connect(stack_, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* it) {
        ProgramEditor* ed = debug_->target();
        const int line = it ? it->data(0, Qt::UserRole).toInt() : 0;
        if (ed && line > 0 && ed->store().find(it->data(0, Qt::UserRole + 1).toInt())) {
            ed->setCursorPosition(line - 1, 0);
            ed->ensureLineVisible(line - 1);
        }
    });

    connect(debug_, &DebugSession::changed, this, &DebugPanel::refresh);
    connect(debug_, &DebugSession::message, this, &DebugPanel::statusMessage);
    if (session_) {
        connect(session_, &SimulationSession::advanced, this, [this] {
            refreshStack();
            refreshWatch();
        });
        const auto showSpeed = [this] {
            const double f = session_->isFastest() ? 0.0 : session_->speed();
            const int i = speed_->findData(f);
            if (i >= 0) {
                const QSignalBlocker b(speed_);
                speed_->setCurrentIndex(i);
            }
        };
        connect(session_, &SimulationSession::speedChanged, this, showSpeed);
        connect(session_, &SimulationSession::fastestChanged, this, showSpeed);
        showSpeed();
    }
    for (int n : {1, 158})
        addWatch(n);
    retranslate();
    refresh();
}

bool DebugPanel::run() {
    if (!session_)
        return false;
    if (debug_->held()) {
        debug_->resume();
        return true;
    }
    if (debug_->programActive() || debug_->phase() != DebugSession::Phase::Idle) {
        emit statusMessage(tr("A program is under way: stop it first."));
        return false;
    }
    ProgramEditor* ed = tab_ ? tab_->currentEditor() : nullptr;
    if (!ed) {
        emit statusMessage(tr("Open a program file first."));
        return false;
    }
    session_->controller().setStartPoint(std::nullopt); // from the top
    debug_->setTarget(ed);
    // Into the simulated machine it debugs (the check-then-load path), never
    // a controller on the link the window may show.
    const ProgramLoad loaded = loadProgramText(*session_, ed->text().toStdString(), tr("the file"));
    if (!loaded.loaded) {
        emit statusMessage(loaded.problem);
        return false;
    }
    ed->validateNow(); // the store of the text just sent: lines of the frames
    // The file's first program, as the loader selects it for АВТОМАТ.
    int first = 0, firstLine = 0;
    for (const program::Program& p : ed->store().programs())
        if (first == 0 || p.headerLine < firstLine) {
            first = p.number;
            firstLine = p.headerLine;
        }
    if (first == 0)
        return false;
    return debug_->start(first);
}

void DebugPanel::hold() { debug_->hold(); }
void DebugPanel::resume() { debug_->resume(); }
void DebugPanel::stop() { debug_->stop(); }
void DebugPanel::reset() { debug_->reset(); }

void DebugPanel::setSingleFrame(bool on) {
    if (stepAction_->isChecked() != on) {
        const QSignalBlocker b(stepAction_);
        stepAction_->setChecked(on);
    }
    debug_->setSingleFrame(on);
}

bool DebugPanel::runToCursor() {
    ProgramEditor* ed = tab_ ? tab_->currentEditor() : nullptr;
    if (!ed || !session_)
        return false;
    if (!debug_->programActive()) {
        ed->validateNow();
        debug_->setTarget(ed);
    } else if (debug_->target() != ed) {
        emit statusMessage(tr("The program under way is another file's."));
        return false;
    }
    int line = 0, index = 0;
    ed->getCursorPosition(&line, &index);
    if (!debug_->setRunTo(line))
        return false;
    if (debug_->programActive())
        return true; // continued when held; a running program stops there
    if (!run()) {
        debug_->gate().clearRunTo();
        return false;
    }
    return true;
}

namespace {

QString discText(std::int64_t disc, const units::AxisScale& s) {
    return QString::fromStdString(units::formatDisc(disc, s));
}

} // namespace

bool DebugPanel::startHere() {
    ProgramEditor* ed = tab_ ? tab_->currentEditor() : nullptr;
    if (!session_ || !ed) {
        emit statusMessage(tr("Open a program file first."));
        return false;
    }
    if (debug_->programActive() || debug_->phase() != DebugSession::Phase::Idle) {
        emit statusMessage(tr("A program is under way: stop it first."));
        return false;
    }
    ed->validateNow();
    if (ed->store().empty()) {
        emit statusMessage(tr("Open a program file first."));
        return false;
    }
    int cursorLine = 0, col = 0;
    ed->getCursorPosition(&cursorLine, &col);
    const int line = cursorLine + 1;
    // The program the cursor is in (the last header at or above it), its
    // first frame at or after the line; the file's first program starts.
    const program::Program* in = nullptr;
    const program::Program* first = nullptr;
    for (const program::Program& p : ed->store().programs()) {
        if (!first || p.headerLine < first->headerLine)
            first = &p;
        if (p.headerLine <= line && (!in || p.headerLine > in->headerLine))
            in = &p;
    }
    if (!in)
        in = first;
    int index = -1;
    for (int i = 0; i < static_cast<int>(in->frames.size()); ++i) {
        const program::Frame& f = in->frames[static_cast<std::size_t>(i)];
        if (f.span.line >= line && !f.skip) {
            index = i;
            break;
        }
    }
    if (index < 0) {
        emit statusMessage(tr("There is no frame at or after line %1.").arg(line));
        return false;
    }
    const program::Frame& frame = in->frames[static_cast<std::size_t>(index)];
    engine::Positioner& ctl = session_->controller();
    engine::PreviewOptions po;
    po.fromReferencePoint = true;
    for (int n = 0; n < engine::kRCount; ++n) // the machine's R-parameters, as they are now
        if (!engine::rReadOnly(n) && n != engine::r::PlcBit && n != engine::r::NestingLevel)
            po.rPresets[n] = ctl.r(n);
    const engine::StartSearch found =
        engine::findStartPoint(ctl.profile(), ed->store(), first->number, {in->number, index, 1}, po);
    if (found.outcome == engine::StartSearch::Outcome::NotReached) {
        emit statusMessage(tr("L%1 never reaches line %2: nothing to start there.")
                               .arg(first->number)
                               .arg(frame.span.line));
        return false;
    }
    if (found.outcome == engine::StartSearch::Outcome::Oscillating) {
        emit statusMessage(tr("Line %1 runs while %2 oscillates (Gx81 up to its Gx80): start from the "
                              "frame of the Gx81 or after the Gx80.")
                               .arg(frame.span.line)
                               .arg(found.oscillatingAxis == 0 ? "X" : "Z"));
        return false;
    }
    const engine::StartPoint point = found.point;

    // The rebuilt state, listed before anything moves: Start or Cancel.
    auto* dlg = new QDialog(this);
    dlg->setObjectName("debug.startHere.dialog");
    dlg->setAttribute(Qt::WA_DeleteOnClose);
    dlg->setWindowTitle(tr("Start here"));
    auto* lay = new QVBoxLayout(dlg);
    const QString where = point.frameNumber > 0
                              ? tr("L%1 N%2 (line %3)").arg(point.program).arg(point.frameNumber).arg(point.line)
                              : tr("L%1 (line %2)").arg(point.program).arg(point.line);
    auto* head = new QLabel(tr("L%1 starts before %2 with the state the preview rebuilt. The axes go there "
                               "first: X to its reference point, then Z, then X, at the rapid speed.")
                                .arg(point.mainProgram)
                                .arg(where),
                            dlg);
    head->setWordWrap(true);
    lay->addWidget(head);
    auto* list = new QTreeWidget(dlg);
    list->setObjectName("debug.startHere.state");
    list->setColumnCount(2);
    list->setRootIsDecorated(false);
    list->setHeaderLabels({tr("State"), tr("Value")});
    const auto row = [&](const QString& what, const QString& value) {
        auto* it = new QTreeWidgetItem(list, {what, value});
        it->setToolTip(1, value);
    };
    row(tr("Frame"), where);
    QString stack = QStringLiteral("L%1").arg(point.mainProgram);
    for (std::size_t i = 1; i < point.callers.size(); ++i)
        stack += QStringLiteral(" > L%1").arg(point.callers[i].program);
    if (!point.callers.empty())
        stack += QStringLiteral(" > L%1").arg(point.program);
    row(tr("Call stack"), stack);
    const engine::ModalState& m = point.modal;
    row(tr("Modal functions"),
        QStringLiteral("%1 G%2 %3 %4")
            .arg(m.rapid ? "G00" : "G01")
            .arg(m.components)
            .arg(m.noOverrideAxis < 0 ? "G55" : m.noOverrideAxis == 0 ? "G156" : "G256")
            .arg(m.incremental ? "G91" : "G90"));
    QString feeds;
    for (int a = 0; a < 2; ++a)
        if (m.feed[static_cast<std::size_t>(a)] >= 0)
            feeds += (feeds.isEmpty() ? "" : " ") + QString(a == 0 ? "FX" : "FZ") +
                     discText(m.feed[static_cast<std::size_t>(a)], point.axes[static_cast<std::size_t>(a)].scale);
    row(tr("Feeds"), feeds.isEmpty() ? tr("none") : feeds);
    QString comps;
    for (int i = 0; i < 8; ++i)
        comps += (i ? " " : "") + QString::number(point.components[static_cast<std::size_t>(i)]);
    row(tr("R224..R231 (coordinate components)"), comps);
    QString rs;
    for (const auto& [n, v] : point.r)
        rs += (rs.isEmpty() ? "" : " ") + QStringLiteral("R%1=%2").arg(n).arg(v);
    row(tr("R-parameters the program set"), rs.isEmpty() ? tr("none") : rs);
    row(tr("Message"), point.messageNumber > 0 ? QStringLiteral("#%1").arg(point.messageNumber) : tr("none"));
    QString ms;
    for (int c : point.mFunctions)
        ms += (ms.isEmpty() ? "" : " ") + QStringLiteral("M%1").arg(c);
    row(tr("M functions handed to the PLC again"), ms.isEmpty() ? tr("none") : ms);
    for (int a = 0; a < 2; ++a) {
        const engine::StartAxis& ax = point.axes[static_cast<std::size_t>(a)];
        if (ax.present)
            row(tr("Start point %1").arg(a == 0 ? "X" : "Z"),
                tr("%1 (machine %2)").arg(discText(ax.currentDisc, ax.scale), discText(ax.machineDisc, ax.scale)));
    }
    if (point.axes[0].present && point.axes[1].present)
        row(tr("Safe path"), tr("X %1, Z %2, X %3 (machine system)")
                                 .arg(discText(ctl.profile().c[45], point.axes[0].scale),
                                      discText(point.axes[1].machineDisc, point.axes[1].scale),
                                      discText(point.axes[0].machineDisc, point.axes[0].scale)));
    for (const engine::StartPoint::Uncertain& u : point.uncertain)
        row(tr("Warning"), tr("line %1 moves %2 until a signal or by handwheel: the start point takes its "
                              "programmed end")
                               .arg(u.line)
                               .arg(u.axis == 0 ? "X" : "Z"));
    list->resizeColumnToContents(0);
    lay->addWidget(list, 1);
    auto* buttons = new QDialogButtonBox(dlg);
    QPushButton* start = buttons->addButton(tr("Start"), QDialogButtonBox::AcceptRole);
    start->setObjectName("debug.startHere.start");
    buttons->addButton(QDialogButtonBox::Cancel)->setObjectName("debug.startHere.cancel");
    lay->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, dlg, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, dlg, &QDialog::reject);
    const int main = first->number;
    QPointer<ProgramEditor> target(ed);
    connect(dlg, &QDialog::accepted, this, [this, point, main, target] {
        if (!target || !session_)
            return;
        const ProgramLoad loaded = loadProgramText(*session_, target->text().toStdString(), tr("the file"));
        if (!loaded.loaded) {
            emit statusMessage(loaded.problem);
            return;
        }
        debug_->setTarget(target);
        session_->controller().setStartPoint(point);
        if (!debug_->start(main))
            session_->controller().setStartPoint(std::nullopt);
    });
    connect(dlg, &QObject::destroyed, this, [this] { startDialog_ = nullptr; });
    dlg->resize(std::min(760, window()->width()), std::min(460, window()->height()));
    startDialog_ = dlg;
    dlg->open();
    return true;
}

bool DebugPanel::addWatch(int number) {
    if (number < 0 || number >= catalog::kRParamCount) {
        emit statusMessage(tr("R-parameters are R0..R299, not R%1.").arg(number));
        return false;
    }
    if (watched_.contains(number))
        return true;
    watched_ << number;
    std::sort(watched_.begin(), watched_.end());
    const QSignalBlocker b(watch_);
    auto* it = new QTreeWidgetItem;
    it->setText(0, QStringLiteral("R%1").arg(number));
    it->setData(0, Qt::UserRole, number);
    const catalog::RParamDef* def = catalog::findRParam(number);
    if (def && def->readOnly())
        it->setForeground(1, palette().color(QPalette::Disabled, QPalette::Text));
    else
        it->setFlags(it->flags() | Qt::ItemIsEditable);
    watch_->insertTopLevelItem(static_cast<int>(watched_.indexOf(number)), it);
    retranslate(); // the meaning column
    refreshWatch();
    return true;
}

void DebugPanel::removeWatch(int number) {
    const qsizetype i = watched_.indexOf(number);
    if (i < 0)
        return;
    watched_.removeAt(i);
    delete watch_->takeTopLevelItem(static_cast<int>(i));
}

bool DebugPanel::setWatchValue(int number, qint64 value) {
    if (!session_)
        return false;
    const engine::OpResult r = session_->controller().setR(number, value);
    if (!r.ok()) {
        emit statusMessage(tr("R%1 was not set: %2").arg(number).arg(refusalText(r)));
        refreshWatch();
        return false;
    }
    session_->advance(0); // every view shows the new value
    return true;
}

void DebugPanel::watchEdited(QTreeWidgetItem* item, int column) {
    if (refreshing_ || column != 1 || !item)
        return;
    bool ok = false;
    const qint64 v = item->text(1).trimmed().toLongLong(&ok);
    const int n = item->data(0, Qt::UserRole).toInt();
    if (!ok) {
        emit statusMessage(tr("R%1: «%2» is not a whole number.").arg(n).arg(item->text(1)));
        refreshWatch();
        return;
    }
    setWatchValue(n, v);
}

void DebugPanel::refreshWatch() {
    if (!session_)
        return;
    refreshing_ = true;
    const engine::Positioner& ctl = session_->controller();
    for (int i = 0; i < watch_->topLevelItemCount(); ++i) {
        QTreeWidgetItem* it = watch_->topLevelItem(i);
        setTextIfChanged(it, 1, QString::number(ctl.r(it->data(0, Qt::UserRole).toInt())));
    }
    refreshing_ = false;
}

void DebugPanel::refreshStack() {
    if (!session_)
        return;
    const std::vector<engine::CallLevel> levels = engine::callStack(session_->controller());
    // Innermost first, as debuggers list it.
    while (stack_->topLevelItemCount() > static_cast<int>(levels.size()))
        delete stack_->takeTopLevelItem(stack_->topLevelItemCount() - 1);
    while (stack_->topLevelItemCount() < static_cast<int>(levels.size()))
        stack_->addTopLevelItem(new QTreeWidgetItem);
    for (std::size_t k = 0; k < levels.size(); ++k) {
        const engine::CallLevel& l = levels[levels.size() - 1 - k];
        QTreeWidgetItem* it = stack_->topLevelItem(static_cast<int>(k));
        setTextIfChanged(it, 0, QString::number(l.level));
        setTextIfChanged(it, 1, QStringLiteral("L%1").arg(l.program));
        setTextIfChanged(it, 2, l.frameNumber > 0 ? QStringLiteral("N%1").arg(l.frameNumber) : QString());
        setTextIfChanged(it, 3, l.line > 0 ? QString::number(l.line) : QString());
        it->setData(0, Qt::UserRole, l.line);
        it->setData(0, Qt::UserRole + 1, l.program);
    }
}

void DebugPanel::refresh() {
    const bool active = debug_->programActive();
    const bool idle = debug_->phase() == DebugSession::Phase::Idle;
    const bool held = debug_->held();
    runAction_->setEnabled(session_ && ((!active && idle) || held));
    holdAction_->setEnabled(active && !held);
    resumeAction_->setEnabled(held);
    cursorAction_->setEnabled(session_ && (held || (!active && idle)));
    startHereAction_->setEnabled(session_ && !active && idle);
    stopAction_->setEnabled(session_ && (active || !idle));
    resetAction_->setEnabled(session_ != nullptr);
    status_->setText(debug_->statusText());
    refreshStack();
    refreshWatch();
}

void DebugPanel::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(e);
}

void DebugPanel::retranslate() {
    runAction_->setText(tr("Run"));
    runAction_->setToolTip(tr("Send the file and run its first program (homing as the operator would), or continue"));
    holdAction_->setText(tr("Hold"));
    holdAction_->setToolTip(tr("Like STOP on the machine's panel: the motion stops, CYCLE START continues"));
    resumeAction_->setText(tr("Continue"));
    resumeAction_->setToolTip(tr("Like CYCLE START: continue the held program"));
    stepAction_->setText(tr("Single frame"));
    stepAction_->setToolTip(tr("Stop after each frame; CYCLE START runs the next one"));
    cursorAction_->setText(tr("Run to cursor"));
    cursorAction_->setToolTip(tr("Run until the frame at the cursor, stopping before it"));
    startHereAction_->setText(tr("Start here"));
    startHereAction_->setToolTip(tr("Start the program before the frame at the cursor, with its state rebuilt "
                                    "(modal functions, R-parameters, call stack) and shown first"));
    stopAction_->setText(tr("Stop"));
    stopAction_->setToolTip(tr("Like RESET: the program ends without continuation"));
    resetAction_->setText(tr("Reset"));
    resetAction_->setToolTip(tr("RESET and ESC: end the program and acknowledge the messages"));
    speedLabel_->setText(tr("Speed"));
    for (int i = 0; i < speed_->count(); ++i) {
        const double f = speed_->itemData(i).toDouble();
        speed_->setItemText(i, f == 0 ? tr("fastest") : f == 1 ? tr("real time") : QStringLiteral("×%1").arg(f));
    }
    stackLabel_->setText(tr("Call stack"));
    stack_->setHeaderLabels({tr("R158"), tr("Program"), tr("Frame"), tr("Line")});
    watchLabel_->setText(tr("Watch"));
    watchAdd_->setPlaceholderText(tr("Add an R-parameter: R12, Enter"));
    watch_->setHeaderLabels({tr("R"), tr("Value"), tr("Meaning")});
    for (int i = 0; i < watch_->topLevelItemCount(); ++i) {
        QTreeWidgetItem* it = watch_->topLevelItem(i);
        const catalog::RParamDef* def = catalog::findRParam(it->data(0, Qt::UserRole).toInt());
        const QSignalBlocker b(watch_);
        if (def)
            it->setText(2, coreText(def->meaningRu, def->meaningEn));
    }
    status_->setText(debug_->statusText());
}

} // namespace k528::studio
