#include "editor/debug_session.h"

#include "editor/program_editor.h"
#include "session/catalog_texts.h"
#include "session/core_texts.h"
#include "session/simulation_session.h"

namespace k528::studio {

namespace {

constexpr std::int64_t kPressMs = 100;        // an operator's push
constexpr std::int64_t kSwitchOnMs = 10000;   // the drives get ready
constexpr std::int64_t kHomingStartMs = 1500; // the cycle starts once the PLC passed the button on
constexpr std::int64_t kStartSeenMs = 2000;   // «Пуск» is taken
constexpr std::int64_t kStartGapMs = 3 * kPressMs; // from one «Пуск» to the next

QString axisName(int i) { return i == 0 ? QStringLiteral("X") : QStringLiteral("Z"); }

QString refusal(const engine::OpResult& r) {
    return refusalText(r);
}

} // namespace

DebugSession::DebugSession(SimulationSession* session, QObject* parent) : QObject(parent), session_(session) {
    if (!session)
        return;
    session->controller().setDebugGate(&gate_);
    connect(session, &SimulationSession::advanced, this, &DebugSession::advanced);
}

DebugSession::~DebugSession() {
    if (session_ && session_->controller().debugGate() == &gate_)
        session_->controller().setDebugGate(nullptr);
}

void DebugSession::setTarget(ProgramEditor* editor) {
    if (target_ == editor)
        return;
    if (target_) {
        disconnect(target_, &ProgramEditor::breakpointsChanged, this, &DebugSession::syncBreakpoints);
        target_->setExecutingLine(-1);
    }
    target_ = editor;
    if (editor)
        connect(editor, &ProgramEditor::breakpointsChanged, this, &DebugSession::syncBreakpoints);
    syncBreakpoints();
}

bool DebugSession::programActive() const {
    return session_ && engine::programActive(session_->controller().state());
}

bool DebugSession::held() const {
    if (!session_)
        return false;
    const engine::ProgramState s = session_->controller().state();
    return s == engine::ProgramState::Interrupted || s == engine::ProgramState::M0;
}

bool DebugSession::heldByGate() const {
    return session_ && session_->controller().state() == engine::ProgramState::Interrupted && gate_.holding();
}

int DebugSession::frameLineAtOrAfter(int program, int line) const {
    if (!target_)
        return 0;
    const program::Program* p = target_->store().find(program);
    if (!p)
        return 0;
    for (const program::Frame& f : p->frames)
        if (f.span.line >= line && !f.skip)
            return f.span.line;
    return 0;
}

void DebugSession::syncBreakpoints() {
    gate_.clearBreakpoints();
    if (!target_)
        return;
    for (int line : target_->breakpointLines()) {
        const int program = target_->programAtLine(line);
        const int frame = frameLineAtOrAfter(program, line + 1);
        if (program > 0 && frame > 0)
            gate_.addBreakpoint(program, frame);
    }
}

void DebugSession::setSingleFrame(bool on) {
    gate_.setSingleFrame(on);
    emit changed();
}

bool DebugSession::setRunTo(int line) {
    if (!target_)
        return false;
    const int program = target_->programAtLine(line);
    const int frame = frameLineAtOrAfter(program, line + 1);
    if (program <= 0 || frame <= 0) {
        emit message(tr("There is no frame at or after line %1.").arg(line + 1));
        return false;
    }
    gate_.runTo(program, frame);
    if (held())
        resume();
    return true;
}

void DebugSession::press(machine::Button b) {
    if (session_)
        session_->simulation().pressFor(b, kPressMs);
}

void DebugSession::fail(const QString& why) {
    phase_ = Phase::Idle;
    startPending_ = false;
    emit message(why);
    emit changed();
}

QString DebugSession::whyNoStart() const {
    const engine::Positioner& ctl = session_->controller();
    if (session_->simulation().emergencyStopPressed())
        return tr("the emergency stop is pressed on the machine's panel");
    if (ctl.mode() != engine::Mode::Auto)
        return tr("the K923 is in %1, not in automatic mode")
            .arg(modeName(ctl.mode()));
    const auto alarms = ctl.alarms();
    if (!alarms.empty())
        return tr("the positioner shows message %1: %2")
            .arg(alarms.back().number)
            .arg(alarmMessage(alarms.back()));
    return tr("the PLC did not pass it on (start enable, the machine's messages)");
}

bool DebugSession::start(int number) {
    if (!session_)
        return false;
    if (!session_->isRunning())
        emit message(tr("The machine is paused (Simulation > Pause the machine): the run goes on when it runs."));
    engine::Positioner& ctl = session_->controller();
    if (engine::programActive(ctl.state())) {
        emit message(tr("A program is under way: stop it first."));
        return false;
    }
    if (!ctl.programs().find(number)) {
        emit message(tr("The controller holds no program L%1.").arg(number));
        return false;
    }
    machine::Simulation& sim = session_->simulation();
    if (sim.emergencyStopPressed()) {
        emit message(tr("The emergency stop is pressed: pull it out on the machine's panel."));
        return false;
    }
    syncBreakpoints();
    program_ = number;
    phaseSinceMs_ = session_->timeMs();
    const auto ready = [&] {
        if (!ctl.words().bit(engine::z::Ready))
            return false;
        for (engine::AxisId a : {engine::AxisId::X, engine::AxisId::Z}) {
            const engine::AxisView v = ctl.axisView(a);
            if (v.present && !(v.loopClosed && v.regulatorOn))
                return false;
        }
        return true;
    };
    if (ready()) {
        homingAxis_ = -1;
        nextHoming();
    } else {
        phase_ = Phase::SwitchingOn;
        press(machine::Button::DrivesOn);
        emit message(tr("Switching the drives on…"));
    }
    emit changed();
    return true;
}

void DebugSession::nextHoming() {
    engine::Positioner& ctl = session_->controller();
    for (int i = homingAxis_ + 1; i < engine::kAxisCount; ++i) {
        const engine::AxisView v = ctl.axisView(engine::axisAt(i));
        if (!v.present || v.referenceOk)
            continue; // referenced, or АВТ.БЕЗ ПБТ
        const engine::OpResult m = ctl.selectMode(engine::Mode::Reference);
        if (!m.ok()) {
            fail(tr("The reference-point mode was refused: %1").arg(refusal(m)));
            return;
        }
        homingAxis_ = i;
        homingSeen_ = false;
        phase_ = Phase::Homing;
        phaseSinceMs_ = session_->timeMs();
        const bool negative = ctl.c()[static_cast<std::size_t>(i == 0 ? 9 : 61)] != 0;
        press(i == 0 ? (negative ? machine::Button::JogXMinus : machine::Button::JogXPlus)
                     : (negative ? machine::Button::JogZMinus : machine::Button::JogZPlus));
        emit message(tr("Reference point of %1…").arg(axisName(i)));
        return;
    }
    // Every axis is ready: АВТОМАТ, the program, «Пуск».
    const engine::OpResult m = ctl.selectMode(engine::Mode::Auto);
    if (!m.ok()) {
        fail(tr("Automatic mode was refused: %1").arg(refusal(m)));
        return;
    }
    const engine::OpResult p = ctl.selectProgram(program_);
    if (!p.ok()) {
        fail(tr("Program L%1 was refused: %2").arg(program_).arg(refusal(p)));
        return;
    }
    phase_ = Phase::Starting;
    phaseSinceMs_ = session_->timeMs();
    pressedAtMs_ = -1;
    pressStartNow();
}

bool DebugSession::startFree() const {
    // A fresh edge: the last push is over and the PLC has seen the button up.
    return !session_->simulation().buttonDown(machine::Button::CycleStart) &&
           (lastStartPressMs_ < 0 || session_->timeMs() - lastStartPressMs_ >= kStartGapMs);
}

void DebugSession::pressStartNow() {
    if (!startFree()) {
        if (!startPending_)
            pendingSinceMs_ = session_->timeMs();
        startPending_ = true;
        return;
    }
    startPending_ = false;
    pressedAtMs_ = lastStartPressMs_ = session_->timeMs();
    if (phase_ != Phase::Starting) { // continuing a held program
        resumeAtMs_ = pressedAtMs_;
        resumeStops_ = gate_.stops();
        resumeFrame_ = session_->controller().programView().frameIndex;
    }
    press(machine::Button::CycleStart);
}

void DebugSession::resume() {
    if (!session_ || !held())
        return;
    if (!session_->isRunning())
        emit message(tr("The machine is paused (Simulation > Pause the machine): the program goes on when it runs."));
    syncBreakpoints();
    pressStartNow();
    emit changed();
}

void DebugSession::hold() {
    if (!session_ || !programActive() || held())
        return;
    press(machine::Button::CycleStop);
}

void DebugSession::stop() {
    if (!session_)
        return;
    phase_ = Phase::Idle;
    startPending_ = false;
    gate_.clearRunTo();
    press(machine::Button::Reset);
    emit changed();
}

void DebugSession::reset() {
    stop();
    if (session_)
        session_->controller().escape();
    if (target_)
        target_->setExecutingLine(-1);
    lastLine_ = lastProgram_ = -1;
    emit changed();
}

void DebugSession::advanced() {
    if (!session_)
        return;
    engine::Positioner& ctl = session_->controller();
    machine::Simulation& sim = session_->simulation();
    const std::int64_t now = session_->timeMs();
    if (startPending_ && startFree())
        pressStartNow();
    // Never a silent wait for «Пуск»: held down by someone, or not taken.
    if (startPending_ && now - pendingSinceMs_ > kStartSeenMs) {
        fail(tr("CYCLE START is held down on the machine's panel: release it, then Run again."));
        resumeAtMs_ = -1;
    }
    if (resumeAtMs_ >= 0) {
        if (!held() || gate_.stops() != resumeStops_ || ctl.programView().frameIndex != resumeFrame_) {
            resumeAtMs_ = -1; // taken
        } else if (now - resumeAtMs_ > kStartSeenMs && !sim.buttonDown(machine::Button::CycleStart)) {
            resumeAtMs_ = -1;
            emit message(tr("CYCLE START was not taken: %1.").arg(whyNoStart()));
        }
    }
    switch (phase_) {
    case Phase::Idle:
    case Phase::Active:
        break;
    case Phase::SwitchingOn: {
        bool ready = ctl.words().bit(engine::z::Ready) && !sim.buttonDown(machine::Button::DrivesOn);
        for (engine::AxisId a : {engine::AxisId::X, engine::AxisId::Z}) {
            const engine::AxisView v = ctl.axisView(a);
            ready = ready && (!v.present || (v.loopClosed && v.regulatorOn));
        }
        if (ready) {
            homingAxis_ = -1;
            nextHoming();
        } else if (now - phaseSinceMs_ > kSwitchOnMs) {
            fail(tr("The machine did not get ready: the drives are off (see the machine's messages)."));
        }
        break;
    }
    case Phase::Homing: {
        const engine::AxisView v = ctl.axisView(engine::axisAt(homingAxis_));
        if (ctl.alarmRegistry().anyLatched() && !v.homing && !v.referenced) {
            fail(tr("The reference-point cycle of %1 stopped with a message.").arg(axisName(homingAxis_)));
        } else if (v.referenced) {
            nextHoming();
        } else if (v.homing) {
            homingSeen_ = true;
        } else if (homingSeen_) {
            fail(tr("The reference-point cycle of %1 ended without the reference point.").arg(axisName(homingAxis_)));
        } else if (now - phaseSinceMs_ > kHomingStartMs) {
            fail(tr("The reference-point cycle of %1 did not start.").arg(axisName(homingAxis_)));
        }
        break;
    }
    case Phase::Starting:
        if (pressedAtMs_ >= 0 && ctl.programStartMs() >= pressedAtMs_) {
            phase_ = Phase::Active;
            emit message(tr("L%1 runs.").arg(program_));
        } else if (pressedAtMs_ >= 0 && now - pressedAtMs_ > kStartSeenMs &&
                   !sim.buttonDown(machine::Button::CycleStart)) {
            fail(tr("CYCLE START was not taken: %1.").arg(whyNoStart()));
        }
        break;
    }
    if (phase_ == Phase::Active && !engine::programActive(ctl.state())) {
        phase_ = Phase::Idle;
        if (ctl.state() == engine::ProgramState::Ended)
            emit message(tr("L%1 ended.").arg(program_));
        else if (ctl.state() == engine::ProgramState::Alarm) {
            const auto alarms = ctl.alarms();
            QString text;
            if (!alarms.empty())
                text = alarmLine(alarms.back());
            emit message(tr("The program stopped with a message: %1").arg(text));
        }
    }
    if (gate_.stops() != lastStops_) {
        lastStops_ = gate_.stops();
        if (heldByGate())
            emit message(statusText());
    }
    updateMarker();
    const int state = static_cast<int>(ctl.state());
    if (state != lastState_ || phase_ != lastPhase_) {
        lastState_ = state;
        lastPhase_ = phase_;
        emit changed();
    }
}

void DebugSession::updateMarker() {
    const engine::ProgramView v = session_->controller().programView();
    int program = -1, line = -1;
    const bool show = engine::programActive(v.state) || v.state == engine::ProgramState::Alarm;
    if (show && target_ && v.line > 0 && target_->store().find(v.program) && v.line <= target_->lines()) {
        program = v.program;
        line = v.line - 1;
    }
    if (program == lastProgram_ && line == lastLine_)
        return;
    lastProgram_ = program;
    lastLine_ = line;
    if (target_)
        target_->setExecutingLine(line);
    emit changed();
}

QString DebugSession::statusText() const {
    if (!session_)
        return tr("No machine");
    switch (phase_) {
    case Phase::SwitchingOn:
        return tr("Switching the drives on…");
    case Phase::Homing:
        return tr("Reference point of %1…").arg(axisName(homingAxis_));
    case Phase::Starting:
        return tr("Starting L%1…").arg(program_);
    case Phase::Idle:
    case Phase::Active:
        break;
    }
    const engine::ProgramView v = session_->controller().programView();
    const QString where = v.frameNumber > 0 ? tr("L%1 N%2 (line %3)").arg(v.program).arg(v.frameNumber).arg(v.line)
                                            : tr("L%1 (line %2)").arg(v.program).arg(v.line);
    switch (v.state) {
    case engine::ProgramState::Idle:
        return tr("No program");
    case engine::ProgramState::Running:
    case engine::ProgramState::Dwell:
    case engine::ProgramState::WaitingM:
        return tr("Running %1").arg(where);
    case engine::ProgramState::M0:
        return tr("M00 at %1: CYCLE START continues").arg(where);
    case engine::ProgramState::Interrupted:
        if (gate_.holding() && gate_.lastStop()) {
            switch (gate_.lastStop()->reason) {
            case engine::DebugGate::Reason::Breakpoint:
                return tr("Breakpoint: before %1").arg(where);
            case engine::DebugGate::Reason::SingleFrame:
                return tr("Single frame: before %1").arg(where);
            case engine::DebugGate::Reason::RunTo:
                return tr("Run to cursor: before %1").arg(where);
            }
        }
        return tr("Held at %1: CYCLE START continues").arg(where);
    case engine::ProgramState::Ended:
        return tr("Ended at %1").arg(where);
    case engine::ProgramState::Alarm:
        return tr("Stopped by a message at %1").arg(where);
    }
    return {};
}

} // namespace k528::studio
