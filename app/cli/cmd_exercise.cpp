// k528 exercise list [--json] [--lang ru|en]
// k528 exercise show ID [--reference | --given] [--json] [--lang ru|en]
// k528 exercise attempts [ID] [--student NAME] [--limit N] [--json | --csv] [--db LOCATION]
// The training course's exercises (core/training, docs/training-course.md).
#include "args.h"
#include "cli.h"
#include "cli_texts.h"
#include "db_cli_util.h"
#include "program_cli.h"
#include "stock/stock.h"
#include "training/exercise_texts.h"
#include "training/exercise.h"
#include "training/record.h"
#include "util/json.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace k528::cli {

namespace {

training::Language languageOf(Lang l) {
    return l == Lang::Ru ? training::Language::Ru : training::Language::En;
}

Json exerciseJson(const training::Exercise& e, training::Language l, std::size_t position) {
    Json o;
    o["id"] = e.id;
    o["position"] = static_cast<long long>(position);
    o["machine"] = e.machine;
    o["title"] = e.title.in(l);
    o["title_ru"] = e.title.ru;
    o["title_en"] = e.title.en;
    return o;
}

std::string toleranceText(const training::Tolerance& t) {
    const auto sign = [](double v) {
        char b[32];
        std::snprintf(b, sizeof b, "%+.3f", v);
        std::string s(b);
        while (s.size() > 2 && s.back() == '0')
            s.pop_back();
        if (s.back() == '.')
            s.pop_back();
        return s;
    };
    return sign(t.upperMm) + "/" + sign(t.lowerMm);
}

int list(const Args& args, Lang lang) {
    const auto& all = training::shippedExercises();
    const training::Language l = languageOf(lang);
    if (args.has("--json")) {
        Json a = Json::array();
        for (std::size_t i = 0; i < all.size(); ++i)
            a.push_back(exerciseJson(all[i], l, i + 1));
        std::printf("%s\n", json::dump(a).c_str());
        return ExitOk;
    }
    std::printf("%s\n", training::starterCourse().title.in(l).c_str());
    for (std::size_t i = 0; i < all.size(); ++i)
        std::printf("%2zu  %-28s %-15s %s\n", i + 1, all[i].id.c_str(), all[i].machine.c_str(),
                    all[i].title.in(l).c_str());
    return ExitOk;
}

int show(const Args& args, Lang lang, const std::string& id) {
    const training::Exercise* e = training::findExercise(id);
    if (!e)
        return usageError(training::exerciseTexts().render("no-exercise", std::vector<std::string>{id}, lang == Lang::Ru),
                          lang == Lang::Ru);
    if (args.has("--reference")) {
        std::fputs(e->reference.c_str(), stdout);
        return ExitOk;
    }
    if (args.has("--given")) {
        if (e->given.empty())
            return usageError(cliText("exercise.no-program", {id}));
        std::fputs(e->given.c_str(), stdout);
        return ExitOk;
    }
    const training::Language l = languageOf(lang);
    const bool ru = lang == Lang::Ru;
    if (args.has("--json")) {
        Json o = exerciseJson(*e, l, 0);
        o.erase("position");
        o["task"] = e->task.in(l);
        Json hints = Json::array();
        for (const training::Bilingual& h : e->hints)
            hints.push_back(h.in(l));
        o["hints"] = std::move(hints);
        o["blank"] = e->ucg.empty() ? Json() : Json(e->ucg);
        o["cycle_time_s"] = e->limits.cycleTimeS > 0 ? Json(e->limits.cycleTimeS) : Json();
        o["alarms_allowed"] = e->limits.alarmsAllowed;
        Json steps = Json::array();
        for (const training::OperatorStep& s : e->steps)
            steps.push_back(std::string(training::stepName(s.kind)));
        o["operator"] = std::move(steps);
        o["has_given_program"] = !e->given.empty();
        std::printf("%s\n", json::dump(o).c_str());
        return ExitOk;
    }
    std::printf("%s — %s\n", e->id.c_str(), e->title.in(l).c_str());
    const auto word = [ru](std::string_view id) { return cliText(id, {}, ru); };
    std::printf("%s %s\n", word("exercise.machine").c_str(), e->machine.c_str());
    if (!e->ucg.empty())
        std::printf("%s %s\n", word("exercise.blank").c_str(), e->ucg.c_str());
    std::printf("\n%s\n", e->task.in(l).c_str());
    const training::Drawing& d = e->drawing;
    if (d.kind == training::Drawing::Kind::Contour) {
        std::printf("%s\n", word("exercise.drawing-contour").c_str());
        for (const training::ContourPoint& p : d.contour)
            std::printf("  Z%-10g Ø%-10g %s\n", p.zMm, p.dMm,
                        toleranceText(p.tol.value_or(d.tolerance)).c_str());
    } else if (d.kind == training::Drawing::Kind::Bore) {
        std::printf("%s Ø%g %s\n", word("exercise.drawing-bore").c_str(), d.boreMm,
                    toleranceText(d.boreTol).c_str());
    } else if (d.kind == training::Drawing::Kind::Reference) {
        std::printf("%s %s\n", word("exercise.drawing-reference").c_str(),
                    toleranceText(d.tolerance).c_str());
    }
    if (e->limits.cycleTimeS > 0)
        std::printf("%s %g %s\n", word("exercise.cycle-time").c_str(), e->limits.cycleTimeS, word("unit.s").c_str());
    if (!e->steps.empty()) {
        std::string s;
        for (const training::OperatorStep& st : e->steps)
            s += (s.empty() ? "" : ", ") + std::string(training::stepName(st.kind));
        std::printf("%s %s\n", word("exercise.steps").c_str(), s.c_str());
    }
    for (const training::Bilingual& h : e->hints)
        std::printf("%s %s\n", word("exercise.hint").c_str(), h.in(l).c_str());
    if (!e->given.empty())
        std::printf("%s k528 exercise show %s --given\n",
                    word("exercise.given").c_str(), e->id.c_str());
    return ExitOk;
}

// The attempts on record (newest first): a table, --json or --csv.
int attempts(const Args& args, Lang lang, const std::string& exercise) {
    const db::Lang dl = lang == Lang::Ru ? db::Lang::Ru : db::Lang::En;
    if (!exercise.empty() && !training::findExercise(exercise))
        return usageError(
            training::exerciseTexts().render("no-exercise", std::vector<std::string>{exercise}, lang == Lang::Ru),
            lang == Lang::Ru);
    db::AttemptFilter f;
    f.exercise = exercise;
    f.student = args.value("--student").value_or("");
    if (const auto n = args.value("--limit")) {
        const auto v = parseInt(*n);
        if (!v || *v < 1)
            return usageError(cliText("exercise.limit", {*n}));
        f.limit = static_cast<int>(std::min<long long>(*v, 1000000));
    }
    dbcli::DbTarget target;
    auto d = dbcli::openDbOf(args, target, false, {}, dl);
    if (!d)
        return ExitUsage;
    std::vector<db::AttemptEntry> rows;
    try {
        rows = d->attempts(f);
    } catch (const db::Error& e) {
        return dbcli::dbFail(e, dl);
    }
    const training::Language l = lang == Lang::Ru ? training::Language::Ru : training::Language::En;
    const bool ru = lang == Lang::Ru;
    const auto deductionsText = [&](const db::AttemptEntry& a) {
        std::string out;
        for (const training::Deduction& x : training::storedDeductions(a)) {
            char pts[32];
            std::snprintf(pts, sizeof pts, "-%g ", x.points);
            out += (out.empty() ? "" : "; ") + std::string(pts) + training::render(x.text, l);
        }
        return out;
    };
    if (args.has("--json")) {
        Json a = Json::array();
        for (const db::AttemptEntry& r : rows) {
            Json o;
            o["id"] = r.id;
            o["at"] = r.at;
            o["recorded_by"] = r.recordedBy;
            o["host"] = r.host;
            o["student"] = r.student;
            o["exercise"] = r.exercise;
            o["file"] = r.file;
            o["sha256"] = r.sha256;
            o["score"] = r.score;
            o["passed"] = r.passed;
            o["status"] = r.status;
            o["cycle_time_s"] = static_cast<double>(r.cycleTimeMs) / 1000.0;
            o["grade"] = training::storedGradeJson(r); // older ids read as today's
            a.push_back(std::move(o));
        }
        std::printf("%s\n", json::dump(a).c_str());
        return ExitOk;
    }
    if (args.has("--csv")) {
        const auto field = [](const std::string& s) {
            if (s.find_first_of(",\"\r\n") == std::string::npos)
                return s;
            std::string q = "\"";
            for (char c : s)
                q += c == '"' ? std::string("\"\"") : std::string(1, c);
            return q + "\"";
        };
        std::printf("id,at,student,exercise,file,score,passed,status,cycle_time_s,deductions\n");
        for (const db::AttemptEntry& r : rows)
            std::printf("%lld,%s,%s,%s,%s,%d,%s,%s,%.3f,%s\n", static_cast<long long>(r.id), r.at.c_str(),
                        field(r.student).c_str(), field(r.exercise).c_str(), field(r.file).c_str(), r.score,
                        r.passed ? "yes" : "no", r.status.c_str(), static_cast<double>(r.cycleTimeMs) / 1000.0,
                        field(deductionsText(r)).c_str());
        return ExitOk;
    }
    const auto word = [ru](std::string_view id) { return cliText(id, {}, ru); };
    std::printf("%-6s %-20s %-20s %-26s %5s  %-10s %s\n", "id", word("training.at").c_str(),
                word("training.student").c_str(), word("training.exercise").c_str(), word("training.score").c_str(),
                word("training.result").c_str(), word("training.run").c_str());
    for (const db::AttemptEntry& r : rows)
        std::printf("%-6lld %-20s %-20s %-26s %5d  %-10s %s\n", static_cast<long long>(r.id), r.at.c_str(),
                    r.student.c_str(), r.exercise.c_str(), r.score,
                    word(r.passed ? "training.passed" : "training.failed").c_str(), r.status.c_str());
    std::printf("%s %zu\n", word("exercise.attempts").c_str(), rows.size());
    return ExitOk;
}

} // namespace

int runExercise(std::span<const std::string> argv) {
    const Args args(argv, {"--json", "--csv", "--reference", "--given"}, {"--lang", "--student", "--limit", "--db"});
    if (!args.ok())
        return usageError(args.error());
    Lang lang = Lang::Ru;
    if (const auto l = args.value("--lang"); l && !parseLang(*l, lang))
        return usageError(cliText("opt.lang", {*l}));
    const auto& pos = args.positional();
    if (pos.empty())
        return usageError(cliText("exercise.needs"));
    try {
        if (pos[0] == "list" && pos.size() == 1)
            return list(args, lang);
        if (pos[0] == "show" && pos.size() == 2)
            return show(args, lang, pos[1]);
        if (pos[0] == "attempts" && pos.size() <= 2)
            return attempts(args, lang, pos.size() == 2 ? pos[1] : std::string());
    } catch (const training::ExerciseError& e) {
        std::fprintf(stderr, "k528: %s\n", e.text(lang == Lang::Ru).c_str());
        return ExitUsage;
    }
    return usageError(cliText("exercise.usage"));
}

} // namespace k528::cli
