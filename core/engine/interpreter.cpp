#include "engine/interpreter.h"

#include "engine/coordinates.h"
#include "engine/program_output.h"
#include "engine/start_point.h"

#include "program/refusals.h"

#include <algorithm>
#include <bitset>
#include <cstdlib>

namespace k528::engine {

using program::FrameKind;
using program::GFunction;

namespace {

// Largest coordinate of the language, ±9999.999 mm (program-language.md), in
// display discretes of an axis.
std::int64_t maxCoordinateDisc(const units::AxisScale& s) {
    return 9999999LL * s.discretesPerMm() / 1000;
}

// Messages of axis Z for the X numbers used here.
int forAxis(int xMessage, int axis) {
    if (axis == 0)
        return xMessage;
    switch (xMessage) {
    case 33:
        return 49;
    case 34:
        return 50;
    case 35:
        return 51;
    case 36:
        return 52;
    case 12:
        return 28;
    case 10:
        return 26;
    case 11:
        return 27;
    case 1:
        return 17;
    default:
        return xMessage;
    }
}

// The line of the first frame whose N repeats an earlier one, 0 if none
// (message 54 «Дублирование номеров кадров»).
int duplicateFrameLine(const program::Program& p) {
    std::bitset<program::kMaxFrameNumber + 1> seen;
    for (const program::Frame& f : p.frames) {
        const int n = f.number();
        if (n < 1 || n > program::kMaxFrameNumber)
            continue;
        if (seen[static_cast<std::size_t>(n)])
            return f.span.line > 0 ? f.span.line : 1;
        seen[static_cast<std::size_t>(n)] = true;
    }
    return 0;
}

} // namespace

int Interpreter::errAxis(int xMessage, int axis) const {
    return forAxis(xMessage, axis);
}

void Interpreter::error(int message) {
    c_.raise(message, program(), line_);
}

int Interpreter::frameNumber() const {
    if (!prog_ || index_ < 0 || index_ >= static_cast<int>(prog_->frames.size()))
        return 0;
    return prog_->frames[static_cast<std::size_t>(index_)].number();
}

int Interpreter::line() const {
    if (!prog_ || index_ < 0 || index_ >= static_cast<int>(prog_->frames.size()))
        return 0;
    return prog_->frames[static_cast<std::size_t>(index_)].span.line;
}

void Interpreter::updateNumbers() {
    c_.r.set(r::ExecutingProgram, program());
    c_.r.set(r::FrameNumber, frameNumber());
    c_.r.set(r::NestingLevel, depth_);
}

void Interpreter::start(int number, int cycle, Mode mode) {
    prog_ = c_.store.find(number);
    mainProgram_ = number;
    depth_ = 0;
    index_ = 0;
    step_ = Step::Fetch;
    modal_ = ModalState{};
    iso_ = {};
    line_ = 0;
    oscOn_ = {};
    c_.programExclusion = 0;
    c_.cycle = cycle;
    c_.programMode = mode;
    c_.state = ProgramState::Running;
    c_.resumeState = ProgramState::Running;
    c_.endOrReset = false;
    c_.stopHold = false;
    c_.messageNumber = 0;
    c_.programStartMs = c_.nowMs;
    c_.programEndMs = -1;
    for (AxisUnit& u : c_.axes) {
        u.programmedDisc = u.toDisc(u.servo.target());
        u.eraseSignal = 0;
        u.erased = false;
        u.noOverride = false;
        u.resumeMove = u.resumeWheel = false;
    }
    c_.r.set(r::CurrentProgram, number);
    updateNumbers();
    c_.out->started();
    if (prog_)
        if (const int dup = duplicateFrameLine(*prog_)) {
            line_ = dup;
            error(54);
        }
}

bool replayedMFunction(int code) {
    using namespace program::mfunc;
    return code != kStop && code != kEnd && code != kSubprogramEnd && code != kEndRewind;
}

void Interpreter::capture(StartPoint& p) const {
    p.mainProgram = mainProgram_;
    p.callers.clear();
    for (int i = 0; i < depth_; ++i) {
        const Level& l = stack_[static_cast<std::size_t>(i)];
        p.callers.push_back({l.program ? l.program->number : 0, l.returnIndex});
    }
    p.program = program();
    p.frameIndex = index_;
    p.frameNumber = frameNumber();
    p.line = line();
    p.modal = modal_;
    p.messageNumber = c_.messageNumber;
    p.oscillatingAxis = oscOn_[0] ? 0 : oscOn_[1] ? 1 : -1;
    for (int i = 0; i < 8; ++i)
        p.components[static_cast<std::size_t>(i)] = c_.r[r::DressingSumX + i];
    for (int a = 0; a < kAxisCount; ++a) {
        const AxisUnit& u = c_.axes[static_cast<std::size_t>(a)];
        StartAxis& s = p.axes[static_cast<std::size_t>(a)];
        s.present = u.present;
        s.scale = u.k.scale;
        s.machineDisc = u.toDisc(u.servo.target());
        s.currentDisc = currentFromMachine(s.machineDisc, c_.r, a, c_.programExclusion);
        s.programmedDisc = u.programmedDisc;
    }
}

void Interpreter::startAt(const StartPoint& p, Mode mode) {
    start(p.mainProgram, 0, mode);
    if (!executing(c_.state) || !prog_)
        return;
    // The call stack: every level's program must be the one the preview had.
    for (std::size_t i = 0; i < p.callers.size() && i < stack_.size(); ++i) {
        const program::Program* caller = c_.store.find(p.callers[i].program);
        if (!caller) {
            error(45);
            return;
        }
        stack_[i] = Level{caller, p.callers[i].returnIndex};
    }
    const program::Program* target = c_.store.find(p.program);
    if (!target || p.frameIndex < 0 || p.frameIndex >= static_cast<int>(target->frames.size())) {
        error(45);
        return;
    }
    depth_ = static_cast<int>(p.callers.size());
    prog_ = target;
    index_ = p.frameIndex;
    line_ = target->frames[static_cast<std::size_t>(index_)].span.line;
    for (const auto& [n, v] : p.r)
        if (rValid(n) && !rReadOnly(n) && n != r::PlcBit && n != r::NestingLevel)
            c_.r.set(n, v);
    modal_ = p.modal;
    c_.programExclusion = exclusionOfG(modal_.components);
    for (AxisUnit& u : c_.axes)
        u.noOverride = modal_.noOverrideAxis == u.index;
    c_.messageNumber = p.messageNumber;
    replayM_.clear();
    for (int m : p.mFunctions)
        if (replayedMFunction(m))
            replayM_.push_back(m);
    replayAt_ = 0;
    replayWait_ = false;
    // The safe path: X away from the part to its reference point, Z to the
    // start point, X to it (an axis the machine lacks is left out).
    legCount_ = 0;
    leg_ = 0;
    legMoving_ = false;
    const auto leg = [&](int a, std::int64_t disc) {
        if (c_.axes[static_cast<std::size_t>(a)].present)
            legs_[static_cast<std::size_t>(legCount_++)] = {a, disc};
    };
    leg(0, c_.axes[0].k.homeValueDisc);
    leg(1, p.axes[1].machineDisc);
    leg(0, p.axes[0].machineDisc);
    for (int a = 0; a < kAxisCount; ++a)
        startProgrammed_[static_cast<std::size_t>(a)] = p.axes[static_cast<std::size_t>(a)].programmedDisc;
    updateNumbers();
    step_ = Step::Approach;
}

bool Interpreter::approach() {
    // 1. The M functions, handed again in order (up to three at a time).
    if (replayWait_) {
        if (!c_.mhs.tick(c_.words, c_.nowMs)) {
            c_.state = ProgramState::WaitingM;
            return false;
        }
        c_.state = ProgramState::Running;
        replayWait_ = false;
    }
    while (replayAt_ < replayM_.size()) {
        const std::size_t n = std::min<std::size_t>(3, replayM_.size() - replayAt_);
        const std::span<const int> codes(replayM_.data() + replayAt_, n);
        replayAt_ += n;
        if (c_.out->mFunctions(frameRef(), codes)) {
            replayWait_ = true;
            if (!c_.mhs.tick(c_.words, c_.nowMs)) {
                c_.state = ProgramState::WaitingM;
                return false;
            }
            c_.state = ProgramState::Running;
            replayWait_ = false;
        }
    }
    // 2. The legs of the safe path, one axis at a time, at the rapid speed.
    if (legMoving_) {
        AxisUnit& u = c_.axes[static_cast<std::size_t>(legs_[static_cast<std::size_t>(leg_)].first)];
        if (u.owner == MotionOwner::Program &&
            !(u.servo.inPosition() && !u.servo.moving() && u.servo.target() == u.moveTarget))
            return false;
        u.owner = MotionOwner::None;
        legMoving_ = false;
        ++leg_;
    }
    while (leg_ < legCount_) {
        const auto [a, disc] = legs_[static_cast<std::size_t>(leg_)];
        AxisUnit& u = c_.axes[static_cast<std::size_t>(a)];
        const double t = u.toInternal(disc);
        if (t == u.servo.target()) {
            ++leg_;
            continue;
        }
        if (u.softLimitsActive() && (disc < u.k.softMinusDisc || disc > u.k.softPlusDisc)) {
            error(forAxis(12, a));
            return false;
        }
        const double from = u.servo.target();
        const int dir = t > from ? 1 : -1;
        if (u.directionLocked(dir)) {
            error(forAxis(dir > 0 ? 11 : 10, a));
            return false;
        }
        const double speed = u.k.speedParamToInternalPerMs(u.k.feedAutoMax);
        if (speed <= 0) {
            error(forAxis(33, a));
            return false;
        }
        c_.out->motionBegins();
        u.moveTarget = t;
        u.eraseSignal = 0;
        u.erased = false;
        if (!c_.out->move(u, from, t, speed, -1, false)) {
            const int f = axis::faultMessage(u.servo.fault(), u.id);
            error(f ? f : forAxis(1, a));
            return false;
        }
        u.owner = MotionOwner::Program;
        u.moveSpeed = speed;
        u.rapid = true;
        c_.out->motionEnds(frameRef(), PreviewKind::Rapid);
        legMoving_ = true;
        return false;
    }
    // 3. The frame, with the programmed positions the preview had.
    for (int a = 0; a < kAxisCount; ++a)
        c_.axes[static_cast<std::size_t>(a)].programmedDisc = startProgrammed_[static_cast<std::size_t>(a)];
    step_ = Step::Fetch;
    return true;
}

void Interpreter::resume() {
    if (c_.state == ProgramState::Interrupted) {
        c_.stopHold = false;
        c_.state = c_.resumeState;
    } else if (c_.state == ProgramState::M0) {
        c_.state = ProgramState::Running;
    } else {
        return;
    }
    c_.out->resumed(); // a frame the debugger held runs now
    // Axes a mode change took from the program come back to it.
    for (std::size_t a = 0; a < c_.axes.size(); ++a) {
        AxisUnit& u = c_.axes[a];
        bool ok = true;
        if (u.resumeMove) {
            u.resumeMove = false;
            ok = u.servo.moveTo(u.moveTarget, u.moveSpeed);
            u.owner = MotionOwner::Program;
        } else if (u.resumeWheel) {
            u.resumeWheel = false;
            u.owner = MotionOwner::HandwheelFrame;
        } else if (c_.osc[a].phase() == Oscillation::Phase::Paused) {
            ok = c_.osc[a].resume(u.servo);
            u.owner = MotionOwner::Oscillation;
        }
        if (!ok) {
            const int f = axis::faultMessage(u.servo.fault(), u.id);
            error(f ? f : forAxis(1, static_cast<int>(a)));
            return;
        }
    }
}

void Interpreter::endProgram() {
    for (std::size_t a = 0; a < c_.axes.size(); ++a) {
        AxisUnit& u = c_.axes[a];
        if (c_.osc[a].active())
            c_.osc[a].abort(u.servo);
        if (programMotion(u.owner))
            u.owner = MotionOwner::None;
    }
    // M02/M30 in a subprogram ends the whole program: no level is open any
    // more (R158 = 0); the program and frame numbers stay where it ended.
    depth_ = 0;
    c_.r.set(r::NestingLevel, 0);
    c_.state = ProgramState::Ended;
    c_.endOrReset = true;
    c_.stopHold = false;
    c_.programEndMs = c_.nowMs;
}

void Interpreter::returnFromSubprogram() {
    --depth_;
    prog_ = stack_[static_cast<std::size_t>(depth_)].program;
    index_ = stack_[static_cast<std::size_t>(depth_)].returnIndex;
    step_ = Step::Fetch;
    updateNumbers();
}

void Interpreter::jump(int n) {
    const int i = prog_->indexOfN(n);
    if (i < 0) {
        error(53);
        return;
    }
    index_ = i;
    step_ = Step::Fetch;
}

bool Interpreter::executeZeroTime(const program::Frame& f) {
    line_ = f.span.line;
    switch (f.kind()) {
    case FrameKind::Compute: {
        const program::ComputeFrame& cf = *f.compute();
        const auto operand = [&](const program::Operand& o) {
            return o.isR() ? c_.r[o.rIndex] : o.literal;
        };
        const ArithResult res =
            arith(operand(cf.a), cf.op, cf.op == program::ArithOp::None ? 0 : operand(cf.b));
        // A read-only parameter has no message of its own: refused as 46 (docs/engine.md).
        if (!res.ok || !rValid(cf.target.number) || rReadOnly(cf.target.number)) {
            error(46);
            return false;
        }
        c_.r.set(cf.target.number, res.value);
        next();
        return true;
    }
    case FrameKind::IfGoto: {
        const program::IfGotoFrame& g = *f.ifGoto();
        if (c_.r[g.r.number] > 0)
            jump(g.target.number);
        else
            next();
        return executing(c_.state);
    }
    case FrameKind::Goto:
        jump(f.jumpTarget());
        return executing(c_.state);
    case FrameKind::Iso:
        break;
    }
    return true;
}

bool Interpreter::valueDisc(const program::Value& v, int axis, std::int64_t& disc) {
    const AxisUnit& u = c_.axes[static_cast<std::size_t>(axis)];
    disc = v.isR() ? c_.r[v.rIndex] : v.literal.toUnits(u.k.scale.decimals());
    if (std::llabs(disc) > maxCoordinateDisc(u.k.scale)) {
        error(forAxis(33, axis));
        return false;
    }
    return true;
}

OscillationPresets Interpreter::presets(int axis) const {
    const int b = axis == 0 ? r::OscillationX : r::OscillationZ;
    OscillationPresets p;
    p.reverseDelayMs = std::max(0, c_.r[b + 3]);
    p.exactMinus = c_.r[b + 4] != 0;
    p.exactPlus = c_.r[b + 5] != 0;
    const int end = c_.r[b + 6];
    p.endPoint = end == 1 || end == 2 ? end : 0;
    p.sparkOut = std::max(0, c_.r[b + 7]);
    return p;
}

void Interpreter::beginIso(const program::Frame& f) {
    iso_ = *f.iso();
    const program::IsoFrame& iso = iso_;
    line_ = f.span.line;
    moving_ = {};
    oscStop_ = {};
    oscStart_ = {};
    setPos_ = {};
    wheel_ = {};
    erase_ = {};
    dwell_ = false;
    dwellLeftMs_ = -1;
    if (f.malformed) {
        error(31); // a frame the parser could not read (the store is damaged)
        return;
    }

    // G-functions: one per group (47), known numbers only (47).
    ModalState m = modal_;
    unsigned groups = 0;
    for (const program::Word& w : iso.g) {
        const program::GInfo gi = program::classifyG(w.number);
        const unsigned bit = 1u << static_cast<unsigned>(gi.group);
        if (!gi.known() || (groups & bit)) {
            error(47);
            return;
        }
        groups |= bit;
        const int ax = gi.axis == program::Axis::Z ? 1 : 0;
        switch (gi.function) {
        case GFunction::Rapid:
            m.rapid = true;
            break;
        case GFunction::Feed:
            m.rapid = false;
            break;
        case GFunction::Dwell:
            dwell_ = true;
            break;
        case GFunction::Handwheel:
            wheel_[static_cast<std::size_t>(ax)] = true;
            break;
        case GFunction::StopOnSignal:
            erase_[static_cast<std::size_t>(ax)] = gi.signal;
            break;
        case GFunction::OmitHandwheelOffset:
        case GFunction::OmitCorrection:
        case GFunction::OmitDressing:
        case GFunction::OmitZeroOffset:
        case GFunction::AllComponents:
            m.components = w.number;
            break;
        case GFunction::OverrideAllAxes:
            m.noOverrideAxis = -1;
            break;
        case GFunction::NoOverride:
            m.noOverrideAxis = ax;
            break;
        case GFunction::Absolute:
            m.incremental = false;
            break;
        case GFunction::Incremental:
            m.incremental = true;
            break;
        case GFunction::SetPosition:
            setPos_[static_cast<std::size_t>(ax)] = true;
            break;
        case GFunction::OscillationStop:
            oscStop_[static_cast<std::size_t>(ax)] = true;
            oscOn_[static_cast<std::size_t>(ax)] = false;
            break;
        case GFunction::OscillationStart:
            oscStart_[static_cast<std::size_t>(ax)] = true;
            break;
        case GFunction::Unknown:
            break;
        }
    }

    // The combinations the positioner refuses (program/refusals.h, the
    // validator's table): the first the frame matches is the alarm.
    const bool hasX = iso.x.has_value();
    const bool call = iso.call.has_value();
    program::refusal::Words words = program::refusalWords(iso);
    if (depth_ > 0 && index_ == static_cast<int>(prog_->frames.size()) - 1)
        words |= program::refusal::LastOfSubprogram;
    if (words)
        if (const program::Refusal* bad = program::firstRefusal(words)) {
            error(bad->message);
            return;
        }
    const bool m17 = (words & program::refusal::SubprogramEnd) != 0;
    const bool m2 = (words & program::refusal::End) != 0;
    const bool m30 = (words & program::refusal::EndRewind) != 0;

    // Modal state, message, feeds.
    modal_ = m;
    c_.programExclusion = exclusionOfG(m.components);
    for (AxisUnit& u : c_.axes)
        u.noOverride = modal_.noOverrideAxis == u.index;
    if (iso.message) {
        c_.messageNumber = iso.message->number;
        c_.out->message(frameRef(), c_.messageNumber);
    }
    const std::optional<program::Value>* feeds[2] = {&iso.fx, &iso.fz};
    for (int a = 0; a < kAxisCount; ++a) {
        const auto& fv = *feeds[a];
        if (!fv)
            continue;
        const AxisUnit& u = c_.axes[static_cast<std::size_t>(a)];
        const std::int64_t feed =
            fv->isR() ? c_.r[fv->rIndex] : fv->literal.toUnits(u.k.scale.decimals());
        if (feed <= 0) {
            error(forAxis(33, a));
            return;
        }
        modal_.feed[static_cast<std::size_t>(a)] = feed;
    }

    // Axis words.
    if (dwell_) {
        if (hasX) {
            const std::int64_t ms = iso.x->isR() ? c_.r[iso.x->rIndex] : iso.x->literal.toUnits(3);
            if (ms < 0) {
                error(33);
                return;
            }
            dwellLeftMs_ = ms;
        }
    } else {
        const std::optional<program::Value>* words[2] = {&iso.x, &iso.z};
        for (int a = 0; a < kAxisCount; ++a) {
            const std::size_t i = static_cast<std::size_t>(a);
            if (!*words[a] || oscStart_[i])
                continue; // Gx81 reads its stroke when it starts
            std::int64_t v = 0;
            if (!valueDisc(**words[a], a, v))
                return;
            value_[i] = v;
            if (!setPos_[i])
                moving_[i] = true;
        }
    }

    // M functions, in the order written.
    mCount_ = 0;
    for (const program::Word& w : iso.m)
        m_[static_cast<std::size_t>(mCount_++)] = w.number;
    m00_ = iso.hasM(program::mfunc::kStop);
    mEnd_ = m2 || m30;
    m17_ = m17;
    callTarget_ = call ? iso.call->number : 0;
    step_ = c_.out->mFunctions(frameRef(), std::span<const int>(m_.data(), static_cast<std::size_t>(mCount_)))
                ? Step::Handshake
                : Step::OscStop;
    if (step_ == Step::OscStop)
        for (int a = 0; a < kAxisCount; ++a)
            if (oscStop_[static_cast<std::size_t>(a)])
                c_.osc[static_cast<std::size_t>(a)].requestStop(presets(a));
}

bool Interpreter::startMove(int a, std::int64_t targetDisc, bool handwheel, int eraseSignal) {
    AxisUnit& u = c_.axes[static_cast<std::size_t>(a)];
    if (!u.present || c_.osc[static_cast<std::size_t>(a)].active()) {
        error(forAxis(33, a));
        return false;
    }
    if (u.softLimitsActive() && (targetDisc < u.k.softMinusDisc || targetDisc > u.k.softPlusDisc)) {
        error(forAxis(12, a));
        return false;
    }
    const double t = u.toInternal(targetDisc);
    const double from = u.servo.target();
    const int dir = t > from ? 1 : (t < from ? -1 : 0);
    if (u.directionLocked(dir)) {
        error(forAxis(dir > 0 ? 11 : 10, a));
        return false;
    }
    u.programmedDisc = targetDisc;
    u.moveTarget = t;
    u.eraseSignal = eraseSignal;
    u.erased = false;
    if (handwheel) {
        u.owner = MotionOwner::HandwheelFrame;
        u.wheelMin = std::min(from, t);
        u.wheelMax = std::max(from, t);
        u.rapid = false;
        return c_.out->move(u, from, t, u.k.speedParamToInternalPerMs(u.k.feedAutoMax), feedOf(a),
                            true);
    }
    const double maxSpeed = u.k.speedParamToInternalPerMs(u.k.feedAutoMax);
    double speed = maxSpeed;
    if (!modal_.rapid) {
        const std::int64_t feed = modal_.feed[static_cast<std::size_t>(a)];
        if (feed < 0) {
            error(forAxis(33, a)); // G01 without a feed for this axis
            return false;
        }
        speed = std::min(u.speedFromDiscPerMin(static_cast<double>(feed)), maxSpeed);
    }
    if (speed <= 0) {
        error(forAxis(33, a)); // F УСК.АВТ. = 0: the axis cannot move in a program
        return false;
    }
    if (!c_.out->move(u, from, t, speed, feedOf(a), false)) {
        const int f = axis::faultMessage(u.servo.fault(), u.id);
        error(f ? f : forAxis(1, a));
        return false;
    }
    u.owner = MotionOwner::Program;
    u.moveSpeed = speed;
    u.rapid = modal_.rapid;
    return true;
}

bool Interpreter::startOscillation(int a, const std::optional<program::Value>& stroke) {
    AxisUnit& u = c_.axes[static_cast<std::size_t>(a)];
    Oscillation& osc = c_.osc[static_cast<std::size_t>(a)];
    if (!u.present || osc.active()) {
        error(forAxis(33, a));
        return false;
    }
    const double cur = u.servo.target();
    double lo = cur, hi = cur;
    bool towardsHi = true;
    const int base = a == 0 ? r::OscillationX : r::OscillationZ;
    if (stroke) {
        std::int64_t s = 0;
        if (!valueDisc(*stroke, a, s))
            return false;
        const double end = cur + u.toInternal(s);
        lo = std::min(cur, end);
        hi = std::max(cur, end);
        towardsHi = end > cur;
    } else {
        // No stroke: the preset reverse points -M / +M (current coordinates).
        const std::uint8_t ex = c_.programExclusion;
        lo = u.toInternal(machineFromCurrent(c_.r[base], c_.r, a, ex));
        hi = u.toInternal(machineFromCurrent(c_.r[base + 1], c_.r, a, ex));
        if (lo > hi)
            std::swap(lo, hi);
        towardsHi = cur - lo <= hi - cur; // first to the farther point
    }
    if (lo == hi) {
        error(forAxis(33, a));
        return false;
    }
    if (u.softLimitsActive() && (lo < u.softMin || hi > u.softMax)) {
        error(forAxis(12, a));
        return false;
    }
    // Speed: F of this frame, else the preset СКОРОСТЬ ОСЦИЛЛЯЦИИ, else the modal F.
    const bool frameFeed = a == 0 ? iso_.fx.has_value() : iso_.fz.has_value();
    std::int64_t feed = modal_.feed[static_cast<std::size_t>(a)];
    if (!frameFeed && c_.r[base + 2] > 0)
        feed = c_.r[base + 2];
    if (feed <= 0) {
        error(forAxis(33, a));
        return false;
    }
    const double speed = std::min(u.speedFromDiscPerMin(static_cast<double>(feed)),
                                  u.k.speedParamToInternalPerMs(u.k.feedAutoMax));
    if (speed <= 0) {
        error(forAxis(33, a));
        return false;
    }
    if (!c_.out->oscillate(u, osc, lo, hi, speed, towardsHi, presets(a), feed)) {
        const int f = axis::faultMessage(u.servo.fault(), u.id);
        error(f ? f : forAxis(1, a));
        return false;
    }
    return true;
}

void Interpreter::actions() {
    const program::IsoFrame& iso = iso_;
    // Gx92: the current coordinate becomes the value; the zero offset absorbs
    // it. The current coordinate of a program is where it commanded the axis
    // (the setpoint, standing at the last target): the servo's rest error,
    // up to ДОПУСК ПОЗ, does not creep into the zero offset.
    for (int a = 0; a < kAxisCount; ++a) {
        const std::size_t i = static_cast<std::size_t>(a);
        if (!setPos_[i] || !(a == 0 ? iso.x : iso.z))
            continue;
        AxisUnit& u = c_.axes[i];
        if (!u.present) {
            error(forAxis(33, a));
            return;
        }
        const std::int64_t zo =
            zeroOffsetFor(u.toDisc(u.servo.setpoint()), value_[i], c_.r, a, c_.programExclusion);
        if (!fitsR(zo)) {
            error(46);
            return;
        }
        c_.r.set(r::ZeroOffsetX + a, static_cast<std::int32_t>(zo));
    }
    c_.out->motionBegins();
    // Gx81
    for (int a = 0; a < kAxisCount; ++a)
        if (oscStart_[static_cast<std::size_t>(a)]) {
            if (!startOscillation(a, a == 0 ? iso.x : iso.z))
                return;
            oscOn_[static_cast<std::size_t>(a)] = true;
        }
    // G04
    if (dwell_ && dwellLeftMs_ > 0) {
        if (c_.out->dwell(frameRef(), dwellLeftMs_)) {
            dwellFresh_ = true;
            c_.state = ProgramState::Dwell;
        } else {
            dwellLeftMs_ = -1; // no waiting
        }
    }
    // Motion of X and Z.
    for (int a = 0; a < kAxisCount; ++a) {
        const std::size_t i = static_cast<std::size_t>(a);
        if (!moving_[i])
            continue;
        const AxisUnit& u = c_.axes[i];
        const std::int64_t target =
            modal_.incremental ? u.programmedDisc + value_[i]
                               : machineFromCurrent(value_[i], c_.r, a, c_.programExclusion);
        if (!startMove(a, target, wheel_[i], erase_[i])) {
            moving_ = {};
            return;
        }
    }
    const bool wheel = wheel_[0] || wheel_[1];
    const bool signal = erase_[0] > 0 || erase_[1] > 0;
    c_.out->motionEnds(frameRef(), wheel    ? PreviewKind::Handwheel
                                   : signal ? PreviewKind::Signal
                                   : modal_.rapid ? PreviewKind::Rapid
                                                  : PreviewKind::Feed);
}

bool Interpreter::waitDone() {
    bool done = true;
    for (int a = 0; a < kAxisCount; ++a) {
        const std::size_t i = static_cast<std::size_t>(a);
        if (!moving_[i])
            continue;
        AxisUnit& u = c_.axes[i];
        if (u.owner != MotionOwner::Program && u.owner != MotionOwner::HandwheelFrame)
            continue;
        // Gx36..Gx39: the signal erases the rest of the path.
        if (u.owner == MotionOwner::Program && u.eraseSignal > 0 && !u.erased &&
            u.erase[static_cast<std::size_t>(u.eraseSignal - 1)]) {
            const double err = u.servo.followingError() / static_cast<double>(u.ipd);
            c_.r.set(r::EraseErrorX + a, static_cast<std::int32_t>(std::llround(err)));
            u.servo.stop();
            u.erased = true;
        }
        const bool there = u.servo.inPosition() && !u.servo.moving() &&
                           (u.erased || u.servo.target() == u.moveTarget);
        if (!there) {
            done = false;
            continue;
        }
        if (u.erased)
            u.programmedDisc = u.toDisc(u.servo.target());
        u.owner = MotionOwner::None;
        u.eraseSignal = 0;
        u.erased = false;
    }
    if (dwellLeftMs_ > 0) {
        if (dwellFresh_)
            dwellFresh_ = false;
        else
            dwellLeftMs_ -= c_.tickMs;
        if (dwellLeftMs_ > 0)
            done = false;
        else
            c_.state = ProgramState::Running;
    }
    return done;
}

void Interpreter::afterFrame() {
    if (m00_) {
        m00_ = false;
        if (c_.out->stopAtM00()) {
            c_.state = ProgramState::M0;
            step_ = Step::Call;
            return;
        }
    }
    if (mEnd_) {
        endProgram();
        return;
    }
    if (m17_) {
        if (depth_ > 0)
            returnFromSubprogram();
        else
            endProgram();
        return;
    }
    step_ = Step::Call;
}

void Interpreter::call() {
    if (callTarget_ == 0) {
        next();
        return;
    }
    const int n = callTarget_;
    callTarget_ = 0;
    const program::Program* target =
        n >= 1 && n <= program::kMaxPrograms ? c_.store.find(n) : nullptr;
    if (!target) {
        error(45);
        return;
    }
    if (depth_ + 1 > c_.nestingLimit) {
        error(48);
        return;
    }
    if (const int dup = duplicateFrameLine(*target)) {
        c_.raise(54, target->number, dup);
        return;
    }
    stack_[static_cast<std::size_t>(depth_)] = Level{prog_, index_ + 1};
    ++depth_;
    prog_ = target;
    index_ = 0;
    step_ = Step::Fetch;
    updateNumbers();
}

void Interpreter::tick() {
    if (!executing(c_.state) || !prog_)
        return;
    int budget = kFramesPerTick;
    for (;;) {
        switch (step_) {
        case Step::Fetch: {
            if (c_.words.bit(z::DataHold))
                return; // «Блокировка ввода данных»: the next frame waits
            if (index_ >= static_cast<int>(prog_->frames.size())) {
                if (depth_ > 0) {
                    returnFromSubprogram(); // the end of a subprogram returns like M17
                } else {
                    endProgram();
                    return;
                }
                break;
            }
            const program::Frame& f = prog_->frames[static_cast<std::size_t>(index_)];
            if (--budget < 0)
                return;
            if (f.skip) {
                ++index_; // «/ – кадр не будет обрабатываться»
                break;
            }
            if (c_.out->holdBefore(program(), index_, f.span.line)) {
                // The debugger's stop before the frame: held as by «Стоп», «Пуск» runs it.
                c_.resumeState = ProgramState::Running;
                c_.state = ProgramState::Interrupted;
                c_.stopHold = false;
                updateNumbers();
                return;
            }
            ++c_.framesExecuted;
            updateNumbers();
            if (f.kind() == FrameKind::Iso)
                beginIso(f);
            else
                executeZeroTime(f);
            if (!executing(c_.state))
                return;
            break;
        }
        case Step::Handshake:
            if (!c_.mhs.tick(c_.words, c_.nowMs)) {
                c_.state = ProgramState::WaitingM;
                return;
            }
            c_.state = ProgramState::Running;
            step_ = Step::OscStop;
            for (int a = 0; a < kAxisCount; ++a)
                if (oscStop_[static_cast<std::size_t>(a)])
                    c_.osc[static_cast<std::size_t>(a)].requestStop(presets(a));
            break;
        case Step::OscStop:
            // Gx80 waits until the oscillation has stopped and the axis stands in position.
            for (int a = 0; a < kAxisCount; ++a) {
                const std::size_t i = static_cast<std::size_t>(a);
                if (!oscStop_[i])
                    continue;
                const axis::Servo& s = c_.axes[i].servo;
                if (c_.osc[i].active() || (s.loopClosed() && (!s.inPosition() || s.moving())))
                    return;
            }
            step_ = Step::Actions;
            break;
        case Step::Actions:
            actions();
            if (!executing(c_.state))
                return;
            step_ = Step::Wait;
            break;
        case Step::Wait:
            if (!waitDone())
                return;
            afterFrame();
            if (!executing(c_.state))
                return;
            break;
        case Step::Call:
            call();
            if (!executing(c_.state))
                return;
            break;
        case Step::Approach:
            if (!approach())
                return;
            break;
        }
    }
}

} // namespace k528::engine
