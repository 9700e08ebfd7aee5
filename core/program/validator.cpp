#include "program/validator.h"

#include <algorithm>
#include <cassert>
#include <climits>
#include <string>

#include "catalog/messages.h"
#include "program/gfunctions.h"
#include "program/iso_frame.h"
#include "program/refusals.h"
#include "program/text_util.h"
#include "util/utf8.h"

namespace k528::program {

// --- CallGraph -----------------------------------------------------------------------------

namespace {
bool inProgramRange(int n) { return n >= 1 && n <= kMaxPrograms; }
const std::vector<CallGraph::Call> kNoCalls;
} // namespace

CallGraph::CallGraph(const ProgramStore& store) {
    for (const Program& p : store.programs())
        update(p);
}

void CallGraph::update(const Program& program) {
    if (!inProgramRange(program.number))
        return;
    const auto n = static_cast<std::size_t>(program.number);
    auto& calls = calls_[n];
    calls.clear();
    edges_[n].reset();
    for (std::size_t i = 0; i < program.frames.size(); ++i) {
        const std::optional<int> call = program.frames[i].body.callTarget();
        if (!call)
            continue;
        calls.push_back({*call, static_cast<int>(i)});
        if (inProgramRange(*call))
            edges_[n].set(static_cast<std::size_t>(*call));
    }
}

void CallGraph::remove(int number) {
    if (!inProgramRange(number))
        return;
    calls_[static_cast<std::size_t>(number)].clear();
    edges_[static_cast<std::size_t>(number)].reset();
}

const std::vector<CallGraph::Call>& CallGraph::callsFrom(int number) const {
    return inProgramRange(number) ? calls_[static_cast<std::size_t>(number)] : kNoCalls;
}

bool CallGraph::isCalled(int number) const { return callerCount(number) > 0; }

int CallGraph::callerCount(int number) const {
    if (!inProgramRange(number))
        return 0;
    int n = 0;
    for (int c = 1; c <= kMaxPrograms; ++c)
        n += edges_[static_cast<std::size_t>(c)].test(static_cast<std::size_t>(number)) ? 1 : 0;
    return n;
}

namespace {

// --- Analysis of the call graph: strongly connected components (call
// cycles) and the longest call chain below each program. --------------------------------------
//
// Heights are per component: a program on a cycle reaches every call out of
// its cycle, so its chain is the shortest way round the cycle to the member
// that calls out, that call, and the longest chain below the callee. (The
// cycle itself nests without bound; it has its own warning.)
struct CallAnalysis {
    std::array<int, kMaxPrograms + 1> scc{};      // component id per program (0 = absent)
    std::array<bool, kMaxPrograms + 1> cyclic{};  // program lies on a call cycle
    std::array<int, kMaxPrograms + 1> height{};   // longest chain of calls below it (cycles cut)
    // The chain that gives that height leaves the program's component by the
    // call exitFrom -> exitTo (exitFrom is the program itself outside a
    // cycle; both 0 when the component calls nothing outside itself).
    std::array<int, kMaxPrograms + 1> exitFrom{};
    std::array<int, kMaxPrograms + 1> exitTo{};
    std::array<std::bitset<kMaxPrograms + 1>, kMaxPrograms + 1> adj{}; // existing callee edges
};

CallAnalysis analyse(const ProgramStore& store, const CallGraph& graph) {
    CallAnalysis a;
    std::bitset<kMaxPrograms + 1> exists;
    for (const Program& p : store.programs())
        if (inProgramRange(p.number))
            exists.set(static_cast<std::size_t>(p.number));
    for (int p = 1; p <= kMaxPrograms; ++p) {
        if (!exists.test(static_cast<std::size_t>(p)))
            continue;
        for (const auto& c : graph.callsFrom(p))
            if (inProgramRange(c.callee) && exists.test(static_cast<std::size_t>(c.callee)))
                a.adj[static_cast<std::size_t>(p)].set(static_cast<std::size_t>(c.callee));
    }
    // Heights of a component's members. Tarjan completes a component after
    // every component it calls, so the callees' heights are known.
    auto heights = [&](std::vector<int>& members, int component) {
        std::sort(members.begin(), members.end()); // ties go to the lowest number
        std::array<int, kMaxPrograms + 1> dist{};
        for (const int v : members) {
            // Calls from v to each member inside the component (breadth first).
            dist.fill(-1);
            dist[static_cast<std::size_t>(v)] = 0;
            if (members.size() > 1) {
                std::vector<int> queue{v};
                for (std::size_t q = 0; q < queue.size(); ++q) {
                    const auto ui = static_cast<std::size_t>(queue[q]);
                    for (const int w : members) {
                        const auto wi = static_cast<std::size_t>(w);
                        if (a.adj[ui].test(wi) && dist[wi] < 0) {
                            dist[wi] = dist[ui] + 1;
                            queue.push_back(w);
                        }
                    }
                }
            }
            int best = 0;
            for (const int m : members) {
                const auto mi = static_cast<std::size_t>(m);
                if (dist[mi] < 0)
                    continue;
                for (int w = 1; w <= kMaxPrograms; ++w) {
                    const auto wi = static_cast<std::size_t>(w);
                    if (!a.adj[mi].test(wi) || a.scc[wi] == component)
                        continue;
                    const int h = dist[mi] + 1 + a.height[wi];
                    if (h > best) {
                        best = h;
                        a.exitFrom[static_cast<std::size_t>(v)] = m;
                        a.exitTo[static_cast<std::size_t>(v)] = w;
                    }
                }
            }
            a.height[static_cast<std::size_t>(v)] = best;
        }
    };
    // Tarjan's algorithm (recursive; at most 99 levels deep).
    std::array<int, kMaxPrograms + 1> index{}, low{};
    std::array<bool, kMaxPrograms + 1> onStack{};
    std::vector<int> stack;
    int counter = 0;
    int components = 0;
    auto strong = [&](auto&& self, int v) -> void {
        const auto vi = static_cast<std::size_t>(v);
        index[vi] = low[vi] = ++counter;
        stack.push_back(v);
        onStack[vi] = true;
        for (int w = 1; w <= kMaxPrograms; ++w) {
            const auto wi = static_cast<std::size_t>(w);
            if (!a.adj[vi].test(wi))
                continue;
            if (index[wi] == 0) {
                self(self, w);
                low[vi] = std::min(low[vi], low[wi]);
            } else if (onStack[wi]) {
                low[vi] = std::min(low[vi], index[wi]);
            }
        }
        if (low[vi] == index[vi]) {
            ++components;
            std::vector<int> members;
            int w = 0;
            do {
                w = stack.back();
                stack.pop_back();
                onStack[static_cast<std::size_t>(w)] = false;
                a.scc[static_cast<std::size_t>(w)] = components;
                members.push_back(w);
            } while (w != v);
            const bool cyc = members.size() > 1 || a.adj[vi].test(vi);
            for (int m : members)
                a.cyclic[static_cast<std::size_t>(m)] = cyc;
            heights(members, components);
        }
    };
    for (int p = 1; p <= kMaxPrograms; ++p)
        if (exists.test(static_cast<std::size_t>(p)) && index[static_cast<std::size_t>(p)] == 0)
            strong(strong, p);
    return a;
}

// A call path from `from` back to `to` inside one component (breadth first).
std::vector<int> cyclePath(const CallAnalysis& a, int from, int to) {
    std::array<int, kMaxPrograms + 1> prev{};
    std::array<bool, kMaxPrograms + 1> seen{};
    std::vector<int> queue{from};
    seen[static_cast<std::size_t>(from)] = true;
    for (std::size_t q = 0; q < queue.size(); ++q) {
        const int v = queue[q];
        if (v == to)
            break;
        for (int w = 1; w <= kMaxPrograms; ++w) {
            const auto wi = static_cast<std::size_t>(w);
            if (a.adj[static_cast<std::size_t>(v)].test(wi) && !seen[wi] && a.scc[wi] == a.scc[static_cast<std::size_t>(from)]) {
                seen[wi] = true;
                prev[wi] = v;
                queue.push_back(w);
            }
        }
    }
    std::vector<int> path;
    if (!seen[static_cast<std::size_t>(to)])
        return path;
    for (int v = to; v != from; v = prev[static_cast<std::size_t>(v)])
        path.push_back(v);
    path.push_back(from);
    std::reverse(path.begin(), path.end());
    return path;
}

// The ranges the checks of a frame's values ask, for both the full check
// and the quick one of ProgramChecker::plainIso.
bool rInRange(std::int64_t index) { return index >= 0 && index < kRCount; }
// A value of at most 3 decimals in thousandths: one multiplication by a
// factor looked up by the scale (a chain of tests on the scale, which
// varies from value to value, was mispredicted for a good part of them).
constexpr std::int64_t milli(const Decimal& d) {
    constexpr std::array<std::int64_t, 4> kFactor = {1000, 100, 10, 1};
    return d.mantissa * kFactor[static_cast<std::size_t>(d.scale)];
}
static_assert(kMaxCoordinate.scale <= 3 && kMinFeed.scale <= 3 && kMaxFeed.scale <= 3);
// d within [lo, hi] thousandths: nearly every value has at most 3 decimals
// and is compared as an integer; the rest exactly as decimals.
[[gnu::always_inline]] inline bool withinMilli(const Decimal& d, std::int64_t lo, std::int64_t hi) {
    if (d.scale >= 0 && d.scale <= 3 && d.mantissa > -1000000000 && d.mantissa < 1000000000) {
        const std::int64_t m = milli(d);
        return m >= lo && m <= hi;
    }
    return !(d < Decimal::fromScaled(lo, 3) || d > Decimal::fromScaled(hi, 3));
}
bool coordinateInRange(const Decimal& d) { return withinMilli(d, -milli(kMaxCoordinate), milli(kMaxCoordinate)); }
bool feedInRange(const Decimal& d) { return withinMilli(d, milli(kMinFeed), milli(kMaxFeed)); }
bool mInRange(std::int64_t m) { return m >= 0 && m <= kMaxM; }

// classifyG() of every G the language has, as a table: one load for each G
// word of a frame instead of a branching switch.
GInfo gInfoOf(int g) {
    static constexpr auto table = [] {
        std::array<GInfo, kMaxG + 1> a{};
        for (int n = 0; n <= kMaxG; ++n)
            a[static_cast<std::size_t>(n)] = classifyG(n);
        return a;
    }();
    return g >= 0 && g <= kMaxG ? table[static_cast<std::size_t>(g)] : classifyG(g);
}

// Whether the table refuses a frame whose only words of it are X and Z
// (index: 1 CoordinateX, 2 Z), computed once from the table.
bool refusedXZ(int index) {
    static const std::array<bool, 4> refused = [] {
        std::array<bool, 4> a{};
        for (int i = 0; i < 4; ++i) {
            const refusal::Words w = static_cast<refusal::Words>(((i & 1) ? refusal::CoordinateX : 0) |
                                                                 ((i & 2) ? refusal::Z : 0));
            for (const Refusal& r : refusals())
                a[static_cast<std::size_t>(i)] = a[static_cast<std::size_t>(i)] || r.matches(w);
        }
        return a;
    }();
    return refused[static_cast<std::size_t>(index)];
}

// The word a refusal points at (the table names it; the frame has it).
ColSpan refusalSpan(const Frame& f, const IsoFrame& iso, RefusalSpot spot) {
    const Word* m = nullptr;
    switch (spot) {
    case RefusalSpot::X:
        return iso.x ? iso.x->span : ColSpan{f.span.column, f.span.endColumn};
    case RefusalSpot::Z:
        return iso.z ? iso.z->span : ColSpan{f.span.column, f.span.endColumn};
    case RefusalSpot::Call:
        return iso.call ? iso.call->span : ColSpan{f.span.column, f.span.endColumn};
    case RefusalSpot::M2:
        m = iso.findM(mfunc::kEnd);
        break;
    case RefusalSpot::M17:
        m = iso.findM(mfunc::kSubprogramEnd);
        break;
    case RefusalSpot::M30:
        m = iso.findM(mfunc::kEndRewind);
        break;
    }
    return m ? m->span : ColSpan{f.span.column, f.span.endColumn};
}

// A chain of calls «L1→L2→L3» ("L1->L2->L3") as parts of the catalog.
DiagnosticPart chainPart(const std::vector<int>& programs) {
    DiagnosticPart last{"chain.end", {programs.empty() ? std::string() : std::to_string(programs.back())}, {}};
    for (std::size_t i = programs.size() > 1 ? programs.size() - 1 : 0; i-- > 0;)
        last = DiagnosticPart{"chain.call", {std::to_string(programs[i])}, {std::move(last)}};
    return last;
}

// --- Checking one program ------------------------------------------------------------------------

class ProgramChecker {
public:
    ProgramChecker(const ProgramStore& store, const Program& program, const CallGraph& graph,
                   const CallAnalysis& calls, const ValidateOptions& options, std::vector<Diagnostic>& out)
        : store_(store), p_(program), graph_(graph), calls_(calls), options_(options), out_(out) {}

    void run();

private:
    const ProgramStore& store_;
    const Program& p_;
    const CallGraph& graph_;
    const CallAnalysis& calls_;
    const ValidateOptions& options_;
    std::vector<Diagnostic>& out_;
    std::array<std::int32_t, kMaxFrameNumber + 1> firstOfN_{};

    void add(Rule rule, Severity severity, int manual, int line, ColSpan span, std::string_view id,
             std::vector<std::string> args, std::vector<DiagnosticPart> within = {}) {
        Diagnostic d;
        d.rule = rule;
        d.severity = severity;
        d.program = p_.number;
        d.line = line;
        d.column = span.column > 0 ? span.column : 1;
        d.endColumn = span.endColumn > d.column ? span.endColumn : d.column + 1;
        d.manualNumber = manual;
        d.textId = id;
        d.args = std::move(args);
        d.within = std::move(within);
        out_.push_back(std::move(d));
    }
    // `id` of diagnostic_texts.h with its arguments.
    void error(Rule r, int manual, const Frame& f, ColSpan s, std::string_view id, std::vector<std::string> args = {},
               std::vector<DiagnosticPart> within = {}) {
        add(r, Severity::Error, manual, f.span.line, s, id, std::move(args), std::move(within));
    }
    void warning(Rule r, int manual, const Frame& f, ColSpan s, std::string_view id, std::vector<std::string> args = {},
                 std::vector<DiagnosticPart> within = {}) {
        add(r, Severity::Warning, manual, f.span.line, s, id, std::move(args), std::move(within));
    }
    static ColSpan whole(const Frame& f) { return {f.span.column, f.span.endColumn}; }
    // «в кадре N12» / "in frame N12" («в кадре» when the frame has no N).
    static DiagnosticPart where(const Frame& f) {
        return f.n ? DiagnosticPart{"frame.numbered", {std::to_string(f.n->number)}, {}} : DiagnosticPart{"frame", {}, {}};
    }

    void frameNumbers();
    bool plainIso(const Frame& f, const IsoFrame& iso) const;
    IsoFrame iso_; // the current ISO frame, decoded into the same place frame after frame
    // Per frame: an ISO frame with M02, M30 or M17 (control flow ends there),
    // noted while it is decoded for the checks.
    std::vector<char> ends_;
    void isoFrame(const Frame& f, const IsoFrame& iso);
    std::array<GInfo, kMaxGPerFrame> gInfo_{}; // classifyG of the current ISO frame's G words
    void gWords(const Frame& f, const IsoFrame& iso);
    void values(const Frame& f, const IsoFrame& iso);
    void combinations(const Frame& f, const IsoFrame& iso);
    bool lastOfSubprogram_ = false; // the program is a subprogram: its last frame ends it
    void rIndex(const Frame& f, int index, ColSpan s);
    void computeFrame(const Frame& f, const ComputeFrame& c);
    void jump(const Frame& f, const Word& target);
    // False when the parser could not read the jump target of a malformed
    // frame (it reported that): there is nothing to check, and the jump may
    // lead anywhere.
    static bool targetRead(const Frame& f, const Word& target) { return !f.malformed || target.span.column > 0; }
    bool lostTarget_ = false; // some jump's target could not be read
    void reachability();
    void nesting();
    void machine();
};

void ProgramChecker::run() {
    if (p_.frames.empty()) {
        add(Rule::EmptyProgram, Severity::Warning, 0, p_.headerLine > 0 ? p_.headerLine : 1, {1, 2},
            "empty-program", {std::to_string(p_.number)});
        return;
    }
    if (p_.frames.size() > static_cast<std::size_t>(kMaxFrames)) {
        const Frame& f = p_.frames[kMaxFrames];
        error(Rule::TooManyFrames, 0, f, whole(f), "too-many-frames",
              {std::to_string(p_.number), std::to_string(p_.frames.size())});
    }
    frameNumbers();
    lastOfSubprogram_ = graph_.isCalled(p_.number);
    ends_.assign(p_.frames.size(), 0);
    for (const Frame& f : p_.frames) {
        switch (f.kind()) {
        case FrameKind::Iso: {
            clearIsoFrame(iso_);
            f.body.decode(iso_);
            for (const Word& m : iso_.m)
                if (m.number == mfunc::kEnd || m.number == mfunc::kEndRewind || m.number == mfunc::kSubprogramEnd)
                    ends_[static_cast<std::size_t>(&f - p_.frames.data())] = 1;
            if (!plainIso(f, iso_))
                isoFrame(f, iso_);
#ifndef NDEBUG
            else {
                // The quick answer stands for the full checks: a debug build
                // (the sanitizer suite, the fuzzer) asks them too and stops
                // where a check added to isoFrame() was not taught to plainIso().
                const std::size_t before = out_.size();
                isoFrame(f, iso_);
                assert(out_.size() == before && "plainIso() passed a frame the full checks question");
            }
#endif
            break;
        }
        case FrameKind::Compute: {
            const auto c = f.compute();
            computeFrame(f, *c);
            break;
        }
        case FrameKind::IfGoto: {
            const IfGotoFrame j = f.body.ifGotoFrame();
            rIndex(f, j.r.number, j.r.span);
            if (targetRead(f, j.target))
                jump(f, j.target);
            else
                lostTarget_ = true;
            break;
        }
        case FrameKind::Goto: {
            const GotoFrame j = f.body.gotoFrame();
            if (targetRead(f, j.target))
                jump(f, j.target);
            else
                lostTarget_ = true;
            break;
        }
        }
    }
    reachability();
    nesting();
    if (options_.machine)
        machine();
}

void ProgramChecker::frameNumbers() {
    firstOfN_.fill(-1);
    for (std::size_t i = 0; i < p_.frames.size(); ++i) {
        const Frame& f = p_.frames[i];
        if (!f.n)
            continue;
        const int n = f.n->number;
        if (n < 1 || n > kMaxFrameNumber) {
            error(Rule::FrameNumberRange, 0, f, f.n->span, "frame-number-range", {std::to_string(n)});
            continue;
        }
        auto& first = firstOfN_[static_cast<std::size_t>(n)];
        if (first < 0) {
            first = static_cast<std::int32_t>(i);
            continue;
        }
        const int firstLine = p_.frames[static_cast<std::size_t>(first)].span.line;
        error(Rule::DuplicateFrameNumber, 54, f, f.n->span, "duplicate-frame-number",
              {std::to_string(n), std::to_string(firstLine)});
    }
}

// True when an ISO frame certainly gets no diagnostic from isoFrame(): most
// frames, found so by a few questions on their numbers instead of every
// check written for each word (that was the larger part of checking a store).
// Whatever is out of the ordinary — a dwell, a call, an end word, the last
// frame, a G or M the checks question, a value out of range, an axis
// function without its value, a message the table lacks — goes the full
// way, which says what is wrong.
bool ProgramChecker::plainIso(const Frame& f, const IsoFrame& iso) const {
    if (&f == &p_.frames.back() || iso.call)
        return false;
    if (iso.message) {
        const int k = iso.message->number;
        if (k < 1 || k > kMaxMessages || (store_.messages.present && !store_.messages.find(k)))
            return false;
    }
    for (int i = 0; i < iso.m.size(); ++i) {
        const int m = iso.m[i].number;
        if (!mInRange(m) || m == mfunc::kEnd || m == mfunc::kSubprogramEnd || m == mfunc::kEndRewind)
            return false;
        for (int j = 0; j < i; ++j)
            if (iso.m[j].number == m)
                return false;
    }
    std::array<GGroup, kMaxGPerFrame> groups{};
    for (int i = 0; i < iso.g.size(); ++i) {
        const GInfo info = gInfoOf(iso.g[i].number);
        if (!info.known() || info.function == GFunction::Dwell)
            return false;
        for (int j = 0; j < i; ++j)
            if (groups[static_cast<std::size_t>(j)] == info.group)
                return false;
        groups[static_cast<std::size_t>(i)] = info.group;
        if ((info.function == GFunction::SetPosition || info.function == GFunction::OscillationStart ||
             info.function == GFunction::StopOnSignal) &&
            !(info.axis == Axis::X ? iso.x.has_value() : info.axis == Axis::Z ? iso.z.has_value() : true))
            return false;
    }
    auto fine = [](const std::optional<Value>& v, bool (*inRange)(const Decimal&)) {
        return !v || (v->isR() ? rInRange(v->rIndex) : inRange(v->literal));
    };
    if (!fine(iso.x, coordinateInRange) || !fine(iso.z, coordinateInRange) || !fine(iso.fx, feedInRange) ||
        !fine(iso.fz, feedInRange))
        return false;
    return !refusedXZ((iso.x ? 1 : 0) | (iso.z ? 2 : 0));
}

void ProgramChecker::rIndex(const Frame& f, int index, ColSpan s) {
    if (!rInRange(index))
        error(Rule::RIndexRange, 0, f, s, "r-index-range", {std::to_string(index)});
}

void ProgramChecker::gWords(const Frame& f, const IsoFrame& iso) {
    for (int i = 0; i < iso.g.size(); ++i)
        gInfo_[static_cast<std::size_t>(i)] = gInfoOf(iso.g[i].number);
    for (int i = 0; i < iso.g.size(); ++i) {
        const Word& w = iso.g[i];
        const GInfo& info = gInfo_[static_cast<std::size_t>(i)];
        if (!info.known()) {
            const bool range = w.number < 0 || w.number > kMaxG;
            error(Rule::UnknownG, 47, f, w.span, range ? "unknown-g.range" : "unknown-g", {gName(w.number)});
            continue;
        }
        for (int j = 0; j < i; ++j) {
            const GInfo& other = gInfo_[static_cast<std::size_t>(j)];
            if (other.known() && other.group == info.group) {
                error(Rule::GSameGroup, 47, f, w.span, "g-same-group",
                      {gName(iso.g[j].number), gName(w.number), std::to_string(groupNumber(info.group))});
                break;
            }
        }
    }
}

void ProgramChecker::values(const Frame& f, const IsoFrame& iso) {
    const bool dwell = iso.hasG(4);
    auto coordinate = [&](const std::optional<Value>& v, char axis, int manual) {
        if (!v)
            return;
        if (v->isR()) {
            rIndex(f, v->rIndex, v->span);
            return;
        }
        const Decimal& d = v->literal;
        if (dwell && axis == 'X') {
            if (d.isNegative())
                error(Rule::DwellNegative, 33, f, v->span, "dwell-negative", {d.toString()});
            else if (d > kMaxCoordinate)
                error(Rule::CoordinateRange, 33, f, v->span, "dwell-range", {d.toString()});
            return;
        }
        if (!coordinateInRange(d)) {
            error(Rule::CoordinateRange, manual, f, v->span, "coordinate-range", {std::string(1, axis), d.toString()});
        }
    };
    auto feed = [&](const std::optional<Value>& v, const char* name) {
        if (!v)
            return;
        if (v->isR()) {
            rIndex(f, v->rIndex, v->span);
            return;
        }
        const Decimal& d = v->literal;
        if (!feedInRange(d))
            error(Rule::FeedRange, 0, f, v->span, "feed-range", {name, d.toString()});
    };
    coordinate(iso.x, 'X', 33);
    coordinate(iso.z, 'Z', 49);
    feed(iso.fx, "FX");
    feed(iso.fz, "FZ");
}

void ProgramChecker::combinations(const Frame& f, const IsoFrame& iso) {
    // The refused combinations (program/refusals.h): each one the frame matches.
    refusal::Words words = refusalWords(iso);
    if (lastOfSubprogram_ && &f == &p_.frames.back() && !f.skip)
        words |= refusal::LastOfSubprogram;
    if (words != 0) {
        // Most frames have words of the table (X, Z) and match none of it:
        // the program's name is written only for a refusal.
        for (const Refusal& r : refusals())
            if (r.matches(words))
                error(r.rule, r.message, f, refusalSpan(f, iso, r.spot), r.textId,
                      {"L" + std::to_string(iso.call ? iso.call->number : p_.number)}, {where(f)});
    }
    if (const Word* g4 = iso.findG(4)) {
        if (!iso.x)
            warning(Rule::DwellWithoutTime, 0, f, g4->span, "dwell-without-time");
    }
    // Axis functions that need a value of their axis.
    for (int i = 0; i < iso.g.size(); ++i) {
        const Word& w = iso.g[i];
        const GInfo& info = gInfo_[static_cast<std::size_t>(i)];
        if (info.axis == Axis::None)
            continue;
        const bool has = info.axis == Axis::X ? iso.x.has_value() : iso.z.has_value();
        const std::string a(1, axisLetter(info.axis));
        switch (info.function) {
        case GFunction::SetPosition:
            if (!has)
                warning(Rule::AxisFunctionWithoutValue, 0, f, w.span, "axis-function.set-position",
                        {gName(w.number), a});
            break;
        case GFunction::OscillationStart:
            if (!has)
                warning(Rule::AxisFunctionWithoutValue, 0, f, w.span, "axis-function.oscillation",
                        {gName(w.number), a});
            break;
        case GFunction::StopOnSignal:
            if (!has)
                warning(Rule::AxisFunctionWithoutValue, 0, f, w.span, "axis-function.signal",
                        {gName(w.number), a, std::to_string(info.signal)});
            break;
        default:
            break;
        }
    }
}

void ProgramChecker::isoFrame(const Frame& f, const IsoFrame& iso) {
    gWords(f, iso);
    for (int i = 0; i < iso.m.size(); ++i) {
        const Word& w = iso.m[i];
        if (!mInRange(w.number))
            error(Rule::MRange, 0, f, w.span, "m-range", {std::to_string(w.number)});
        for (int j = 0; j < i; ++j)
            if (iso.m[j].number == w.number) {
                warning(Rule::MRepeated, 0, f, w.span, "m-repeated", {std::to_string(w.number)});
                break;
            }
    }
    if (iso.message) {
        const int k = iso.message->number;
        if (k < 1 || k > kMaxMessages)
            error(Rule::MessageRange, 0, f, iso.message->span, "message-range", {std::to_string(k)});
        else if (store_.messages.present && !store_.messages.find(k))
            warning(Rule::MessageUndefined, 0, f, iso.message->span, "message-undefined", {std::to_string(k)});
    }
    if (iso.call) {
        const int l = iso.call->number;
        if (l < 1 || l > kMaxPrograms)
            error(Rule::CallRange, 0, f, iso.call->span, "call-range", {std::to_string(l)});
        else if (!store_.contains(l))
            error(Rule::CallMissing, 45, f, iso.call->span, "call-missing", {std::to_string(l)});
    }
    values(f, iso);
    combinations(f, iso);
}

void ProgramChecker::computeFrame(const Frame& f, const ComputeFrame& c) {
    const int t = c.target.number;
    if (t < 0 || t >= kRCount)
        rIndex(f, t, c.target.span);
    else if (t >= kFirstReadOnlyR && t <= kLastReadOnlyR)
        error(Rule::ReadOnlyR, 0, f, c.target.span, "read-only-r", {std::to_string(t)});
    if (c.a.isR())
        rIndex(f, c.a.rIndex, c.a.span);
    if (c.op == ArithOp::None)
        return;
    if (c.b.isR())
        rIndex(f, c.b.rIndex, c.b.span);
    if (c.op == ArithOp::Div && !c.b.isR() && c.b.literal == 0) {
        error(Rule::DivisionByZero, 46, f, c.b.span, "division-by-zero");
        return;
    }
    if (c.a.isR() || c.b.isR())
        return;
    const std::int64_t a = c.a.literal;
    const std::int64_t b = c.b.literal;
    std::int64_t r = 0;
    switch (c.op) {
    case ArithOp::Add:
        r = a + b;
        break;
    case ArithOp::Sub:
        r = a - b;
        break;
    case ArithOp::Mul:
        r = a * b;
        break;
    case ArithOp::Div:
        r = a / b;
        break;
    case ArithOp::None:
        break;
    }
    if (r < INT32_MIN || r > INT32_MAX)
        error(Rule::ConstantOverflow, 46, f, whole(f), "constant-overflow", {std::to_string(r)});
}

void ProgramChecker::jump(const Frame& f, const Word& target) {
    const int n = target.number;
    if (n < 1 || n > kMaxFrameNumber) {
        error(Rule::JumpTarget, 53, f, target.span, "jump-target.range", {std::to_string(n)});
        return;
    }
    if (firstOfN_[static_cast<std::size_t>(n)] < 0)
        error(Rule::JumpTarget, 53, f, target.span, "jump-target", {std::to_string(n), std::to_string(p_.number)});
}

void ProgramChecker::reachability() {
    // Control flow inside the program: a frame continues to the next one,
    // except an unconditional jump, an end of program (M02, M30) and an end
    // of subprogram (M17); a conditional jump goes both ways; a call comes
    // back. A skipped frame ('/') just passes on to the next one.
    // A jump whose target could not be read may lead to any frame: nothing
    // is reported as unreachable then (the syntax error comes first).
    if (lostTarget_)
        return;
    const std::size_t count = p_.frames.size();
    std::vector<char> reached(count, 0);
    std::vector<std::size_t> work;
    work.reserve(16);
    auto visit = [&](std::size_t i) {
        if (i < count && !reached[i]) {
            reached[i] = 1;
            work.push_back(i);
        }
    };
    auto target = [&](int n) -> std::int64_t {
        return n >= 1 && n <= kMaxFrameNumber ? firstOfN_[static_cast<std::size_t>(n)] : -1;
    };
    visit(0);
    while (!work.empty()) {
        // Walk straight runs without the work list.
        std::size_t i = work.back();
        work.pop_back();
        while (true) {
            const Frame& f = p_.frames[i];
            bool next = true;
            if (!f.skip) {
                switch (f.kind()) {
                case FrameKind::Iso: {
                    if (ends_[i])
                        next = false;
                    break;
                }
                case FrameKind::Compute:
                    break;
                case FrameKind::IfGoto: {
                    const auto t = target(f.jumpTarget());
                    if (t >= 0)
                        visit(static_cast<std::size_t>(t));
                    break;
                }
                case FrameKind::Goto: {
                    const auto t = target(f.jumpTarget());
                    if (t >= 0)
                        visit(static_cast<std::size_t>(t));
                    next = false;
                    break;
                }
                }
            }
            if (!next || i + 1 >= count || reached[i + 1])
                break;
            reached[++i] = 1;
        }
    }
    for (std::size_t i = 0; i < count;) {
        if (reached[i]) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j + 1 < count && !reached[j + 1])
            ++j;
        const Frame& first = p_.frames[i];
        const Frame& last = p_.frames[j];
        if (i == j)
            warning(Rule::Unreachable, 0, first, whole(first), "unreachable", {std::to_string(first.span.line)});
        else
            warning(Rule::Unreachable, 0, first, whole(first), "unreachable.lines",
                    {std::to_string(first.span.line), std::to_string(last.span.line)});
        i = j + 1;
    }
}

void ProgramChecker::nesting() {
    const auto self = static_cast<std::size_t>(p_.number);
    if (!inProgramRange(p_.number))
        return;
    const int limit = options_.nestingLimit;
    for (const auto& c : graph_.callsFrom(p_.number)) {
        if (!inProgramRange(c.callee) || !store_.contains(c.callee))
            continue;
        if (static_cast<std::size_t>(c.frameIndex) >= p_.frames.size())
            continue;
        const Frame& f = p_.frames[static_cast<std::size_t>(c.frameIndex)];
        const auto fi = f.iso();
        const ColSpan s = fi && fi->call ? fi->call->span : whole(f);
        const auto ci = static_cast<std::size_t>(c.callee);
        if (calls_.scc[ci] == calls_.scc[self]) {
            std::vector<int> cycle = cyclePath(calls_, c.callee, p_.number);
            cycle.insert(cycle.begin(), p_.number);
            warning(Rule::NestingCycle, 48, f, s, "nesting-cycle", {std::to_string(limit)}, {chainPart(cycle)});
            continue;
        }
        const int depth = 1 + calls_.height[ci];
        if (depth <= limit)
            continue;
        std::vector<int> chain{p_.number};
        for (int v = c.callee; v != 0; v = calls_.exitTo[static_cast<std::size_t>(v)]) {
            const int m = calls_.exitFrom[static_cast<std::size_t>(v)];
            if (m == 0 || m == v) {
                chain.push_back(v);
                continue;
            }
            const std::vector<int> round = cyclePath(calls_, v, m); // v ... m inside the cycle
            chain.insert(chain.end(), round.begin(), round.end());
        }
        warning(Rule::NestingDepth, 48, f, s, "nesting-depth", {std::to_string(depth), std::to_string(limit)},
                {chainPart(chain)});
    }
}

std::string discreteText(int decimals) {
    return Decimal::fromScaled(1, decimals).toString();
}

void ProgramChecker::machine() {
    const MachineLimits& m = *options_.machine;
    // Absolute or incremental X/Z, followed in text order: a program that
    // never writes G91 is taken as absolute; otherwise only frames after a
    // G90 are checked against the limits (best effort; jumps are ignored).
    bool usesIncremental = false;
    for (const Frame& f : p_.frames)
        if (const auto iso = f.iso(); iso && iso->hasG(91))
            usesIncremental = true;
    bool absolute = !usesIncremental;
    int omitted = 54; // group 6: G54 (all components) at power-on, or the G50..G53 in force
    for (const Frame& f : p_.frames) {
        const auto iso = f.iso();
        if (!iso)
            continue;
        if (iso->hasG(90))
            absolute = true;
        if (iso->hasG(91))
            absolute = false;
        for (const Word& w : iso->g)
            if (w.number >= 50 && w.number <= 54)
                omitted = w.number;
        const bool dwell = iso->hasG(4);
        auto axis = [&](Axis which, const AxisLimits& lim, const std::optional<Value>& pos,
                        const std::optional<Value>& feed) {
            const char a = axisLetter(which);
            const std::string as(1, a);
            const bool dwellTime = dwell && which == Axis::X; // X of G04 is seconds
            if (!lim.present) {
                auto absent = [&](ColSpan s, const std::string& word) {
                    warning(Rule::AxisAbsent, 0, f, s, "axis-absent", {word, as});
                };
                if (pos && !dwellTime)
                    absent(pos->span, as);
                if (feed)
                    absent(feed->span, "F" + as);
                for (const Word& w : iso->g)
                    if (classifyG(w.number).axis == which)
                        absent(w.span, gName(w.number));
                return;
            }
            bool setsPosition = false, stroke = false, handwheel = false;
            for (const Word& w : iso->g) {
                const GInfo info = classifyG(w.number);
                if (info.axis != which)
                    continue;
                setsPosition |= info.function == GFunction::SetPosition;
                stroke |= info.function == GFunction::OscillationStart;
                handwheel |= info.function == GFunction::Handwheel;
            }
            if (pos && !pos->isR() && !dwellTime) {
                const Decimal& v = pos->literal;
                const bool motionTarget = absolute && !setsPosition && !stroke && !handwheel;
                Decimal offset;
                if (omitted != 53)
                    offset = offset + lim.zeroOffsetMm;
                if (omitted != 52)
                    offset = offset + lim.dressingMm;
                if (omitted != 51)
                    offset = offset + lim.correctionMm;
                if (omitted != 50)
                    offset = offset + lim.handwheelMm;
                const Decimal machinePos = v + offset;
                if (lim.softLimits && motionTarget && (machinePos < lim.minMm || machinePos > lim.maxMm)) {
                    const bool above = machinePos > lim.maxMm;
                    const int message = which == Axis::X ? 12 : 28;
                    // The text of message 12/28 as `run` shows it (catalog, table М.1).
                    const std::string name(catalog::positionerMessage(message).textRu);
                    warning(Rule::SoftLimit, message, f, pos->span, above ? "soft-limit.above" : "soft-limit.below",
                            {name, as, v.toString(), (above ? lim.maxMm : lim.minMm).toString()},
                            {DiagnosticPart{lim.diameter ? "soft-limit.diameter" : "", {}, {}},
                             DiagnosticPart{offset.isZero() ? "" : "soft-limit.machine", {machinePos.toString()}, {}}});
                }
                if (lim.decimals && v.fractionDigits() > *lim.decimals)
                    warning(Rule::DiscreteRounding, 0, f, pos->span, "discrete-rounding",
                            {as, v.toString(), discreteText(*lim.decimals), v.rounded(*lim.decimals).toString()});
            }
            if (feed && !feed->isR()) {
                const Decimal& v = feed->literal;
                if (lim.maxFeedMmPerMin && v > *lim.maxFeedMmPerMin)
                    warning(Rule::FeedAboveMax, 0, f, feed->span, "feed-above-max",
                            {as, v.toString(), lim.maxFeedMmPerMin->toString()});
                if (lim.decimals && v.fractionDigits() > *lim.decimals)
                    warning(Rule::DiscreteRounding, 0, f, feed->span, "discrete-rounding.feed",
                            {as, v.toString(), discreteText(*lim.decimals), v.rounded(*lim.decimals).toString()});
            }
        };
        axis(Axis::X, m.x, iso->x, iso->fx);
        axis(Axis::Z, m.z, iso->z, iso->fz);
    }
}

bool displayable(char32_t cp) {
    return (cp >= 0x20 && cp < 0x7F) || (cp >= 0x410 && cp <= 0x44F) || cp == 0x401 || cp == 0x451 ||
           cp == U'№';
}

} // namespace

std::vector<Diagnostic> validateMessages(const MessageTable& table) {
    std::vector<Diagnostic> out;
    for (const Message& m : table.entries) {
        const auto cps = utf8::decode(m.text);
        auto add = [&](Rule rule, Severity sev, int col, int end, std::string_view id, std::vector<std::string> args) {
            Diagnostic d;
            d.rule = rule;
            d.severity = sev;
            d.line = m.span.line;
            d.column = col > 0 ? col : 1;
            d.endColumn = end > d.column ? end : d.column + 1;
            d.textId = id;
            d.args = std::move(args);
            out.push_back(std::move(d));
        };
        const int base = m.textColumn > 0 ? m.textColumn : 1;
        if (cps.size() > static_cast<std::size_t>(kMessageLength))
            add(Rule::MessageTooLong, Severity::Error, base + kMessageLength, base + static_cast<int>(cps.size()),
                "message-too-long", {std::to_string(m.number), std::to_string(cps.size())});
        bool warned = false;
        for (std::size_t i = 0; i < cps.size(); ++i) {
            const char32_t cp = cps[i];
            const int col = base + static_cast<int>(i);
            if (cp < 0x20 || cp == 0x7F || (cp >= 0x80 && cp < 0xA0)) {
                add(Rule::MessageCharacter, Severity::Error, col, col + 1, "message-character",
                    {std::to_string(m.number)});
            } else if (!displayable(cp) && !warned) {
                warned = true;
                std::string ch;
                utf8::append(ch, cp);
                add(Rule::MessageCharset, Severity::Warning, col, col + 1, "message-charset",
                    {ch, std::to_string(m.number)});
            }
        }
    }
    return out;
}

std::vector<Diagnostic> validateProgram(const ProgramStore& store, int number, const CallGraph& graph,
                                        const ValidateOptions& options) {
    std::vector<Diagnostic> out;
    const Program* p = store.find(number);
    if (!p)
        return out;
    const CallAnalysis calls = analyse(store, graph);
    ProgramChecker(store, *p, graph, calls, options, out).run();
    sortDiagnostics(out);
    return out;
}

std::vector<Diagnostic> validate(const ProgramStore& store, const ValidateOptions& options) {
    std::vector<Diagnostic> out;
    const CallGraph graph(store);
    const CallAnalysis calls = analyse(store, graph);
    for (const Program& p : store.programs())
        ProgramChecker(store, p, graph, calls, options, out).run();
    auto messages = validateMessages(store.messages);
    for (auto& d : messages)
        out.push_back(std::move(d));
    sortDiagnostics(out);
    return out;
}

CheckResult check(std::string_view text, const ParseOptions& parseOptions, const ValidateOptions& options) {
    ParseResult parsed = parse(text, parseOptions);
    CheckResult r;
    r.syntaxErrors = parsed.hasErrors();
    r.diagnostics = std::move(parsed.diagnostics);
    auto more = validate(parsed.store, options);
    for (auto& d : more)
        r.diagnostics.push_back(std::move(d));
    // A file of nothing but comments or blank lines: say so, a batch check
    // would otherwise pass it silently.
    if (!r.syntaxErrors && parsed.store.empty() && parsed.store.messages.entries.empty()) {
        Diagnostic d;
        d.rule = Rule::NoProgram;
        d.severity = Severity::Warning;
        d.line = 1;
        d.column = 1;
        d.endColumn = 2;
        d.textId = "no-program";
        r.diagnostics.push_back(std::move(d));
    }
    sortDiagnostics(r.diagnostics);
    r.store = std::move(parsed.store);
    return r;
}

} // namespace k528::program
