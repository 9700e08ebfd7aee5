// k528 grade ID FILE... [--json | --csv] [--student NAME] [--lang ru|en] [--jobs N] [--geometry]
//                        [--record] [--db LOCATION]
// Grades students' program files against an exercise of the training course
// (core/training/grade.h, docs/training-course.md): each file runs on its own
// simulated machine, several at once on threads; one file gives a report,
// several a table (a class), --json an array of objects, one per file,
// --csv the trainer's record of the class (one line a file). --record (or
// --db) keeps every graded attempt in the database (training/record.h).
#include "args.h"
#include "cli.h"
#include "cli_texts.h"
#include "db_cli_util.h"
#include "program_cli.h"
#include "training/exercise_texts.h"
#include "training/grade.h"
#include "training/record.h"
#include "util/json.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace k528::cli {

namespace {

// How the attempt's run ended (Grade::status, the JSON's "status"), in
// words: "grade.status." and the status in the catalog, a status it does
// not name as it is.
std::string statusText(const std::string& status, bool ru) {
    if (const util::CatalogText* t = cliTexts().find("grade.status." + status))
        return std::string(t->in(ru));
    return status;
}

// A word of the catalog, for a column or a label printed with a width.
std::string word(std::string_view id, bool ru) { return cliText(id, {}, ru); }

void printReport(const training::Grade& g, Lang lang) {
    const training::Language l = lang == Lang::Ru ? training::Language::Ru : training::Language::En;
    const bool ru = lang == Lang::Ru;
    std::printf("%s %s", word("grade.file", ru).c_str(), g.file.c_str());
    if (!g.student.empty())
        std::printf(" (%s)", g.student.c_str());
    std::printf(" — %s %s\n", word("training.exercise", ru).c_str(), g.exercise.c_str());
    std::printf("%s %d/100, %s\n", word("grade.score", ru).c_str(), g.score,
                word(g.passed ? "training.passed" : "grade.not-passed", ru).c_str());
    std::printf("%s %s", word("grade.run", ru).c_str(), statusText(g.status, ru).c_str());
    const std::string s = word("unit.s", ru);
    if (g.cycleTimeS > 0)
        std::printf(", %s %.3f %s", word("grade.cycle-time", ru).c_str(), g.cycleTimeS, s.c_str());
    if (g.limitS > 0)
        std::printf(" (%s %g %s)", word("grade.limit", ru).c_str(), g.limitS, s.c_str());
    std::printf("\n");
    for (const training::Deduction& d : g.deductions)
        std::printf("  -%-5g %s%s\n", d.points, training::render(d.text, l).c_str(),
                    d.fails ? (" " + word("grade.fails", ru)).c_str() : "");
    if (g.deductions.empty())
        std::printf("  %s\n", word("grade.no-deductions", ru).c_str());
    for (const training::StepNote& n : g.notes)
        std::printf("  %s %d «%s»: %s\n", word("grade.line", ru).c_str(), n.line, n.token.c_str(),
                    training::render(n.text, l).c_str());
}

void printTable(const std::vector<training::Grade>& grades, Lang lang) {
    const bool ru = lang == Lang::Ru;
    const training::Language l = ru ? training::Language::Ru : training::Language::En;
    std::printf("%-24s %5s  %-10s %-12s %9s  %s\n", word("training.student", ru).c_str(),
                word("training.score", ru).c_str(), word("training.result", ru).c_str(),
                word("training.run", ru).c_str(), word("grade.cycle-s", ru).c_str(),
                word("grade.main-deduction", ru).c_str());
    int passed = 0;
    for (const training::Grade& g : grades) {
        passed += g.passed;
        const training::Deduction* worst = nullptr;
        for (const training::Deduction& d : g.deductions)
            if (!worst || d.points > worst->points)
                worst = &d;
        const std::string who = g.student.empty() ? g.file : g.student;
        std::printf("%-24s %5d  %-10s %-12s %9.3f  %s\n", who.c_str(), g.score,
                    word(g.passed ? "training.passed" : "training.failed", ru).c_str(),
                    g.status.c_str(), g.cycleTimeS,
                    worst ? training::render(worst->text, l).c_str() : "");
    }
    std::printf("%s %d/%zu\n", word("grade.passed-count", ru).c_str(), passed, grades.size());
}

// One CSV field (RFC 4180): quoted when it holds a comma, a quote or a line break.
std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"\r\n") == std::string::npos)
        return s;
    std::string q = "\"";
    for (char c : s)
        q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

void printCsv(const std::vector<training::Grade>& grades, Lang lang) {
    const training::Language l = lang == Lang::Ru ? training::Language::Ru : training::Language::En;
    std::printf("student,file,exercise,score,passed,status,cycle_time_s,deductions\n");
    for (const training::Grade& g : grades) {
        std::string ded;
        for (const training::Deduction& d : g.deductions) {
            char pts[32];
            std::snprintf(pts, sizeof pts, "-%g ", d.points);
            ded += (ded.empty() ? "" : "; ") + std::string(pts) + training::render(d.text, l);
        }
        std::printf("%s,%s,%s,%d,%s,%s,%.3f,%s\n", csvField(g.student).c_str(), csvField(g.file).c_str(),
                    csvField(g.exercise).c_str(), g.score, g.passed ? "yes" : "no", g.status.c_str(),
                    g.cycleTimeS, csvField(ded).c_str());
    }
}

} // namespace

int runGrade(std::span<const std::string> argv) {
    const Args args(argv, {"--json", "--csv", "--geometry", "--record"}, {"--student", "--lang", "--jobs", "--db"});
    if (!args.ok())
        return usageError(args.error());
    if (args.has("--json") && args.has("--csv"))
        return usageError(cliText("grade.json-csv"));
    Lang lang = Lang::Ru;
    if (const auto l = args.value("--lang"); l && !parseLang(*l, lang))
        return usageError(cliText("opt.lang", {*l}));
    const auto& pos = args.positional();
    if (pos.size() < 2)
        return usageError(cliText("grade.usage"));
    const auto student = args.value("--student");
    if (student && pos.size() != 2)
        return usageError(cliText("grade.student"));
    unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
    if (const auto j = args.value("--jobs")) {
        const auto n = parseInt(*j);
        if (!n || *n < 1 || *n > 64)
            return usageError(cliText("grade.jobs", {*j}));
        jobs = static_cast<unsigned>(*n);
    }
    const training::Exercise* e = nullptr;
    try {
        e = training::findExercise(pos[0]);
    } catch (const training::ExerciseError& err) {
        std::fprintf(stderr, "k528: %s\n", err.text(lang == Lang::Ru).c_str());
        return ExitUsage;
    }
    if (!e)
        return usageError(
            training::exerciseTexts().render("no-exercise", std::vector<std::string>{pos[0]}, lang == Lang::Ru),
            lang == Lang::Ru);

    // Every file is read before anything runs: a missing one is a usage error.
    struct Item {
        std::string file, student, text;
    };
    // The database the attempts go to, opened (and checked) before anything
    // is graded: a database that cannot take them is said at once.
    std::optional<db::Database> database;
    if (args.has("--record") || args.value("--db")) {
        dbcli::DbTarget target;
        database = dbcli::openDbOf(args, target, false, {}, lang == Lang::Ru ? db::Lang::Ru : db::Lang::En);
        if (!database)
            return ExitUsage;
        try {
            database->requireWritable();
        } catch (const db::Error& err) {
            return dbcli::dbFail(err, lang == Lang::Ru ? db::Lang::Ru : db::Lang::En);
        }
    }
    std::vector<Item> items;
    for (std::size_t i = 1; i < pos.size(); ++i) {
        Item it;
        it.file = displayName(pos[i]);
        if (!readProgramFile(pos[i], it.text))
            return ExitUsage;
        it.student = student ? *student : std::filesystem::path(pos[i]).stem().string();
        if (pos[i] == "-" && !student)
            it.student.clear();
        items.push_back(std::move(it));
    }

    std::optional<training::Grader> grader;
    try {
        grader.emplace(*e);
    } catch (const std::exception& err) {
        std::fprintf(stderr, "k528: %s\n", cliText("grade.exercise", {e->id, err.what()}).c_str());
        return ExitUsage;
    }
    std::vector<training::Grade> grades(items.size());
    std::vector<std::string> failures(items.size());
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        for (std::size_t i = next++; i < items.size(); i = next++) {
            try {
                grades[i] = grader->grade(items[i].text, items[i].file, items[i].student);
            } catch (const std::exception& err) {
                failures[i] = err.what();
            }
        }
    };
    const unsigned threads = std::min<unsigned>(jobs, static_cast<unsigned>(items.size()));
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t)
        pool.emplace_back(work);
    work();
    for (std::thread& t : pool)
        t.join();
    for (std::size_t i = 0; i < items.size(); ++i)
        if (!failures[i].empty()) {
            std::fprintf(stderr, "k528: %s: %s\n", items[i].file.c_str(), failures[i].c_str());
            return ExitUsage;
        }

    // One row an attempt, in the order of the files, each its own
    // transaction: one the database refuses is said (its grade is still
    // printed) and the others are recorded.
    std::size_t notRecorded = 0;
    if (database)
        for (std::size_t i = 0; i < items.size(); ++i) {
            try {
                database->recordAttempt(training::attemptEntry(grades[i], items[i].text));
            } catch (const db::Error& err) {
                ++notRecorded;
                std::fprintf(stderr, "%s\n",
                             cliText("grade.not-recorded",
                                     {items[i].file, err.text(lang == Lang::Ru ? db::Lang::Ru : db::Lang::En)},
                                     lang == Lang::Ru)
                                 .c_str());
            }
        }
    if (args.has("--json")) {
        Json a = Json::array();
        for (const training::Grade& g : grades)
            a.push_back(training::gradeJson(g, args.has("--geometry")));
        std::printf("%s\n", json::dump(a).c_str());
    } else if (args.has("--csv")) {
        printCsv(grades, lang);
    } else if (grades.size() == 1) {
        printReport(grades.front(), lang);
    } else {
        printTable(grades, lang);
    }
    if (notRecorded > 0)
        return ExitUsage;
    const bool all = std::all_of(grades.begin(), grades.end(),
                                 [](const training::Grade& g) { return g.passed; });
    return all ? ExitOk : ExitInputErrors;
}

} // namespace k528::cli
