#include "training/record.h"

#include "util/json.h"

#include <cmath>

namespace k528::training {

db::AttemptEntry attemptEntry(const Grade& g, std::string_view programText) {
    db::AttemptEntry a;
    a.student = g.student.empty() ? g.file : g.student;
    a.exercise = g.exercise;
    a.file = g.file;
    a.program = std::string(programText);
    a.score = g.score;
    a.passed = g.passed;
    a.status = g.status;
    a.cycleTimeMs = std::llround(std::max(0.0, g.cycleTimeS) * 1000.0);
    a.grade = json::dump(gradeJson(g));
    return a;
}

namespace {

// A collision's kind as grades wrote it before the prove-out's rules (its
// rule id and the text id of its deduction, without "collision.").
struct OldCollision {
    std::string_view kind, rule, text;
};
constexpr OldCollision kOldCollisions[] = {
    {"rapid_into_material", "rapid-into-material", "rapid-into-material"},
    {"manual_into_material", "manual-into-material", "manual-into-material"},
    {"cut_without_spindle", "feed-spindle-stopped", "feed-spindle-stopped"},
    {"tool_into_chuck", "tool-into-chuck", "tool-into-chuck"}, // the jaws or the body: not told apart then
    {"rapid_into_ring", "rapid-into-material", "rapid-into-material.ring"},
};

const OldCollision* oldCollision(std::string_view kind) {
    for (const OldCollision& c : kOldCollisions)
        if (c.kind == kind)
            return &c;
    return nullptr;
}

} // namespace

std::string currentTextId(std::string_view id) {
    constexpr std::string_view prefix = "collision.";
    if (id.substr(0, prefix.size()) != prefix)
        return std::string(id);
    std::string_view rest = id.substr(prefix.size());
    std::string_view suffix;
    if (const auto dot = rest.find('.'); dot != std::string_view::npos) {
        suffix = rest.substr(dot); // ".manual"
        rest = rest.substr(0, dot);
    }
    const OldCollision* c = oldCollision(rest);
    if (!c)
        return std::string(id);
    if (!suffix.empty()) // an old "collision.tool_into_chuck.manual"
        return std::string(prefix) + std::string(c->rule) + std::string(suffix);
    return std::string(prefix) + std::string(c->text);
}

Json storedGradeJson(const db::AttemptEntry& a) {
    Json o;
    try {
        o = json::parse(a.grade);
    } catch (const std::exception&) {
        return Json(a.grade); // kept as stored
    }
    if (!o.is_object())
        return o;
    if (o.contains("deductions") && o["deductions"].is_array())
        for (Json& d : o["deductions"])
            if (d.is_object() && d.contains("id") && d["id"].is_string())
                d["id"] = currentTextId(d["id"].get<std::string>());
    if (o.contains("collisions") && o["collisions"].is_array())
        for (Json& c : o["collisions"]) {
            if (!c.is_object() || c.contains("rule") || !c.contains("kind") || !c["kind"].is_string())
                continue;
            const OldCollision* old = oldCollision(c["kind"].get<std::string>());
            if (!old)
                continue;
            // Today's shape: "rule" and "text" where "kind" was, the rest as it was.
            Json n = Json::object();
            for (auto it = c.begin(); it != c.end(); ++it) {
                if (it.key() == "kind") {
                    n["rule"] = old->rule;
                    n["text"] = old->text;
                } else {
                    n[it.key()] = it.value();
                }
            }
            c = std::move(n);
        }
    return o;
}

std::vector<Deduction> storedDeductions(const db::AttemptEntry& a) {
    std::vector<Deduction> out;
    Json o = storedGradeJson(a);
    if (!o.is_object() || !o.contains("deductions") || !o["deductions"].is_array())
        return out;
    const auto num = [](const Json& j, const char* key) {
        return j.contains(key) && j[key].is_number_integer() ? j[key].get<int>() : 0;
    };
    for (const Json& j : o["deductions"]) {
        if (!j.is_object())
            continue;
        Deduction d;
        d.category = j.value("category", std::string());
        d.points = j.contains("points") && j["points"].is_number() ? j["points"].get<double>() : 0.0;
        d.fails = j.value("fails", false);
        d.program = num(j, "program");
        d.n = num(j, "frame");
        d.line = num(j, "line");
        d.text.id = j.value("id", std::string());
        if (j.contains("args") && j["args"].is_array())
            for (const Json& arg : j["args"]) {
                if (arg.is_string())
                    d.text.args.emplace_back(arg.get<std::string>());
                else if (arg.is_object())
                    d.text.args.emplace_back(arg.value("ru", std::string()), arg.value("en", std::string()));
            }
        out.push_back(std::move(d));
    }
    return out;
}

} // namespace k528::training
