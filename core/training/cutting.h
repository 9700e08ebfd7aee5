// Material removal and the collision rules along the tool's actual path —
// what grading needs of a prove-out now, written as one small function over
// the path and the stock so that it can move to core/proveout (the general
// collision rules) as it is: it knows nothing of exercises or grades.
//
// The path is the decimated actual path of a run (toolpath::ActualSample:
// the tip in the program's coordinates, what moved it — G00, G01, the
// operator — and the frame). Each stretch between two samples sweeps the
// tool (stock::toolSweep: the convex hull of the tool's rectangle at both
// ends) and takes what it covers out of the stock, in the order the tool
// moved. A stretch that takes material out counts as
//   - a rapid into the material: a program's G00 that takes out a region
//     at least kPenetrationMm thick in both directions (a retract grazing
//     the finished surface within the servo's tolerance is not one);
//   - a manual move into the material: the same by the operator (jog,
//     handwheel, the reference-point cycle);
//   - a cut with the spindle stopped: a G01 that takes material while the
//     spindle does not turn;
// and a stretch whose sweep meets the chuck's body or jaws is the tool in
// the chuck. Each collision names its frame (program, line, N) and where
// the tip was.
#pragma once

#include "stock/stock.h"
#include "toolpath/actual_path.h"

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace k528::training {

// A polygon of the half profile: its outer ring and its holes.
struct Shape {
    stock::Ring outer;
    std::vector<stock::Ring> holes;
};

// The chuck as rectangles of the half profile (z0, z1, r0, r1).
struct Rect {
    double z0 = 0, z1 = 0, r0 = 0, r1 = 0;
};
struct Fixture {
    std::vector<Rect> parts; // the chuck's body and its jaws
};

enum class CollisionKind : std::uint8_t {
    RapidIntoMaterial,
    ManualIntoMaterial,
    CutWithoutSpindle,
    ToolIntoChuck,
    RapidIntoRing, // the grinder's wheel (found by the attempt, training/attempt.h)
};
std::string_view collisionName(CollisionKind k); // "rapid_into_material", ...

struct Collision {
    CollisionKind kind = CollisionKind::RapidIntoMaterial;
    int program = 0, line = 0, n = 0; // 0: the operator's move
    stock::PointZR at;                // the tip where it happened (z, r)
    double depthMm = 0;               // how far into the material or the chuck
    double areaMm2 = 0;
};

// A stretch of the path that took material out: its sweep and its frame.
struct Removal {
    stock::Ring sweep;
    toolpath::SegmentKind kind = toolpath::SegmentKind::Feed;
    bool manual = false;
    int program = 0, line = 0, n = 0;
    double areaMm2 = 0;
};

struct CutResult {
    std::vector<Shape> finished; // the stock after the whole path
    std::vector<Collision> collisions;
    std::vector<Removal> removals; // in the order the tool moved
    double removedMm2 = 0;
};

inline constexpr double kPenetrationMm = 0.02;

// When the spindle turned: it was `runningAtStart`, and changed at each of
// `changesMs` (in order).
struct SpindleTimeline {
    std::vector<double> changesMs;
    bool runningAtStart = false;
    bool runningAt(double tMs) const;
    // Turning all the time from t0 to t1.
    bool runningThrough(double t0Ms, double t1Ms) const;
};

// `blank` placed with its part zero at `blankZMm`; the path's X is a
// diameter when `diameterX`.
CutResult cutAlong(const stock::Blank& blank, double blankZMm, const stock::Tool& tool,
                   const Fixture& fixture, std::span<const toolpath::ActualSample> path,
                   bool diameterX, const SpindleTimeline& spindle);

} // namespace k528::training
