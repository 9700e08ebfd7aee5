// The K528-05 positioner (БП): the public facade of core/engine.
//
// One Positioner is built from a machine profile. Time advances only when
// the caller ticks it (tick() = one tick of `tick_ms`, 1 ms by default); the
// same inputs give the same outputs, bit for bit. Its doors:
//   - the PLC interface words of appendix И (words()): the PLC side writes
//     Z1000..Z1013, Z1300..Z1307, Z1900..Z1907 before a tick, the engine
//     writes Z2000..Z2008 during it;
//   - the machine-side I/O (io()): encoder and handwheel pulse channels, fast
//     inputs, module health in; DAC codes and regulator enable out;
//   - the operator functions of the K923 panel (selectMode, L keys, program
//     number, R and C parameters, current value, programs, ESC);
//   - read-only views for displays.
// The order of one tick is fixed (docs/engine.md): inputs and edges, PLC
// messages, system checks, emergency stop, reset and acknowledgement, mode,
// program control, manual functions, the axes (limits, servo, reference
// cycle, oscillation), the interpreter, outputs (Z2000..Z2008, DAC, R232..R262).
#pragma once

#include "engine/core.h"
#include "engine/interpreter.h"
#include "engine/start_point.h"
#include "engine/views.h"
#include "util/same_bytes.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace k528::engine {

class Positioner {
public:
    explicit Positioner(const profile::MachineProfile& profile);

    // --- power and time -----------------------------------------------
    // Power-on (2.6.1): the self-test (machine constants: 15, 13/29, 37..39;
    // program store: 31), start in РУЧНОЙ. tick() powers on if needed.
    void powerOn();
    bool poweredOn() const { return c_.powered; }
    void tick();
    // Advances by `ms`, in whole ticks (rounded up).
    void advance(std::int64_t ms);
    std::int64_t timeMs() const { return c_.nowMs; }
    std::int64_t tickMs() const { return c_.tickMs; }

    // --- the doors --------------------------------------------------------
    InterfaceWords& words() { return c_.words; }
    const InterfaceWords& words() const { return c_.words; }
    MachineIo& io() { return c_.io; }
    const MachineIo& io() const { return c_.io; }

    // --- operator functions (K923) ----------------------------------------
    // F1..F7; refused while the PLC imposes a mode (Z1000.8-10 != 0).
    OpResult selectMode(Mode m);
    // L1..L4: the override code of C139..C142.
    OpResult pressOverrideKey(int l);
    // The program of АВТОМАТ (R252), 1..99 (a missing one gives 45 at «Пуск»).
    OpResult selectProgram(int number);
    // R-parameter from the panel: read-only ones refused; not while a program executes.
    OpResult setR(int number, std::int64_t value);
    // C-parameter (РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ only), checked against its
    // definition; the servo constants follow, the cross-checks give
    // messages 13/29, 37, 38, 39, 15.
    OpResult setC(int number, std::int64_t value);
    // «Установка фактического значения» (ПРЕДУСТАНОВКИ): the current
    // coordinate of the axis becomes `valueDisc`; the zero offset (R228/R229)
    // is recomputed.
    OpResult setCurrentValue(AxisId axis, std::int64_t valueDisc);
    // ESC: reset (C123), acknowledge machine faults (C124), system messages (C125).
    void escape();
    // Program store: editable only while no program is active (else nullptr);
    // call programsEdited() after a change.
    program::ProgramStore* editablePrograms();
    const program::ProgramStore& programs() const { return c_.store; }
    OpResult programsEdited();
    // Counts the changes of the program store (programsEdited, clearPrograms):
    // a view redraws the programs when it changed.
    std::uint64_t programsRevision() const { return programsRevision_; }
    // УПРАВЛЕНИЕ ДАННЫМИ: clear the C-parameters / R-parameters / programs.
    OpResult clearCParameters();
    // УПРАВЛЕНИЕ ДАННЫМИ, «ввести в K528-05 С-параметры» (the PC link): all
    // 152 values at once (index = number, element 0 unused), each checked
    // against its definition; one bad value refuses all and changes nothing.
    OpResult loadCParameters(std::span<const std::int64_t> c);
    OpResult clearRParameters();
    OpResult clearPrograms();

    // --- views ------------------------------------------------------------
    AxisView axisView(AxisId axis) const;
    ProgramView programView() const;
    std::vector<AlarmView> alarms() const; // latched messages, in the order they came
    const AlarmRegistry& alarmRegistry() const { return c_.alarms; }
    PlcMessagesView plcMessages() const;
    const RStore& r() const { return c_.r; }
    std::int32_t r(int number) const { return c_.r[number]; }
    std::span<const std::int32_t> rValues() const { return c_.r.values(); } // R0..R299
    std::span<const std::int64_t> c() const { return c_.c; }
    const profile::MachineProfile& profile() const { return c_.profile; }
    Mode mode() const { return c_.mode; }
    ProgramState state() const { return c_.state; }
    const ModalState& modal() const { return interp_.modal(); }
    std::int64_t framesExecuted() const { return c_.framesExecuted; }
    // Time the last program started / ended (ms), -1 if not yet.
    std::int64_t programStartMs() const { return c_.programStartMs; }
    std::int64_t programEndMs() const { return c_.programEndMs; }
    // The servo of an axis (diagnostics, tests).
    const axis::Servo& servo(AxisId a) const { return unit(a).servo; }
    // What axisView() tells of the reference point, without building a view
    // (a run asks every tick): the axis is present; referenced; referenced
    // or АВТ.БЕЗ ПБТ; its reference-point cycle runs.
    bool axisPresent(AxisId a) const { return unit(a).present; }
    bool referenced(AxisId a) const { return unit(a).referenced; }
    bool referenceOk(AxisId a) const { return unit(a).referenceOk(); }
    bool homing(AxisId a) const { return unit(a).homing.running(); }
    // Preview (engine/preview_run.h, PreviewOptions::fromReferencePoint):
    // every present axis stands referenced at its reference point (ЗНАЧЕНИЕ
    // БТ, C45/C97), where the reference-point cycle leaves it. Only before a
    // program starts.
    void placeAtReferencePoint();
    // Preview mode (engine/preview.h; driven by engine/preview_run.h): null ends it.
    void setPreview(PreviewSink* sink) {
        wake();
        previewSink_ = sink;
        chooseOutput();
    }
    // The preview holds the program before a frame (start from a frame).
    void setPreviewStopBefore(const FrameTarget& t) {
        previewOutput_.stopBefore(t.program, t.frameIndex, t.pass);
    }
    // The debugger's gate (engine/debug_gate.h): breakpoints, single frame,
    // run to a frame; null detaches it. The gate outlives its attachment.
    void setDebugGate(DebugGate* gate) {
        wake();
        debugGate_ = gate;
        chooseOutput();
    }
    DebugGate* debugGate() const { return debugGate_; }
    // The shortcuts' two paths (docs/engine.md, "Speed"): with this on,
    // a routine tick also takes the full path — the reading of the inputs,
    // Z2000, the wheel's bits and the sums of the offsets computed anew —
    // and so does program control where it took its shortcut within a full
    // reading; and a settled tick runs the full tick instead and compares it
    // with what the settled tick leaves. Each compares what both leave; a
    // debug build has it on and asserts they agree. Counts the checks (of
    // the settled tick also apart) and those that disagreed.
    void setCheckShortcuts(bool on) { checkShortcuts_ = on; }
    std::int64_t shortcutChecks() const { return shortcutChecks_; }
    std::int64_t settledChecks() const { return settledChecks_; }
    std::int64_t shortcutDisagreements() const { return shortcutDisagreements_; }
    const Interpreter& interpreter() const { return interp_; }
    // Start from a frame (engine/start_point.h): the next «Пуск» of АВТОМАТ
    // that starts `point`'s main program starts it before the point's frame,
    // with the state rebuilt and the axes brought there by the safe path;
    // used once. Empty: programs start from their first frame again.
    void setStartPoint(std::optional<StartPoint> point) {
        wake();
        startPoint_ = std::move(point);
    }
    const std::optional<StartPoint>& startPoint() const { return startPoint_; }
    // The state before the frame the program is held at (the preview
    // stopped before it, or the debugger): program, stack, modal state, axes.
    void captureStartPoint(StartPoint& point) const { interp_.capture(point); }
    bool oscillating(AxisId a) const {
        return c_.osc[static_cast<std::size_t>(axisIndex(a))].active();
    }

private:
    const AxisUnit& unit(AxisId a) const { return c_.axes[static_cast<std::size_t>(axisIndex(a))]; }
    void readInputs();
    void systemChecks();
    // Program control: with the inputs of the last full reading and no
    // operator function since (inputsAsRead()), programControlAgain(); else
    // programControlInFull(), which reads the edges of Z1000/Z1001 and the
    // fast inputs.
    void programControl();
    void programControlInFull();
    // What program control does again each tick with unchanged inputs.
    [[gnu::always_inline]] inline void programControlAgain();
    void resetSystem();
    void acknowledgeFaults();
    void acknowledgeSystem();
    void changeMode(Mode to);
    void interrupt(bool dropPath);
    void startProgram(int number, int cycle);
    void manualFunctions();
    void axisInputs(AxisUnit& u);
    // Inlined into tick(): both axes in one frame (no call per axis).
    [[gnu::always_inline]] inline void axisTick(AxisUnit& u);
    void handwheels(AxisUnit& u);
    void jog(AxisUnit& u);
    void homingStart(AxisUnit& u);
    // `routine`: this tick is a routine one (routineInputs()).
    void writeOutputs(bool routine);
    void refreshR();
    void axisR(const AxisUnit& u, std::int64_t machineDisc);
    // R232..R262 and Z2005/Z2007 of a present axis (wheelBits: Z2005.11/.12
    // of the wheel, X only) and of an absent one.
    void axisOutputs(const AxisUnit& u, unsigned wheelBits);
    void absentAxisOutputs(int a);
    void configurationCheck();
    void programStoreCheck();
    void trackFault(AxisUnit& u);
    // The settled tick (docs/engine.md, "Speed"): once two full ticks in a
    // row found the words and the machine I/O as the tick before left them,
    // changed nothing of them, of the R-parameters or of the messages, and
    // ended with no program executing, every servo quiet and no motion,
    // cycle or handwheel pulse, the next tick with the same words and I/O
    // can change nothing but the time: it advances the clock and the
    // servos' time at rest only. Any operator function, or any change of a
    // word or of the I/O, ends it.
    bool settled() const;
    void noteSettled(bool inputsAsLeft);
    // The tick past the settled shortcut: the clock, the routine or full
    // reading, the axes, the interpreter, the outputs.
    void fullTick(bool inputsAsLeft);
    // Both paths of the settled tick (setCheckShortcuts): the full tick with
    // the same inputs must change nothing the settled tick leaves as it was
    // (observed()) and find the machine still settled.
    void checkSettledTick();
    // An operator function acted (or a door was used): the next tick is a
    // full one, and programControl() reads its inputs again.
    void wake() {
        unsettle();
        operatorActed_ = true;
        routine_.valid = false;
    }
    void unsettle() {
        quiet_.valid = false;
        quiet_.ticks = 0;
    }
    // The sum of the offset R-parameters in effect for each axis (2.4), kept
    // for as long as R224..R231 and the exclusions stay (writeOutputs()).
    void refreshOffsets();

    // The interpreter's output: the preview's when a sink is set, else the
    // debugger's when a gate is, else the machine's.
    void chooseOutput();

    Core c_;
    Interpreter interp_;
    RunOutput runOutput_{c_};
    PreviewOutput previewOutput_{c_};
    DebugOutput debugOutput_{c_};
    PreviewSink* previewSink_ = nullptr;
    DebugGate* debugGate_ = nullptr;
    std::optional<StartPoint> startPoint_;
    std::array<axis::Fault, kAxisCount> lastFault_{};
    std::array<std::int64_t, 2> wheelDelta_{}; // handwheel pulses this tick
    std::array<std::int64_t, 2> wheelCount_{};
    bool wheelInit_ = false;
    std::array<bool, 65> configMessages_{};
    std::uint64_t lastSystemInputs_ = ~0ull; // systemChecks(): the inputs last applied
    std::array<bool, kAxisCount> servoRKnown_{}; // axisR(): the servo's R values are written
    // An operator function acted since program control last read its inputs
    // in full.
    bool operatorActed_ = true;
    // The routine tick (docs/engine.md, "Speed"): the inputs the last full
    // reading of inputs, PLC messages, system checks, program control and
    // manual functions saw. While they stay, with no operator function, no
    // handwheel pulse and not in РУЧНОЙ, that reading would change nothing.
    bool routineInputs() const;
    // The same inputs as that reading, and no operator function since: the
    // condition of both shortcuts (the routine tick's, program control's
    // within a full reading), one snapshot compared as one block.
    bool inputsAsRead() const;
    void noteRoutineInputs();
    // What that reading depends on, as one snapshot with one equality: the
    // words the positioner reads (Z1000..Z1907), the fast inputs and module
    // health, the counters of the handwheels' pulse channels.
    struct TickInputs {
        std::array<std::uint16_t, InterfaceWords::kInputWords> words{};
        std::array<std::uint8_t, kMachineStatusBytes> status{};
        std::array<std::uint8_t, 3> zero{}; // no padding: the bytes compare as one block
        std::array<std::int64_t, 2> wheelCounts{};
        friend bool operator==(const TickInputs& a, const TickInputs& b) {
            return util::sameBytes<sizeof(TickInputs)>(&a, &b);
        }
    };
    static_assert(sizeof(TickInputs) == 2 * InterfaceWords::kInputWords + kMachineStatusBytes + 3 +
                                            2 * sizeof(std::int64_t),
                  "TickInputs has no padding");
    TickInputs tickInputs() const;
    // What the settled tick depends on: the same snapshot of the inputs,
    // and the rest of the machine's side a tick reads or writes (every
    // pulse channel, the positioner's words Z2000..Z2008, the DAC codes and
    // regulator enables) and the messages, again with one equality. The
    // R-parameters are not in it: they change only within a full tick or by
    // an operator function, which ends the shortcut anyway, so a settled tick
    // need not copy them; noteSettled() compares them after a full tick.
    struct SettledInputs {
        TickInputs reading;
        std::array<std::int64_t, kPulseChannels> counts{}, markCounts{};
        std::uint64_t latched = 0, active = 0;
        std::array<std::int32_t, kDacChannels> dac{};
        std::array<std::uint16_t, InterfaceWords::kOutputWords> outputs{};
        std::array<std::uint8_t, 3 * kPulseChannels> lines{}; // line 1, line 2, zero mark of each channel
        std::array<std::uint8_t, 2> regulatorEnable{};
        friend bool operator==(const SettledInputs& a, const SettledInputs& b) {
            return util::sameBytes<sizeof(SettledInputs)>(&a, &b);
        }
    };
    static_assert(sizeof(SettledInputs) ==
                      sizeof(TickInputs) + 2 * kPulseChannels * sizeof(std::int64_t) + 2 * sizeof(std::uint64_t) +
                          kDacChannels * sizeof(std::int32_t) +
                          2 * InterfaceWords::kOutputWords + 3 * kPulseChannels + 2,
                  "SettledInputs has no padding");
    SettledInputs settledInputs() const;
    // The full reading of the inputs (the other path of a routine tick).
    void readAll();
    struct {
        bool valid = false;
        TickInputs inputs;
    } routine_;
    // Both paths of a shortcut (setCheckShortcuts): what the full reading,
    // run after the shortcut, would change.
    struct Observed;
    Observed observed() const;
    // A shortcut ran (the routine tick's: programControlAgain instead of
    // readAll; program control's: instead of programControlInFull); `full`,
    // the long way with the same inputs, must find nothing more to do.
    void checkShortcut(void (Positioner::*full)());
#ifdef NDEBUG
    bool checkShortcuts_ = false;
#else
    bool checkShortcuts_ = true;
#endif
    std::int64_t shortcutChecks_ = 0, shortcutDisagreements_ = 0, settledChecks_ = 0;
    // writeOutputs(): Z2000, the wheel's bits of Z2005 and the state they
    // were computed for (see there).
    struct CommonOutputs {
        struct Key {
            std::int64_t frames = 0;  // frames executed
            std::uint64_t active = 0; // messages active
            ProgramState state = ProgramState::Idle;
            bool endOrReset = false;
            std::uint8_t exclusion = 0; // G50..G53 of the program
            bool operator==(const Key&) const = default;
        } key;
        bool valid = false;
        std::uint16_t z2000 = 0;
        unsigned wheelBits = 0;
    } common_;
    struct OffsetSums {
        bool valid = false;
        std::array<std::int32_t, 8> r{};          // R224..R231 as summed
        std::array<std::uint8_t, kAxisCount> ex{}; // the exclusions as summed
        std::array<std::int64_t, kAxisCount> sum{};
    } offsets_;
    bool storeCorrupt_ = false;
    std::uint64_t programsRevision_ = 0;
    int overrideFactorPercent_ = -1; // overrideFactor_ = overridePercent / 100 of this percent
    double overrideFactor_ = 1.0;
    struct QuietState {
        bool valid = false; // `left` and `r` are what the last full tick left
        int ticks = 0;      // full settled ticks in a row that changed nothing
        SettledInputs left;
        RStore r;
    } quiet_;
};

} // namespace k528::engine
