// What a debugger of the program editor needs from the engine:
// breakpoints on frames, single frame and run to a frame — each stops the
// program *before* a frame executes — and the call stack of the interpreter.
//
// The K528-05 itself has no single-frame mode (the manual's «пошаговое
// выполнение» is the K749's, 2.2.1); the gate is the emulator's debugger,
// attached to a Positioner with Positioner::setDebugGate(). With no gate
// (the default) nothing changes.
//
// A stop holds the program as «Стоп» does between frames: the state is
// Interrupted, no motion is under way, the interpreter's frame pointer
// (ProgramView program/frameIndex/frameNumber/line, R253/R254) is on the
// frame that has not executed yet, and «Пуск» continues with it. The gate
// lets that frame pass once, then checks again:
//   - a breakpoint (program number, source line) stops before its frame;
//   - run to (program, line): a one-shot breakpoint, forgotten when reached;
//   - single frame: after a frame has executed, stops before the next one
//     (the first frame after the program's start or a stop runs: one frame
//     per «Пуск»).
// Skipped frames («/») are not frames executed: the gate does not stop on
// them. Deterministic: no clock, only the interpreter's calls.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace k528::engine {

class Positioner;

class DebugGate {
public:
    enum class Reason : std::uint8_t { Breakpoint, SingleFrame, RunTo };
    struct Stop {
        Reason reason = Reason::Breakpoint;
        int program = 0;
        int frameIndex = 0;
        int line = 0;
    };

    // --- set by the debugger --------------------------------------------
    void addBreakpoint(int program, int line) { breakpoints_.insert({program, line}); }
    void removeBreakpoint(int program, int line) { breakpoints_.erase({program, line}); }
    void clearBreakpoints() { breakpoints_.clear(); }
    bool hasBreakpoint(int program, int line) const { return breakpoints_.count({program, line}) > 0; }
    const std::set<std::pair<int, int>>& breakpoints() const { return breakpoints_; }

    void setSingleFrame(bool on) { singleFrame_ = on; }
    bool singleFrame() const { return singleFrame_; }

    void runTo(int program, int line) { runTo_ = std::make_pair(program, line); }
    void clearRunTo() { runTo_.reset(); }
    std::optional<std::pair<int, int>> runToTarget() const { return runTo_; }

    // --- state ----------------------------------------------------------
    // The program is held by the gate (until «Пуск» or a new start).
    bool holding() const { return holding_; }
    // The last stop of the gate, if any since it was made.
    const std::optional<Stop>& lastStop() const { return lastStop_; }
    std::int64_t stops() const { return stops_; }

    // --- called by the interpreter --------------------------------------
    // A program starts from its first frame.
    void started();
    // «Пуск» continues a held program.
    void resumed();
    // The interpreter is about to execute frame `frameIndex` (source line
    // `line`) of program `program`: true = stop before it.
    bool beforeFrame(int program, int frameIndex, int line);

private:
    std::set<std::pair<int, int>> breakpoints_;
    std::optional<std::pair<int, int>> runTo_;
    bool singleFrame_ = false;
    bool fresh_ = false;   // no frame has executed since the start or the last stop
    bool holding_ = false; // stopped by the gate, «Пуск» not yet pressed
    std::optional<std::pair<int, int>> pass_; // (program, frame index) let through once
    std::optional<Stop> lastStop_;
    std::int64_t stops_ = 0;
};

// One level of the interpreter's call stack: level 0 is the main program;
// the last level is the frame executing (or held before); a level below it
// is the frame whose L called the next level.
struct CallLevel {
    int level = 0;   // R158 of this level
    int program = 0; // program number
    int frameIndex = 0;
    int frameNumber = 0; // N, 0 if the frame has none
    int line = 0;        // source line, 0 if unknown
};

// The call stack of the program under way, outermost first (empty when no
// program is active).
std::vector<CallLevel> callStack(const Positioner& controller);

} // namespace k528::engine
