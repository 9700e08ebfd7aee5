// k528 run [options] FILE — runs a program on the simulated machine (the
// positioner, the PLC running the machine description, the plant: machine/run.h),
// headless (shared/spec/cli.md; extensions in docs/engine.md).
#include "args.h"
#include "catalog/messages.h"
#include "cli.h"
#include "output_file.h"
#include "engine/program_check.h"
#include "machine_profile.h"
#include "engine/rparams.h"
#include "engine/self_test.h"
#include "machine/run.h"
#include "machine/trace.h"
#include "plc/description.h"
#include "profile/builtin.h"
#include "profile/validate.h"
#include "program/validator.h"
#include "program_cli.h"
#include "program_setup.h"
#include "util/json.h"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <map>
#include <set>
#include <string>

namespace k528::cli {

namespace {

Json resultJson(const engine::RunResult& r) {
    Json root;
    root["status"] = engine::runStatusName(r.status);
    Json alarms = Json::array();
    for (const engine::AlarmView& a : r.alarms) {
        Json j;
        j["number"] = a.number;
        j["text_ru"] = a.textRu;
        j["program"] = a.program > 0 ? Json(a.program) : Json();
        j["line"] = a.line > 0 ? Json(a.line) : Json();
        alarms.push_back(std::move(j));
    }
    root["alarms"] = std::move(alarms);
    // Extension of cli.md (docs/engine.md): why a run with status "blocked"
    // never started, most direct reason first.
    Json blockers = Json::array();
    for (const engine::RunBlocker& b : r.blockedBy) {
        Json j;
        j["source"] = b.source;
        j["number"] = b.number;
        j["text_ru"] = engine::describeBlocker(b, true);
        j["text_en"] = engine::describeBlocker(b, false);
        blockers.push_back(std::move(j));
    }
    root["blocked_by"] = std::move(blockers);
    root["time_s"] = r.timeS;
    root["home_time_s"] = r.homeTimeS;
    root["frames"] = static_cast<long long>(r.frames);
    Json axes;
    const char* names[2] = {"X", "Z"};
    for (int i = 0; i < 2; ++i) {
        const engine::RunAxis& a = r.axes[static_cast<std::size_t>(i)];
        if (!a.present)
            continue;
        Json j;
        j["current"] = units::discToMm(a.currentDisc, a.scale);
        j["machine"] = units::discToMm(a.machineDisc, a.scale);
        j["max_following_error"] = units::fractionalDiscToMm(a.maxFollowingErrorDisc, a.scale);
        axes[names[i]] = std::move(j);
    }
    if (axes.is_null())
        axes = Json::object();
    root["axes"] = std::move(axes);
    Json rv = Json::object();
    for (int n = 0; n < 300; ++n)
        rv[std::to_string(n)] = static_cast<long long>(r.r[static_cast<std::size_t>(n)]);
    root["r"] = std::move(rv);
    return root;
}

void printPlain(const engine::RunResult& r, Lang lang) {
    std::printf("status     %s\n", std::string(engine::runStatusName(r.status)).c_str());
    std::printf("time       %.3f s (reference-point cycles %.3f s)\n", r.timeS, r.homeTimeS);
    std::printf("frames     %" PRId64 "\n", r.frames);
    const char* names[2] = {"X", "Z"};
    for (int i = 0; i < 2; ++i) {
        const engine::RunAxis& a = r.axes[static_cast<std::size_t>(i)];
        if (!a.present)
            continue;
        std::printf("%-10s current %12s   machine %12s%s\n", names[i],
                    units::formatDisc(a.currentDisc, a.scale).c_str(),
                    units::formatDisc(a.machineDisc, a.scale).c_str(),
                    a.scale.diameter ? "   (diameter)" : "");
    }
    if (r.alarms.empty())
        std::printf("alarms     none\n");
    for (const engine::AlarmView& a : r.alarms) {
        std::printf("alarm      %s", engine::alarmText(a, lang == Lang::Ru).c_str());
        if (a.program > 0)
            std::printf("  (L%d, line %d)", a.program, a.line);
        std::printf("\n");
    }
    for (const engine::RunBlocker& b : r.blockedBy)
        std::printf("blocked by %s\n", engine::describeBlocker(b, lang == Lang::Ru).c_str());
    if (r.program > 0) {
        std::printf("stopped at L%d", r.program);
        if (r.frameNumber > 0)
            std::printf(" N%d", r.frameNumber);
        if (r.line > 0)
            std::printf(" (line %d)", r.line);
        std::printf(", %s\n", std::string(engine::programStateName(r.state)).c_str());
    }
    if (r.messageNumber > 0)
        std::printf("message    #%d %s\n", r.messageNumber, r.messageText.c_str());
    if (!r.mFunctions.empty()) {
        std::printf("M to PLC  ");
        for (int m : r.mFunctions)
            std::printf(" M%d", m);
        std::printf("\n");
    }
    std::string user;
    for (int n = 0; n < 150; ++n)
        if (r.r[static_cast<std::size_t>(n)] != 0)
            user +=
                " R" + std::to_string(n) + "=" + std::to_string(r.r[static_cast<std::size_t>(n)]);
    std::printf("R0..R149  %s\n", user.empty() ? " all 0" : user.c_str());
}

} // namespace

int runRun(std::span<const std::string> argv) {
    const Args args(argv, {"--json", "--no-home", "--no-check"},
                    {"--profile", "--db", "--program", "--param", "--r", "--override", "--max-seconds",
                     "--number", "--lang", "--m0-wait", "--trace"});
    if (!args.ok())
        return usageError(args.error());
    if (args.positional().size() != 1)
        return usageError("run needs exactly one FILE");
    Lang lang = Lang::Ru;
    program::ParseOptions parseOptions;
    profile::MachineProfile prof;
    engine::RunOptions options;
    if (const int rc = readProgramOptions(args, lang, parseOptions, prof, options.rPresets); rc >= 0)
        return rc;
    options.home = !args.has("--no-home");
    if (const auto o = args.value("--override")) {
        const auto pct = parseInt(*o);
        if (!pct || units::overridePercentToCode(static_cast<int>(*pct)) < 0)
            return usageError("--override is one of 0 1 2 5 10 20 35 50 75 90 100, not '" + *o +
                              "'");
        options.overridePercent = static_cast<int>(*pct);
    }
    if (const auto s = args.value("--max-seconds")) {
        const auto v = parseNumber(*s);
        if (!v || *v <= 0 || *v > 1e7)
            return usageError("--max-seconds needs a number of seconds > 0, not '" + *s + "'");
        options.maxSeconds = *v;
    }
    if (const auto s = args.value("--m0-wait")) {
        const auto v = parseNumber(*s);
        if (!v || *v < 0 || *v > 1e6)
            return usageError("--m0-wait needs a number of seconds >= 0, not '" + *s + "'");
        options.m0WaitS = *v;
    }

    // The program file: syntax first, then the rules over the machine's store
    // (--no-check: not the rules: the file runs as the controller would hold
    // it, and a refused combination is the alarm of its frame, docs/engine.md).
    const std::string path = args.positional().front();
    std::string text;
    if (!readProgramFile(path, text))
        return ExitUsage;
    const bool asJson = args.has("--json");
    const bool noCheck = args.has("--no-check");
    std::FILE* diagOut = asJson ? stderr : stdout;
    engine::FileCheck checked;
    if (noCheck) {
        checked.parsed = program::parse(text, parseOptions);
        for (const program::Program& p : checked.parsed.store.programs())
            checked.programs.insert(p.number);
    } else {
        bool intact = true;
        checked = engine::checkFileForMachine(text, parseOptions, prof, engine::loadStore(prof, intact));
    }
    const program::ParseResult& parsed = checked.parsed;
    const std::set<int>& filePrograms = checked.programs;
    if (parsed.hasErrors()) {
        printDiagnostics(diagOut, displayName(path), parsed.diagnostics, lang);
        return ExitInputErrors;
    }
    if (parsed.store.empty()) {
        std::fprintf(stderr, "k528: %s holds no program\n", displayName(path).c_str());
        return ExitInputErrors;
    }
    if (checked.hasErrors()) {
        printDiagnostics(diagOut, displayName(path), checked.diagnostics, lang);
        return ExitInputErrors;
    }
    if (!asJson && !checked.diagnostics.empty())
        printDiagnostics(stderr, displayName(path), checked.diagnostics, lang);

    // Which program: --program N, else the first of the file.
    int number = 0;
    if (const auto p = args.value("--program")) {
        const auto n = parseInt(*p);
        if (!n || *n < 1 || *n > 99)
            return usageError("--program needs a program number 1..99, not '" + *p + "'");
        if (!filePrograms.count(static_cast<int>(*n)))
            return usageError("--program " + *p + ": " + displayName(path) + " has no program L" +
                              *p);
        number = static_cast<int>(*n);
    } else {
        // The first program as written (the one `k528 format` keeps first).
        number = parsed.store.firstWritten();
    }

    // --trace FILE.csv: one row per tick (machine/trace.h, docs/engine.md),
    // written beside the file and renamed over it when whole (output_file.h).
    OutputStream traceOut;
    const auto tracePath = args.value("--trace");
    if (tracePath) {
        std::string error;
        if (!traceOut.open(*tracePath, error)) {
            std::fprintf(stderr, "k528: the trace: %s\n", error.c_str());
            return ExitUsage;
        }
    }
    engine::RunResult result;
    try {
        if (tracePath) {
            machine::TraceRecorder trace(0, traceOut.file());
            result = machine::runProgramTraced(prof, parsed.store, number, options, trace);
            std::string error;
            if (!traceOut.commit(error)) {
                std::fprintf(stderr, "k528: the trace: %s\n", error.c_str());
                return ExitUsage;
            }
        } else {
            result = machine::runProgram(prof, parsed.store, number, options);
        }
    } catch (const plc::DescriptionError& e) {
        std::fprintf(stderr, "k528: machine description %s\n", e.what());
        return ExitUsage;
    } catch (const std::invalid_argument& e) {
        return usageError(e.what());
    }
    if (asJson)
        std::printf("%s\n", json::dump(resultJson(result)).c_str());
    else
        printPlain(result, lang);
    return result.status == engine::RunStatus::Completed ? ExitOk : ExitInputErrors;
}

} // namespace k528::cli
