// The interpreter of control programs (manual 2.7; program-language.md):
// frames of the four kinds, the G-functions of table 5, the built-in M
// functions, subprograms and the hand-over of every M to the PLC.
//
// Frame by frame, in program order; a frame that takes no time (a
// computation, a jump, a skipped frame, an ISO frame without motion, M or
// dwell) is followed at once by the next, up to kFramesPerTick frames a
// tick, so a loop without motion cannot hang the engine: it just runs at
// that many frames per tick.
//
// An ISO frame runs in this order (docs/engine.md):
//   1. the run-time checks of the combinations the validator refuses
//      (34/50, 35/51, 36/52, 47, 58..64);
//   2. its message #k, its modal G (group 1, 6, 7, 8) and feeds FX/FZ;
//   3. its M functions handed to the PLC one by one (m_handshake.h);
//   4. Gx80 (waits for the oscillation to stop), then Gx92, Gx81, G04, and
//      the motion of X and Z (G00/G01, Gx10, Gx36..39);
//   5. when the motion, dwell or oscillation stop is over: M00 (wait for
//      «Пуск»), M02/M30 (end), M17 (return), then the call L.
//
// What a frame asks of the machine — moves, M functions, dwells, messages,
// M00's stop, a debugger's stop before a frame — goes to the output the
// controller set (Core::out, engine/program_output.h): the machine, the
// preview's instant axes or the machine under the debugger.
#pragma once

#include "engine/core.h"
#include "engine/program_output.h"
#include "program/gfunctions.h"
#include "program/model.h"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace k528::engine {

inline constexpr int kFramesPerTick = 100;

// Modal state of a program run (table 5: '**' marks the defaults set at
// power-on and «Сброс»; docs/engine.md: also at every program start).
struct ModalState {
    bool rapid = false;       // G00 (true) / G01
    int components = 54;      // G50..G54
    int noOverrideAxis = -1;  // G55 (-1) / G156 (0) / G256 (1)
    bool incremental = false; // G91 / G90
    std::array<std::int64_t, kAxisCount> feed{-1,
                                              -1}; // FX/FZ, display discretes per minute; -1 none
    friend bool operator==(const ModalState&, const ModalState&) = default;
};

struct StartPoint;

class Interpreter {
public:
    explicit Interpreter(Core& core) : c_(core) {}

    // Starts program `number` from its first frame (the caller checked that
    // it exists). `cycle`: manual cycle 1..8, 0 for a program of АВТОМАТ.
    void start(int number, int cycle, Mode mode);
    // Starts the main program of `point` before its frame, with the state
    // rebuilt (engine/start_point.h): its R-parameters, the M functions
    // handed again, the safe path to the start point, then the frame.
    void startAt(const StartPoint& point, Mode mode);
    // The state before the frame the interpreter stands at (held before it).
    void capture(StartPoint& point) const;
    // «Пуск» after M00 or «Стоп»/mode change.
    void resume();
    // Power-on / «Сброс»: modal defaults.
    void resetModal() { modal_ = ModalState{}; }
    // Executes frames while the program is executing (after the axes' tick).
    void tick();

    // --- views ----------------------------------------------------------
    const ModalState& modal() const { return modal_; }
    int program() const { return prog_ ? prog_->number : 0; } // executing (sub)program
    int mainProgram() const { return mainProgram_; }
    int frameIndex() const { return index_; }
    int frameNumber() const; // N of the current frame, 0 if none
    int line() const;        // source line of the current frame, 0 if none
    int level() const { return depth_; }
    bool oscillationStopWait() const { return step_ == Step::OscStop; }
    // The call stack (engine/debug_gate.h): level i < level() called from
    // frame callerReturnIndex(i) - 1 of callerProgram(i).
    const program::Program* currentProgram() const { return prog_; }
    const program::Program* callerProgram(int i) const {
        return stack_[static_cast<std::size_t>(i)].program;
    }
    int callerReturnIndex(int i) const { return stack_[static_cast<std::size_t>(i)].returnIndex; }

private:
    enum class Step : std::uint8_t { Fetch, Handshake, OscStop, Actions, Wait, Call, Approach };
    struct Level {
        const program::Program* program = nullptr;
        int returnIndex = 0;
    };

    bool executeZeroTime(const program::Frame& f); // compute / jumps; false on alarm
    void beginIso(const program::Frame& f);
    void actions();
    bool waitDone();
    void afterFrame();
    void call();
    void next() {
        ++index_;
        step_ = Step::Fetch;
    }
    void jump(int n);
    void endProgram();
    void returnFromSubprogram();
    void error(int message);
    int errAxis(int xMessage, int axis) const; // 33 -> 49 for Z ...
    bool valueDisc(const program::Value& v, int axis, std::int64_t& disc);
    bool startMove(int axis, std::int64_t targetMachineDisc, bool handwheel, int eraseSignal);
    bool startOscillation(int axis, const std::optional<program::Value>& stroke);
    OscillationPresets presets(int axis) const;
    void updateNumbers();
    bool approach(); // Step::Approach: false while it waits
    // The frame executing, for the output (engine/program_output.h).
    FrameRef frameRef() const { return {program(), line_, frameNumber()}; }
    // The programmed feed of axis a for the output: -1 under G00 or when none was set.
    std::int64_t feedOf(int a) const {
        return modal_.rapid ? -1 : modal_.feed[static_cast<std::size_t>(a)];
    }

    Core& c_;
    ModalState modal_;
    std::array<Level, 100> stack_{};
    int depth_ = 0;
    const program::Program* prog_ = nullptr;
    int index_ = 0;
    int mainProgram_ = 0;
    Step step_ = Step::Fetch;

    // The ISO frame in progress.
    program::IsoFrame iso_; // the ISO frame being executed (decoded from its compact form)
    int line_ = 0;
    std::array<int, 3> m_{};
    int mCount_ = 0;
    bool m00_ = false, mEnd_ = false, m17_ = false;
    int callTarget_ = 0;
    std::array<std::int64_t, kAxisCount> value_{}; // X/Z of the frame, display discretes
    std::int64_t dwellLeftMs_ = -1;
    bool dwellFresh_ = false;
    std::array<bool, kAxisCount> moving_{};   // this frame moves the axis
    std::array<bool, kAxisCount> oscStop_{};  // Gx80 on the axis
    std::array<bool, kAxisCount> oscStart_{}; // Gx81
    std::array<bool, kAxisCount> setPos_{};   // Gx92
    std::array<bool, kAxisCount> wheel_{};    // Gx10
    std::array<int, kAxisCount> erase_{};     // Gx36..39: signal 1..4
    bool dwell_ = false;

    // A start from a frame (startAt): the M functions handed again, then
    // the legs of the safe path (axis, machine target), then the frame.
    std::vector<int> replayM_;
    std::size_t replayAt_ = 0;
    bool replayWait_ = false;
    std::array<std::pair<int, std::int64_t>, 3> legs_{};
    int legCount_ = 0, leg_ = 0;
    bool legMoving_ = false;
    std::array<std::int64_t, kAxisCount> startProgrammed_{};
    // Gx81 given and its Gx80 not yet (the preview's axes do not oscillate).
    std::array<bool, kAxisCount> oscOn_{};
};

} // namespace k528::engine
