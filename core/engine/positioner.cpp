#include "engine/positioner.h"

#include "catalog/messages.h"
#include "engine/coordinates.h"
#include "engine/self_test.h"
#include "profile/english.h"
#include "profile/problem.h"
#include "profile/validate.h"
#include "util/same_bytes.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <optional>
#include <tuple>
#include <utility>

namespace k528::engine {

namespace {

// A value into the 32-bit range of an R-parameter (kRMin..kRMax); the value
// almost always fits, and one comparison tells.
constexpr std::int32_t clampR(std::int64_t v) {
    const auto fit = static_cast<std::int32_t>(v); // modulo 2^32 (C++20)
    if (fit == v) [[likely]]
        return fit;
    return static_cast<std::int32_t>(v < kRMin ? kRMin : kRMax);
}
constexpr bool rising(std::uint16_t now, std::uint16_t before, int bit) {
    return ((now >> bit) & 1u) && !((before >> bit) & 1u);
}
constexpr bool on(std::uint16_t w, int bit) {
    return ((w >> bit) & 1u) != 0;
}

// Message of axis a: X number for a = 0, the Z counterpart for a = 1.
constexpr int axisMsg(int x, int z, int a) {
    return a == 0 ? x : z;
}

std::string num(std::int64_t v) {
    return std::to_string(v);
}

int channelIndex(std::int64_t code) {
    return code >= 1 && code <= 4 ? static_cast<int>(code - 1) : -1;
}

// УПРАВЛЕНИЕ ДАННЫМИ clears a memory area (C, R, the programs) only in that
// mode and with no program active: the refusal, or none.
std::optional<OpResult> memoryClearRefused(Mode mode, ProgramState state) {
    if (mode != Mode::DataControl)
        return OpResult::refused(Refusal::WrongMode, "clear-mode");
    if (programActive(state))
        return OpResult::refused(Refusal::ProgramActive, "program-active");
    return std::nullopt;
}

} // namespace

Positioner::Positioner(const profile::MachineProfile& profile) : c_(profile), interp_(c_) {
    chooseOutput();
    bool intact = true;
    c_.store = loadStore(profile, intact);
    storeCorrupt_ = !intact;
    for (const auto& [n, v] : profile.r)
        if (rValid(n) && !rReadOnly(n) && fitsR(v))
            c_.r.set(n, static_cast<std::int32_t>(v));
}

// ---------------------------------------------------------------------------
// Power-on and the self-test

void Positioner::configurationCheck() {
    configMessages_ = configurationMessages(c_.c);
    for (int n : {13, 29, 37, 38, 39, 15})
        c_.condition(n, configMessages_[static_cast<std::size_t>(n)]);
}

void Positioner::programStoreCheck() {
    c_.condition(31, storeCorrupt_ || !storeIntact(c_.store));
}

void Positioner::powerOn() {
    wake();
    if (c_.powered)
        return;
    c_.powered = true;
    c_.mode = c_.panelMode = Mode::Manual;
    c_.state = ProgramState::Idle;
    interp_.resetModal();
    configurationCheck();
    programStoreCheck();
    c_.lastZ1000 = c_.words.word(1000);
    c_.lastZ1001 = c_.words.word(1001);
    for (int a = 0; a < kAxisCount; ++a) {
        c_.lastAxisWord0[static_cast<std::size_t>(a)] =
            c_.words.axisControl(a, 0);
        c_.lastAxisWord1[static_cast<std::size_t>(a)] =
            c_.words.axisControl(a, 1);
        c_.lastAxisWord2[static_cast<std::size_t>(a)] =
            c_.words.axisControl(a, 2);
    }
    writeOutputs(false);
}

void Positioner::advance(std::int64_t ms) {
    const std::int64_t ticks = (ms + c_.tickMs - 1) / c_.tickMs;
    for (std::int64_t i = 0; i < ticks; ++i)
        tick();
}

// ---------------------------------------------------------------------------
// One tick

void Positioner::tick() {
    if (!c_.powered)
        powerOn();
    const bool inputsAsLeft = quiet_.valid && settledInputs() == quiet_.left;
    if (inputsAsLeft && quiet_.ticks >= 2) {
        if (checkShortcuts_) [[unlikely]] {
            checkSettledTick();
            return;
        }
        // Settled: what a full tick would do (see positioner.h).
        c_.nowMs += c_.tickMs;
        for (AxisUnit& u : c_.axes)
            if (u.present)
                u.servo.quietTick(c_.dtMs);
        return;
    }
    fullTick(inputsAsLeft);
}

void Positioner::fullTick(bool inputsAsLeft) {
    c_.nowMs += c_.tickMs;
    const bool routine = routineInputs();
    if (routine) {
        // Program control with the inputs of the last tick (the shortcut of
        // programControl(), whose condition holds here).
        programControlAgain();
        if (checkShortcuts_) [[unlikely]]
            checkShortcut(&Positioner::readAll);
    } else {
        readAll();
    }
    for (AxisUnit& u : c_.axes)
        if (u.present)
            axisTick(u);
    interp_.tick();
    writeOutputs(routine);
    noteSettled(inputsAsLeft);
}

void Positioner::chooseOutput() {
    previewOutput_.setSink(previewSink_);
    debugOutput_.setGate(debugGate_);
    c_.instantAxes = previewSink_ != nullptr;
    c_.out = previewSink_ ? static_cast<ProgramOutput*>(&previewOutput_)
             : debugGate_ ? static_cast<ProgramOutput*>(&debugOutput_)
                          : static_cast<ProgramOutput*>(&runOutput_);
}

bool Positioner::settled() const {
    if (!c_.powered || executing(c_.state) || c_.instantAxes || wheelDelta_[0] != 0 || wheelDelta_[1] != 0)
        return false;
    for (const AxisUnit& u : c_.axes) {
        if (!u.present)
            continue;
        if (!u.servo.quiet() || u.owner != MotionOwner::None || u.homing.running() || u.jogDir != 0 ||
            c_.osc[static_cast<std::size_t>(u.index)].active())
            return false;
    }
    return true;
}

void Positioner::noteSettled(bool inputsAsLeft) {
    if (!settled()) {
        unsettle();
        return;
    }
    const SettledInputs now = settledInputs();
    const bool unchanged = inputsAsLeft && now == quiet_.left && c_.r == quiet_.r;
    quiet_.ticks = unchanged ? quiet_.ticks + 1 : 0;
    if (!unchanged) {
        quiet_.left = now;
        quiet_.r = c_.r;
    }
    quiet_.valid = true;
}

// MachineIo and InterfaceWords as SettledInputs copies them: a field added
// to either must be added there too, or a settled tick would not see it
// change.
static_assert(sizeof(PulseChannel) == 24 && sizeof(MachineIo) == 128,
              "SettledInputs copies every field of MachineIo");
static_assert(sizeof(InterfaceWords) == InterfaceWords::kWordCount * sizeof(std::uint16_t),
              "SettledInputs copies every interface word");

Positioner::SettledInputs Positioner::settledInputs() const {
    SettledInputs s;
    s.reading = tickInputs();
    for (std::size_t k = 0; k < c_.io.pulse.size(); ++k) {
        const PulseChannel& p = c_.io.pulse[k];
        s.counts[k] = p.count;
        s.markCounts[k] = p.zeroMarkCount;
        s.lines[3 * k] = p.line1Ok;
        s.lines[3 * k + 1] = p.line2Ok;
        s.lines[3 * k + 2] = p.zeroMark;
    }
    s.latched = c_.alarms.latchedMask();
    s.active = c_.alarms.activeMask();
    std::copy(c_.io.dac.begin(), c_.io.dac.end(), s.dac.begin());
    std::memcpy(s.outputs.data(), c_.words.outputs(), sizeof s.outputs);
    s.regulatorEnable = {c_.io.regulatorEnable[0], c_.io.regulatorEnable[1]};
    return s;
}

Positioner::TickInputs Positioner::tickInputs() const {
    TickInputs t;
    std::memcpy(t.words.data(), c_.words.inputs(), sizeof t.words);
    std::memcpy(t.status.data(), machineStatusBytes(c_.io), kMachineStatusBytes);
    for (std::size_t k = 0; k < t.wheelCounts.size(); ++k) {
        const int ch = c_.wheelChannel[k];
        t.wheelCounts[k] = ch >= 0 ? c_.io.pulse[static_cast<std::size_t>(ch)].count : 0;
    }
    return t;
}

bool Positioner::inputsAsRead() const {
    return routine_.valid && !operatorActed_ && tickInputs() == routine_.inputs;
}

bool Positioner::routineInputs() const {
    // A reading of the same inputs would: count no handwheel pulse, decode
    // the same signals, raise or clear no message, find no edge (so start,
    // stop, reset, acknowledge nothing and keep mode and override) and, out
    // of РУЧНОЙ with no pulse, move no axis by hand.
    return c_.mode != Mode::Manual && wheelDelta_[0] == 0 && wheelDelta_[1] == 0 && inputsAsRead();
}

void Positioner::noteRoutineInputs() {
    routine_.valid = true;
    routine_.inputs = tickInputs();
}

void Positioner::readAll() {
    readInputs();
    c_.plc.update(c_.words);
    systemChecks();
    programControl();
    manualFunctions();
    noteRoutineInputs();
}

// What the full reading of the inputs can change, for the check of a
// routine tick, and what a full tick could change beyond the settled tick's
// clock and servos' time at rest: the words, the machine I/O, the
// R-parameters, the messages, the mode, program and override state, and
// each axis' signals, servo inputs, motion owner, commanded motion and what
// its servo shows (position, DAC code, regulator, loop, fault, quiet).
struct Positioner::Observed {
    InterfaceWords words;
    MachineIo io;
    RStore r;
    std::uint64_t latched = 0, active = 0;
    PlcMessages plc;
    Mode mode = Mode::Manual, panelMode = Mode::Manual;
    ProgramState state = ProgramState::Idle;
    bool endOrReset = false, stopHold = false;
    int overridePercent = 0;
    std::array<std::int64_t, 2> wheelDelta{};
    struct Axis {
        bool limitPlus, limitMinus, cam, driveReady, feedEnableWords;
        std::array<bool, 4> erase;
        MotionOwner owner;
        int jogDir;
        double target, setpoint;
        double actual;
        int dac;
        std::int64_t pulses;
        axis::Fault fault;
        bool regulatorOn, loopClosed, inPosition, quiet;
        bool operator==(const Axis&) const = default;
    };
    std::array<Axis, kAxisCount> axes{};
    bool operator==(const Observed&) const = default;
};

Positioner::Observed Positioner::observed() const {
    Observed o;
    o.words = c_.words;
    o.io = c_.io;
    o.r = c_.r;
    o.latched = c_.alarms.latchedMask();
    o.active = c_.alarms.activeMask();
    o.plc = c_.plc;
    o.mode = c_.mode;
    o.panelMode = c_.panelMode;
    o.state = c_.state;
    o.endOrReset = c_.endOrReset;
    o.stopHold = c_.stopHold;
    o.overridePercent = c_.overridePercent;
    o.wheelDelta = wheelDelta_;
    for (const AxisUnit& u : c_.axes)
        o.axes[static_cast<std::size_t>(u.index)] = {
            u.limitPlus, u.limitMinus,     u.cam,      u.driveReady,        u.feedEnableWords,
            u.erase,     u.owner,          u.jogDir,   u.servo.target(),    u.servo.setpoint(),
            u.servo.actual(), u.servo.dac(), u.servo.pulsesLastTick(), u.servo.fault(),
            u.servo.regulatorOn(), u.servo.loopClosed(), u.servo.inPosition(), u.servo.quiet()};
    return o;
}

void Positioner::checkShortcut(void (Positioner::*full)()) {
    const Observed shortcut = observed();
    (this->*full)();
    ++shortcutChecks_;
    const bool agree = observed() == shortcut;
    shortcutDisagreements_ += agree ? 0 : 1;
    assert(agree && "a shortcut of the tick and the full reading of the same inputs disagree");
}

void Positioner::checkSettledTick() {
    // The settled tick would advance the clock and the servos' time at rest
    // and leave all else as it is; the full tick, run instead, must leave
    // the same and find nothing changed (the shortcut holds for the next).
    const Observed before = observed();
    const std::int64_t clock = c_.nowMs + c_.tickMs;
    fullTick(true);
    ++shortcutChecks_;
    ++settledChecks_;
    const bool agree = observed() == before && c_.nowMs == clock && quiet_.ticks > 0;
    shortcutDisagreements_ += agree ? 0 : 1;
    assert(agree && "the settled tick and the full tick of the same inputs disagree");
}

void Positioner::readInputs() {
    const std::uint16_t w = c_.words.word(1000);
    // Handwheels (C105/C106 name their pulse channels).
    for (int k = 0; k < 2; ++k) {
        const int ch = c_.wheelChannel[static_cast<std::size_t>(k)];
        const std::int64_t count = ch >= 0 ? c_.io.pulse[static_cast<std::size_t>(ch)].count : 0;
        wheelDelta_[static_cast<std::size_t>(k)] =
            wheelInit_ ? count - wheelCount_[static_cast<std::size_t>(k)] : 0;
        wheelCount_[static_cast<std::size_t>(k)] = count;
    }
    wheelInit_ = true;
    for (AxisUnit& u : c_.axes)
        if (u.present)
            axisInputs(u);
    // Emergency stop (and a lost PLC link) — message 9.
    const bool estop = !on(w, 0);
    if (estop && !c_.alarms.active(9)) {
        c_.condition(9, true);
        c_.stopAllMotion();
    } else if (!estop) {
        c_.condition(9, false);
    }
}

void Positioner::axisInputs(AxisUnit& u) {
    const int a = u.index;
    const std::uint16_t w0 = c_.words.axisControl(u.index, 0);
    const std::uint16_t w1 = c_.words.axisControl(u.index, 1);
    const std::uint16_t z1000 = c_.words.word(1000);
    const std::uint8_t fi = c_.io.fastInputs[static_cast<std::size_t>(a)];
    const bool plcLink = c_.io.plcLinkOk;
    if (u.inputsKnown && w0 == u.inputsW0 && w1 == u.inputsW1 && fi == u.inputsFast &&
        z1000 == u.inputsZ1000 && plcLink == u.inputsPlcLink)
        return; // the same words and inputs decode to the same signals
    u.inputsKnown = true;
    u.inputsW0 = w0;
    u.inputsW1 = w1;
    u.inputsFast = fi;
    u.inputsZ1000 = z1000;
    u.inputsPlcLink = plcLink;
    const FastInputMap& f = c_.fast;
    u.limitPlus = on(w0, 5) || f.active(a, FastFunction::LimitPlus, fi);
    u.limitMinus = on(w0, 6) || f.active(a, FastFunction::LimitMinus, fi);
    u.cam = on(w0, 3) || f.active(a, FastFunction::DecelCam, fi);
    u.driveReady =
        !f.wired(a, FastFunction::DriveReady) || f.active(a, FastFunction::DriveReady, fi);
    u.displayMode = f.active(a, FastFunction::DisplayMode, fi);
    for (int n = 0; n < 4; ++n)
        u.erase[static_cast<std::size_t>(n)] =
            on(w1, 12 + n) ||
            f.active(a, static_cast<FastFunction>(static_cast<int>(FastFunction::Erase1) + n), fi);
    // The servo's inputs of these words (feed enable without «Стоп»'s hold).
    axis::ServoInputs& in = u.servoIn;
    in.emergencyStop = !on(z1000, 0) || !plcLink;
    in.loopOff = on(w0, 0) || u.displayMode;
    in.regulatorEnable = on(w0, 1);
    u.feedEnableWords = on(z1000, 1) && on(w0, 2);
    in.accel2 = on(w0, 4);
    in.driveReady = u.driveReady;
}

void Positioner::systemChecks() {
    const MachineIo& io = c_.io;
    // The checks' inputs as one word: the same inputs raise or clear nothing
    // once they have been applied (a message acknowledged meanwhile is not
    // raised again while its cause lasts: condition() acts on a change only).
    // The seven health flags are read as the bytes they are (machine_io.h).
    std::uint64_t state = 0;
    std::memcpy(&state, machineHealthBytes(io), kMachineHealthFlags);
    state |= static_cast<std::uint64_t>(c_.words.word(z::SystemMessagesWord) != 0) << 56;
    if (state == lastSystemInputs_)
        return;
    lastSystemInputs_ = state;
    c_.condition(2, !io.pulseModule1Ok);
    c_.condition(18, !io.pulseModule2Ok);
    c_.condition(3, !io.dacModuleOk);
    c_.condition(14, !io.commModuleOk);
    c_.condition(19, !io.plcLinkOk);
    c_.condition(25, !io.panelLinkOk);
    c_.condition(30, !io.memoryOk);
    c_.condition(55, c_.words.word(z::SystemMessagesWord) != 0);
}

// ---------------------------------------------------------------------------
// Reset, acknowledgement, modes, program control

void Positioner::resetSystem() {
    if (programActive(c_.state))
        c_.abortProgram(ProgramState::Idle);
    c_.state = ProgramState::Idle;
    c_.mhs.cancel(c_.words);
    for (std::size_t i = 0; i < c_.axes.size(); ++i) {
        AxisUnit& u = c_.axes[i];
        if (c_.osc[i].active())
            c_.osc[i].abort(u.servo);
        if (u.homing.running())
            u.homing.cancel(u.servo);
        if (u.owner != MotionOwner::None && u.servo.moving())
            u.servo.stop();
        u.owner = MotionOwner::None;
        u.noOverride = false;
    }
    interp_.resetModal();
    c_.programExclusion = 0;
    c_.endOrReset = true;
    c_.cycle = 0;
    c_.alarms.acknowledge(AlarmCategory::Program);
}

void Positioner::trackFault(AxisUnit& u) {
    const std::size_t i = static_cast<std::size_t>(u.index);
    const axis::Fault f = u.servo.fault();
    if (f == lastFault_[i])
        return;
    if (lastFault_[i] != axis::Fault::None)
        c_.alarms.clear(axis::faultMessage(lastFault_[i], u.id));
    lastFault_[i] = f;
    if (f != axis::Fault::None)
        c_.raise(axis::faultMessage(f, u.id), 0, 0, true);
}

void Positioner::acknowledgeFaults() {
    for (AxisUnit& u : c_.axes) {
        if (!u.present)
            continue;
        if (u.servo.fault() != axis::Fault::None)
            u.servo.resetFault();
        trackFault(u);
        u.softLimitStop = false;
    }
    c_.alarms.acknowledge(AlarmCategory::Fault);
    c_.plc.acknowledgeAlarms();
}

void Positioner::acknowledgeSystem() {
    c_.alarms.acknowledge(AlarmCategory::System);
    c_.plc.acknowledgeSystem();
}

void Positioner::escape() {
    wake();
    if (c_.c[c::EscResets] != 0)
        resetSystem();
    if (c_.c[c::EscAcknowledgesFaults] != 0)
        acknowledgeFaults();
    if (c_.c[c::EscAcknowledgesSystem] != 0)
        acknowledgeSystem();
}

void Positioner::interrupt(bool dropPath) {
    if (executing(c_.state) || c_.state == ProgramState::M0) {
        c_.resumeState = c_.state;
        c_.state = ProgramState::Interrupted;
        c_.stopHold = true;
    }
    if (!dropPath || !programActive(c_.state))
        return;
    // A mode change: the motion stops and the axes are free (an operator may
    // jog away in РУЧНОЙ); «Пуск» gives them back to the program.
    for (std::size_t i = 0; i < c_.axes.size(); ++i) {
        AxisUnit& u = c_.axes[i];
        if (u.owner == MotionOwner::Program) {
            if (u.servo.moving())
                u.servo.stop();
            u.resumeMove = !u.erased;
            u.owner = MotionOwner::None;
        } else if (u.owner == MotionOwner::HandwheelFrame) {
            u.resumeWheel = true;
            u.owner = MotionOwner::None;
        } else if (u.owner == MotionOwner::Oscillation) {
            c_.osc[i].pause(u.servo);
            u.owner = MotionOwner::None;
        }
    }
}

void Positioner::changeMode(Mode to) {
    if (to == c_.mode)
        return;
    // «Если в предыдущем режиме выполнялось перемещение, оно прекращается.»
    for (AxisUnit& u : c_.axes) {
        if (!u.present)
            continue;
        if (u.owner == MotionOwner::Jog || u.owner == MotionOwner::Handwheel) {
            u.servo.stop();
            u.owner = MotionOwner::None;
            u.jogDir = 0;
        } else if (u.owner == MotionOwner::Homing) {
            u.homing.cancel(u.servo);
            u.owner = MotionOwner::None;
        }
    }
    if (programActive(c_.state))
        interrupt(true);
    c_.mode = to;
}

void Positioner::startProgram(int number, int cycle) {
    if (c_.alarms.anyLatched())
        return; // «Пуск» is refused while a message is shown
    if (number < 1 || number > program::kMaxPrograms || !c_.store.contains(number)) {
        c_.raise(45);
        c_.state = ProgramState::Alarm;
        return;
    }
    for (const AxisUnit& u : c_.axes)
        if (u.present && !u.referenceOk()) {
            c_.raise(42);
            c_.state = ProgramState::Alarm;
            return;
        }
    if (cycle == 0) {
        // 43/44: the program is blocked, manual cycles are allowed.
        const std::int32_t d = c_.r[r::WheelCurrent], dmin = c_.r[r::WheelMin],
                           dmax = c_.r[r::WheelMax];
        if (dmax > 0 && d > dmax) {
            c_.raise(43);
            c_.state = ProgramState::Alarm;
            return;
        }
        if (dmin > 0 && d < dmin) {
            c_.raise(44);
            c_.state = ProgramState::Alarm;
            return;
        }
    }
    if (cycle == 0 && startPoint_ && startPoint_->mainProgram == number) {
        const StartPoint point = std::move(*startPoint_);
        startPoint_.reset();
        interp_.startAt(point, c_.mode);
        return;
    }
    interp_.start(number, cycle, c_.mode);
}

void Positioner::programControlAgain() {
    // What the program itself may have changed since the last tick is done
    // again: Z2000.10 ends with a new program, the PLC's remembered alarms
    // are acknowledged while Z1000.7 is 1, R150 follows Z1001.8.
    if (c_.endOrReset && c_.state != ProgramState::Ended && c_.state != ProgramState::Idle)
        c_.endOrReset = false;
    if (on(c_.words.word(1000), 7))
        c_.plc.acknowledgeAlarms();
    c_.r.set(r::PlcBit, on(c_.words.word(1001), 8) ? 1 : 0);
}

void Positioner::programControl() {
    // A full reading runs in РУЧНОЙ, with a handwheel pulse or after another
    // input changed; with the inputs of the last one and no operator
    // function since, no edge: nothing resets, acknowledges, stops or
    // starts, and the mode and the override stay what it made them.
    if (inputsAsRead()) {
        programControlAgain();
        if (checkShortcuts_) [[unlikely]]
            checkShortcut(&Positioner::programControlInFull);
        return;
    }
    programControlInFull();
}

void Positioner::programControlInFull() {
    const std::uint16_t w = c_.words.word(1000), before = c_.lastZ1000;
    const std::uint16_t w1 = c_.words.word(1001), before1 = c_.lastZ1001;
    const std::array<std::uint8_t, 2> fi = c_.io.fastInputs;
    operatorActed_ = false;
    c_.lastZ1000 = w;
    c_.lastZ1001 = w1;

    // «Сброс»: Z1000.5 0->1 or fast input function 1 (either module).
    bool fastReset = false;
    for (int a = 0; a < kAxisCount; ++a)
        fastReset = fastReset || c_.fast.active(a, FastFunction::Reset,
                                                fi[static_cast<std::size_t>(a)]);
    const bool resetEdge = rising(w, before, 5) || (fastReset && !c_.lastFastReset);
    c_.lastFastReset = fastReset;
    if (resetEdge)
        resetSystem();
    else if (c_.endOrReset && c_.state != ProgramState::Ended && c_.state != ProgramState::Idle)
        c_.endOrReset = false;
    // Acknowledgement of faults: positioner messages on the rising edge,
    // remembered PLC alarm bits for as long as the signal is 1.
    if (rising(w, before, 7))
        acknowledgeFaults();
    if (on(w, 7))
        c_.plc.acknowledgeAlarms();

    // Mode: the PLC's code, or the panel's choice.
    const unsigned code = (w >> z::ModeCodeFirst) & 7u;
    if (code != 0) {
        c_.modeFromPlc = true;
        changeMode(static_cast<Mode>(code));
    } else {
        if (c_.modeFromPlc)
            c_.panelMode = c_.mode; // the PLC lets go: the mode stays
        c_.modeFromPlc = false;
        changeMode(c_.panelMode);
    }

    // Override: the PLC's code (Z1001.11) or the last L key.
    const int ovCode = on(w1, 11) ? static_cast<int>((w1 >> 12) & 0xF) : c_.panelOverrideCode;
    c_.overridePercent = units::overrideCodeToPercent(ovCode);

    // «Стоп»: acts as feed hold plus data hold; «Пуск» continues.
    if (rising(w, before, 4) && (executing(c_.state) || c_.state == ProgramState::M0))
        interrupt(false);
    // «Пуск» (with «Деблокировка пуска»).
    if (rising(w, before, 3) && on(w, 2)) {
        const bool held = c_.state == ProgramState::Interrupted || c_.state == ProgramState::M0;
        if (c_.mode == Mode::Auto || c_.mode == Mode::Manual) {
            if (held && c_.programMode == c_.mode)
                interp_.resume();
            else if (c_.mode == Mode::Auto && !programActive(c_.state))
                startProgram(c_.r[r::SelectedProgram], 0);
        }
    }
    // Manual cycles: Z1001.0..7 0->1. Cycle 1 («ВЫХОД В ИСХОДНОЕ») interrupts
    // a running program; cycles 2..8 start in РУЧНОЙ when no program is active.
    for (int n = 1; n <= 8 && (w1 & ~before1 & 0xFFu) != 0; ++n) { // no rising edge: none starts
        if (!rising(w1, before1, n - 1))
            continue;
        const int number = static_cast<int>(c_.c[c::manualCycle(n)]);
        if (number == 0)
            continue; // «Цикл не задан»
        if (n == 1 && (c_.mode == Mode::Auto || c_.mode == Mode::Manual)) {
            if (programActive(c_.state))
                c_.abortProgram(ProgramState::Idle);
            startProgram(number, 1);
        } else if (n > 1 && c_.mode == Mode::Manual && !programActive(c_.state)) {
            startProgram(number, n);
        }
    }
    c_.r.set(r::PlcBit, on(w1, 8) ? 1 : 0);
}

// ---------------------------------------------------------------------------
// Manual functions: jog, handwheels, DRF, reference-point start, adjustments

void Positioner::jog(AxisUnit& u) {
    const std::uint16_t w0 = c_.words.axisControl(u.index, 0);
    const int dir = on(w0, 7) == on(w0, 8) ? 0 : (on(w0, 7) ? 1 : -1);
    const bool rapid = on(w0, 9);
    if (dir != 0)
        u.commandDir = dir;
    if (u.owner == MotionOwner::Handwheel && dir != 0)
        u.owner = MotionOwner::None; // the buttons have priority over the handwheel
    if (u.owner != MotionOwner::None && u.owner != MotionOwner::Jog)
        return;
    if (dir == 0 || u.directionLocked(dir)) {
        if (u.owner == MotionOwner::Jog) {
            if (u.jogDir != 0) {
                u.servo.jog(0, 0);
                u.jogDir = 0;
            }
            if (!u.servo.moving())
                u.owner = MotionOwner::None;
        }
        if (dir == 0)
            u.softLimitStop = false;
        return;
    }
    const int a = u.index;
    if (u.owner == MotionOwner::Jog && u.jogDir == dir && u.jogRapid == rapid) {
        // Reached the soft limit: stopped there, the message tells why.
        if (u.softLimitsActive() && !u.servo.jogging() && !u.servo.moving() && !u.softLimitStop) {
            u.softLimitStop = true;
            c_.raise(axisMsg(12, 28, a));
        }
        return;
    }
    const double speed = u.k.speedParamToInternalPerMs(rapid ? u.k.feedRapid : u.k.feedNormal);
    double limit = 0;
    const double* lim = nullptr;
    if (u.softLimitsActive()) {
        limit = dir > 0 ? u.softMax : u.softMin;
        lim = &limit;
        const double pos = u.servo.target();
        if ((dir > 0 && pos >= limit) || (dir < 0 && pos <= limit)) {
            if (!u.softLimitStop) {
                u.softLimitStop = true;
                c_.raise(axisMsg(12, 28, a));
            }
            return;
        }
    }
    if (u.servo.jog(dir, speed, lim)) {
        u.owner = MotionOwner::Jog;
        u.jogDir = dir;
        u.jogRapid = rapid;
        u.rapid = rapid;
        u.softLimitStop = false;
    }
}

void Positioner::handwheels(AxisUnit& u) {
    const std::uint16_t w0 = c_.words.axisControl(u.index, 0);
    double delta = 0, drf = 0;
    for (int k = 0; k < 2; ++k) {
        const std::int64_t pulses = wheelDelta_[static_cast<std::size_t>(k)];
        if (pulses == 0 || !on(w0, 10 + k))
            continue;
        const bool invert = k == 0 ? u.k.handwheel1Invert : u.k.handwheel2Invert;
        const std::int64_t mult =
            on(w0, 12 + k) ? (k == 0 ? u.k.handwheel1Mult : u.k.handwheel2Mult) : 1;
        // Discretes of motion per pulse: 2 internal units each.
        const double d = static_cast<double>((invert ? -pulses : pulses) * mult * 2);
        delta += d;
        if (on(w0, 14 + k))
            drf += d;
    }
    if (delta == 0)
        return;
    const bool manual = c_.mode == Mode::Manual;
    const double wheelSpeed = u.k.speedParamToInternalPerMs(u.k.feedRapid);
    const double from = u.servo.target();
    double to = from + delta;
    if (u.owner == MotionOwner::HandwheelFrame) {
        // Gx10: the handwheel drives the axis towards the programmed point, never past it.
        to = std::clamp(to, u.wheelMin, u.wheelMax);
        drf = 0;
    } else if (!manual && drf == 0) {
        return; // in АВТОМАТ only the DRF function moves an axis by handwheel
    } else if (u.owner == MotionOwner::Program) {
        // DRF during a program move: the target moves, the feed stays.
        if (drf == 0)
            return;
        delta = drf;
        to = from + delta;
    } else if (u.owner != MotionOwner::None && u.owner != MotionOwner::Handwheel) {
        return; // keys have priority over the handwheel; a cycle owns the axis
    } else if (!manual) {
        delta = drf;
        to = from + delta;
    }
    if (u.softLimitsActive())
        to = std::clamp(to, std::min(u.softMin, from), std::max(u.softMax, from));
    const int dir = to > from ? 1 : (to < from ? -1 : 0);
    if (dir == 0 || u.directionLocked(dir))
        return;
    const double speed = u.owner == MotionOwner::Program ? u.moveSpeed : wheelSpeed;
    if (!u.servo.nudge(to - from, speed))
        return;
    u.commandDir = dir;
    if (u.owner == MotionOwner::None)
        u.owner = manual ? MotionOwner::Handwheel : MotionOwner::None;
    if (u.owner == MotionOwner::Program)
        u.moveTarget = to;
    if (drf != 0) {
        // DRF: the motion goes into the handwheel offset R230/R231; the
        // current coordinate stays.
        const std::int64_t disc = std::llround((to - from) / static_cast<double>(u.ipd));
        if (!c_.r.add(r::DrfX + u.index, disc))
            c_.raise(46);
        u.programmedDisc += disc;
    }
}

void Positioner::homingStart(AxisUnit& u) {
    const std::uint16_t w0 = c_.words.axisControl(u.index, 0);
    const std::uint16_t before = c_.lastAxisWord0[static_cast<std::size_t>(u.index)];
    const int bit = u.k.homeNegative ? 8 : 7; // «ПЕРЕМЕЩЕНИЕ В +» (or «В -» with ПБТ В "-")
    if (!rising(w0, before, bit) || u.owner != MotionOwner::None || u.k.autoWithoutHoming)
        return; // АВТ.БЕЗ ПБТ = 1: the reference point is blocked
    u.referenced = false;
    u.homeDistanceDisc = 0;
    if (u.homing.start(u.servo, u.cam))
        u.owner = MotionOwner::Homing;
}

void Positioner::manualFunctions() {
    const Mode mode = c_.mode; // none of the functions below changes it
    const bool wheels =
        (wheelDelta_[0] | wheelDelta_[1]) != 0 && (mode == Mode::Manual || mode == Mode::Auto);
    for (AxisUnit& u : c_.axes) {
        if (!u.present)
            continue;
        const std::size_t i = static_cast<std::size_t>(u.index);
        u.commandDir = 0;
        if (mode == Mode::Manual)
            jog(u);
        else if (mode == Mode::Reference)
            homingStart(u);
        if (wheels)
            handwheels(u);
        const std::uint16_t w1 = c_.words.axisControl(u.index, 1);
        const std::uint16_t w2 = c_.words.axisControl(u.index, 2);
        if (w1 == c_.lastAxisWord1[i] && w2 == c_.lastAxisWord2[i])
            continue;
        // Подналадка (C13 ВКЛ.ПОДНАЛ.): ±R218/R219 into the correction.
        if (u.k.adjustEnabled) {
            const int sign = rising(w1, c_.lastAxisWord1[i], 1)
                                 ? 1
                                 : (rising(w1, c_.lastAxisWord1[i], 2) ? -1 : 0);
            if (sign != 0 &&
                !c_.r.add(r::CorrectionX + u.index,
                          sign * static_cast<std::int64_t>(c_.r[r::AdjustX + u.index])))
                c_.raise(46);
        }
        // Компенсация правки: the dressing amount into the dressing sum.
        for (int k = 0; k < 2; ++k) {
            if (!rising(w2, c_.lastAxisWord2[i], k))
                continue;
            const int amount = u.index == 0 ? (k == 0 ? r::DressRoughX : r::DressFinishX)
                                            : (k == 0 ? r::DressRoughZ : r::DressFinishZ);
            if (!c_.r.add(r::DressingSumX + u.index, c_.r[amount]))
                c_.raise(46);
        }
        c_.lastAxisWord1[i] = w1;
        c_.lastAxisWord2[i] = w2;
    }
}

// ---------------------------------------------------------------------------
// The axes

void Positioner::axisTick(AxisUnit& u) {
    const int a = u.index;
    const std::size_t i = static_cast<std::size_t>(a);
    const std::uint16_t w0 = c_.words.axisControl(u.index, 0);
    c_.lastAxisWord0[i] = w0;

    // Limit switches: brake with acceleration 2, the direction locked (with
    // neither switch nor its message, nothing to do).
    constexpr std::array<std::uint64_t, kAxisCount> kLimitMessages{
        AlarmRegistry::messageBit(11) | AlarmRegistry::messageBit(10),
        AlarmRegistry::messageBit(27) | AlarmRegistry::messageBit(26)};
    if (u.limitPlus || u.limitMinus || (c_.alarms.activeMask() & kLimitMessages[i]) != 0) {
        c_.condition(axisMsg(11, 27, a), u.limitPlus);
        c_.condition(axisMsg(10, 26, a), u.limitMinus);
        const double v = u.servo.commandVelocity();
        if ((u.limitPlus && v > 0) || (u.limitMinus && v < 0)) {
            u.servo.stop(true);
            if (c_.osc[i].active())
                c_.osc[i].abort(u.servo);
            if (u.homing.running())
                u.homing.cancel(u.servo);
        }
    }

    // Feed override; «Стоп» holds the feed of program motion.
    const bool programOwned = programMotion(u.owner);
    const bool hold = c_.stopHold && programOwned;
    if (c_.overridePercent != overrideFactorPercent_) {
        overrideFactorPercent_ = c_.overridePercent;
        overrideFactor_ = c_.overridePercent / 100.0;
    }
    u.overrideFactor = programOwned && u.noOverride ? 1.0 : overrideFactor_;
    u.servo.setOverride(u.overrideFactor);

    // The servo's inputs: the encoder of this tick; the rest as decoded from
    // the words (axisInputs(), every tick they may have changed).
    axis::ServoInputs& in = u.servoIn;
    if (u.encoderChannel >= 0) {
        const PulseChannel& p = c_.io.pulse[static_cast<std::size_t>(u.encoderChannel)];
        in.encoderCount = p.count;
        in.channel1Ok = p.line1Ok;
        in.channel2Ok = p.line2Ok;
        in.zeroMark = p.zeroMark;
        in.zeroMarkCount = p.zeroMarkCount;
    }
    in.feedEnable = u.feedEnableWords && !hold;
    if (!c_.instantAxes) // preview: the interpreter places the axes (engine/preview.h)
        u.servo.tick(in, c_.dtMs);
    if (u.servo.fault() != lastFault_[i])
        trackFault(u);
    Oscillation& osc = c_.osc[i];
    if ((u.owner == MotionOwner::Program || u.owner == MotionOwner::None) && !u.homing.running() &&
        !osc.active())
        return; // no cycle runs and no manual motion to end: nothing below acts

    // Reference-point cycle.
    if (u.homing.running() || u.owner == MotionOwner::Homing) {
        u.homing.tick(u.servo, u.cam);
        u.homeDistanceDisc = u.homing.distanceDisc();
        if (!u.homing.running() && u.owner == MotionOwner::Homing) {
            u.owner = MotionOwner::None;
            if (u.homing.done())
                u.referenced = true;
            else if (u.homing.alarm() != 0)
                c_.raise(u.homing.alarm());
        }
    }

    // Oscillation.
    if (osc.active()) {
        osc.tick(u.servo, c_.dtMs);
        if (!osc.active() && u.owner == MotionOwner::Oscillation)
            u.owner = MotionOwner::None;
    } else if (u.owner == MotionOwner::Oscillation) {
        u.owner = MotionOwner::None;
    }
    if ((u.owner == MotionOwner::Jog || u.owner == MotionOwner::Handwheel) && !u.servo.moving() &&
        u.jogDir == 0)
        u.owner = MotionOwner::None;
}

// ---------------------------------------------------------------------------
// Outputs

namespace {

// Z2000 bits of a program state (.8 program executing, .9 interrupted, .11
// dwell, .12 M00), one entry per ProgramState.
constexpr std::array<std::uint16_t, 8> kStateBitsZ2000 = [] {
    std::array<std::uint16_t, 8> t{};
    for (int i = 0; i < 8; ++i) {
        const auto st = static_cast<ProgramState>(i);
        t[static_cast<std::size_t>(i)] = static_cast<std::uint16_t>(
            (executing(st) ? 1u << 8 : 0u) | (st == ProgramState::Interrupted ? 1u << 9 : 0u) |
            (st == ProgramState::Dwell ? 1u << 11 : 0u) | (st == ProgramState::M0 ? 1u << 12 : 0u));
    }
    return t;
}();
static_assert(static_cast<int>(ProgramState::Alarm) == 7, "kStateBitsZ2000 covers every state");

// Z2005/Z2007 bits of who owns an axis' motion: .9 «Gx10 active» and
// whether the rapid bit .5 counts (a frame's or a jog's rapid motion).
constexpr std::uint16_t kOwnerHandwheelFrame = 1u << 9;
constexpr std::uint16_t kOwnerRapidCounts = 1u << 5;
constexpr std::array<std::uint16_t, 7> kOwnerBits = [] {
    std::array<std::uint16_t, 7> t{};
    for (int i = 0; i < 7; ++i) {
        const auto o = static_cast<MotionOwner>(i);
        t[static_cast<std::size_t>(i)] = static_cast<std::uint16_t>(
            (o == MotionOwner::HandwheelFrame ? kOwnerHandwheelFrame : 0u) |
            (o == MotionOwner::Program || o == MotionOwner::Jog ? kOwnerRapidCounts : 0u));
    }
    return t;
}();
static_assert(static_cast<int>(MotionOwner::Homing) == 6, "kOwnerBits covers every owner");

constexpr unsigned bitIf(bool v, int bit) {
    return static_cast<unsigned>(v) << bit;
}

} // namespace

void Positioner::writeOutputs(bool routine) {
    InterfaceWords& w = c_.words;

    // Z2000, the wheel's bits of Z2005 and the offsets of the current
    // coordinates. In a routine tick (no operator function, the same inputs:
    // mode, override and power stay) they change only with what a program,
    // its end or a message changes: computed again when one of those did.
    const CommonOutputs::Key key{c_.framesExecuted, c_.alarms.activeMask(), c_.state,
                                 c_.endOrReset, c_.programExclusion};
    const auto fresh = [&] {
        const std::int32_t wheel = c_.r[r::WheelCurrent], wmin = c_.r[r::WheelMin],
                           wmax = c_.r[r::WheelMax];
        const bool wheelBelowMin = wmin > 0 && wheel < wmin;
        const bool wheelAboveMax = wmax > 0 && wheel > wmax;
        const auto z2000 = static_cast<std::uint16_t>(
            bitIf(c_.powered && !c_.alarms.anyActive(AlarmCategory::System), 0) |
            bitIf(c_.powered, modeKey(c_.mode)) | kStateBitsZ2000[static_cast<std::size_t>(c_.state)] |
            bitIf(c_.endOrReset, 10) | bitIf(c_.overridePercent == 0, 14) | bitIf(wheelBelowMin, 15));
        const unsigned wheelBits = bitIf(wheelBelowMin, 11) | bitIf(wheelAboveMax, 12); // X only
        return std::pair{z2000, wheelBits};
    };
    if (!routine || !common_.valid || !(key == common_.key)) {
        std::tie(common_.z2000, common_.wheelBits) = fresh();
        refreshOffsets();
        common_.key = key;
        common_.valid = true;
    }
    else if (checkShortcuts_) [[unlikely]] {
        // Both paths: what the routine tick kept is what they compute.
        const bool agree = fresh() == std::pair(common_.z2000, common_.wheelBits) &&
                           offsets_.sum[0] == c_.offsetDisc(0) && offsets_.sum[1] == c_.offsetDisc(1);
        ++shortcutChecks_;
        shortcutDisagreements_ += agree ? 0 : 1;
        assert(agree && "the routine tick's kept outputs and the full computation disagree");
    }
    w.setWord(2000, common_.z2000);
    // Z2001.8..15: manual cycle n runs.
    std::uint16_t w2001 = static_cast<std::uint16_t>(w.word(2001) & 0x00FF);
    if (c_.cycle >= 1 && c_.cycle <= 8 && programActive(c_.state))
        w2001 = static_cast<std::uint16_t>(w2001 | (1u << (7 + c_.cycle)));
    w.setWord(2001, w2001);

    // The machine side (DAC, regulator enable), Z2005..Z2008 and R232..R262.
    c_.io.dac.fill(0);
    for (const AxisUnit& u : c_.axes) {
        const std::size_t i = static_cast<std::size_t>(u.index);
        c_.io.regulatorEnable[i] = u.present && u.servo.regulatorOn();
        const int ch = channelIndex(u.k.dacChannel);
        if (u.present && ch >= 0)
            c_.io.dac[static_cast<std::size_t>(ch)] = u.servo.dac();
        if (u.present)
            axisOutputs(u, u.index == 0 ? common_.wheelBits : 0u);
        else
            absentAxisOutputs(u.index);
        w.setAxisState(u.index, 1, c_.io.fastInputs[i]);
    }
    c_.r.set(r::Override, c_.overridePercent);
    c_.r.set(r::NestingLevel, interp_.level());
}

void Positioner::absentAxisOutputs(int a) {
    axisR(c_.axes[static_cast<std::size_t>(a)], 0);
    c_.words.setAxisState(a, 0, 0);
}

void Positioner::axisR(const AxisUnit& u, std::int64_t machine) {
    RStore& r = c_.r;
    const int a = u.index;
    const std::size_t i = static_cast<std::size_t>(a);
    if (!u.present) {
        for (int n : {r::MachineX, r::CurrentX, r::SpeedX, r::ErrorX, r::DacX, r::RemainingX,
                      r::HomeDistanceX, r::PulsesX})
            r.set(n + a, 0);
        return;
    }
    const axis::Servo& sv = u.servo;
    r.set(r::CurrentX + a, clampR(machine - offsets_.sum[i]));
    r.set(r::HomeDistanceX + a, clampR(u.homeDistanceDisc));
    // What comes of the servo alone stays while its ticks are quiet (at rest,
    // nothing asked): written when it may have changed.
    if (servoRKnown_[i] && sv.quiet())
        return;
    servoRKnown_[i] = true;
    const double perDisc = u.perIpd; // 1 / internal units per discrete (exact)
    r.set(r::MachineX + a, clampR(machine));
    r.set(r::SpeedX + a, clampR(roundToInt(std::fabs(sv.commandVelocity()) * 60000.0 * perDisc)));
    r.set(r::ErrorX + a, clampR(roundToInt(sv.followingError() * perDisc)));
    r.set(r::DacX + a, sv.dac());
    r.set(r::RemainingX + a, clampR(roundToInt(sv.remaining() * perDisc)));
    r.set(r::PulsesX + a, clampR(sv.pulsesLastTick()));
}

void Positioner::axisOutputs(const AxisUnit& u, unsigned wheelBits) {
    const RStore& r = c_.r;
    const int a = u.index;
    const axis::Servo& sv = u.servo;
    const double actual = sv.actual();
    const std::int64_t machine = u.toDisc(actual);
    axisR(u, machine);

    // Z2005 / Z2007.
    const bool moving = sv.moving();
    const unsigned owner = kOwnerBits[static_cast<std::size_t>(u.owner)];
    // «В исходном положении»: referenced, at rest, within ДОПУСК ПОЗ. of R220/R221
    // (the distance truncated to whole internal units, as it always was).
    const bool atInitial =
        u.referenced && !moving &&
        std::llabs(static_cast<long long>(u.toInternal(r[r::InitialX + a]) - actual)) <=
            static_cast<double>(u.k.posToleranceInternal);
    const std::int32_t zlo = r[r::SafetyZoneXMinus + 2 * a];
    const std::int32_t zhi = r[r::SafetyZoneXMinus + 2 * a + 1];
    const unsigned st =
        bitIf(sv.fault() != axis::Fault::None, 0) | bitIf(u.commandDir > 0, 1) |
        bitIf(u.commandDir < 0, 2) | bitIf(moving || !sv.inPosition(), 3) |
        bitIf(u.referenceOk(), 4) | ((u.rapid && moving) ? owner & kOwnerRapidCounts : 0u) |
        bitIf(sv.loopClosed(), 6) | bitIf(sv.regulatorOn(), 7) | bitIf(atInitial, 8) |
        (owner & kOwnerHandwheelFrame) | bitIf(zlo < zhi && machine >= zlo && machine <= zhi, 10) |
        wheelBits;
    c_.words.setAxisState(a, 0, static_cast<std::uint16_t>(st));
}

void Positioner::refreshOffsets() {
    // R224..R231: the dressing sums, corrections, zero offsets and DRF of
    // both axes (coordinates.h), compared as one block.
    std::array<std::int32_t, 8> now;
    std::copy_n(c_.r.values().begin() + r::DressingSumX, now.size(), now.begin());
    const std::array<std::uint8_t, kAxisCount> ex{c_.exclusion(0), c_.exclusion(1)};
    if (offsets_.valid && util::sameBytes<sizeof now>(now.data(), offsets_.r.data()) &&
        ex == offsets_.ex)
        return;
    offsets_.valid = true;
    offsets_.r = now;
    offsets_.ex = ex;
    for (int a = 0; a < kAxisCount; ++a)
        offsets_.sum[static_cast<std::size_t>(a)] = c_.offsetDisc(a);
}

void Positioner::refreshR() {
    servoRKnown_.fill(false);
    refreshOffsets();
    for (const AxisUnit& u : c_.axes)
        axisR(u, u.present ? u.machineDisc() : 0);
    c_.r.set(r::Override, c_.overridePercent);
    c_.r.set(r::NestingLevel, interp_.level());
}

// ---------------------------------------------------------------------------
// Operator functions

OpResult Positioner::selectMode(Mode m) {
    wake();
    if (!validModeKey(modeKey(m)))
        return OpResult::refused(Refusal::NoSuchKey, "mode-key", {num(modeKey(m))});
    if (c_.modeFromPlc)
        return OpResult::refused(Refusal::ModeFromPlc, "mode-from-plc", {num(modeKey(c_.mode))});
    c_.panelMode = m;
    if (c_.powered)
        changeMode(m);
    return OpResult::accepted();
}

OpResult Positioner::pressOverrideKey(int l) {
    wake();
    if (l < 1 || l > 4)
        return OpResult::refused(Refusal::NoSuchKey, "override-key", {num(l)});
    const std::int64_t code = c_.c[c::overrideKey(l)];
    c_.panelOverrideCode = static_cast<int>(std::clamp<std::int64_t>(code, 0, 10));
    if (!(c_.words.word(1001) & (1u << 11)))
        c_.overridePercent = units::overrideCodeToPercent(c_.panelOverrideCode);
    c_.r.set(r::Override, c_.overridePercent);
    return OpResult::accepted();
}

OpResult Positioner::selectProgram(int number) {
    wake();
    if (number < 1 || number > program::kMaxPrograms)
        return OpResult::refused(Refusal::NoSuchProgram, "program-number", {num(number)});
    c_.r.set(r::SelectedProgram, number);
    return OpResult::accepted();
}

OpResult Positioner::setR(int number, std::int64_t value) {
    wake();
    if (!rValid(number))
        return OpResult::refused(Refusal::NoSuchParameter, "r-number", {num(number)});
    if (rReadOnly(number))
        return OpResult::refused(Refusal::ReadOnly, "r-read-only", {num(number)});
    if (!fitsR(value))
        return OpResult::refused(Refusal::ValueOutOfRange, "r-range", {num(value)});
    if (executing(c_.state))
        return OpResult::refused(Refusal::ProgramActive, "program-executing");
    c_.r.set(number, static_cast<std::int32_t>(value));
    // R256/R257: the panel's write, as the K923 hands it to the positioner.
    c_.r.set(r::PanelValue, static_cast<std::int32_t>(value));
    c_.r.set(r::PanelAddress, static_cast<std::int32_t>((1 << 16) | number));
    return OpResult::accepted();
}

OpResult Positioner::setC(int number, std::int64_t value) {
    wake();
    if (number < 1 || number > kCCount)
        return OpResult::refused(Refusal::NoSuchParameter, "c-number", {num(number)});
    if (c_.mode != Mode::MachineData)
        return OpResult::refused(Refusal::WrongMode, "c-mode");
    if (programActive(c_.state))
        return OpResult::refused(Refusal::ProgramActive, "program-active");
    if (const profile::Problem e = profile::cValueProblem(number, value); !e.empty())
        return OpResult::refused(Refusal::ValueOutOfRange, "c-range", e.args);
    c_.c[static_cast<std::size_t>(number)] = value;
    c_.profile.setC(number, value);
    c_.applyConstants();
    configurationCheck();
    return OpResult::accepted();
}

OpResult Positioner::setCurrentValue(AxisId axis, std::int64_t valueDisc) {
    wake();
    AxisUnit& u = c_.axes[static_cast<std::size_t>(axisIndex(axis))];
    if (!u.present)
        return OpResult::refused(Refusal::AxisAbsent, "axis-absent", {std::string(axis::axisName(axis))});
    if (c_.mode != Mode::SetActual)
        return OpResult::refused(Refusal::WrongMode, "set-actual-mode");
    if (programActive(c_.state))
        return OpResult::refused(Refusal::ProgramActive, "program-active");
    const std::int64_t zo =
        zeroOffsetFor(u.machineDisc(), valueDisc, c_.r, u.index, c_.exclusion(u.index));
    if (!fitsR(zo) || !fitsR(valueDisc))
        return OpResult::refused(Refusal::ValueOutOfRange, "zero-offset-range");
    c_.r.set(r::ZeroOffsetX + u.index, static_cast<std::int32_t>(zo));
    refreshR();
    return OpResult::accepted();
}

void Positioner::placeAtReferencePoint() {
    wake();
    if (programActive(c_.state))
        return;
    for (AxisUnit& u : c_.axes) {
        if (!u.present)
            continue;
        const double v = u.toInternal(u.k.homeValueDisc);
        u.servo.setActualValue(v);
        u.servo.place(v);
        u.referenced = true;
    }
    refreshR();
}

program::ProgramStore* Positioner::editablePrograms() {
    wake();
    return programActive(c_.state) ? nullptr : &c_.store;
}

OpResult Positioner::programsEdited() {
    wake();
    if (programActive(c_.state))
        return OpResult::refused(Refusal::ProgramActive, "program-active");
    for (program::Program& p : c_.store.programs())
        p.reindex();
    storeCorrupt_ = false;
    ++programsRevision_;
    programStoreCheck();
    return OpResult::accepted();
}

OpResult Positioner::loadCParameters(std::span<const std::int64_t> c) {
    wake();
    if (c_.mode != Mode::DataControl)
        return OpResult::refused(Refusal::WrongMode, "c-load-mode");
    if (programActive(c_.state))
        return OpResult::refused(Refusal::ProgramActive, "program-active");
    if (c.size() != static_cast<std::size_t>(kCCount) + 1)
        return OpResult::refused(Refusal::NoSuchParameter, "c-count");
    for (int n = 1; n <= kCCount; ++n)
        if (const profile::Problem e = profile::cValueProblem(n, c[static_cast<std::size_t>(n)]); !e.empty())
            return OpResult::refused(Refusal::ValueOutOfRange, "c-range", e.args);
    for (int n = 1; n <= kCCount; ++n) {
        c_.c[static_cast<std::size_t>(n)] = c[static_cast<std::size_t>(n)];
        c_.profile.setC(n, c[static_cast<std::size_t>(n)]);
    }
    c_.applyConstants();
    configurationCheck();
    return OpResult::accepted();
}

OpResult Positioner::clearCParameters() {
    wake();
    if (std::optional<OpResult> refused = memoryClearRefused(c_.mode, c_.state))
        return *refused;
    c_.c.fill(0);
    c_.profile.c.fill(0);
    c_.applyConstants();
    configurationCheck();
    return OpResult::accepted();
}

OpResult Positioner::clearRParameters() {
    wake();
    if (std::optional<OpResult> refused = memoryClearRefused(c_.mode, c_.state))
        return *refused;
    c_.r.clear();
    refreshR();
    return OpResult::accepted();
}

OpResult Positioner::clearPrograms() {
    wake();
    if (std::optional<OpResult> refused = memoryClearRefused(c_.mode, c_.state))
        return *refused;
    c_.store = program::ProgramStore{};
    storeCorrupt_ = false;
    ++programsRevision_;
    programStoreCheck();
    return OpResult::accepted();
}

// ---------------------------------------------------------------------------
// Views

AxisView Positioner::axisView(AxisId axis) const {
    const AxisUnit& u = c_.axes[static_cast<std::size_t>(axisIndex(axis))];
    AxisView v;
    v.axis = axis;
    v.present = u.present;
    v.scale = u.k.scale;
    if (!u.present)
        return v;
    const axis::Servo& sv = u.servo;
    const double ipd = static_cast<double>(u.ipd);
    v.referenced = u.referenced;
    v.referenceOk = u.referenceOk();
    v.homing = u.homing.running();
    v.machineDisc = u.machineDisc();
    v.currentDisc = c_.currentDisc(u.index);
    v.remainingDisc = std::llround(sv.remaining() / ipd);
    v.feedDiscPerMin = std::llround(std::fabs(sv.commandVelocity()) * 60000.0 / ipd);
    v.moving = sv.commandVelocity() != 0.0; // '*': the setpoint moves (not during a feed hold)
    v.dac = sv.dac();
    v.errorInternal = sv.followingError();
    v.absInternal = sv.actual();
    v.pulsesPerTick = sv.pulsesLastTick();
    v.homeDistanceDisc = u.homeDistanceDisc;
    v.limitPlus = u.limitPlus;
    v.limitMinus = u.limitMinus;
    v.decelCam = u.cam;
    v.atSoftLimit = u.softLimitsActive() && (sv.actual() <= u.softMin || sv.actual() >= u.softMax);
    v.loopClosed = sv.loopClosed();
    v.regulatorOn = sv.regulatorOn();
    v.inPosition = sv.inPosition();
    v.oscillating = c_.osc[static_cast<std::size_t>(u.index)].active();
    v.fault = axis::faultMessage(sv.fault(), u.id);
    return v;
}

ProgramView Positioner::programView() const {
    ProgramView v;
    v.mode = c_.mode;
    v.modeFromPlc = c_.modeFromPlc;
    v.state = c_.state;
    v.selectedProgram = c_.r[r::SelectedProgram];
    v.mainProgram = c_.r[r::CurrentProgram];
    v.program = interp_.program();
    v.cycle = programActive(c_.state) ? c_.cycle : 0;
    v.frameIndex = interp_.frameIndex();
    v.frameNumber = interp_.frameNumber();
    v.line = interp_.line();
    v.nesting = interp_.level();
    v.messageNumber = c_.messageNumber;
    if (c_.messageNumber > 0) {
        const program::Message* m = c_.store.messages.find(c_.messageNumber);
        v.messageOrigin = !m ? MessageOrigin::None : m->machineFile ? MessageOrigin::MachineFile : MessageOrigin::Program;
        if (m)
            v.messageText = m->text;
    }
    v.overridePercent = c_.overridePercent;
    v.overrideFromPlc = c_.words.bit(z::OverrideFromPlc);
    v.endOrReset = c_.endOrReset;
    v.mCode = c_.mhs.currentCode();
    v.framesExecuted = c_.framesExecuted;
    v.dataHold = c_.words.bit(z::DataHold);
    return v;
}

std::string programMessageText(const ProgramView& v, const profile::MachineProfile& machine, bool english) {
    if (english && v.messageOrigin == MessageOrigin::MachineFile)
        return profile::messageText(machine, v.messageNumber, true);
    return v.messageText;
}

std::vector<AlarmView> Positioner::alarms() const {
    std::vector<AlarmView> list;
    for (const int n : c_.alarms.latchedList()) {
        const AlarmEntry& e = c_.alarms.entry(n);
        AlarmView a;
        a.number = n;
        a.axis = alarmAxis(n);
        a.program = e.program;
        a.line = e.line;
        a.active = e.active;
        a.latched = e.latched;
        a.category = alarmCategory(n);
        if (const catalog::PositionerMessage* m = catalog::findPositionerMessage(n)) {
            a.textRu = std::string(m->textRu);
            a.textEn = std::string(m->textEn);
        }
        list.push_back(std::move(a));
    }
    return list;
}

PlcMessagesView Positioner::plcMessages() const {
    PlcMessagesView v;
    v.alarms = c_.plc.alarms();
    v.alarmsPresent = c_.plc.alarmsPresent();
    v.work = c_.plc.work();
    v.system = c_.plc.system();
    v.systemPresent = c_.plc.systemPresent();
    return v;
}

} // namespace k528::engine
