// k528 run [options] FILE — runs a program on the simulated machine (the
// positioner, the PLC running the machine description, the plant: machine/run.h),
// headless (shared/spec/cli.md; extensions in docs/engine.md).
#include "args.h"
#include "catalog/messages.h"
#include "cli.h"
#include "cli_texts.h"
#include "output_file.h"
#include "engine/program_check.h"
#include "machine_profile.h"
#include "engine/rparams.h"
#include "engine/self_test.h"
#include "machine/run.h"
#include "machine/trace.h"
#include "engine/preview_run.h"
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
#include <optional>
#include <set>
#include <string>

namespace k528::cli {

namespace {

// How a preview ended, in the command line's language.
std::string previewEnded(engine::PreviewStatus status) {
    switch (status) {
    case engine::PreviewStatus::Completed: return cliText("preview.completed");
    case engine::PreviewStatus::Alarm: return cliText("preview.alarm");
    case engine::PreviewStatus::Limit: return cliText("preview.limit");
    case engine::PreviewStatus::Cancelled: return cliText("preview.cancelled");
    }
    return std::string(engine::previewStatusName(status));
}


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

// --from: "N", "N40", "L2:N40", "L2:40" -> (program or 0 for the main program, N).
bool parseFromSpec(const std::string& spec, int& program, int& n) {
    std::string s = spec;
    program = 0;
    const std::size_t colon = s.find(':');
    if (colon != std::string::npos) {
        std::string l = s.substr(0, colon);
        if (!l.empty() && (l[0] == 'L' || l[0] == 'l'))
            l.erase(0, 1);
        const auto v = parseInt(l);
        if (!v || *v < 1 || *v > 99)
            return false;
        program = static_cast<int>(*v);
        s = s.substr(colon + 1);
    }
    if (!s.empty() && (s[0] == 'N' || s[0] == 'n'))
        s.erase(0, 1);
    const auto v = parseInt(s);
    if (!v || *v < 0 || *v > 9999)
        return false;
    n = static_cast<int>(*v);
    return true;
}

std::string modalText(const engine::ModalState& m, const engine::StartPoint& p) {
    std::string t = m.rapid ? "G00" : "G01";
    t += " G" + std::to_string(m.components);
    t += m.noOverrideAxis < 0 ? " G55" : m.noOverrideAxis == 0 ? " G156" : " G256";
    t += m.incremental ? " G91" : " G90";
    const char* fn[2] = {" FX", " FZ"};
    for (int a = 0; a < 2; ++a) {
        const std::int64_t f = m.feed[static_cast<std::size_t>(a)];
        if (f >= 0)
            t += fn[a] + units::formatDisc(f, p.axes[static_cast<std::size_t>(a)].scale);
    }
    return t;
}

std::string frameName(int program, int n, int line) {
    std::string t = "L" + std::to_string(program);
    if (n > 0)
        t += " N" + std::to_string(n);
    if (line > 0)
        t += " (line " + std::to_string(line) + ")";
    return t;
}

Json startPointJson(const engine::StartPoint& p, const profile::MachineProfile& prof) {
    Json j;
    j["program"] = p.program;
    j["n"] = p.frameNumber > 0 ? Json(p.frameNumber) : Json();
    j["line"] = p.line;
    j["pass"] = p.pass;
    j["frames_before"] = static_cast<long long>(p.framesBefore);
    Json stack = Json::array();
    for (const engine::StartLevel& l : p.callers) {
        Json c;
        c["program"] = l.program;
        c["return_index"] = l.returnIndex;
        stack.push_back(std::move(c));
    }
    j["call_stack"] = std::move(stack);
    Json modal;
    modal["motion"] = p.modal.rapid ? "G00" : "G01";
    modal["components"] = "G" + std::to_string(p.modal.components);
    modal["override"] = p.modal.noOverrideAxis < 0 ? "G55" : p.modal.noOverrideAxis == 0 ? "G156" : "G256";
    modal["distance"] = p.modal.incremental ? "G91" : "G90";
    const char* axisNames[2] = {"X", "Z"};
    Json feeds;
    for (int a = 0; a < 2; ++a) {
        const std::int64_t f = p.modal.feed[static_cast<std::size_t>(a)];
        feeds[axisNames[a]] =
            f < 0 ? Json() : Json(units::discToMm(f, p.axes[static_cast<std::size_t>(a)].scale));
    }
    modal["feed_mm_min"] = std::move(feeds);
    j["modal"] = std::move(modal);
    Json comps = Json::object();
    for (int i = 0; i < 8; ++i)
        comps[std::to_string(224 + i)] = static_cast<long long>(p.components[static_cast<std::size_t>(i)]);
    j["components"] = std::move(comps);
    Json r = Json::object();
    for (const auto& [n, v] : p.r)
        r[std::to_string(n)] = static_cast<long long>(v);
    j["r"] = std::move(r);
    j["message"] = p.messageNumber > 0 ? Json(p.messageNumber) : Json();
    Json m = Json::array();
    for (int code : p.mFunctions)
        m.push_back(code);
    j["m_functions"] = std::move(m);
    Json at;
    for (int a = 0; a < 2; ++a) {
        const engine::StartAxis& ax = p.axes[static_cast<std::size_t>(a)];
        if (!ax.present)
            continue;
        Json c;
        c["current"] = units::discToMm(ax.currentDisc, ax.scale);
        c["machine"] = units::discToMm(ax.machineDisc, ax.scale);
        at[axisNames[a]] = std::move(c);
    }
    j["at"] = std::move(at);
    // The safe path, machine system: X to its reference point, Z, X.
    Json path = Json::array();
    const auto leg = [&](int a, std::int64_t disc) {
        const engine::StartAxis& ax = p.axes[static_cast<std::size_t>(a)];
        if (!ax.present)
            return;
        Json l;
        l["axis"] = axisNames[a];
        l["machine"] = units::discToMm(disc, ax.scale);
        path.push_back(std::move(l));
    };
    leg(0, prof.c[45]);
    leg(1, p.axes[1].machineDisc);
    leg(0, p.axes[0].machineDisc);
    j["approach"] = std::move(path);
    Json unc = Json::array();
    for (const engine::StartPoint::Uncertain& u : p.uncertain) {
        Json x;
        x["program"] = u.program;
        x["line"] = u.line;
        x["n"] = u.n > 0 ? Json(u.n) : Json();
        x["axis"] = axisNames[u.axis];
        unc.push_back(std::move(x));
    }
    j["uncertain"] = std::move(unc);
    return j;
}

void printStartPoint(const engine::StartPoint& p, const profile::MachineProfile& prof) {
    std::printf("start      before %s, pass %d (%lld frames before it)\n",
                frameName(p.program, p.frameNumber, p.line).c_str(), p.pass,
                static_cast<long long>(p.framesBefore));
    if (!p.callers.empty()) {
        std::printf("call stack L%d", p.mainProgram);
        for (std::size_t i = 1; i < p.callers.size(); ++i)
            std::printf(" > L%d", p.callers[i].program);
        std::printf(" > L%d\n", p.program);
    }
    std::printf("modal      %s\n", modalText(p.modal, p).c_str());
    std::printf("R224..R231");
    for (int i = 0; i < 8; ++i)
        std::printf(" %d", p.components[static_cast<std::size_t>(i)]);
    std::printf("\n");
    std::string rs;
    for (const auto& [n, v] : p.r)
        rs += " R" + std::to_string(n) + "=" + std::to_string(v);
    std::printf("R set     %s\n", rs.empty() ? " none" : rs.c_str());
    if (p.messageNumber > 0)
        std::printf("message    #%d\n", p.messageNumber);
    std::string ms;
    for (int m : p.mFunctions)
        ms += " M" + std::to_string(m);
    std::printf("M again   %s\n", ms.empty() ? " none" : ms.c_str());
    const char* names[2] = {"X", "Z"};
    for (int a = 0; a < 2; ++a) {
        const engine::StartAxis& ax = p.axes[static_cast<std::size_t>(a)];
        if (ax.present)
            std::printf("start %s    current %12s   machine %12s\n", names[a],
                        units::formatDisc(ax.currentDisc, ax.scale).c_str(),
                        units::formatDisc(ax.machineDisc, ax.scale).c_str());
    }
    std::printf("approach  ");
    if (p.axes[0].present)
        std::printf(" X %s (reference point),", units::formatDisc(prof.c[45], p.axes[0].scale).c_str());
    if (p.axes[1].present)
        std::printf(" Z %s,", units::formatDisc(p.axes[1].machineDisc, p.axes[1].scale).c_str());
    if (p.axes[0].present)
        std::printf(" X %s", units::formatDisc(p.axes[0].machineDisc, p.axes[0].scale).c_str());
    std::printf(" (machine system, rapid)\n");
    for (const engine::StartPoint::Uncertain& u : p.uncertain)
        std::printf("warning    %s moves %s until a signal or by handwheel: the start point takes its "
                    "programmed end\n",
                    frameName(u.program, u.n, u.line).c_str(), names[u.axis]);
}

} // namespace

int runRun(std::span<const std::string> argv) {
    const Args args(argv, {"--json", "--no-home", "--no-check"},
                    {"--profile", "--db", "--program", "--param", "--r", "--override", "--max-seconds",
                     "--number", "--lang", "--m0-wait", "--trace", "--from", "--pass"});
    if (!args.ok())
        return usageError(args.error());
    if (args.positional().size() != 1)
        return usageError(cliText("run.usage"));
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
            return usageError(cliText("run.override", {*o}));
        options.overridePercent = static_cast<int>(*pct);
    }
    if (const auto s = args.value("--max-seconds")) {
        const auto v = parseNumber(*s);
        if (!v || *v <= 0 || *v > 1e7)
            return usageError(cliText("run.max-seconds", {*s}));
        options.maxSeconds = *v;
    }
    if (const auto s = args.value("--m0-wait")) {
        const auto v = parseNumber(*s);
        if (!v || *v < 0 || *v > 1e6)
            return usageError(cliText("run.m0-wait", {*s}));
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
        std::fprintf(stderr, "k528: %s\n", cliText("file.no-program", {displayName(path)}).c_str());
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
            return usageError(cliText("opt.program", {*p}));
        if (!filePrograms.count(static_cast<int>(*n)))
            return usageError(cliText("opt.program-none", {*p, displayName(path)}));
        number = static_cast<int>(*n);
    } else {
        // The first program as written (the one `k528 format` keeps first).
        number = parsed.store.firstWritten();
    }

    // --from N: the state before the frame, rebuilt by the preview
    // (engine/preview_run.h findStartPoint), shown before the machine moves.
    std::optional<Json> fromJson;
    if (const auto from = args.value("--from")) {
        int fromProgram = 0, fromN = 0;
        if (!parseFromSpec(*from, fromProgram, fromN))
            return usageError(cliText("run.from", {*from}));
        int pass = 1;
        if (const auto ps = args.value("--pass")) {
            const auto v = parseInt(*ps);
            if (!v || *v < 1 || *v > 1000000)
                return usageError(cliText("run.pass", {*ps}));
            pass = static_cast<int>(*v);
        }
        if (fromProgram == 0)
            fromProgram = number;
        bool intact = true;
        program::ProgramStore all = engine::loadStore(prof, intact);
        for (const program::Program& p : parsed.store.programs())
            all.insert(p);
        const program::Program* target = all.find(fromProgram);
        if (!target)
            return usageError(cliText("run.from-program", {*from, std::to_string(fromProgram)}));
        const int index = target->indexOfN(fromN);
        if (index < 0)
            return usageError(cliText("run.from-frame", {*from, std::to_string(fromProgram), std::to_string(fromN)}));
        engine::PreviewOptions po;
        po.rPresets = options.rPresets;
        po.fromReferencePoint = options.home;
        const engine::StartSearch found =
            engine::findStartPoint(prof, parsed.store, number, {fromProgram, index, pass}, po);
        if (found.outcome == engine::StartSearch::Outcome::NotReached) {
            const std::string ended = previewEnded(found.preview.status);
            std::fprintf(stderr, "k528: %s\n",
                         cliText(pass > 1 ? "run.from-never-pass" : "run.from-never",
                                 {*from, std::to_string(fromProgram), std::to_string(fromN), ended, std::to_string(pass)})
                             .c_str());
            return ExitInputErrors;
        }
        if (found.outcome == engine::StartSearch::Outcome::Oscillating) {
            std::fprintf(stderr, "k528: %s\n",
                         cliText("run.from-oscillating", {*from, std::to_string(fromProgram), std::to_string(fromN),
                                                          found.oscillatingAxis == 0 ? "X" : "Z"})
                             .c_str());
            return ExitInputErrors;
        }
        options.from = found.point;
        if (asJson)
            fromJson = startPointJson(found.point, prof);
        else
            printStartPoint(found.point, prof);
    } else if (args.value("--pass")) {
        return usageError(cliText("run.pass-alone"));
    }

    // --trace FILE.csv: one row per tick (machine/trace.h, docs/engine.md),
    // written beside the file and renamed over it when whole (output_file.h).
    OutputStream traceOut;
    const auto tracePath = args.value("--trace");
    if (tracePath) {
        std::string error;
        if (!traceOut.open(*tracePath, error)) {
            std::fprintf(stderr, "k528: %s\n", cliText("run.trace-error", {error}).c_str());
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
                std::fprintf(stderr, "k528: %s\n", cliText("run.trace-error", {error}).c_str());
                return ExitUsage;
            }
        } else {
            result = machine::runProgram(prof, parsed.store, number, options);
        }
    } catch (const plc::DescriptionError& e) {
        printDescriptionError(e, lang);
        return ExitUsage;
    } catch (const std::invalid_argument& e) {
        return usageError(e.what());
    }
    if (asJson) {
        Json root = resultJson(result);
        if (fromJson)
            root["from"] = std::move(*fromJson);
        std::printf("%s\n", json::dump(root).c_str());
    }
    else
        printPlain(result, lang);
    return result.status == engine::RunStatus::Completed ? ExitOk : ExitInputErrors;
}

} // namespace k528::cli
