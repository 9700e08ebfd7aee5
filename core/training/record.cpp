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

std::vector<Deduction> storedDeductions(const db::AttemptEntry& a) {
    std::vector<Deduction> out;
    Json o;
    try {
        o = json::parse(a.grade);
    } catch (const std::exception&) {
        return out;
    }
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
