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

// How the attempt's run ended (Grade::status, the JSON's "status"), in words.
const char* statusText(const std::string& status, bool ru) {
    static const struct {
        const char *id, *ru, *en;
    } kStatus[] = {
        {"completed", "программа выполнена до конца", "the program ran to its end"},
        {"alarm", "остановлена сообщением", "stopped by a message"},
        {"interrupted", "прервана", "interrupted"},
        {"timeout", "не закончилась за отведённое время", "did not end in the time allowed"},
        {"not_started", "программа не запускалась", "the program was not started"},
        {"procedure", "только действия оператора", "the operator's procedure only"},
        {"errors", "станок не принял файл", "the machine does not take the file"},
    };
    for (const auto& t : kStatus)
        if (status == t.id)
            return ru ? t.ru : t.en;
    return status.c_str();
}

void printReport(const training::Grade& g, Lang lang) {
    const training::Language l = lang == Lang::Ru ? training::Language::Ru : training::Language::En;
    const bool ru = lang == Lang::Ru;
    std::printf("%s %s", ru ? "Файл" : "File", g.file.c_str());
    if (!g.student.empty())
        std::printf(" (%s)", g.student.c_str());
    std::printf(" — %s %s\n", ru ? "упражнение" : "exercise", g.exercise.c_str());
    std::printf("%s %d/100, %s\n", ru ? "Оценка" : "Score", g.score,
                g.passed ? (ru ? "зачтено" : "passed") : (ru ? "не зачтено" : "not passed"));
    std::printf("%s %s", ru ? "Выполнение:" : "Run:", statusText(g.status, ru));
    const char* s = ru ? "с" : "s";
    if (g.cycleTimeS > 0)
        std::printf(", %s %.3f %s", ru ? "время цикла" : "cycle time", g.cycleTimeS, s);
    if (g.limitS > 0)
        std::printf(" (%s %g %s)", ru ? "норма" : "limit", g.limitS, s);
    std::printf("\n");
    for (const training::Deduction& d : g.deductions)
        std::printf("  -%-5g %s%s\n", d.points, training::render(d.text, l).c_str(),
                    d.fails ? (ru ? " [не зачтено]" : " [fails]") : "");
    if (g.deductions.empty())
        std::printf("  %s\n", ru ? "замечаний нет" : "no deductions");
    for (const training::StepNote& n : g.notes)
        std::printf("  %s %d «%s»: %s\n", ru ? "строка" : "line", n.line, n.token.c_str(),
                    training::render(n.text, l).c_str());
}

void printTable(const std::vector<training::Grade>& grades, Lang lang) {
    const bool ru = lang == Lang::Ru;
    const training::Language l = ru ? training::Language::Ru : training::Language::En;
    std::printf("%-24s %5s  %-10s %-12s %9s  %s\n", ru ? "ученик" : "student", ru ? "балл" : "score",
                ru ? "итог" : "result", ru ? "выполнение" : "run", ru ? "цикл, с" : "cycle, s",
                ru ? "главное замечание" : "main deduction");
    int passed = 0;
    for (const training::Grade& g : grades) {
        passed += g.passed;
        const training::Deduction* worst = nullptr;
        for (const training::Deduction& d : g.deductions)
            if (!worst || d.points > worst->points)
                worst = &d;
        const std::string who = g.student.empty() ? g.file : g.student;
        std::printf("%-24s %5d  %-10s %-12s %9.3f  %s\n", who.c_str(), g.score,
                    g.passed ? (ru ? "зачтено" : "passed") : (ru ? "незачёт" : "failed"),
                    g.status.c_str(), g.cycleTimeS,
                    worst ? training::render(worst->text, l).c_str() : "");
    }
    std::printf("%s %d/%zu\n", ru ? "Зачтено:" : "Passed:", passed, grades.size());
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
                std::fprintf(stderr, lang == Lang::Ru ? "k528: %s: оценено, но попытка не записана: %s\n"
                                                      : "k528: %s: graded, but the attempt was not recorded: %s\n",
                             items[i].file.c_str(), err.text(lang == Lang::Ru ? db::Lang::Ru : db::Lang::En).c_str());
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
