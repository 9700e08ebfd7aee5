// The simulated PLC (ПЛК) of the K528-05 with the role of the manual's
// «RP-UUKP» (2.2, appendices И and К): one scan, in a fixed order,
//
//   1. inputs: terminal levels -> debounced input signals (GOST 26642 6.1.7);
//      the inputs of a failed module read 0;
//   2. segment 0, in: the positioner's words Z2000..Z2008 (zero while the link
//      is lost) and the K923 keys of Z1300; the M function on Z2001: a new
//      strobe starts the function's actions;
//   3. segment 1: the keys K1..K12 -> their actions (the bits are then
//      cleared: «Сброс сигнала должна выполнить программа ПЛК»);
//   4. segment 2: the machine's logic, rung by rung, in the order written;
//   5. interlocks: conditions -> feed hold, data hold, start inhibit,
//      emergency stop, «Стоп»/«Сброс» pulses, messages, outputs forced off;
//   6. segment 0, M acknowledgement: Z1000.11 once the function is done and
//      at least T3 after the strobe; dropped when the strobe drops;
//   7. segment 0, out: the words Z1000..Z1013 from the positioner section
//      (and the interlocks), the mode and override codes;
//      segment 1, out: LEDs Z1906/Z1907, machine alarms Z1900/Z1901, work
//      messages Z1902/Z1903, module failures Z1307;
//   8. outputs: the output signals to the terminals (0 on a failed module).
//
// The machine's own logic is data (plc/description.h). Time comes from the
// caller (scan(nowMs)); a scan that could change nothing is skipped
// (scanDue()): the inputs, the positioner's words, the keys and the timers
// are unchanged and the previous scan changed no signal, so it would be a
// no-op — the result is the same as scanning every tick, bit for bit.
#pragma once

#include "engine/interface_words.h"
#include "plc/description.h"
#include "plc/expression.h"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace k528::plc {

// One M function as the PLC saw it (GOST 26642 §6.4 timing; -1 = not yet).
struct MEvent {
    int code = 0;
    std::int64_t codeMs = -1;   // the code appeared on Z2001.0-6
    std::int64_t strobeMs = -1; // the strobe Z2001.7 rose
    std::int64_t ackMs = -1;    // the PLC set Z1000.11
    std::int64_t dropMs = -1;   // the strobe dropped (the PLC dropped Z1000.11)
    bool described = true;      // the description has this M
    bool timedOut = false;      // its `done` did not come within timeout_ms
};

class Plc {
public:
    // Compiles the description's conditions; throws DescriptionError naming
    // the path of a bad condition, an unknown or misused name.
    explicit Plc(const MachineDescription& description);

    const MachineDescription& description() const { return d_; }

    // --- the terminals -------------------------------------------------------
    int inputCount() const { return static_cast<int>(d_.inputs.size()); }
    int outputCount() const { return static_cast<int>(d_.outputs.size()); }
    std::optional<int> inputIndex(std::string_view name) const;
    std::optional<int> outputIndex(std::string_view name) const;
    // The level at input terminal i (1 = +24 V), before debouncing.
    void setInput(int i, bool level) {
        if (terminal_[static_cast<std::size_t>(i)] != level) {
            terminal_[static_cast<std::size_t>(i)] = level;
            dirty_ = true;
        }
    }
    bool inputTerminal(int i) const { return terminal_[static_cast<std::size_t>(i)]; }
    // Output terminal i after the last scan (0 while its module has failed).
    bool output(int i) const { return outputs_[static_cast<std::size_t>(i)] != 0; }

    // --- the positioner -----------------------------------------------------
    // Reads Z2000..Z2008 and the keys of Z1300 (only while the link works).
    void readPositioner(const engine::InterfaceWords& w);
    // Writes Z1000..Z1013, Z1900..Z1907 and Z1307, and clears in Z1300 the
    // keys the PLC has taken.
    void writePositioner(engine::InterfaceWords& w);

    // --- the scan -----------------------------------------------------------
    bool scanDue(std::int64_t nowMs) const { return dirty_ || nowMs >= wakeMs_; }
    void scan(std::int64_t nowMs);
    std::int64_t scans() const { return scans_; }

    // --- faults ---------------------------------------------------------------
    void setModuleFailed(int place, bool failed);
    bool moduleFailed(int place) const { return (failedModules_ >> place) & 1u; }
    // The exchange with the positioner works (built-in signal link_ok); while
    // it does not, the PLC reads 0 for Z2000..Z2008.
    void setLinkOk(bool ok);
    // «ОТЛАДКА СТОП»: the program does not run; every output drops and the
    // words to the positioner are 0 (its E-stop input Z1000.0 among them)
    // until the PLC runs again, which then scans from the state it had.
    void setStopped(bool stopped);
    bool stopped() const { return stopped_; }
    // A trainer's key switch: the PLC imposes mode `code` (1..7) on Z1000.8-10
    // whatever the description's mode rules say; 0 lets the K923 choose,
    // -1 gives the word back to the rules.
    void imposeMode(int code);
    int imposedMode() const { return imposedMode_; }
    bool linkOk() const { return linkOk_; }

    // --- views ----------------------------------------------------------------
    // The value of a named signal (input, output, flag, timer, interlock,
    // built-in) or a Z bit ("Z1000.1"); nullopt for an unknown name.
    std::optional<bool> signal(std::string_view name) const;
    // The PLC's image of the interface words (what it last wrote and read).
    const engine::InterfaceWords& words() const { return words_; }
    const std::vector<MEvent>& mLog() const { return mLog_; }
    bool mBusy() const { return mActive_ && !mAcked_; }
    std::vector<std::string> activeInterlocks() const;

private:
    enum class Kind : std::uint8_t { Input, Output, Flag, Timer, Interlock, Builtin, ZOut, ZIn };
    struct Target {
        std::uint32_t signal = 0;
        bool driven = false; // a coil or a slot writes it every scan
    };
    struct Rung {
        RungKind kind;
        std::uint32_t target;
        Expr when;
        int ms = 0;
        // timer state
        bool lastIn = false, running = false;
        std::int64_t startMs = 0;
    };
    struct CompiledActions {
        std::vector<std::uint32_t> set, reset, toggle, pulse;
    };
    struct MFunction {
        const MFunctionDef* def;
        CompiledActions actions;
        std::optional<Expr> done;
    };
    struct Interlock {
        const InterlockDef* def;
        Expr when;
        std::uint32_t signal;
        std::vector<std::uint32_t> off;
    };
    struct Key {
        const KeyDef* def;
        std::optional<Expr> when;
        CompiledActions actions;
    };
    struct Led {
        int key;
        std::optional<Expr> green, red;
    };
    struct Message {
        int k;
        Expr when;
    };
    struct Slot {
        std::uint32_t signal;
        Expr when;
    };
    struct ModeRuleC {
        int code;
        Expr when;
    };
    struct Pulse {
        std::uint32_t signal;
        std::int64_t endMs;
    };

    std::uint32_t addSignal(const std::string& name, Kind kind, const std::string& path);
    std::optional<std::uint32_t> resolve(std::string_view name) const;
    // Index of a held word, -1 if none: the words in the order of
    // engine::InterfaceWords (1000..1013, 1300..1307, 1900..1907,
    // 2000..2008). Arithmetic, inline: the scan packs and unpacks words by
    // address, and with a constant address this folds to a constant.
    static constexpr int zSlot(int word) { return engine::InterfaceWords::slotOf(word); }
    static constexpr int kZWords = engine::InterfaceWords::kWordCount;
    std::uint32_t zSignal(int word, int bit) const {
        return zBase_ + static_cast<std::uint32_t>(zSlot(word) * 16 + bit);
    }
    Expr compile(const std::string& text, const std::string& path) const;
    profile::Problem declaredAt(std::string id, const std::string& name, std::uint32_t s) const;
    std::uint32_t writable(const std::string& name, const std::string& path, bool asDriver);
    CompiledActions compileActions(const Actions& a, const std::string& path);
    void apply(const CompiledActions& a, std::int64_t nowMs, int pulseMs);
    void setLatched(std::uint32_t s, bool v);
    void startPulse(std::uint32_t s, std::int64_t endMs);
    bool pulseActive(std::uint32_t s, std::int64_t nowMs) const;
    void refreshPulses(std::int64_t nowMs);
    void unpackWord(int word, std::uint16_t value);
    std::uint16_t packWord(int word) const;
    void wake(std::int64_t atMs) {
        if (atMs < nextWake_)
            nextWake_ = atMs;
    }
    void segment0In(std::int64_t nowMs);
    void segment1Keys(std::int64_t nowMs);
    void segment2(std::int64_t nowMs);
    void interlocks(std::int64_t nowMs);
    void mAcknowledge(std::int64_t nowMs);
    void segment0Out(std::int64_t nowMs);

    MachineDescription d_;
    std::vector<std::string> names_;
    std::vector<Kind> kinds_;
    std::vector<std::string> declaredAt_;
    std::map<std::string, std::uint32_t, std::less<>> index_;
    std::uint32_t zBase_ = 0;
    std::uint32_t firstScanSig_ = 0, linkOkSig_ = 0, mBusySig_ = 0, ackSig_ = 0, alarmSig_ = 0;
    std::uint32_t keySig_[13]{};

    std::vector<std::uint8_t> sig_, prev_;
    std::vector<std::uint8_t> latch_;  // set/reset state of latched signals
    std::vector<std::uint8_t> driven_; // 1: written by a coil or slot
    std::vector<std::uint8_t> pulseTarget_;
    std::vector<Pulse> pulses_;

    // inputs
    std::vector<std::uint32_t> inputSig_;
    std::vector<std::uint8_t> terminal_, candidate_;
    std::vector<std::int64_t> candidateSince_;
    // outputs
    std::vector<std::uint32_t> outputSig_;
    std::vector<std::uint8_t> outputs_;

    std::vector<Rung> rungs_;
    std::map<int, MFunction> mfuncs_;
    std::vector<Interlock> interlocks_;
    std::vector<std::uint8_t> interlockLatched_;
    std::vector<Key> keys_;
    std::vector<Led> leds_;
    std::vector<Message> alarms_, work_;
    std::vector<Slot> slots_;
    std::vector<ModeRuleC> modeRules_;
    int imposedMode_ = -1;
    bool modeImposedOnce_ = false; // the field is the PLC's from then on (0 when no rule holds)
    std::optional<Expr> overrideFromPlc_;
    std::array<std::uint32_t, 4> overrideBits_{};

    engine::InterfaceWords words_;
    std::uint16_t keysPending_ = 0, keysTaken_ = 0;
    std::uint16_t failedModules_ = 0;
    bool linkOk_ = true;
    bool stopped_ = false;
    bool dirty_ = true;
    std::int64_t wakeMs_ = 0, nextWake_ = 0;
    std::int64_t scans_ = 0;

    // M function (segment 0)
    bool mActive_ = false, mAcked_ = false, mTimedOut_ = false, mUnknownAlarm_ = false;
    const MFunction* mCurrent_ = nullptr;
    int lastCode_ = -1;
    std::int64_t codeSinceMs_ = -1, mStartMs_ = 0;
    std::vector<MEvent> mLog_;

    // interlock effects of this scan
    bool ilEstop_ = false, ilFeedHold_ = false, ilDataHold_ = false, ilStartInhibit_ = false;
    int ilOverrideMax_ = -1;
    std::uint32_t ilAlarms_ = 0, ilWork_ = 0;
};

} // namespace k528::plc
