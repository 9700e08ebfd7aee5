// The prove-out's rules (rules.h) along the path a machine actually took —
// what the grade of a student's attempt needs (core/training) — with the
// material it removed.
//
// The path is the decimated actual path of a run (toolpath::ActualSample:
// the tip in the program's coordinates, what moved it — G00, G01, the
// operator — and the frame). Each stretch between two samples sweeps the
// tool (stock::toolSweep: the convex hull of the tool's rectangle at both
// ends) and takes what it covers out of the stock, in the order the tool
// moved. Where the tool meets the material is decided as for a program's
// path (rules.h firstMeeting, over the prove-out's 0.01 mm columns of
// material.h); the polygons keep the part's exact shape for the drawing. A
// stretch that meets the material breaks the rule materialRule() names for
// its motion (a rapid, the operator's move, a feed with the spindle stopped)
// when it goes at least kPenetrationMm into it (Cut::penetrationMm): a retract
// grazing the finished surface within the servo's tolerance breaks none — the
// actual path lags the programmed one, the preview's path (proveout.h) does
// not. A stretch whose tool runs into the
// chuck (chuckContact) breaks tool-into-chuck. Each collision names its rule,
// its frame (program, line, N) and where the tip was.
#pragma once

#include "proveout/geometry.h"
#include "proveout/rules.h"
#include "stock/stock.h"
#include "toolpath/actual_path.h"

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace k528::proveout {

// A polygon of the half profile: its outer ring and its holes.
struct Shape {
    stock::Ring outer;
    std::vector<stock::Ring> holes;
};

struct Collision {
    Rule rule = Rule::RapidIntoMaterial;
    std::string_view text;            // its text's id (proveout::texts(): "tool-into-chuck.jaws")
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

// The servo's tolerance: a region thinner than this taken out by a rapid is
// the lag of a retract along the finished surface, not a collision.
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
// diameter when `diameterX`; `chuck` in the path's coordinates (not present:
// no chuck rule), gripping the blank.
CutResult cutAlong(const stock::Blank& blank, double blankZMm, const stock::Tool& tool,
                   const ChuckGeometry& chuck, std::span<const toolpath::ActualSample> path,
                   bool diameterX, const SpindleTimeline& spindle);

} // namespace k528::proveout
