// Start from a frame (docs/engine.md, "Start from a frame"): the state of a
// program before one of its frames, as the preview (engine/preview_run.h,
// findStartPoint) rebuilds it by running the one interpreter up to that
// frame, and what a start from it does on the machine (Positioner::
// setStartPoint): the R-parameters the program wrote up to the frame are
// set, the M functions it handed to the PLC are handed again in order, the
// axes go to the frame's start point by a safe path — X to its reference
// point (ЗНАЧЕНИЕ БТ, where the reference-point cycle leaves it: away from
// the part), then Z, then X — at the rapid speed, and the program continues
// with the frame, its modal state and call stack as they were.
#pragma once

#include "engine/interpreter.h"
#include "units/units.h"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace k528::engine {

// A frame of a program: `pass` counts the times the frame is reached (a
// frame of a loop or of a subprogram called again), 1 = the first.
struct FrameTarget {
    int program = 0;
    int frameIndex = 0;
    int pass = 1;
};

// A level of the call stack at the start frame: `program` called the next
// level from its frame `returnIndex - 1`.
struct StartLevel {
    int program = 0;
    int returnIndex = 0;
};

struct StartAxis {
    bool present = false;
    units::AxisScale scale;
    std::int64_t machineDisc = 0;    // where the axis stands before the frame (machine system)
    std::int64_t currentDisc = 0;    // the same as the panel shows it
    std::int64_t programmedDisc = 0; // the last programmed target (G91 adds to it)
};

struct StartPoint {
    int mainProgram = 0;
    std::vector<StartLevel> callers; // outermost first; empty in the main program
    int program = 0, frameIndex = 0, frameNumber = 0, line = 0, pass = 1;
    ModalState modal;
    std::vector<std::pair<int, std::int32_t>> r; // R the program changed before the frame
    std::array<std::int32_t, 8> components{};    // R224..R231 before the frame
    int messageNumber = 0;                       // technological message #k in effect
    std::vector<int> mFunctions;                 // handed to the PLC before the frame, in order
    std::array<StartAxis, 2> axes{};
    std::int64_t framesBefore = 0; // frames executed before it
    int oscillatingAxis = -1;      // the frame runs while it oscillates (Gx81 .. Gx80)
    // Frames whose end on the machine the preview cannot know: a move until
    // a signal (Gx36..Gx39) or by handwheel (Gx10) ended, in the preview, at
    // its programmed point; the start point follows from it.
    struct Uncertain {
        int program = 0, line = 0, n = 0;
        int axis = 0;
    };
    std::vector<Uncertain> uncertain;
};

// The M functions a start hands to the PLC again: every M the program
// handed before the frame, in order, but the ones of program control (M00,
// M02, M17, M30), which the interpreter acts on itself.
bool replayedMFunction(int code);

} // namespace k528::engine
