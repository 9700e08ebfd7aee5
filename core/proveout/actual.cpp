#include "proveout/actual.h"

#include "proveout/polygons.h"

#include <algorithm>
#include <cmath>

namespace k528::proveout {

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
namespace bg = boost::geometry;
using geo::Multi;
using geo::polygonOf;

// The thickness of a region taken out: the smaller side of its box.
double thickness(const Multi& m) {
    geo::Box b;
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
                   const ChuckGeometry& chuck, std::span<const toolpath::ActualSample> path,
                   bool diameterX, const SpindleTimeline& spindle) {
    CutResult res;
    Multi stock = geo::translated(geo::multiOf(stock::Stock(blank)), blankZMm);
    const ChuckBoxes chuckParts = chuckBoxes(chuck, blank.outerDiameterMm);
    const Box toolBox{0, tool.widthMm, 0, tool.heightMm};
    const double toR = diameterX ? 0.5 : 1.0;
    // One collision of a rule per frame (a crash is named once, where it began).
    const auto already = [&](Rule r, const toolpath::ActualSample& s) {
        for (const Collision& c : res.collisions)
            if (c.rule == r && c.program == s.program && c.line == s.line && c.n == s.n)
                return true;
        return false;
    };
    for (std::size_t i = 1; i < path.size(); ++i) {
        const toolpath::ActualSample& a = path[i - 1];
        const toolpath::ActualSample& b = path[i];
        // The stretch a -> b belongs to b's frame (the decimator starts each
        // frame with its first sample).
        const stock::PointZR pa{a.z, a.x * toR}, pb{b.z, b.x * toR};
        if (chuck.present && !already(Rule::ToolIntoChuck, b)) {
            const PointZR ca{pa.z, pa.r}, cb{pb.z, pb.r};
            const ChuckHit hit = chuckContact(chuckParts, toolBox, ca, cb);
            if (hit.part != ChuckContact::None) {
                const auto at = [&](double t) {
                    return PointZR{ca.z + (cb.z - ca.z) * t, ca.r + (cb.r - ca.r) * t};
                };
                const PointZR where = at(firstContact([&](double t) {
                    return Sweep(toolBox, ca, at(t)).overlaps(hit.obstacle, kContactEpsMm);
                }));
                const Box end = toolBox.moved(cb);
                const Box& o = hit.obstacle;
                const double depth = std::max(
                    0.0, std::min(std::min(end.z1, o.z1) - std::max(end.z0, o.z0),
                                  std::min(end.r1, o.r1) - std::max(end.r0, o.r0)));
                res.collisions.push_back({Rule::ToolIntoChuck,
                                          hit.part == ChuckContact::Jaws ? "tool-into-chuck.jaws"
                                                                         : "tool-into-chuck.body",
                                          b.program, b.line, b.n, {where.z, where.r}, depth, 0});
            }
        }
        if (stock.empty())
            continue;
        const stock::Ring sweepRing = stock::toolSweep(pa, pb, tool);
        const geo::Poly sweep = polygonOf(sweepRing);
        geo::Box sb, stockBox;
        bg::envelope(sweep, sb);
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
            const Motion motion = b.manual ? Motion::Manual
                                  : b.kind == toolpath::SegmentKind::Rapid ? Motion::Rapid
                                                                             : Motion::Feed;
            const bool turning = motion == Motion::Feed && spindle.runningThrough(a.tMs, b.tMs);
            if (const std::optional<Rule> rule = materialRule(motion, turning, false);
                rule && !already(*rule, b))
                res.collisions.push_back({*rule, ruleId(*rule), b.program, b.line, b.n,
                                          entry(stock, pa, pb, tool), thick, area});
        }
        Multi left;
        bg::difference(stock, sweep, left);
        stock = std::move(left);
        res.removedMm2 += area;
        res.removals.push_back({sweepRing, b.kind, b.manual, b.program, b.line, b.n, area});
    }
    res.finished = geo::shapesOf(stock);
    return res;
}

} // namespace k528::proveout
