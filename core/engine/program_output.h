// The interpreter's output: what a frame asks of the machine, in the order
// the frame runs (docs/engine.md "The interpreter's output"). The
// interpreter decides everything a frame means — modal state, R arithmetic,
// jumps, calls, coordinates and their components, the run-time checks and
// their messages — and hands the machine its part through this interface:
// the moves of the axes, the M functions, the dwells, the technological
// messages, the stop of M00, and the debugger's stops before a frame. As
// LinuxCNC's interpreter calls its canonical machining functions (one
// interface; the real machine, the preview and the simulators implement
// it) and CAMotics' machine pipeline passes moves and dwells down a chain
// of MachineInterface implementations.
//
// Three implementations, each `final` (the calls happen when a frame
// starts or ends, never in a tick without a frame):
//   RunOutput     the machine: the servos move, the PLC acknowledges the M
//                 functions (m_handshake.h), dwells and M00 wait;
//   PreviewOutput instant axes: each frame's motion goes to a PreviewSink
//                 (engine/preview.h) and the axes stand at its end at once;
//                 M functions are acknowledged at once, dwells and M00 take
//                 no time (`k528 path`, the backplot);
//   DebugOutput   the machine, with the editor's debugger (debug_gate.h)
//                 holding the program before the frames it stops at.
#pragma once

#include "engine/oscillation.h"
#include "engine/preview.h"

#include <cstdint>
#include <span>

namespace k528::engine {

struct AxisUnit;
struct Core;
class DebugGate;

// The frame a call comes from.
struct FrameRef {
    int program = 0, line = 0, n = 0;
};

class ProgramOutput {
public:
    virtual ~ProgramOutput() = default;

    // A program starts from its first frame; «Пуск» continues a held one.
    virtual void started() = 0;
    virtual void resumed() = 0;
    // The interpreter is about to execute frame `frameIndex` (source line
    // `line`) of program `program`: true holds the program before it.
    virtual bool holdBefore(int program, int frameIndex, int line) = 0;
    // The frame's technological message #k (it stays on LCD line 2 until
    // another frame names one).
    virtual void message(const FrameRef& f, int k) = 0;
    // The frame's M functions, in the order written (0..3 of them): true =
    // the frame waits until the PLC has acknowledged them.
    virtual bool mFunctions(const FrameRef& f, std::span<const int> codes) = 0;
    // The frame's motion begins (after its Gx92, before its Gx81, G04 and moves).
    virtual void motionBegins() = 0;
    // Axis `u` goes from `from` to `to` (internal units, machine system) at
    // `speed` (internal units per ms); `feedDisc` is the programmed feed
    // (display discretes per minute, -1 for G00). A Gx10 frame's `handwheel`
    // motion is the operator's, between the two points. False: the servo
    // refused (its fault says why).
    virtual bool move(AxisUnit& u, double from, double to, double speed, std::int64_t feedDisc,
                      bool handwheel) = 0;
    // Gx81: axis `u` oscillates between `lo` and `hi` (internal units) at
    // `speed`, first towards hi if `towardsHi`. False: the servo refused.
    virtual bool oscillate(AxisUnit& u, Oscillation& osc, double lo, double hi, double speed,
                           bool towardsHi, const OscillationPresets& presets,
                           std::int64_t feedDisc) = 0;
    // G04 of `ms`: true = the frame waits it out.
    virtual bool dwell(const FrameRef& f, std::int64_t ms) = 0;
    // Every motion of the frame is commanded; `kind` says what it is.
    virtual void motionEnds(const FrameRef& f, PreviewKind kind) = 0;
    // M00 after the frame: true = the program waits for «Пуск».
    virtual bool stopAtM00() = 0;
};

// The machine.
class RunOutput final : public ProgramOutput {
public:
    explicit RunOutput(Core& core) : c_(core) {}
    void started() override {}
    void resumed() override {}
    bool holdBefore(int, int, int) override { return false; }
    void message(const FrameRef&, int) override {}
    bool mFunctions(const FrameRef& f, std::span<const int> codes) override;
    void motionBegins() override {}
    bool move(AxisUnit& u, double from, double to, double speed, std::int64_t feedDisc,
              bool handwheel) override;
    bool oscillate(AxisUnit& u, Oscillation& osc, double lo, double hi, double speed,
                   bool towardsHi, const OscillationPresets& presets,
                   std::int64_t feedDisc) override;
    bool dwell(const FrameRef&, std::int64_t) override { return true; }
    void motionEnds(const FrameRef&, PreviewKind) override {}
    bool stopAtM00() override { return true; }

private:
    Core& c_;
};

// The machine with the editor's debugger.
class DebugOutput final : public ProgramOutput {
public:
    explicit DebugOutput(Core& core) : run_(core) {}
    void setGate(DebugGate* gate) { gate_ = gate; }
    void started() override;
    void resumed() override;
    bool holdBefore(int program, int frameIndex, int line) override;
    void message(const FrameRef& f, int k) override { run_.message(f, k); }
    bool mFunctions(const FrameRef& f, std::span<const int> codes) override {
        return run_.mFunctions(f, codes);
    }
    void motionBegins() override {}
    bool move(AxisUnit& u, double from, double to, double speed, std::int64_t feedDisc,
              bool handwheel) override {
        return run_.move(u, from, to, speed, feedDisc, handwheel);
    }
    bool oscillate(AxisUnit& u, Oscillation& osc, double lo, double hi, double speed,
                   bool towardsHi, const OscillationPresets& presets,
                   std::int64_t feedDisc) override {
        return run_.oscillate(u, osc, lo, hi, speed, towardsHi, presets, feedDisc);
    }
    bool dwell(const FrameRef& f, std::int64_t ms) override { return run_.dwell(f, ms); }
    void motionEnds(const FrameRef&, PreviewKind) override {}
    bool stopAtM00() override { return true; }

private:
    RunOutput run_;
    DebugGate* gate_ = nullptr;
};

// Instant axes, reported to a sink.
class PreviewOutput final : public ProgramOutput {
public:
    explicit PreviewOutput(Core& core) : c_(core) {}
    void setSink(PreviewSink* sink) { sink_ = sink; }
    // Holds the program before frame `frameIndex` of `program` the `pass`-th
    // time it is reached (a start from a frame: engine/start_point.h);
    // frameIndex -1: never.
    void stopBefore(int program, int frameIndex, int pass) {
        stopProgram_ = program;
        stopIndex_ = frameIndex;
        stopPass_ = pass;
    }
    void started() override {}
    void resumed() override {}
    bool holdBefore(int program, int frameIndex, int) override {
        if (frameIndex != stopIndex_ || program != stopProgram_ || --stopPass_ > 0)
            return false;
        stopIndex_ = -1;
        return true;
    }
    void message(const FrameRef& f, int k) override;
    bool mFunctions(const FrameRef& f, std::span<const int> codes) override;
    void motionBegins() override { frame_ = PreviewFrame{}; }
    bool move(AxisUnit& u, double from, double to, double speed, std::int64_t feedDisc,
              bool handwheel) override;
    bool oscillate(AxisUnit& u, Oscillation& osc, double lo, double hi, double speed,
                   bool towardsHi, const OscillationPresets& presets,
                   std::int64_t feedDisc) override;
    bool dwell(const FrameRef& f, std::int64_t ms) override;
    void motionEnds(const FrameRef& f, PreviewKind kind) override;
    bool stopAtM00() override { return false; }

private:
    Core& c_;
    PreviewSink* sink_ = nullptr;
    PreviewFrame frame_; // the motion of the frame in progress
    int stopProgram_ = 0, stopIndex_ = -1, stopPass_ = 0;
};

} // namespace k528::engine
