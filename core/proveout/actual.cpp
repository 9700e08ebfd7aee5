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
} // namespace

CutResult cutAlong(const stock::Blank& blank, double blankZMm, const stock::Tool& tool,
                   const ChuckGeometry& chuck, std::span<const toolpath::ActualSample> path,
                   bool diameterX, const SpindleTimeline& spindle) {
    CutResult res;
    // The material twice, for two jobs: the prove-out's columns decide where
    // the tool meets it (rules.h, the same as for a program's path); the
    // polygons keep the part's exact shape for the drawing (the grade's over-
    // and under-cut) and what each stretch took out of it.
    LatheMaterial material(blank); // in the part's Z: the path's Z − blankZMm
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
        // The material: first where the tool meets it, then the cut.
        const PointZR ma{pa.z - blankZMm, pa.r}, mb{pb.z - blankZMm, pb.r};
        if (material.mayTouch(toolBox.sweptBounds(ma, mb))) {
            Sweep sweep(toolBox, ma, mb);
            const auto at = [&](double t) {
                return PointZR{ma.z + (mb.z - ma.z) * t, ma.r + (mb.r - ma.r) * t};
            };
            std::optional<PointZR> entry;
            if (material.touches(sweep))
                entry = at(firstMeeting(material, toolBox, ma, at));
            const LatheMaterial::Cut cut = material.cut(sweep, mb.z - ma.z, mb.r - ma.r);
            if (entry && cut.penetrationMm() >= kPenetrationMm) {
                const Motion motion = b.manual ? Motion::Manual
                                      : b.kind == toolpath::SegmentKind::Rapid ? Motion::Rapid
                                                                                 : Motion::Feed;
                const bool turning = motion == Motion::Feed && spindle.runningThrough(a.tMs, b.tMs);
                if (const std::optional<Rule> rule = materialRule(motion, turning, false);
                    rule && !already(*rule, b))
                    res.collisions.push_back({*rule, ruleId(*rule), b.program, b.line, b.n,
                                              {entry->z + blankZMm, entry->r}, cut.penetrationMm(), cut.areaMm2});
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
