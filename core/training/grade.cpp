#include "training/grade.h"

#include "engine/program_check.h"
#include "engine/self_test.h"
#include "program/diagnostic_texts.h"
#include "program/parser.h"
#include "training/geometry.h"
#include "util/json.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace k528::training {

namespace {
using namespace geo;

// The boundary of a region as segments.
std::vector<bg::model::segment<P>> boundaryOf(const Multi& m) {
    std::vector<bg::model::segment<P>> out;
    const auto ring = [&](const auto& r) {
        for (std::size_t k = 1; k < r.size(); ++k)
            out.emplace_back(r[k - 1], r[k]);
    };
    for (const Poly& p : m) {
        ring(p.outer());
        for (const auto& h : p.inners())
            ring(h);
    }
    return out;
}

double distanceTo(const P& q, const std::vector<bg::model::segment<P>>& segs) {
    double best = 1e300;
    for (const auto& s : segs)
        best = std::min(best, static_cast<double>(bg::distance(q, s)));
    return best;
}

// The deepest point of a region from the boundary of the limit it crossed:
// its corners and the quarter points of its edges.
double depthOf(const Poly& region, const std::vector<bg::model::segment<P>>& limit, P& deepest) {
    double best = 0;
    const auto look = [&](const P& q) {
        const double d = distanceTo(q, limit);
        if (d > best) {
            best = d;
            deepest = q;
        }
    };
    const auto ring = [&](const auto& r) {
        for (std::size_t k = 1; k < r.size(); ++k) {
            const P& a = r[k - 1];
            const P& b = r[k];
            for (int j = 0; j < 4; ++j) {
                const double t = j / 4.0;
                look(P(a.x() + (b.x() - a.x()) * t, a.y() + (b.y() - a.y()) * t));
            }
        }
    };
    deepest = region.outer().empty() ? P(0, 0) : region.outer().front();
    ring(region.outer());
    for (const auto& h : region.inners())
        ring(h);
    return best;
}

// Regions smaller than these are the arithmetic's, not the tool's.
constexpr double kMinDepthMm = 0.0005, kMinAreaMm2 = 1e-5;

struct RemovalGeo {
    Poly sweep;
    Box box;
    const proveout::Removal* r;
};

double round3(double v) {
    return std::round(v * 1000.0) / 1000.0;
}

std::string frameName(int program, int n) {
    return frameArg(program, n);
}

bool allowed(const Exercise& e, const SeenMessage& m) {
    return std::find(e.limits.alarmsAllowed.begin(), e.limits.alarmsAllowed.end(), m.code) !=
           e.limits.alarmsAllowed.end();
}

// The finished ring from its bands: the outer surface, the bore band by band.
Multi ringPart(const Ring& ring, const std::vector<BandCell>& bands, double bandMm) {
    Poly p;
    const double R = ring.outerMm / 2;
    bg::append(p.outer(), P(ring.zMinMm, R));
    bg::append(p.outer(), P(ring.zMaxMm, R));
    for (std::size_t k = bands.size(); k-- > 0;) {
        const double r = bands[k].boreMm / 2;
        const double z1 = k + 1 == bands.size() ? ring.zMaxMm : bands[k].zMm + bandMm;
        bg::append(p.outer(), P(z1, r));
        bg::append(p.outer(), P(k == 0 ? ring.zMinMm : bands[k].zMm, r));
    }
    bg::correct(p);
    Multi m;
    Multi cleaned;
    m.push_back(p);
    bg::union_(m, Multi(), cleaned); // merges the collinear steps of equal bores
    return cleaned.empty() ? m : cleaned;
}

} // namespace

Grader::Grader(const Exercise& e) : Grader(e, exerciseProfile(e)) {}

Grader::Grader(const Exercise& e, profile::MachineProfile machine)
    : e_(e), machine_(std::move(machine)) {
    for (const auto& [n, v] : e.setupR)
        machine_.r[n] = v;
    prepare();
}

void Grader::prepare() {
    if (e_.drawing.kind != Drawing::Kind::Reference) {
        drawing_ = drawingShapes(e_);
        return;
    }
    // The part the reference program makes is the drawing.
    Exercise plain = e_;
    plain.drawing = Drawing{};
    const Grader ref(plain, machine_);
    const Grade g = ref.grade(e_.reference, "reference");
    drawing_ = drawingFromPart(g.finished, e_.drawing.tolerance);
}

Grade Grader::grade(std::string_view text, std::string file, std::string student) const {
    Grade g;
    g.exercise = e_.id;
    g.file = std::move(file);
    g.student = std::move(student);
    g.limitS = e_.limits.cycleTimeS;
    g.drawing = drawing_;
    const Scoring& sc = e_.scoring;
    const auto deduct = [&](std::string category, double points, bool fails, int program, int line,
                            int n, std::string id, std::vector<TextArg> args) {
        g.deductions.push_back({std::move(category), std::round(points), fails, program, line, n,
                                Text{std::move(id), std::move(args)}});
    };

    // The file as the machine would take it.
    bool intact = true;
    const program::ProgramStore store = engine::loadStore(machine_, intact);
    const engine::FileCheck checked =
        engine::checkFileForMachine(text, program::ParseOptions{}, machine_, store);
    if (checked.hasErrors()) {
        g.status = "errors";
        for (const program::Diagnostic& d : checked.diagnostics)
            if (d.isError())
                g.diagnostics.push_back(d);
        const program::Diagnostic& d = g.diagnostics.front();
        deduct("program_errors", sc.programErrors, true, d.program, d.line, 0, "program-errors",
               {intArg(static_cast<long long>(g.diagnostics.size())), intArg(d.line),
                TextArg(program::diagnosticText(d, true), program::diagnosticText(d, false))});
        g.score = 0;
        g.passed = false;
        return g;
    }
    const bool hasProgram = !checked.parsed.store.empty();
    const int first = hasProgram ? checked.parsed.store.firstWritten() : 1;

    AttemptInput in;
    in.exercise = &e_;
    in.profile = machine_;
    in.programs = checked.parsed.store;
    in.procedure = readProcedure(text, first, g.procedureErrors);
    for (const ProcedureError& err : g.procedureErrors) {
        std::vector<TextArg> args{intArg(err.line), err.token};
        deduct("procedure", 10, true, 0, err.line, 0, "procedure-error", args);
        g.deductions.back().text.args.push_back(TextArg(render(err.why, Language::Ru),
                                                        render(err.why, Language::En)));
    }
    const bool needsProgram = e_.drawing.kind != Drawing::Kind::None;
    if (!hasProgram && in.procedure.standard && needsProgram) {
        g.status = "not_started";
        deduct("program_errors", sc.programErrors, true, 0, 0, 0, "no-program", {});
        g.score = 0;
        return g;
    }

    const AttemptRecord rec = runAttempt(in);
    g.path = rec.path;
    g.faults = rec.faults;
    g.notes = rec.notes;

    // How the run ended.
    if (rec.guardHit)
        g.status = "timeout";
    else if (rec.starts == 0)
        g.status = hasProgram ? "not_started" : "procedure";
    else if (rec.endState == engine::ProgramState::Ended)
        g.status = "completed";
    else if (rec.endState == engine::ProgramState::Alarm)
        g.status = "alarm";
    else
        g.status = "interrupted";
    if (rec.firstStartMs >= 0) {
        const double end = g.status == "completed" && rec.lastEndMs >= 0 ? rec.lastEndMs : rec.endMs;
        g.cycleTimeS = round3((end - rec.firstStartMs) / 1000.0);
    }

    // The part.
    Multi blankM, finishedM;
    std::vector<RemovalGeo> removals;
    proveout::CutResult cut;
    std::vector<proveout::Removal> ringRemovals;
    if (e_.lathe()) {
        proveout::ChuckGeometry chuck; // the exercise's chuck, in the program's coordinates
        const Chuck& c = e_.chuck;
        chuck.present = true;
        chuck.jawFaceZMm = c.faceZMm + c.jawLengthMm;
        chuck.jawLengthMm = c.jawLengthMm;
        chuck.jawHeightMm = c.jawHeightMm;
        chuck.gripDiameterMm = e_.blank->outerDiameterMm;
        chuck.bodyDiameterMm = c.diameterMm;
        chuck.bodyLengthMm = 80;
        proveout::SpindleTimeline sp;
        for (std::size_t i = 0; i < rec.spindle.size(); ++i) {
            if (i == 0)
                sp.runningAtStart = rec.spindle[i].running;
            else
                sp.changesMs.push_back(rec.spindle[i].tMs);
        }
        cut = proveout::cutAlong(*e_.blank, e_.blankZMm, e_.tool, chuck, rec.path, true, sp);
        blankM = translated(multiOf(stock::Stock(*e_.blank)), e_.blankZMm);
        finishedM = multiOf(cut.finished);
        g.collisions = cut.collisions;
        for (const proveout::Removal& r : cut.removals) {
            RemovalGeo rg{polygonOf(r.sweep), Box(), &r};
            bg::envelope(rg.sweep, rg.box);
            removals.push_back(std::move(rg));
        }
    } else if (e_.grinder() && !rec.bands.empty()) {
        const Ring& ring = *e_.ring;
        std::vector<BandCell> blankBands = rec.bands;
        for (BandCell& b : blankBands)
            b.boreMm = rec.blankBoreMm;
        blankM = ringPart(ring, blankBands, rec.bandMm);
        finishedM = ringPart(ring, rec.bands, rec.bandMm);
        // The bands each frame ground last: what it took out.
        for (std::size_t k = 0; k < rec.bands.size();) {
            const BandCell& b = rec.bands[k];
            std::size_t j = k + 1;
            if (!b.ground) {
                k = j;
                continue;
            }
            double top = b.boreMm;
            while (j < rec.bands.size() && rec.bands[j].ground &&
                   std::tie(rec.bands[j].program, rec.bands[j].line, rec.bands[j].n) ==
                       std::tie(b.program, b.line, b.n)) {
                top = std::max(top, rec.bands[j].boreMm);
                ++j;
            }
            const double z1 = j == rec.bands.size() ? ring.zMaxMm : rec.bands[j].zMm;
            proveout::Removal r;
            r.program = b.program;
            r.line = b.line;
            r.n = b.n;
            const Poly p = rect(b.zMm, z1, rec.blankBoreMm / 2, top / 2);
            for (std::size_t q = 0; q + 1 < p.outer().size(); ++q)
                r.sweep.push_back({p.outer()[q].x(), p.outer()[q].y()});
            r.areaMm2 = bg::area(p);
            ringRemovals.push_back(r);
            k = j;
        }
        for (const proveout::Removal& r : ringRemovals) {
            RemovalGeo rg{polygonOf(r.sweep), Box(), &r};
            bg::envelope(rg.sweep, rg.box);
            removals.push_back(std::move(rg));
        }
        for (const RingContact& c : rec.ringContacts)
            g.collisions.push_back({c.rule, c.rule == proveout::Rule::RapidIntoMaterial
                                                ? std::string_view("rapid-into-material.ring")
                                                : proveout::ruleId(c.rule),
                                    c.program, c.line, c.n, {c.zMm, c.edgeMm / 2},
                                    (c.edgeMm - c.boreMm) / 2, 0});
    }
    g.blank = shapesOf(blankM);
    g.finished = shapesOf(finishedM);

    // The part against the drawing.
    if (drawing_.present && !blankM.empty()) {
        const Multi most = multiOf(drawing_.most), least = multiOf(drawing_.least);
        Multi need, over, under;
        bg::intersection(least, blankM, need);
        bg::difference(need, finishedM, over);
        bg::difference(finishedM, most, under);
        const auto leastEdges = boundaryOf(least), mostEdges = boundaryOf(most);
        using Key = std::tuple<int, int, int, bool, bool>;
        const auto collect = [&](const Multi& regions, bool isOver, std::vector<Deviation>& out) {
            std::map<Key, std::size_t> byFrame;
            for (const Poly& region : regions) {
                const double area = bg::area(region);
                P deep;
                const double depth = depthOf(region, isOver ? leastEdges : mostEdges, deep);
                if (depth < kMinDepthMm || area < kMinAreaMm2)
                    continue;
                Box rb;
                bg::envelope(region, rb);
                const RemovalGeo* who = nullptr;
                double best = isOver ? 0 : 1e300;
                for (const RemovalGeo& r : removals) {
                    if (isOver) {
                        if (!bg::intersects(rb, r.box))
                            continue;
                        Multi inter;
                        bg::intersection(region, r.sweep, inter);
                        const double a = bg::area(inter);
                        if (a > best + 1e-12) {
                            best = a;
                            who = &r;
                        }
                    } else {
                        const double d = bg::distance(region, r.sweep);
                        // The nearest pass; among passes equally near, the last.
                        if (d <= best + 1e-9) {
                            best = d;
                            who = &r;
                        }
                    }
                }
                Deviation dv;
                dv.areaMm2 = area;
                dv.depthUm = depth * 1000.0;
                dv.deepest = {deep.x(), deep.y()};
                // An under-cut no pass came within a millimetre of was not machined at all.
                if (who && (isOver || best <= 1.0)) {
                    dv.located = true;
                    dv.program = who->r->program;
                    dv.line = who->r->line;
                    dv.n = who->r->n;
                    dv.manual = who->r->manual;
                    dv.distanceMm = isOver ? 0 : best;
                }
                Multi one;
                one.push_back(region);
                dv.shapes = shapesOf(one);
                const Key key{dv.program, dv.line, dv.n, dv.manual, dv.located};
                const auto it = byFrame.find(key);
                if (it == byFrame.end()) {
                    byFrame.emplace(key, out.size());
                    out.push_back(std::move(dv));
                    continue;
                }
                Deviation& d0 = out[it->second];
                d0.areaMm2 += dv.areaMm2;
                if (dv.depthUm > d0.depthUm) {
                    d0.depthUm = dv.depthUm;
                    d0.deepest = dv.deepest;
                }
                d0.distanceMm = std::min(d0.distanceMm, dv.distanceMm);
                d0.shapes.insert(d0.shapes.end(), dv.shapes.begin(), dv.shapes.end());
            }
        };
        collect(over, true, g.overcut);
        collect(under, false, g.undercut);
        for (const Deviation& d : g.overcut) {
            const double pts =
                std::min(sc.overcutCap, sc.overcutBase + sc.overcutPerMm * d.depthUm / 1000.0);
            std::vector<TextArg> args{intArg(std::llround(d.depthUm)), areaArg(d.areaMm2),
                                      mmArg(d.deepest.r * 2), mmArg(d.deepest.z)};
            if (!d.located)
                deduct("overcut", pts, false, 0, 0, 0, "overcut.unknown", args);
            else if (d.manual)
                deduct("overcut", pts, false, 0, 0, 0, "overcut.manual", args);
            else {
                args.push_back(frameName(d.program, d.n));
                args.push_back(intArg(d.line));
                deduct("overcut", pts, false, d.program, d.line, d.n, "overcut", args);
            }
        }
        for (const Deviation& d : g.undercut) {
            const double pts =
                std::min(sc.undercutCap, sc.undercutBase + sc.undercutPerMm * d.depthUm / 1000.0);
            std::vector<TextArg> args{intArg(std::llround(d.depthUm)), areaArg(d.areaMm2),
                                      mmArg(d.deepest.r * 2), mmArg(d.deepest.z)};
            if (!d.located || d.manual) {
                deduct("undercut", pts, false, 0, 0, 0, "undercut.untouched", args);
            } else {
                args.push_back(frameName(d.program, d.n));
                args.push_back(intArg(d.line));
                deduct("undercut", pts, false, d.program, d.line, d.n, "undercut", args);
            }
        }
    }

    // Collisions.
    for (const Collision& c : g.collisions) {
        double pts = sc.rapidIntoMaterial;
        switch (c.rule) {
        case proveout::Rule::RapidIntoMaterial:
            pts = sc.rapidIntoMaterial;
            break;
        case proveout::Rule::ManualIntoMaterial:
            pts = sc.jogIntoMaterial;
            break;
        case proveout::Rule::FeedSpindleStopped:
        case proveout::Rule::FeedWheelStopped:
        case proveout::Rule::CutTooDeep:
            pts = sc.cutWithoutSpindle;
            break;
        case proveout::Rule::ToolIntoChuck:
        case proveout::Rule::TurretIntoChuck:
            pts = sc.toolIntoChuck;
            break;
        }
        std::vector<TextArg> args{mmArg(c.at.r * 2), mmArg(c.at.z), mmArg(c.depthMm)};
        // The deduction's text by the rule's text id ("collision.rapid-into-material.ring").
        std::string id = "collision." + std::string(c.text);
        if (c.program > 0) {
            args.push_back(frameName(c.program, c.n));
            args.push_back(intArg(c.line));
        } else if (c.rule != proveout::Rule::ManualIntoMaterial) {
            id = "collision." + std::string(proveout::ruleId(c.rule)) + ".manual";
        }
        deduct("collision", pts, true, c.program, c.line, c.n, id, args);
    }

    // Messages.
    double messagePoints = 0;
    for (const SeenMessage& m : rec.messages) {
        const bool ok = allowed(e_, m);
        g.messages.push_back(m);
        g.messageAllowed.push_back(ok);
        if (ok)
            continue;
        const double pts = std::min(sc.alarm, std::max(0.0, sc.alarmCap - messagePoints));
        messagePoints += pts;
        std::vector<TextArg> args{m.code, TextArg(m.textRu, m.textEn)};
        if (m.program > 0) {
            args.push_back(frameName(m.program, 0));
            args.push_back(intArg(m.line));
            deduct("message", pts, false, m.program, m.line, 0, "message", args);
        } else {
            deduct("message", pts, false, 0, 0, 0, "message.machine", args);
        }
    }

    // The run.
    if (hasProgram && needsProgram) {
        if (rec.starts == 0) {
            std::string ru, en;
            for (const engine::RunBlocker& b : rec.blockedBy) {
                ru += (ru.empty() ? "" : "; ") + engine::describeBlocker(b, true);
                en += (en.empty() ? "" : "; ") + engine::describeBlocker(b, false);
            }
            deduct("not_started", sc.notCompleted, true, 0, 0, 0,
                   ru.empty() ? "not-started" : "not-started.why", {TextArg(ru, en)});
        } else if (g.status != "completed") {
            std::string id = "not-completed." + g.status;
            deduct("not_completed", sc.notCompleted, true, rec.endProgram, rec.endLine, rec.endN,
                   id, {frameName(rec.endProgram, rec.endN), intArg(rec.endLine)});
        }
    }
    if (g.status == "completed" && g.limitS > 0 && g.cycleTimeS > g.limitS) {
        const double percent = (g.cycleTimeS / g.limitS - 1) * 100;
        deduct("cycle_time", std::min(sc.cycleTimeCap, sc.cycleTimePerPercent * percent), false, 0, 0,
               0, "cycle-time", {mmArg(g.cycleTimeS), mmArg(g.limitS)});
    }

    // The operator's steps.
    const bool started = rec.firstStartMs >= 0;
    for (const OperatorStep& s : e_.steps) {
        StepResult r;
        r.step = s;
        switch (s.kind) {
        case OperatorStep::Kind::Home: {
            const auto& ref = started ? rec.referencedAtFirstStart : rec.referencedAtEnd;
            r.done = ref[0] && ref[1];
            r.text = {"step.home", {}};
            break;
        }
        case OperatorStep::Kind::Preset: {
            const auto& rv = started ? rec.rAtFirstStart : rec.rAtEnd;
            const std::int64_t found = rv[static_cast<std::size_t>(s.r)];
            r.done = found == s.value;
            r.text = {"step.preset", {intArg(s.r), intArg(found), intArg(s.value)}};
            break;
        }
        case OperatorStep::Kind::Acknowledge: {
            r.done = true;
            std::string open;
            for (const SeenMessage& m : rec.messages)
                if (!m.acknowledged) {
                    r.done = false;
                    open += (open.empty() ? "" : ", ") + m.code;
                }
            r.text = {"step.acknowledge", {open}};
            break;
        }
        case OperatorStep::Kind::Position: {
            const double x = rec.currentAtEndMm[0], z = rec.currentAtEndMm[1];
            r.done = std::fabs(x - s.xMm) <= s.toleranceMm + 1e-9 &&
                     std::fabs(z - s.zMm) <= s.toleranceMm + 1e-9;
            r.text = {"step.position",
                      {mmArg(x), mmArg(z), mmArg(s.xMm), mmArg(s.zMm), mmArg(s.toleranceMm)}};
            break;
        }
        case OperatorStep::Kind::NewWheel:
            r.done = rec.wheelChanged;
            r.text = {"step.new_wheel", {}};
            break;
        case OperatorStep::Kind::Completed:
            r.done = rec.starts > 0 && g.status == "completed";
            r.text = {"step.completed", {}};
            break;
        }
        if (!r.done)
            deduct("step", sc.operatorStep, true, 0, 0, 0, r.text.id, r.text.args);
        g.steps.push_back(std::move(r));
    }

    // The machine as it is left.
    for (const EndCheck& c : e_.atEnd) {
        EndResult r;
        r.check = c;
        std::string id;
        std::vector<TextArg> args;
        switch (c.kind) {
        case EndCheck::Kind::SpindleStopped:
            r.ok = rec.spindlesStoppedAtEnd;
            id = "end.spindle_stopped";
            break;
        case EndCheck::Kind::CoolantOff:
            r.ok = rec.coolantOffAtEnd;
            id = "end.coolant_off";
            break;
        case EndCheck::Kind::GaugeOut:
            r.ok = rec.gaugeOutAtEnd;
            id = "end.gauge_out";
            break;
        case EndCheck::Kind::RDelta:
        case EndCheck::Kind::RValue: {
            const auto i = static_cast<std::size_t>(c.r);
            r.found = rec.rAtEnd[i];
            const std::int64_t want =
                c.kind == EndCheck::Kind::RValue ? c.value : rec.rAtBegin[i] + c.value;
            r.ok = r.found == want;
            id = "end.r";
            args = {intArg(c.r), intArg(r.found), intArg(want)};
            break;
        }
        }
        if (!r.ok)
            deduct("end_state", sc.endCheck, false, 0, 0, 0, id, args);
        g.atEnd.push_back(r);
    }

    double total = 0;
    bool fails = false;
    for (const Deduction& d : g.deductions) {
        total += d.points;
        fails = fails || d.fails;
    }
    g.score = static_cast<int>(std::max(0.0, std::round(100.0 - total)));
    g.passed = g.score >= sc.passScore && !fails;
    return g;
}

namespace {

Json shapesJson(const std::vector<Shape>& shapes) {
    Json a = Json::array();
    const auto ring = [](const stock::Ring& r) {
        Json pts = Json::array();
        for (const stock::PointZR& q : r)
            pts.push_back(Json::array({round3(q.z), round3(q.r * 2)}));
        return pts;
    };
    for (const Shape& s : shapes) {
        Json o;
        o["outer"] = ring(s.outer);
        Json holes = Json::array();
        for (const stock::Ring& h : s.holes)
            holes.push_back(ring(h));
        o["holes"] = std::move(holes);
        a.push_back(std::move(o));
    }
    return a;
}

Json frameJson(int program, int line, int n) {
    Json o;
    o["program"] = program > 0 ? Json(program) : Json();
    o["frame"] = n > 0 ? Json(n) : Json();
    o["line"] = line > 0 ? Json(line) : Json();
    return o;
}

Json textJson(const Text& t) {
    Json o;
    o["id"] = t.id;
    Json args = Json::array();
    for (const TextArg& a : t.args)
        args.push_back(a.ru == a.en ? Json(a.ru) : Json::object({{"ru", a.ru}, {"en", a.en}}));
    o["args"] = std::move(args);
    o["text_ru"] = render(t, Language::Ru);
    o["text_en"] = render(t, Language::En);
    return o;
}

} // namespace

Json gradeJson(const Grade& g, bool geometry) {
    Json o;
    o["file"] = g.file;
    o["student"] = g.student.empty() ? Json() : Json(g.student);
    o["exercise"] = g.exercise;
    o["score"] = g.score;
    o["passed"] = g.passed;
    o["status"] = g.status;
    o["cycle_time_s"] = g.cycleTimeS;
    o["limit_s"] = g.limitS > 0 ? Json(g.limitS) : Json();
    Json ded = Json::array();
    for (const Deduction& d : g.deductions) {
        Json j;
        j["category"] = d.category;
        j["points"] = d.points;
        j["fails"] = d.fails;
        const Json f = frameJson(d.program, d.line, d.n);
        j["program"] = f["program"];
        j["frame"] = f["frame"];
        j["line"] = f["line"];
        const Json t = textJson(d.text);
        j["text_ru"] = t["text_ru"];
        j["text_en"] = t["text_en"];
        j["id"] = t["id"];
        j["args"] = t["args"];
        ded.push_back(std::move(j));
    }
    o["deductions"] = std::move(ded);
    const auto deviations = [&](const std::vector<Deviation>& v) {
        Json a = Json::array();
        for (const Deviation& d : v) {
            Json j = frameJson(d.program, d.line, d.n);
            j["area_mm2"] = std::round(d.areaMm2 * 10000.0) / 10000.0;
            j["depth_um"] = std::llround(d.depthUm);
            j["at"] = Json::object({{"z", round3(d.deepest.z)}, {"d", round3(d.deepest.r * 2)}});
            j["manual"] = d.manual;
            j["located"] = d.located;
            if (geometry)
                j["shapes"] = shapesJson(d.shapes);
            a.push_back(std::move(j));
        }
        return a;
    };
    o["overcut"] = deviations(g.overcut);
    o["undercut"] = deviations(g.undercut);
    Json col = Json::array();
    for (const Collision& c : g.collisions) {
        Json j = frameJson(c.program, c.line, c.n);
        j["rule"] = proveout::ruleId(c.rule); // the prove-out's rule id (docs/proveout.md)
        j["text"] = c.text;
        j["at"] = Json::object({{"z", round3(c.at.z)}, {"d", round3(c.at.r * 2)}});
        j["depth_mm"] = round3(c.depthMm);
        col.push_back(std::move(j));
    }
    o["collisions"] = std::move(col);
    Json msgs = Json::array();
    for (std::size_t i = 0; i < g.messages.size(); ++i) {
        const SeenMessage& m = g.messages[i];
        Json j;
        j["code"] = m.code;
        j["text_ru"] = m.textRu;
        j["text_en"] = m.textEn;
        j["program"] = m.program > 0 ? Json(m.program) : Json();
        j["line"] = m.line > 0 ? Json(m.line) : Json();
        j["time_s"] = round3(m.tMs / 1000.0);
        j["acknowledged"] = m.acknowledged;
        j["allowed"] = static_cast<bool>(g.messageAllowed[i]);
        msgs.push_back(std::move(j));
    }
    o["messages"] = std::move(msgs);
    Json steps = Json::array();
    for (const StepResult& s : g.steps) {
        Json j;
        j["step"] = stepName(s.step.kind);
        j["done"] = s.done;
        steps.push_back(std::move(j));
    }
    o["steps"] = std::move(steps);
    Json ends = Json::array();
    for (const EndResult& e : g.atEnd) {
        Json j;
        j["check"] = endCheckName(e.check.kind);
        if (e.check.kind == EndCheck::Kind::RDelta || e.check.kind == EndCheck::Kind::RValue) {
            j["r"] = e.check.r;
            j["found"] = e.found;
        }
        j["ok"] = e.ok;
        ends.push_back(std::move(j));
    }
    o["at_end"] = std::move(ends);
    Json faults = Json::array();
    for (const FaultEvent& f : g.faults) {
        Json j;
        j["fault"] = f.id;
        j["args"] = f.args;
        j["injected_s"] = f.injectedMs >= 0 ? Json(round3(f.injectedMs / 1000.0)) : Json();
        j["cleared_s"] = f.clearedMs >= 0 ? Json(round3(f.clearedMs / 1000.0)) : Json();
        const Json fr = frameJson(f.program, f.line, f.n);
        j["program"] = fr["program"];
        j["frame"] = fr["frame"];
        j["line"] = fr["line"];
        faults.push_back(std::move(j));
    }
    o["faults"] = std::move(faults);
    Json notes = Json::array();
    for (const StepNote& n : g.notes) {
        Json j = textJson(n.text);
        j["line"] = n.line > 0 ? Json(n.line) : Json();
        j["token"] = n.token;
        notes.push_back(std::move(j));
    }
    o["procedure_notes"] = std::move(notes);
    if (geometry) {
        o["blank"] = shapesJson(g.blank);
        o["finished"] = shapesJson(g.finished);
        Json d;
        d["nominal"] = shapesJson(g.drawing.nominal);
        d["most"] = shapesJson(g.drawing.most);
        d["least"] = shapesJson(g.drawing.least);
        o["drawing"] = std::move(d);
    }
    return o;
}

} // namespace k528::training
