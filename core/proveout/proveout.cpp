#include "proveout/proveout.h"

#include "profile/problem.h"
#include "proveout/material.h"
#include "proveout/sweep.h"
#include "proveout/tool_change.h"
#include "units/units.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <tuple>

namespace k528::proveout {

namespace {

// clang-format off
constexpr Text kTexts[] = {
    {"rapid-into-material",
     "Быстрый ход (G00) входит в материал заготовки: X%1 Z%2",
     "A rapid (G00) enters the material of the blank: X%1 Z%2"},
    {"rapid-into-material.dogleg",
     "Быстрый ход (G00) входит в материал на изломе: ось %3 приходит первой (X%1 Z%2), хотя обе точки кадра вне заготовки",
     "A rapid (G00) enters the material at its dogleg: axis %3 arrives first (X%1 Z%2), although both end points are outside the blank"},
    {"rapid-into-material.ring",
     "Быстрый ход (G00) вводит круг в материал кольца: X%1 Z%2",
     "A rapid (G00) takes the wheel into the ring's material: X%1 Z%2"},
    {"tool-into-chuck.jaws",
     "Инструмент T%3 задевает кулачки патрона: X%1 Z%2",
     "Tool T%3 runs into the chuck's jaws: X%1 Z%2"},
    {"tool-into-chuck.body",
     "Инструмент T%3 задевает корпус патрона: X%1 Z%2",
     "Tool T%3 runs into the chuck's body: X%1 Z%2"},
    {"turret-into-chuck.jaws",
     "Резцедержатель задевает кулачки патрона (инструмент T%3 у X%1 Z%2)",
     "The turret runs into the chuck's jaws (tool T%3 at X%1 Z%2)"},
    {"turret-into-chuck.body",
     "Резцедержатель задевает корпус патрона (инструмент T%3 у X%1 Z%2)",
     "The turret runs into the chuck's body (tool T%3 at X%1 Z%2)"},
    {"feed-spindle-stopped",
     "Рабочая подача в материал при остановленном шпинделе: X%1 Z%2",
     "A feed into the material with the spindle stopped: X%1 Z%2"},
    {"feed-wheel-stopped",
     "Рабочая подача в материал кольца при остановленном круге: X%1 Z%2",
     "A feed into the ring's material with the wheel stopped: X%1 Z%2"},
    {"manual-into-material",
     "Ручное перемещение вводит инструмент в материал заготовки: X%1 Z%2",
     "A manual move takes the tool into the material of the blank: X%1 Z%2"},
    {"cut-too-deep",
     "Глубина резания %1 мм больше допустимой для инструмента T%2 (%3 мм)",
     "A cut %1 mm deep, deeper than tool T%2 takes (%3 mm)"},
};
// clang-format on

const Text* findText(std::string_view id) {
    for (const Text& t : kTexts)
        if (t.id == id)
            return &t;
    return nullptr;
}

// A length in mm as the panel shows it: up to 3 decimals, no trailing zeros.
std::string mm(double v) {
    return units::formatTrimmed(std::round(v * 1000) / 1000, 3);
}

// The tool's body relative to its tip, in (z, r).
Box bodyOf(const profile::Tool& t) {
    if (t.kind == profile::ToolKind::Drill)
        return {t.zDirection > 0 ? 0 : -t.widthMm, t.zDirection > 0 ? t.widthMm : 0,
                -t.heightMm / 2, t.heightMm / 2};
    Box b;
    b.z0 = t.zDirection > 0 ? 0 : -t.widthMm;
    b.z1 = t.zDirection > 0 ? t.widthMm : 0;
    b.r0 = t.xDirection > 0 ? 0 : -t.heightMm;
    b.r1 = t.xDirection > 0 ? t.heightMm : 0;
    return b;
}

struct Leg {
    toolpath::PointMm a, b; // the path's coordinates (what the finding names)
};

class Prover {
public:
    Prover(const toolpath::ProgrammedPath& path, const MachineGeometry& g, const Options& o)
        : path_(path), g_(g), o_(o) {
        toR_ = path.diameterX ? 0.5 : 1.0;
        if (o.blank && !g.ring.present) {
            material_ = std::make_unique<LatheMaterial>(*o.blank, o.resolutionMm);
            res_.material = true;
        }
        if (g.ring.present) {
            boreR_ = g.ring.blankBoreMm / 2;
            res_.material = true;
        }
        if (g.chuck.present) {
            res_.chuck = true;
            chuck_ = chuckBoxes(g.chuck, o.blank ? o.blank->outerDiameterMm : 0.0);
        }
        for (const std::string& s : o.spindlesRunning)
            running_.push_back(s);
        station_ = g.firstStation;
    }

    Result run() {
        std::size_t m = 0;
        for (std::size_t i = 0; i < path_.segments.size(); ++i) {
            for (; m < path_.mFunctions.size() && path_.mFunctions[m].segment <= i; ++m)
                mFunctions(path_.mFunctions[m]);
            segment(i);
        }
        return std::move(res_);
    }

private:
    void mFunctions(const toolpath::MFunctions& f) {
        for (int k = 0; k < f.count; ++k) {
            const int code = f.codes[static_cast<std::size_t>(k)];
            for (const SpindleUse& s : g_.spindles) {
                const bool on = std::find(s.on.begin(), s.on.end(), code) != s.on.end();
                const bool off = std::find(s.off.begin(), s.off.end(), code) != s.off.end();
                auto it = std::find(running_.begin(), running_.end(), s.name);
                if (on && it == running_.end())
                    running_.push_back(s.name);
                if (off && it != running_.end())
                    running_.erase(it);
            }
        }
        station_ = stationAfter(g_, f, station_);
    }

    bool turning(const std::string& name) const {
        return name.empty() ||
               std::find(running_.begin(), running_.end(), name) != running_.end();
    }

    void segment(std::size_t i) {
        const toolpath::Segment& s = path_.segments[i];
        const toolpath::ComponentsChange& c = path_.componentsAt(i);
        const toolpath::AxisComponentsMm& cx = c.axes[0];
        const toolpath::AxisComponentsMm& cz = c.axes[1];
        if (toolStation_ != station_) { // the tool in use changed
            toolStation_ = station_;
            const std::optional<profile::Tool> t = profile::toolAt(o_.tools, station_);
            haveTool_ = t.has_value();
            tool_ = t ? *t : profile::Tool{};
            tool_.station = station_;
        }
        double offX = cx.correction, offZ = cz.correction; // the correction taken as the offsets
        if (haveTool_ && tool_.offsetR >= 0) {
            const auto it = o_.offsets.find(station_);
            offX = it != o_.offsets.end() ? it->second.xMm : 0;
            offZ = it != o_.offsets.end() ? it->second.zMm : 0;
        }
        const Box body = bodyOf(tool_);
        const toolpath::PointMm* p = path_.pointsOf(s);
        // The frames of the leg's points: the reference point and the tool's
        // tip in the machine, the tip in the part.
        const auto refM = [&](toolpath::PointMm q) {
            return PointZR{q.z + cz.active, (q.x + cx.active) * toR_};
        };
        const auto tipM = [&](toolpath::PointMm q) {
            return PointZR{q.z + cz.active - offZ, (q.x + cx.active - offX) * toR_};
        };
        const auto tipP = [&](toolpath::PointMm q) {
            return PointZR{q.z + cz.active - offZ - cz.zeroOffset - cz.drf,
                           (q.x + cx.active - offX - cx.zeroOffset - cx.drf) * toR_};
        };
        const bool rapid = s.kind == toolpath::SegmentKind::Rapid;
        for (int k = 1; k < s.pointCount; ++k) {
            const Leg leg{p[k - 1], p[k]};
            const auto lerp = [&](double t) {
                return toolpath::PointMm{leg.a.x + (leg.b.x - leg.a.x) * t,
                                         leg.a.z + (leg.b.z - leg.a.z) * t};
            };
            // The chuck: the tool, then the turret. A move that starts where a
            // collision left the tool goes on with that collision (found
            // where it began): not again.
            if (res_.chuck) {
                chuckLeg(i, Rule::ToolIntoChuck, body, tipM(leg.a),
                         tipM(leg.b), [&](double t) { return tipM(lerp(t)); }, lerp);
                if (g_.turret.present) {
                    const TurretGeometry& t = g_.turret;
                    chuckLeg(i, Rule::TurretIntoChuck, Box{t.zMinMm, t.zMaxMm, t.rMinMm, t.rMaxMm}, refM(leg.a), refM(leg.b),
                             [&](double q) { return refM(lerp(q)); }, lerp);
                }
            }
            if (material_)
                latheLeg(i, s, leg, body, tipP, lerp, rapid);
            else if (g_.ring.present)
                ringLeg(i, s, leg, tipM, lerp, rapid, cx);
        }
    }

    // The chuck's jaws, then its body, against `box` moving from a to b
    // (at(t): where it is at t of the leg).
    template <class At, class Lerp>
    void chuckLeg(std::size_t i, Rule rule, const Box& box, PointZR a, PointZR b, const At& at,
                  const Lerp& lerp) {
        const bool tool = rule == Rule::ToolIntoChuck;
        const ChuckHit hit = chuckContact(chuck_, box, a, b);
        if (hit.part == ChuckContact::None)
            return;
        const bool jaws = hit.part == ChuckContact::Jaws;
        const Box o = hit.obstacle;
        report(rule, i,
               jaws ? (tool ? "tool-into-chuck.jaws" : "turret-into-chuck.jaws")
                    : (tool ? "tool-into-chuck.body" : "turret-into-chuck.body"),
               [&] {
                   return firstContact(
                       [&](double t) { return Sweep(box, a, at(t)).overlaps(o, kContactEpsMm); });
               },
               lerp, true);
    }

    template <class TipP, class Lerp>
    void latheLeg(std::size_t i, const toolpath::Segment& s, const Leg& leg, const Box& body,
                  const TipP& tipP, const Lerp& lerp, bool rapid) {
        const PointZR a = tipP(leg.a), b = tipP(leg.b);
        if (!material_->mayTouch(body.sweptBounds(a, b)))
            return; // through air
        Sweep sw(body, a, b);
        const std::optional<Rule> rule =
            materialRule(rapid ? Motion::Rapid : Motion::Feed, turning(g_.cuttingSpindle), false);
        // (Found before the cut takes the material away.)
        if (rule && material_->touches(sw)) {
            // The dogleg: the straight line between the frame's end points
            // misses the material, the corner does not.
            bool dogleg = false;
            std::string axis;
            if (*rule == Rule::RapidIntoMaterial && s.pointCount == 3) {
                const toolpath::PointMm* p = path_.pointsOf(s);
                const toolpath::PointMm first = p[0], last = p[s.pointCount - 1];
                Sweep chord(body, tipP(first), tipP(last));
                dogleg = !material_->touches(chord);
                axis = p[1].x == last.x ? "X" : "Z";
            }
            const std::string_view text = *rule == Rule::RapidIntoMaterial
                                              ? (dogleg ? "rapid-into-material.dogleg" : "rapid-into-material")
                                              : ruleId(*rule);
            report(*rule, i, text,
                   [&] { return firstMeeting(*material_, body, a, [&](double t) { return tipP(lerp(t)); }); },
                   lerp, true, axis);
        }
        const LatheMaterial::Cut cut = material_->cut(sw, b.z - a.z, b.r - a.r);
        res_.removedMm2 += cut.areaMm2;
        if (!rapid && tool_.maxDepthMm > 0 && cut.depthMm > tool_.maxDepthMm + 1e-3) {
            Finding* f = report(Rule::CutTooDeep, i, "cut-too-deep", [] { return 0.0; }, lerp, false);
            if (f && f->args.empty())
                f->args = {mm(cut.depthMm), std::to_string(tool_.station), mm(tool_.maxDepthMm)};
        }
    }

    template <class TipM, class Lerp>
    void ringLeg(std::size_t i, const toolpath::Segment& s, const Leg& leg, const TipM& tipM,
                 const Lerp& lerp, bool rapid, const toolpath::AxisComponentsMm& cx) {
        // The wheel's working edge (machine::Grinding): machine X + wheel −
        // the wheel at which the dressing sum was zero (R207 + R224 at the start).
        if (!referenceKnown_) {
            reference_ = path_.wheelDiameterAt(i) + cx.dressing;
            referenceKnown_ = true;
        }
        const double shift = (path_.wheelDiameterAt(i) - reference_) * toR_;
        PointZR a = tipM(leg.a), b = tipM(leg.b);
        a.r += shift;
        b.r += shift;
        const RingGeometry& ring = g_.ring;
        // The leg within the ring's Z.
        const auto edgeAt = [&](PointZR p, PointZR q, double& rMax) {
            double t0 = 0, t1 = 1;
            if (q.z != p.z) {
                double ta = (ring.zMinMm - p.z) / (q.z - p.z), tb = (ring.zMaxMm - p.z) / (q.z - p.z);
                if (ta > tb)
                    std::swap(ta, tb);
                t0 = std::max(t0, ta);
                t1 = std::min(t1, tb);
            } else if (p.z < ring.zMinMm || p.z > ring.zMaxMm) {
                return false;
            }
            if (t0 > t1)
                return false;
            rMax = std::max(p.r + (q.r - p.r) * t0, p.r + (q.r - p.r) * t1);
            return true;
        };
        double rMax = 0;
        if (!edgeAt(a, b, rMax) || rMax <= boreR_ + kContactEpsMm)
            return;
        const auto hit = [&](double t) {
            double r = 0;
            const PointZR e{a.z + (b.z - a.z) * t, a.r + (b.r - a.r) * t};
            return edgeAt(a, e, r) && r > boreR_ + kContactEpsMm;
        };
        if (const std::optional<Rule> rule =
                materialRule(rapid ? Motion::Rapid : Motion::Feed, turning(g_.cuttingSpindle), true))
            report(*rule, i, *rule == Rule::RapidIntoMaterial ? "rapid-into-material.ring" : ruleId(*rule),
                   [&] { return firstContact(hit); }, lerp, true);
        boreR_ = std::max(boreR_, rMax);
        (void)s;
    }

    // Records a finding of rule `r` at segment i (or counts it again for its
    // frame); `where()` finds the place along the leg (t), asked only for a
    // new finding.
    template <class Where, class Lerp>
    Finding* report(Rule r, std::size_t i, std::string_view text, const Where& where, const Lerp& lerp,
                    bool placeArgs,
                    const std::string& axis = {}) {
        const toolpath::Segment& s = path_.segments[i];
        const auto key = std::make_tuple(static_cast<int>(r), s.program, s.line);
        if (const auto it = seen_.find(key); it != seen_.end()) {
            Finding& f = res_.findings[it->second];
            if (f.segment != i && lastCounted_[it->second] != i) {
                ++f.occurrences;
                lastCounted_[it->second] = i;
            }
            return nullptr;
        }
        seen_.emplace(key, res_.findings.size());
        lastCounted_.push_back(i);
        Finding f;
        f.rule = r;
        f.severity = r == Rule::CutTooDeep ? Severity::Warning : Severity::Error;
        f.program = s.program;
        f.line = s.line;
        f.n = s.n;
        f.segment = static_cast<std::uint32_t>(i);
        f.text = text;
        f.at = lerp(where());
        if (placeArgs) {
            f.args = {mm(f.at.x), mm(f.at.z)};
            if (r == Rule::ToolIntoChuck || r == Rule::TurretIntoChuck)
                f.args.push_back(std::to_string(tool_.station));
            else if (!axis.empty())
                f.args.push_back(axis);
        }
        res_.findings.push_back(std::move(f));
        return &res_.findings.back();
    }

    const toolpath::ProgrammedPath& path_;
    const MachineGeometry& g_;
    const Options& o_;
    Result res_;
    double toR_ = 0.5;
    std::unique_ptr<LatheMaterial> material_;
    ChuckBoxes chuck_;
    std::vector<std::string> running_;
    int station_ = 0;
    int toolStation_ = -1; // the station tool_ is of
    bool haveTool_ = false;
    profile::Tool tool_;
    double boreR_ = 0, reference_ = 0;
    bool referenceKnown_ = false;
    std::map<std::tuple<int, int, int>, std::size_t> seen_; // (rule, program, line) -> finding
    std::vector<std::size_t> lastCounted_;                  // the segment last counted, per finding
};

} // namespace

std::span<const Text> texts() {
    return kTexts;
}

std::string Finding::message(bool russian) const {
    const Text* t = findText(text);
    if (!t)
        return std::string(text);
    return profile::fillPattern(russian ? t->ru : t->en, args);
}

std::size_t Result::errors() const {
    return static_cast<std::size_t>(
        std::count_if(findings.begin(), findings.end(), [](const Finding& f) { return f.isError(); }));
}

Result prove(const toolpath::ProgrammedPath& path, const MachineGeometry& g, const Options& o) {
    return Prover(path, g, o).run();
}

Options optionsFor(const profile::MachineProfile& p, const std::map<int, std::int64_t>& rPresets,
                   std::optional<stock::Blank> blank) {
    Options o;
    o.blank = std::move(blank);
    o.tools = profile::tools(p);
    for (const profile::Tool& t : o.tools)
        o.offsets[t.station] = profile::toolOffsets(t, p, rPresets);
    return o;
}

std::vector<int> mainPrograms(const program::ProgramStore& store) {
    std::vector<bool> called(program::kMaxPrograms + 1, false);
    for (const program::Program& p : store.programs())
        for (const program::Frame& f : p.frames)
            if (const std::optional<int> t = f.body.callTarget(); t && *t >= 1 && *t <= program::kMaxPrograms && *t != p.number)
                called[static_cast<std::size_t>(*t)] = true;
    std::vector<int> out;
    for (const program::Program& p : store.programs())
        if (!called[static_cast<std::size_t>(p.number)])
            out.push_back(p.number);
    return out;
}

Proof proveProgram(const profile::MachineProfile& profile, const program::ProgramStore& programs,
                   int number, const engine::PreviewOptions& preview,
                   std::optional<stock::Blank> blank) {
    const MachineGeometry g = geometryOf(profile);
    const Options o = optionsFor(profile, preview.rPresets, std::move(blank));
    Proof proof;
    toolpath::PathOptions po;
    po.preview = preview;
    proof.path = toolpath::programmedPath(profile, programs, number, po);
    proof.result = prove(proof.path, g, o);
    return proof;
}

Result proveStore(const profile::MachineProfile& profile, const program::ProgramStore& programs,
                  const engine::PreviewOptions& preview, const std::optional<stock::Blank>& blank) {
    Result all;
    for (const int n : mainPrograms(programs)) {
        const Proof proof = proveProgram(profile, programs, n, preview, blank);
        all.material = all.material || proof.result.material;
        all.chuck = all.chuck || proof.result.chuck;
        all.removedMm2 += proof.result.removedMm2;
        for (const Finding& f : proof.result.findings) {
            const bool seen = std::any_of(all.findings.begin(), all.findings.end(), [&](const Finding& g) {
                return g.rule == f.rule && g.program == f.program && g.line == f.line;
            });
            if (!seen)
                all.findings.push_back(f);
        }
    }
    return all;
}

} // namespace k528::proveout
