#include "editor/cycle_time_label.h"

#include "editor/program_editor.h"
#include "machine/run.h"
#include "program/diagnostic.h"
#include "session/machine_source.h"

#include <QCoreApplication>
#include <QEvent>
#include <QPointer>
#include <QThreadPool>
#include <cmath>

namespace k528::studio {

namespace {
constexpr int kDebounceMs = 700; // after the last validation: typing goes on meanwhile
} // namespace

CycleTimeLabel::CycleTimeLabel(QWidget* parent) : ElidedLabel(parent) {
    setObjectName("editor.cycleTime");
    debounce_.setSingleShot(true);
    debounce_.setInterval(kDebounceMs);
    connect(&debounce_, &QTimer::timeout, this, &CycleTimeLabel::start);
}

CycleTimeLabel::~CycleTimeLabel() { *alive_ = false; }

QString CycleTimeLabel::durationText(double seconds) {
    const double tenths = std::round(seconds * 10.0) / 10.0;
    const int minutes = static_cast<int>(tenths / 60.0);
    const QString s = QString::number(tenths - 60.0 * minutes, 'f', 1); // a point, as the panel shows numbers
    return minutes > 0 ? tr("%1 min %2 s").arg(minutes).arg(s) : tr("%1 s").arg(s);
}

void CycleTimeLabel::follow(const ProgramEditor* ed) {
    ++generation_; // whatever runs now is for an older text
    editor_ = ed;
    seconds_.reset();
    debounce_.stop();
    if (!ed || ed->store().programs().empty()) {
        state_ = State::None;
    } else if (program::countErrors(ed->diagnostics()) > 0) {
        state_ = State::Errors;
    } else if (!ed->machine()) {
        state_ = State::NoMachine;
    } else {
        state_ = State::Measuring;
        debounce_.start();
    }
    retranslate();
}

void CycleTimeLabel::start() {
    if (!editor_ || !editor_->machine() || editor_->store().programs().empty())
        return;
    if (running_) { // one run at a time: the newest text is measured when it ends
        debounce_.start();
        return;
    }
    running_ = true;
    const std::uint64_t gen = generation_;
    auto profile = std::make_shared<const profile::MachineProfile>(*editor_->machine());
    auto store = editor_->store();
    const int number = store.programs().front().number;
    program_ = number;
    machine_ = profile;
    std::weak_ptr<bool> alive = alive_;
    QPointer<CycleTimeLabel> self(this);
    QThreadPool::globalInstance()->start([profile = std::move(profile), store = std::move(store), number, gen,
                                          alive, self] {
        std::optional<double> seconds;
        QString status;
        try {
            const machine::CycleTime t = machine::cycleTime(*profile, store, number, {});
            seconds = t.seconds;
            status = QString::fromUtf8(engine::runStatusName(t.run.status).data());
        } catch (const std::exception&) {
            status = QStringLiteral("blocked");
        }
        if (alive.expired())
            return;
        QMetaObject::invokeMethod(
            QCoreApplication::instance(),
            [self, gen, seconds, status] {
                if (!self)
                    return;
                self->running_ = false;
                if (gen != self->generation_)
                    return; // the text changed meanwhile: the debounce measures the new one
                self->seconds_ = seconds;
                self->runStatus_ = status;
                self->state_ = seconds ? State::Measured : State::NotCompleted;
                self->retranslate();
                emit self->measured();
            },
            Qt::QueuedConnection);
    });
}

void CycleTimeLabel::retranslate() {
    switch (state_) {
    case State::None:
        setText(QString());
        break;
    case State::Errors:
        setText(tr("Cycle time: none while the file has errors"));
        break;
    case State::NoMachine:
        setText(tr("Cycle time: choose the machine the file is for"));
        break;
    case State::Measuring:
        setText(tr("Cycle time: measuring on the simulated machine…"));
        break;
    case State::Measured:
        // The figure before the machine's title: a narrow line cuts the title, not the figure.
        setText(tr("Cycle time of L%1: %2 (%3)").arg(program_).arg(durationText(*seconds_), machineTitle(*machine_)));
        break;
    case State::NotCompleted: {
        QString why = runStatus_;
        if (runStatus_ == "alarm")
            why = tr("the run ends in an alarm");
        else if (runStatus_ == "timeout")
            why = tr("the run does not end within an hour");
        else if (runStatus_ == "blocked")
            why = tr("the program cannot be started on this machine");
        setText(tr("Cycle time of L%1: none, %2 (%3)").arg(program_).arg(why, machineTitle(*machine_)));
        break;
    }
    }
}

void CycleTimeLabel::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange)
        retranslate();
    ElidedLabel::changeEvent(e);
}

} // namespace k528::studio
