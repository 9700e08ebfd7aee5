// Preview mode of the one interpreter: the engine runs a program with
// instant axes — every move arrives at once, M functions are acknowledged
// at once, dwells, M00 and moves-until-signal take no waiting — and its
// output (engine/program_output.h, PreviewOutput) reports, in the order the
// program runs, each frame's motion, dwell, M functions and technological
// message to a PreviewSink. Everything else (R arithmetic, jumps, calls,
// G90/G91, Gx92, the coordinate components, the diameter axis, the run-time
// checks and their messages) is the run's own code. Start it through
// engine/preview_run.h; toolpath/programmed_path.h collects it all.
#pragma once

#include "engine/coordinates.h"

#include <array>
#include <cstdint>

namespace k528::engine {

enum class PreviewKind : std::uint8_t { Rapid, Feed, Oscillation, Signal, Handwheel };

// One axis of a frame's motion, in display discretes of the axis (machine
// system); `offsetDisc` = machine − current at that frame (the active
// coordinate components), so current = machine − offset. An axis that does
// not move has from = to = where it stands.
struct PreviewAxisMotion {
    bool moves = false;
    std::int64_t fromDisc = 0, toDisc = 0;
    std::int64_t offsetDisc = 0;
    // The coordinate components of the axis (R224..R231) when the frame
    // moves, whether in effect or left out: where the tool's tip and the part
    // lie in the machine (core/proveout).
    Components components{};
    double speedDiscPerMin = 0; // the speed the axis runs at (feed or rapid, capped)
    double feedDiscPerMin = -1; // the programmed feed (FX/FZ), -1 none (G00)
    // Oscillation: the two reverse points.
    std::int64_t oscLoDisc = 0, oscHiDisc = 0;
};

struct PreviewFrame {
    int program = 0, line = 0, n = 0;
    PreviewKind kind = PreviewKind::Feed;
    std::array<PreviewAxisMotion, 2> axes{};
    // R207 ТЕК.ДИАМЕТР КРУГА when the frame starts: the grinding wheel's
    // current diameter in X discretes (without the diameter axis' halving).
    std::int64_t wheelDiameterDisc = 0;
};

struct PreviewDwell {
    int program = 0, line = 0, n = 0;
    std::int64_t ms = 0;
};

// The M functions of a frame, in the order written (handed to the PLC when
// the frame starts, before its motion).
struct PreviewMFunctions {
    int program = 0, line = 0, n = 0;
    std::array<int, 3> codes{};
    int count = 0;
};

// A frame's technological message #k (from this frame on, LCD line 2).
struct PreviewMessage {
    int program = 0, line = 0, n = 0;
    int number = 0;
};

// What the preview reports, frame by frame in program order: a frame's M
// functions and message come before its motion or dwell.
class PreviewSink {
public:
    virtual ~PreviewSink() = default;
    virtual void motion(const PreviewFrame& f) = 0;
    virtual void dwell(const PreviewDwell& d) = 0;
    virtual void mFunctions(const PreviewMFunctions&) {}
    virtual void message(const PreviewMessage&) {}
};

} // namespace k528::engine
