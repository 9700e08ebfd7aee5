#include "monitor/program_monitor.h"

#include "controller/controller.h"
#include "engine/types.h"
#include "program/formatter.h"

#include <QComboBox>
#include <QEvent>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>

#include "workspace/elided_label.h"
#include <QListWidget>
#include <QVBoxLayout>

namespace k528::studio {

namespace {

QString fromStd(const std::string& s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

QString stateName(engine::ProgramState s) {
    using engine::ProgramState;
    switch (s) {
    case ProgramState::Idle:
        return ProgramMonitor::tr("ready");
    case ProgramState::Running:
        return ProgramMonitor::tr("running");
    case ProgramState::Dwell:
        return ProgramMonitor::tr("dwell");
    case ProgramState::WaitingM:
        return ProgramMonitor::tr("waiting for the PLC (M)");
    case ProgramState::M0:
        return ProgramMonitor::tr("M00: waiting for START");
    case ProgramState::Interrupted:
        return ProgramMonitor::tr("interrupted: START continues");
    case ProgramState::Ended:
        return ProgramMonitor::tr("ended");
    case ProgramState::Alarm:
        return ProgramMonitor::tr("stopped by a message: START begins again");
    }
    return {};
}

} // namespace

ProgramMonitor::ProgramMonitor(Controller& controller, QWidget* parent)
    : QWidget(parent), controller_(&controller) {
    setObjectName("programMonitor");
    choice_ = new QComboBox(this);
    choice_->setObjectName("programMonitor.choice");
    // As wide as a program's number and title need, not its longest title:
    // the state beside it gets the room.
    choice_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    choice_->setMinimumContentsLength(16);
    // Elided when long (a frame's message): it never widens the window.
    status_ = new ElidedLabel(this);
    status_->setObjectName("programMonitor.status");
    list_ = new QListWidget(this);
    list_->setObjectName("programMonitor.frames");
    list_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    list_->setSelectionMode(QAbstractItemView::NoSelection);
    list_->setUniformItemSizes(true);
    auto* top = new QHBoxLayout;
    top->addWidget(choice_);
    top->addWidget(status_, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(list_, 1);
    connect(choice_, &QComboBox::activated, this, [this] { refresh(); });
    connect(controller_, &Controller::updated, this, &ProgramMonitor::refresh);
    retranslate();
    refresh();
}

void ProgramMonitor::setController(Controller& controller) {
    if (controller_ == &controller)
        return;
    disconnect(controller_, nullptr, this, nullptr);
    controller_ = &controller;
    connect(controller_, &Controller::updated, this, &ProgramMonitor::refresh);
    revision_ = ~std::uint64_t{0};
    refresh();
}

void ProgramMonitor::fillChoice() {
    const int pinned = choice_->currentData().toInt();
    choice_->clear();
    choice_->addItem(tr("Follow the controller"), 0);
    for (const program::Program& p : controller_->programs().programs())
        choice_->addItem(p.title ? QStringLiteral("L%1 (%2)").arg(p.number).arg(fromStd(*p.title))
                                 : QStringLiteral("L%1").arg(p.number),
                         p.number);
    const int at = choice_->findData(pinned);
    choice_->setCurrentIndex(at < 0 ? 0 : at);
}

void ProgramMonitor::showProgram(int number) {
    shown_ = number;
    marked_ = -1;
    list_->clear();
    const program::Program* p = controller_->programs().find(number);
    if (!p)
        return;
    for (const program::Frame& f : p->frames)
        list_->addItem(fromStd(program::formatFrame(f)));
}

void ProgramMonitor::refresh() {
    const Controller& c = *controller_;
    if (c.programsRevision() != revision_) {
        revision_ = c.programsRevision();
        fillChoice();
        shown_ = -1; // redraw
    }
    const engine::ProgramView& v = c.state().program;
    const bool active = engine::programActive(v.state) || v.state == engine::ProgramState::Alarm;
    const int pinned = choice_->currentData().toInt();
    const int follow = active && v.program > 0 ? v.program : v.selectedProgram;
    // Nothing selected yet (after power-on R252 = 0): the catalog's first
    // program, as the editor menu shows it («номер первой существующей в
    // каталоге программы»).
    const auto& all = c.programs().programs();
    const int first = all.empty() ? 0 : all.front().number;
    const int want = pinned > 0 ? pinned : (follow > 0 ? follow : first);
    if (want != shown_)
        showProgram(want);
    // The frame being executed, when this program is the one running.
    const int row = active && v.program == shown_ && v.frameIndex >= 0 &&
                            v.frameIndex < list_->count()
                        ? v.frameIndex
                        : -1;
    if (row != marked_) {
        if (marked_ >= 0 && marked_ < list_->count()) {
            QListWidgetItem* old = list_->item(marked_);
            old->setBackground(QBrush());
            old->setForeground(QBrush());
        }
        marked_ = row;
        if (row >= 0) {
            QListWidgetItem* it = list_->item(row);
            it->setBackground(palette().highlight());
            it->setForeground(palette().highlightedText());
            list_->scrollToItem(it, QAbstractItemView::PositionAtCenter);
        }
    }
    QString text = shown_ > 0 ? tr("L%1: %2").arg(shown_).arg(stateName(v.state)) : tr("no program");
    if (row >= 0 && v.frameNumber > 0)
        text += tr(", frame N%1").arg(v.frameNumber);
    if (row >= 0 && !v.messageText.empty())
        text += QStringLiteral(" — «%1»").arg(fromStd(v.messageText));
    if (text != statusText_) {
        statusText_ = text;
        status_->setText(text);
    }
}

void ProgramMonitor::retranslate() {
    if (choice_->count() > 0)
        choice_->setItemText(0, tr("Follow the controller"));
    statusText_.clear();
}

void ProgramMonitor::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        refresh();
    }
    QWidget::changeEvent(event);
}

} // namespace k528::studio
