#include "training/exercise.h"
#include "training/exercise_texts.h"

#include "profile/builtin.h"
#include "resources/embedded.h"
#include "util/json.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <span>

namespace k528::training {

namespace {

// The names of the exercise files' operator steps and end checks: one table
// each, read both ways (the name of a kind, the kind of a name).
template <typename Kind> struct Named {
    Kind kind;
    std::string_view name;
};

constexpr Named<OperatorStep::Kind> kStepNames[] = {
    {OperatorStep::Kind::Home, "home"},
    {OperatorStep::Kind::Preset, "preset"},
    {OperatorStep::Kind::Acknowledge, "acknowledge"},
    {OperatorStep::Kind::Position, "position"},
    {OperatorStep::Kind::NewWheel, "new_wheel"},
    {OperatorStep::Kind::Completed, "completed"},
};

constexpr Named<EndCheck::Kind> kEndCheckNames[] = {
    {EndCheck::Kind::SpindleStopped, "spindle_stopped"},
    {EndCheck::Kind::CoolantOff, "coolant_off"},
    {EndCheck::Kind::GaugeOut, "gauge_out"},
    {EndCheck::Kind::RDelta, "r_delta"},
    {EndCheck::Kind::RValue, "r_value"},
};

template <typename Kind, std::size_t N> std::string_view nameOf(const Named<Kind> (&names)[N], Kind k) {
    for (const Named<Kind>& n : names)
        if (n.kind == k)
            return n.name;
    return "";
}

template <typename Kind, std::size_t N>
std::optional<Kind> kindNamed(const Named<Kind> (&names)[N], std::string_view name) {
    for (const Named<Kind>& n : names)
        if (n.name == name)
            return n.kind;
    return std::nullopt;
}

} // namespace

std::string_view stepName(OperatorStep::Kind k) {
    return nameOf(kStepNames, k);
}

std::string_view endCheckName(EndCheck::Kind k) {
    return nameOf(kEndCheckNames, k);
}

namespace {

constexpr std::string_view kUcgPrefix = "ucg."; // "ucg.<id of stock::ucgTexts()>": a bad blank

// "<source>: <path>: <why>" in a language.
std::string exerciseErrorText(const std::string& source, const std::optional<std::string>& at,
                              std::string_view id, std::span<const std::string> args, bool russian) {
    std::string s = source + ": ";
    if (at)
        s += (at->empty() ? exerciseTexts().render("the-file", {}, russian) : *at) + ": ";
    if (id.starts_with(kUcgPrefix)) // said as the prove-out and `k528 prove` say it
        return s + stock::ucgErrorText(id.substr(kUcgPrefix.size()), args, russian);
    return s + exerciseTexts().render(id, args, russian);
}

} // namespace

ExerciseError::ExerciseError(std::string source, std::optional<std::string> at, std::string id,
                             std::vector<std::string> args)
    : std::runtime_error(exerciseErrorText(source, at, id, args, false)),
      message_(std::string(what()).substr(source.size() + 2)), source_(std::move(source)),
      at_(std::move(at)), id_(std::move(id)), args_(std::move(args)) {}

std::string ExerciseError::text(bool russian) const {
    if (id_.empty())
        return what();
    return exerciseErrorText(source_, at_, id_, args_, russian);
}

namespace {

// A JSON value with the path that leads to it, for messages that name the
// key: "drawing.contour[2].d: expected a number".
class Node {
public:
    Node(const Json& v, std::string path, const std::string& source)
        : v_(v), path_(std::move(path)), source_(source) {}

    // What is wrong here: an id of exercise_texts.h and its arguments.
    [[noreturn]] void fail(std::string id, std::vector<std::string> args = {}) const {
        throw ExerciseError(source_, path_, std::move(id), std::move(args));
    }
    const Json& json() const { return v_; }
    const std::string& path() const { return path_; }
    bool has(std::string_view key) const { return v_.is_object() && v_.contains(key); }
    Node at(std::string_view key) const {
        if (!v_.is_object())
            fail("expected-object");
        const auto it = v_.find(key);
        const std::string p = path_.empty() ? std::string(key) : path_ + "." + std::string(key);
        if (it == v_.end())
            throw ExerciseError(source_, p, "missing");
        return Node(*it, p, source_);
    }
    std::optional<Node> opt(std::string_view key) const {
        if (!has(key))
            return std::nullopt;
        return at(key);
    }
    Node item(std::size_t i) const {
        return Node(v_.at(i), path_ + "[" + std::to_string(i) + "]", source_);
    }
    std::size_t size() const { return v_.size(); }
    // Keys other than `known` are refused (a misspelt key must not pass unnoticed).
    void only(std::initializer_list<std::string_view> known) const {
        if (!v_.is_object())
            fail("expected-object");
        for (auto it = v_.begin(); it != v_.end(); ++it)
            if (std::find(known.begin(), known.end(), it.key()) == known.end())
                Node(*it, path_.empty() ? it.key() : path_ + "." + it.key(), source_)
                    .fail("unknown-key");
    }
    std::string str() const {
        if (!v_.is_string())
            fail("expected-string");
        return v_.get<std::string>();
    }
    double num() const {
        if (!v_.is_number())
            fail("expected-number");
        const double d = v_.get<double>();
        if (!std::isfinite(d))
            fail("expected-finite");
        return d;
    }
    std::int64_t integer() const {
        if (!v_.is_number_integer())
            fail("expected-whole");
        return v_.get<std::int64_t>();
    }
    bool boolean() const {
        if (!v_.is_boolean())
            fail("expected-bool");
        return v_.get<bool>();
    }
    void array() const {
        if (!v_.is_array())
            fail("expected-array");
    }
    // A text: one string, or an array of lines joined with "\n".
    std::string text() const {
        if (v_.is_string())
            return v_.get<std::string>();
        array();
        std::string out;
        for (std::size_t i = 0; i < size(); ++i)
            out += item(i).str() + "\n";
        return out;
    }
    Bilingual bilingual() const {
        only({"ru", "en"});
        return {at("ru").text(), at("en").text()};
    }

private:
    const Json& v_;
    std::string path_;
    const std::string& source_;
};

Tolerance tolerance(const Node& n) {
    n.array();
    if (n.size() != 2)
        n.fail("tolerance-pair");
    Tolerance t{n.item(0).num(), n.item(1).num()};
    if (t.lowerMm > t.upperMm)
        n.fail("tolerance-order");
    if (std::fabs(t.lowerMm) > 10 || std::fabs(t.upperMm) > 10)
        n.fail("tolerance-range");
    return t;
}

engine::AxisId axisOf(const Node& n) {
    const std::string a = n.str();
    if (a == "X")
        return engine::AxisId::X;
    if (a == "Z")
        return engine::AxisId::Z;
    n.fail("axis");
}

machine::FaultSpec faultSpec(const Node& n) {
    const std::string name = n.at("fault").str();
    int kind = -1;
    for (int k = 0; k < machine::kFaultCount; ++k)
        if (machine::faultName(static_cast<machine::Fault>(k)) == name)
            kind = k;
    if (kind < 0) {
        std::string all;
        for (int k = 0; k < machine::kFaultCount; ++k)
            all += (k ? ", " : "") + std::string(machine::faultName(static_cast<machine::Fault>(k)));
        n.at("fault").fail("fault-unknown", {name, all});
    }
    machine::FaultSpec f;
    f.kind = static_cast<machine::Fault>(kind);
    using machine::Fault;
    switch (f.kind) {
    case Fault::EncoderChannelBreak: {
        f.axis = axisOf(n.at("axis"));
        f.detail = static_cast<int>(n.at("channel").integer());
        if (f.detail != 1 && f.detail != 2)
            n.at("channel").fail("channel");
        break;
    }
    case Fault::DriveNotReady:
    case Fault::DacLimit:
        f.axis = axisOf(n.at("axis"));
        break;
    case Fault::LimitSwitch: {
        f.axis = axisOf(n.at("axis"));
        const std::string d = n.at("side").str();
        if (d != "+" && d != "-")
            n.at("side").fail("side");
        f.detail = d == "+" ? 1 : -1;
        break;
    }
    case Fault::PlcModuleFailure:
        f.detail = static_cast<int>(n.at("place").integer());
        break;
    case Fault::SpindleDrive:
    case Fault::SpindleOverheat:
    case Fault::PumpOverload:
        f.equipment = n.at("equipment").str();
        break;
    case Fault::PositionerModule:
    case Fault::K923:
        f.detail = static_cast<int>(n.at("part").integer());
        break;
    default:
        break;
    }
    return f;
}

FaultInjection injection(const Node& n) {
    n.only({"fault", "axis", "channel", "side", "place", "equipment", "part", "at_s", "at_frame",
            "until", "for_s", "move_off_mm"});
    FaultInjection j;
    j.fault = faultSpec(n);
    if (const auto a = n.opt("at_s")) {
        j.atS = a->num();
        if (*j.atS < 0)
            a->fail("time-after-start");
    }
    if (const auto f = n.opt("at_frame")) {
        f->only({"program", "n"});
        FrameAt at{static_cast<int>(f->at("program").integer()),
                   static_cast<int>(f->at("n").integer())};
        if (at.program < 1 || at.program > 99 || at.n < 1 || at.n > 999)
            f->fail("frame-at");
        j.atFrame = at;
    }
    if (j.atS.has_value() == j.atFrame.has_value())
        n.fail("at-one");
    const std::string until = n.opt("until") ? n.at("until").str() : "never";
    if (until == "never") {
        j.until = FaultInjection::Until::Never;
    } else if (until == "moved_off") {
        if (j.fault.kind != machine::Fault::LimitSwitch)
            n.at("until").fail("moved-off");
        j.until = FaultInjection::Until::MovedOff;
        if (const auto m = n.opt("move_off_mm")) {
            j.moveOffMm = m->num();
            if (j.moveOffMm <= 0 || j.moveOffMm > 50)
                m->fail("mm-50");
        }
    } else if (until == "time") {
        j.until = FaultInjection::Until::Time;
        j.forS = n.at("for_s").num();
        if (j.forS <= 0)
            n.at("for_s").fail("seconds");
    } else {
        n.at("until").fail("until");
    }
    return j;
}

OperatorStep step(const Node& n) {
    n.only({"step", "r", "value", "x", "z", "tolerance"});
    const std::string s = n.at("step").str();
    OperatorStep st;
    const std::optional<OperatorStep::Kind> kind = kindNamed(kStepNames, s);
    if (!kind)
        n.at("step").fail("step");
    st.kind = *kind;
    if (st.kind == OperatorStep::Kind::Preset) {
        st.r = static_cast<int>(n.at("r").integer());
        if (st.r < 0 || st.r > 231)
            n.at("r").fail("r-writable");
        st.value = n.at("value").integer();
    } else if (st.kind == OperatorStep::Kind::Position) {
        st.xMm = n.at("x").num();
        st.zMm = n.at("z").num();
        st.toleranceMm = n.at("tolerance").num();
        if (st.toleranceMm <= 0)
            n.at("tolerance").fail("mm-positive");
    }
    return st;
}

EndCheck endCheck(const Node& n) {
    if (n.json().is_string()) {
        const std::string s = n.str();
        if (s == "spindle_stopped")
            return {EndCheck::Kind::SpindleStopped};
        if (s == "coolant_off")
            return {EndCheck::Kind::CoolantOff};
        if (s == "gauge_out")
            return {EndCheck::Kind::GaugeOut};
        n.fail("end-check");
    }
    n.only({"r", "delta", "value"});
    EndCheck c;
    c.r = static_cast<int>(n.at("r").integer());
    if (c.r < 0 || c.r > 299)
        n.at("r").fail("r-number");
    if (n.has("delta") == n.has("value"))
        n.fail("delta-or-value");
    c.kind = n.has("delta") ? EndCheck::Kind::RDelta : EndCheck::Kind::RValue;
    c.value = n.at(c.kind == EndCheck::Kind::RDelta ? "delta" : "value").integer();
    return c;
}

Drawing drawing(const Node& n) {
    n.only({"contour", "reference", "tolerance", "bore"});
    Drawing d;
    if (const auto t = n.opt("tolerance"))
        d.tolerance = tolerance(*t);
    const int kinds = n.has("contour") + n.has("reference") + n.has("bore");
    if (kinds != 1)
        n.fail("drawing-one");
    if (const auto c = n.opt("contour")) {
        d.kind = Drawing::Kind::Contour;
        c->array();
        if (c->size() < 3)
            c->fail("contour-points");
        for (std::size_t i = 0; i < c->size(); ++i) {
            const Node p = c->item(i);
            p.only({"z", "d", "tol"});
            ContourPoint q{p.at("z").num(), p.at("d").num(), std::nullopt};
            if (q.dMm < 0)
                p.at("d").fail("diameter-nonnegative");
            if (const auto t = p.opt("tol"))
                q.tol = tolerance(*t);
            if (i > 0 && q.zMm == d.contour.back().zMm && q.dMm == d.contour.back().dMm)
                p.fail("same-point");
            d.contour.push_back(q);
        }
        if (d.contour.front().dMm != 0 || d.contour.back().dMm != 0)
            c->fail("contour-axis");
    } else if (const auto r = n.opt("reference")) {
        if (!r->boolean())
            r->fail("reference-true");
        d.kind = Drawing::Kind::Reference;
    } else {
        const Node b = n.at("bore");
        b.only({"d", "tol"});
        d.kind = Drawing::Kind::Bore;
        d.boreMm = b.at("d").num();
        if (d.boreMm <= 0)
            b.at("d").fail("diameter-positive");
        d.boreTol = tolerance(b.at("tol"));
    }
    return d;
}

std::string idOk(std::string_view id, const std::string& source) {
    if (id.empty() || id.size() > 64)
        throw ExerciseError(source, std::nullopt, "id-length");
    for (char c : id)
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-'))
            throw ExerciseError(source, std::nullopt, "id-chars", {std::string(id)});
    return std::string(id);
}

// The JSON of an exercise or a course file; a syntax error names the file's line and column.
Json parseDocument(std::string_view text, const std::string& source) {
    try {
        return json::parse(text);
    } catch (const json::ParseError& e) {
        throw ExerciseError(source + ":" + std::to_string(e.line) + ":" + std::to_string(e.column),
                            e.what());
    }
}

} // namespace

Exercise readExercise(std::string_view text, std::string_view id, std::string_view sourceView) {
    const std::string source(sourceView);
    const Json root = parseDocument(text, source);
    const Node n(root, "", source);
    n.only({"format", "machine", "title", "task", "hints", "blank", "tool", "chuck", "ring",
            "drawing", "setup", "faults", "operator", "at_end", "limits", "scoring", "reference",
            "given"});
    Exercise e;
    e.id = idOk(id, source);
    if (n.at("format").integer() != 1)
        n.at("format").fail("format");
    e.machine = n.at("machine").str();
    if (!profile::isBuiltin(e.machine))
        n.at("machine").fail("machine", {e.machine});
    e.title = n.at("title").bilingual();
    e.task = n.at("task").bilingual();
    if (const auto h = n.opt("hints")) {
        h->array();
        for (std::size_t i = 0; i < h->size(); ++i)
            e.hints.push_back(h->item(i).bilingual());
    }
    if (const auto b = n.opt("blank")) {
        b->only({"ucg", "z_mm"});
        e.ucg = b->at("ucg").str();
        std::string why, whyId;
        e.blank = stock::parseUcg(e.ucg, &why, &whyId);
        if (!e.blank)
            b->at("ucg").fail(std::string(kUcgPrefix) + whyId);
        if (const auto z = b->opt("z_mm"))
            e.blankZMm = z->num();
    }
    if (const auto t = n.opt("tool")) {
        t->only({"width_mm"});
        e.tool.widthMm = t->at("width_mm").num();
        if (e.tool.widthMm <= 0 || e.tool.widthMm > 50)
            t->at("width_mm").fail("mm-50");
    }
    if (const auto c = n.opt("chuck")) {
        c->only({"face_z_mm", "diameter_mm", "jaw_length_mm", "jaw_height_mm"});
        e.chuck.faceZMm = c->at("face_z_mm").num();
        e.chuck.diameterMm = c->at("diameter_mm").num();
        e.chuck.jawLengthMm = c->at("jaw_length_mm").num();
        e.chuck.jawHeightMm = c->at("jaw_height_mm").num();
    }
    if (const auto r = n.opt("ring")) {
        r->only({"z_mm", "outer_d", "wheel_width_mm"});
        Ring ring;
        const Node z = r->at("z_mm");
        z.array();
        if (z.size() != 2)
            z.fail("zone");
        ring.zMinMm = z.item(0).num();
        ring.zMaxMm = z.item(1).num();
        if (ring.zMaxMm <= ring.zMinMm)
            z.fail("zone-order");
        ring.outerMm = r->at("outer_d").num();
        ring.wheelWidthMm = r->at("wheel_width_mm").num();
        if (ring.wheelWidthMm <= 0)
            r->at("wheel_width_mm").fail("mm-positive");
        e.ring = ring;
    }
    if (e.blank && e.ring)
        n.fail("blank-and-ring");
    e.drawing = n.opt("drawing") ? drawing(n.at("drawing")) : Drawing{};
    if (e.drawing.kind == Drawing::Kind::Bore && !e.ring)
        n.at("drawing").fail("bore-needs-ring");
    if ((e.drawing.kind == Drawing::Kind::Contour || e.drawing.kind == Drawing::Kind::Reference) &&
        !e.blank)
        n.at("drawing").fail("part-needs-blank");
    if (const auto s = n.opt("setup"))
        s->only({"r"});
    if (n.has("setup") && n.at("setup").has("r")) {
        const Node r = n.at("setup").at("r");
        if (!r.json().is_object())
            r.fail("r-value");
        for (auto it = r.json().begin(); it != r.json().end(); ++it) {
            const Node v(*it, r.path() + "." + it.key(), source);
            int number = -1;
            try {
                std::size_t used = 0;
                number = std::stoi(it.key(), &used);
                if (used != it.key().size())
                    number = -1;
            } catch (const std::exception&) {
            }
            if (number < 0 || number > 231)
                v.fail("r-writable");
            e.setupR[number] = v.integer();
        }
    }
    if (const auto f = n.opt("faults")) {
        f->array();
        for (std::size_t i = 0; i < f->size(); ++i)
            e.faults.push_back(injection(f->item(i)));
    }
    if (const auto o = n.opt("operator")) {
        o->array();
        for (std::size_t i = 0; i < o->size(); ++i)
            e.steps.push_back(step(o->item(i)));
    }
    if (const auto a = n.opt("at_end")) {
        a->array();
        for (std::size_t i = 0; i < a->size(); ++i)
            e.atEnd.push_back(endCheck(a->item(i)));
    }
    if (const auto l = n.opt("limits")) {
        l->only({"cycle_time_s", "alarms_allowed"});
        if (const auto c = l->opt("cycle_time_s")) {
            e.limits.cycleTimeS = c->num();
            if (e.limits.cycleTimeS <= 0)
                c->fail("seconds");
        }
        if (const auto a = l->opt("alarms_allowed")) {
            a->array();
            for (std::size_t i = 0; i < a->size(); ++i)
                e.limits.alarmsAllowed.push_back(a->item(i).str());
        }
    }
    if (const auto s = n.opt("scoring")) {
        s->only({"pass_score"});
        e.scoring.passScore = static_cast<int>(s->at("pass_score").integer());
        if (e.scoring.passScore < 0 || e.scoring.passScore > 100)
            s->at("pass_score").fail("score");
    }
    e.reference = n.at("reference").text();
    if (const auto g = n.opt("given"))
        e.given = g->text();
    return e;
}

Course readCourse(std::string_view text, std::string_view sourceView) {
    const std::string source(sourceView);
    const Json root = parseDocument(text, source);
    const Node n(root, "", source);
    n.only({"format", "id", "title", "exercises"});
    if (n.at("format").integer() != 1)
        n.at("format").fail("format");
    Course c;
    c.id = idOk(n.at("id").str(), source);
    c.title = n.at("title").bilingual();
    const Node x = n.at("exercises");
    x.array();
    std::set<std::string> seen;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const std::string id = x.item(i).str();
        if (!seen.insert(id).second)
            x.item(i).fail("'" + id + "' is listed twice");
        c.exercises.push_back(id);
    }
    return c;
}

namespace {
constexpr std::string_view kCoursePath = "exercises/course.json";

std::string dataOf(std::string_view path) {
    const auto d = resources::find(path);
    if (!d)
        throw ExerciseError(std::string(path), std::nullopt, "not-embedded");
    return std::string(*d);
}
} // namespace

const Course& starterCourse() {
    static const Course c = readCourse(dataOf(kCoursePath), kCoursePath);
    return c;
}

const std::vector<Exercise>& shippedExercises() {
    static const std::vector<Exercise> all = [] {
        std::vector<Exercise> v;
        for (const std::string& id : starterCourse().exercises) {
            const std::string path = "exercises/" + id + ".json";
            v.push_back(readExercise(dataOf(path), id, path));
        }
        return v;
    }();
    return all;
}

const Exercise* findExercise(std::string_view id) {
    for (const Exercise& e : shippedExercises())
        if (e.id == id)
            return &e;
    return nullptr;
}

} // namespace k528::training
