#include "training/cutting.h"

#include "training/geometry.h"

#include <algorithm>
#include <cmath>

namespace k528::training {

std::string_view collisionName(CollisionKind k) {
    switch (k) {
    case CollisionKind::RapidIntoMaterial:
        return "rapid_into_material";
    case CollisionKind::ManualIntoMaterial:
        return "manual_into_material";
    case CollisionKind::CutWithoutSpindle:
        return "cut_without_spindle";
    case CollisionKind::ToolIntoChuck:
        return "tool_into_chuck";
    case CollisionKind::RapidIntoRing:
        return "rapid_into_ring";
    }
    return "";
}

bool SpindleTimeline::runningAt(double t) const {
    bool on = runningAtStart;
    for (double c : changesMs) {
        if (c > t)
            break;
        on = !on;
    }
    return on;
}

bool SpindleTimeline::runningThrough(double t0, double t1) const {
    if (!runningAt(t0))
        return false;
    for (double c : changesMs)
        if (c > t0 && c <= t1)
            return false;
    return true;
}

namespace {
using namespace geo;

// The thickness of a region taken out: the smaller side of its box.
double thickness(const Multi& m) {
    Box b;
    bg::envelope(m, b);
    return std::min(b.max_corner().x() - b.min_corner().x(),
                    b.max_corner().y() - b.min_corner().y());
}
// Where the tip was when the tool first met the material on its way from a
// to b (the sweep grows with the way: halving finds the moment).
stock::PointZR entry(const Multi& material, stock::PointZR a, stock::PointZR b,
                     const stock::Tool& tool) {
    const auto at = [&](double t) {
        return stock::PointZR{a.z + (b.z - a.z) * t, a.r + (b.r - a.r) * t};
    };
    const auto meets = [&](double t) {
        Multi inter;
        bg::intersection(material, polygonOf(stock::toolSweep(a, at(t), tool)), inter);
        return bg::area(inter) > 1e-9;
    };
    if (meets(0))
        return a;
    double lo = 0, hi = 1;
    for (int i = 0; i < 30 && hi - lo > 1e-6; ++i) {
        const double mid = (lo + hi) / 2;
        (meets(mid) ? hi : lo) = mid;
    }
    return at(hi);
}

} // namespace

CutResult cutAlong(const stock::Blank& blank, double blankZMm, const stock::Tool& tool,
                   const Fixture& fixture, std::span<const toolpath::ActualSample> path,
                   bool diameterX, const SpindleTimeline& spindle) {
    CutResult res;
    Multi stock = translated(multiOf(stock::Stock(blank)), blankZMm);
    std::vector<Poly> chuck;
    for (const Rect& r : fixture.parts)
        chuck.push_back(rect(r.z0, r.z1, r.r0, r.r1));
    Box chuckBox;
    bool haveChuck = !chuck.empty();
    if (haveChuck) {
        Multi all;
        for (const Poly& c : chuck)
            all.push_back(c);
        bg::envelope(all, chuckBox);
    }
    const double toR = diameterX ? 0.5 : 1.0;
    // One collision of a kind per frame (a crash is named once, where it began).
    const auto already = [&](CollisionKind k, const toolpath::ActualSample& s) {
        for (const Collision& c : res.collisions)
            if (c.kind == k && c.program == s.program && c.line == s.line && c.n == s.n)
                return true;
        return false;
    };
    for (std::size_t i = 1; i < path.size(); ++i) {
        const toolpath::ActualSample& a = path[i - 1];
        const toolpath::ActualSample& b = path[i];
        // The stretch a -> b belongs to b's frame (the decimator starts each
        // frame with its first sample).
        const stock::PointZR pa{a.z, a.x * toR}, pb{b.z, b.x * toR};
        const stock::Ring sweepRing = stock::toolSweep(pa, pb, tool);
        const Poly sweep = polygonOf(sweepRing);
        Box sb;
        bg::envelope(sweep, sb);
        if (haveChuck && bg::intersects(sb, chuckBox) && !already(CollisionKind::ToolIntoChuck, b)) {
            for (const Poly& c : chuck) {
                Multi inter;
                bg::intersection(sweep, c, inter);
                if (bg::area(inter) > 1e-9) {
                    res.collisions.push_back(
                        {CollisionKind::ToolIntoChuck, b.program, b.line, b.n, pb, thickness(inter),
                         bg::area(inter)});
                    break;
                }
            }
        }
        if (stock.empty())
            continue;
        Box stockBox;
        bg::envelope(stock, stockBox);
        if (!bg::intersects(sb, stockBox))
            continue;
        Multi taken;
        bg::intersection(stock, sweep, taken);
        const double area = bg::area(taken);
        if (area <= 1e-9)
            continue;
        const double thick = thickness(taken);
        if (thick >= kPenetrationMm) {
            CollisionKind k = CollisionKind::RapidIntoMaterial;
            bool crash = false;
            if (b.manual) {
                k = CollisionKind::ManualIntoMaterial;
                crash = true;
            } else if (b.kind == toolpath::SegmentKind::Rapid) {
                crash = true;
            } else if (!spindle.runningThrough(a.tMs, b.tMs)) {
                k = CollisionKind::CutWithoutSpindle;
                crash = true;
            }
            if (crash && !already(k, b))
                res.collisions.push_back({k, b.program, b.line, b.n, entry(stock, pa, pb, tool),
                                          thick, area});
        }
        Multi left;
        bg::difference(stock, sweep, left);
        stock = std::move(left);
        res.removedMm2 += area;
        res.removals.push_back({sweepRing, b.kind, b.manual, b.program, b.line, b.n, area});
    }
    res.finished = shapesOf(stock);
    return res;
}

} // namespace k528::training
