// The collision rules of the prove-out, in one place for every caller: the
// check of a program before the machine runs it (proveout.h, over the
// preview's path) and the grade of a student's attempt (core/training, over
// the path the simulated machine actually took). Each rule has a stable id
// (docs/proveout.md); which rule a motion into the part's material breaks,
// where a moving body first meets that material (the 0.01 mm columns of
// material.h), what the chuck is made of and when a moving body runs into it
// are decided here, so that a program and its attempt are judged by the same
// rules and the same material.
#pragma once

#include "proveout/geometry.h"
#include "proveout/material.h"
#include "proveout/sweep.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace k528::proveout {

enum class Rule : std::uint8_t {
    RapidIntoMaterial,
    ToolIntoChuck,
    TurretIntoChuck,
    FeedSpindleStopped,
    FeedWheelStopped,
    CutTooDeep,
    ManualIntoMaterial, // the operator's move (jog, handwheel, homing): only on a real or simulated run
};
std::string_view ruleId(Rule r); // "rapid-into-material", …
std::span<const Rule> allRules();

// What moved the tool.
enum class Motion : std::uint8_t {
    Rapid,  // a program's G00 (the positioner's dogleg included)
    Feed,   // a program's feed (G01, a move to a signal, an oscillation)
    Manual, // the operator: jog, handwheel, the reference-point cycle
};

// The rule a motion breaks when it takes the tool into the part's material
// (the blank, the grinder's ring): a rapid, an operator's move, a feed while
// the spindle that cuts (the grinder's wheel) stands. None: an ordinary cut.
std::optional<Rule> materialRule(Motion m, bool cuttingSpindleTurning, bool grinder);

// The chuck as boxes of the half profile: its jaws gripping a part of
// `gripDiameterMm` (0: the chuck's own grip diameter) and its body. The
// chuck turns: a body reaches both sides of the spindle's axis (mirrored()).
struct ChuckBoxes {
    Box jaws, body;
};
ChuckBoxes chuckBoxes(const ChuckGeometry& c, double gripDiameterMm);

// Overlaps closer than this are the arithmetic's, not a contact (mm).
inline constexpr double kContactEpsMm = 1e-4;

// Where `box` (relative to the moving point) moving straight from `a` to `b`
// first runs into the chuck: not at all, its jaws or its body. A move that
// starts inside (a collision found where it began) runs into nothing new.
enum class ChuckContact : std::uint8_t { None, Jaws, Body };
struct ChuckHit {
    ChuckContact part = ChuckContact::None;
    Box obstacle; // the jaw or body box met (mirrored when below the axis)
};
ChuckHit chuckContact(const ChuckBoxes& chuck, const Box& box, PointZR a, PointZR b);

// The smallest t in (0, 1] at which `hit(t)` holds, hit(1) holding (30 halvings).
template <class Hit> double firstContact(const Hit& hit) {
    double lo = 0, hi = 1;
    for (int i = 0; i < 30; ++i) {
        const double mid = (lo + hi) / 2;
        if (hit(mid))
            hi = mid;
        else
            lo = mid;
    }
    return hi;
}

// Where a body moving straight from `a` to `b`, whose sweep touches the
// part's material (LatheMaterial::touches, read before the motion cuts it),
// first meets it: t of the way (`at(t)`: where the moving point is then).
// The one contact rule for the preview's path and the path a machine took.
template <class At>
double firstMeeting(const LatheMaterial& m, const Box& body, PointZR a, const At& at) {
    return firstContact([&](double t) {
        Sweep part(body, a, at(t));
        return m.touches(part);
    });
}

} // namespace k528::proveout
