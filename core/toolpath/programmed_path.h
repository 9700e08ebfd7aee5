// The programmed toolpath (shared/spec/cli.md `k528 path`): the
// engine's own interpreter runs the program in preview (engine/preview.h,
// instant axes) and every motion frame becomes a segment — program, frame N,
// source line, kind, feeds and its corner points in mm as the panel shows
// them (current coordinates, X as a diameter on a diameter axis).
//
// The K528-05 is a positioner (manual 1.1.3): in a frame that moves X and Z
// each axis runs at its own speed (G01: its FX/FZ; G00: its F УСК.АВТ.), so
// the segment has a corner where the first axis arrives (a dogleg).
// Acceleration is not modelled. An oscillation (Gx81) is drawn as its
// stroke: start, the far reverse point, the near one. Dwells, the M
// functions and the technological messages are recorded in program order
// beside the segments (each names the segment it precedes), so a reader of
// the path (collision checks, a start from a frame) sees what the machine
// does between the moves.
//
// Software limits: C46/C47 (X) and C98/C99 (Z), machine system. A segment
// with a point beyond them (on an axis whose ВКЛ.ПРГ.КОН C10/C62 is on) is
// `outside` («ВНЕ ГРАНИЦ»). Storage is flat (one point array) so that a
// million segments fit in ~50 MB.
#pragma once

#include "engine/preview_run.h"

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace k528::toolpath {

enum class SegmentKind : std::uint8_t { Rapid, Feed, Oscillation, Signal, Handwheel };
std::string_view kindName(SegmentKind k); // "rapid", "feed", "oscillation", "signal", "handwheel"

struct PointMm {
    double x = 0, z = 0;
};

inline constexpr double kNoFeed = std::numeric_limits<double>::quiet_NaN();

struct Segment {
    int program = 0, line = 0, n = 0;
    SegmentKind kind = SegmentKind::Feed;
    bool outside = false;
    std::uint8_t pointCount = 0;
    std::uint32_t firstPoint = 0; // into ProgrammedPath::points
    float feedXMmMin = kNoFeed, feedZMmMin = kNoFeed; // programmed feed of a moving axis, NaN none
    float durationS = 0; // without acceleration: the slower axis' time (an oscillation: one double stroke)
    std::uint64_t frameIndex = 0; // order of the frame among the motion frames
};

struct Dwell {
    int program = 0, line = 0, n = 0;
    PointMm at;
    double seconds = 0;
    std::uint32_t segment = 0; // the segments before it (it comes before segments[segment])
};

// The M functions of a frame, handed to the PLC before the frame's motion:
// they come before segments[segment] (the frame's own segment, if it moves).
struct MFunctions {
    int program = 0, line = 0, n = 0;
    std::array<int, 3> codes{};
    int count = 0;
    std::uint32_t segment = 0;
};

// A frame's technological message #number (LCD line 2 from there on).
struct Message {
    int program = 0, line = 0, n = 0;
    int number = 0;
    std::uint32_t segment = 0;
};

// R207 (ТЕК.ДИАМЕТР КРУГА, the grinding wheel's current diameter) from
// segment `segment` on; recorded where it changes (dressing lowers it), the
// first entry at segment 0. Empty when R207 stays 0 (no wheel: a lathe).
struct WheelChange {
    std::uint32_t segment = 0;
    double diameterMm = 0;
};

// The coordinate components of an axis (manual 2.4, R224..R231) in mm as the
// panel shows them (X as a diameter on a diameter axis), and `active`, the
// sum of those in effect (G50..G53 leave one out): machine = current + active.
struct AxisComponentsMm {
    double dressing = 0, correction = 0, zeroOffset = 0, drf = 0;
    double active = 0;
    bool operator==(const AxisComponentsMm&) const = default;
};

// The components of both axes from segment `segment` on; recorded where they
// change, the first entry at segment 0 (a path with motion has one at least).
// Where the tool's tip and the part lie in the machine follows from them
// (core/proveout).
struct ComponentsChange {
    std::uint32_t segment = 0;
    std::array<AxisComponentsMm, 2> axes{};
};

struct AxisLimits {
    bool present = false;
    bool on = false;          // ВКЛ.ПРГ.КОН
    double minMm = 0, maxMm = 0; // machine system
    double offsetMm = 0;      // machine − current at the start (to draw them in current coordinates)
};

struct ProgrammedPath {
    int program = 0;
    std::vector<Segment> segments;
    std::vector<PointMm> points;
    std::vector<Dwell> dwells;
    std::vector<MFunctions> mFunctions; // in program order, with dwells and segments by `segment`
    std::vector<Message> messages;
    std::vector<WheelChange> wheel;
    std::vector<ComponentsChange> components;
    AxisLimits limitX, limitZ;
    bool diameterX = false;
    PointMm start, end;
    engine::PreviewResult run;

    std::size_t size() const { return segments.size(); }
    const PointMm* pointsOf(const Segment& s) const { return points.data() + s.firstPoint; }
    // The wheel's diameter (mm) during segment i, 0 if none.
    double wheelDiameterAt(std::size_t i) const;
    // The components during segment i (all 0 before the first motion).
    const ComponentsChange& componentsAt(std::size_t i) const;
};

struct PathOptions {
    engine::PreviewOptions preview;
};

ProgrammedPath programmedPath(const profile::MachineProfile& profile,
                              const program::ProgramStore& programs, int number,
                              const PathOptions& options = {});

} // namespace k528::toolpath
