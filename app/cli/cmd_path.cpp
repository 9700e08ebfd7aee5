// k528 path [options] FILE — the programmed toolpath (shared/spec/cli.md):
// the engine's interpreter in preview (engine/preview.h) through
// core/toolpath. Output is streamed (a million segments print in a second),
// so the JSON is written here rather than built as a tree.
#include "cli.h"
#include "cli_texts.h"
#include "machine/run.h"
#include "plc/description.h"
#include "program_setup.h"
#include "proveout_cli.h"
#include "toolpath/programmed_path.h"
#include "util/json.h"

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <string>

namespace k528::cli {

namespace {

// A coordinate in mm, shortest exact form up to 0.1 µm ("12.5", "-0.001", "0").
std::string mm(double v) {
    if (!std::isfinite(v))
        return "null";
    double r = std::round(v * 1e7) / 1e7;
    if (r == 0)
        r = 0; // no "-0"
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.7f", r);
    std::string s = buf;
    while (!s.empty() && s.back() == '0')
        s.pop_back();
    if (!s.empty() && s.back() == '.')
        s.pop_back();
    return s;
}

std::string jsonText(const std::string& s) {
    std::string o = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\')
            o += '\\', o += c;
        else if (static_cast<unsigned char>(c) < 0x20) {
            char b[8];
            std::snprintf(b, sizeof b, "\\u%04x", c);
            o += b;
        } else
            o += c;
    }
    return o + "\"";
}

constexpr const char* kOutsideRu = "ВНЕ ГРАНИЦ";
constexpr const char* kOutsideEn = "OUT OF BOUNDS";

// The cycle time (machine/run.h) and how its run ended: "completed",
// "alarm", "timeout", "blocked", or "not_run" when the preview already ended
// in an alarm or at the frame limit.
struct Cycle {
    std::optional<double> seconds;
    std::string run = "not_run";
};

// Seconds to the millisecond ("83.412", "0.5"); null when there is no figure.
std::string seconds(const std::optional<double>& s) {
    if (!s)
        return "null";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3f", *s);
    std::string t = buf;
    while (t.back() == '0')
        t.pop_back();
    if (t.back() == '.')
        t.pop_back();
    return t;
}

void printJson(const toolpath::ProgrammedPath& p, const proveout::Result& proof,
               const ProgramSetup& setup, const Cycle& cycle) {
    std::FILE* o = stdout;
    std::fprintf(o, "{\"program\":%d,\"segments\":[", p.program);
    bool first = true;
    for (const toolpath::Segment& s : p.segments) {
        std::fprintf(o, "%s{\"program\":%d,\"line\":%d,\"n\":%d,\"kind\":\"%s\",\"points\":[",
                     first ? "" : ",", s.program, s.line, s.n,
                     std::string(toolpath::kindName(s.kind)).c_str());
        first = false;
        const toolpath::PointMm* pt = p.pointsOf(s);
        for (int i = 0; i < s.pointCount; ++i)
            std::fprintf(o, "%s[%s,%s]", i ? "," : "", mm(pt[i].x).c_str(), mm(pt[i].z).c_str());
        std::fprintf(o, "],\"feed_mm_min\":{\"X\":%s,\"Z\":%s},\"outside\":%s}",
                     mm(s.feedXMmMin).c_str(), mm(s.feedZMmMin).c_str(),
                     s.outside ? "true" : "false");
    }
    std::fprintf(o, "],\"dwells\":[");
    first = true;
    for (const toolpath::Dwell& d : p.dwells) {
        std::fprintf(o, "%s{\"program\":%d,\"line\":%d,\"n\":%d,\"at\":[%s,%s],\"seconds\":%s}",
                     first ? "" : ",", d.program, d.line, d.n, mm(d.at.x).c_str(),
                     mm(d.at.z).c_str(), mm(d.seconds).c_str());
        first = false;
    }
    std::fprintf(o, "],\"limits\":{");
    first = true;
    const toolpath::AxisLimits* lim[2] = {&p.limitX, &p.limitZ};
    const char* names[2] = {"X", "Z"};
    for (int i = 0; i < 2; ++i) {
        if (!lim[i]->present)
            continue;
        std::fprintf(o, "%s\"%s\":[%s,%s]", first ? "" : ",", names[i], mm(lim[i]->minMm).c_str(),
                     mm(lim[i]->maxMm).c_str());
        first = false;
    }
    std::fprintf(o, "},\"warnings\":[");
    first = true;
    for (const toolpath::Segment& s : p.segments) {
        if (!s.outside)
            continue;
        std::fprintf(o, "%s{\"program\":%d,\"line\":%d,\"n\":%d,\"text_ru\":\"%s\",\"text_en\":\"%s\"}",
                     first ? "" : ",", s.program, s.line, s.n, kOutsideRu, kOutsideEn);
        first = false;
    }
    // The prove-out's findings (docs/proveout.md), each with its "rule".
    std::fprintf(o, "],\"diagnostics\":[");
    first = true;
    for (const proveout::Finding& f : proof.findings) {
        const bool inFile = setup.store.find(f.program) != nullptr;
        std::fprintf(o, "%s%s", first ? "" : ",",
                     json::dump(findingJson(f, setup.text, inFile)).c_str());
        first = false;
    }
    std::fprintf(o, "],\"alarms\":[");
    first = true;
    for (const engine::AlarmView& a : p.run.alarms) {
        std::fprintf(o, "%s{\"number\":%d,\"text_ru\":%s,\"program\":%d,\"line\":%d}",
                     first ? "" : ",", a.number, jsonText(a.textRu).c_str(), a.program, a.line);
        first = false;
    }
    std::fprintf(o,
                 "],\"end\":{\"X\":%s,\"Z\":%s},\"frames\":%" PRId64
                 ",\"cycle_time_s\":%s,\"cycle_run\":\"%s\",\"status\":\"%s\"}\n",
                 mm(p.end.x).c_str(), mm(p.end.z).c_str(), p.run.frames, seconds(cycle.seconds).c_str(),
                 cycle.run.c_str(), std::string(engine::previewStatusName(p.run.status)).c_str());
}

void printPlain(const toolpath::ProgrammedPath& p, const proveout::Result& proof, Lang lang,
                const Cycle& cycle) {
    for (const toolpath::Segment& s : p.segments) {
        std::FILE* o = stdout;
        std::fprintf(o, "L%d N%d line %d %s ", s.program, s.n, s.line,
                     std::string(toolpath::kindName(s.kind)).c_str());
        const toolpath::PointMm* pt = p.pointsOf(s);
        for (int i = 0; i < s.pointCount; ++i)
            std::fprintf(o, "%sX%s Z%s", i ? " -> " : " ", mm(pt[i].x).c_str(), mm(pt[i].z).c_str());
        if (std::isfinite(s.feedXMmMin))
            std::fprintf(o, "  FX %s", mm(s.feedXMmMin).c_str());
        if (std::isfinite(s.feedZMmMin))
            std::fprintf(o, "  FZ %s", mm(s.feedZMmMin).c_str());
        if (s.outside)
            std::fprintf(o, "  %s", lang == Lang::Ru ? kOutsideRu : kOutsideEn);
        std::fputc('\n', o);
    }
    for (const toolpath::Dwell& d : p.dwells)
        std::fprintf(stdout, "L%d N%d line %d dwell  X%s Z%s  %s s\n", d.program, d.n, d.line,
                     mm(d.at.x).c_str(), mm(d.at.z).c_str(), mm(d.seconds).c_str());
    for (const proveout::Finding& f : proof.findings)
        std::fprintf(stdout, "L%d N%d line %d %s [%s] %s%s\n", f.program, f.n, f.line,
                     f.isError() ? "error" : "warning",
                     std::string(proveout::ruleId(f.rule)).c_str(), f.message(lang == Lang::Ru).c_str(),
                     f.occurrences > 1 ? (" (×" + std::to_string(f.occurrences) + ")").c_str() : "");
    for (const engine::AlarmView& a : p.run.alarms)
        std::fprintf(stdout, "alarm %s  (L%d, line %d)\n",
                     engine::alarmText(a, lang == Lang::Ru).c_str(), a.program, a.line);
    std::fprintf(stdout, "end  X%s Z%s  frames %" PRId64 "  status %s\n", mm(p.end.x).c_str(),
                 mm(p.end.z).c_str(), p.run.frames,
                 std::string(engine::previewStatusName(p.run.status)).c_str());
    if (cycle.seconds)
        std::fprintf(stdout, "%s\n", cliText("path.cycle-time-s", {seconds(cycle.seconds)}, lang == Lang::Ru).c_str());
    else
        std::fprintf(stdout, "%s\n", cliText("path.cycle-time-none", {cycle.run}, lang == Lang::Ru).c_str());
}

} // namespace

int runPath(std::span<const std::string> argv) {
    std::vector<std::string_view> options = kSetupOptions;
    options.push_back("--max-frames");
    options.push_back(kBlankOption);
    const Args args(argv, {"--json", "--home"}, options);
    if (!args.ok())
        return usageError(args.error());
    const bool asJson = args.has("--json");
    ProgramSetup setup;
    if (const int rc = loadProgramSetup(args, setup, asJson ? stderr : stdout); rc >= 0)
        return rc;
    toolpath::PathOptions po;
    po.preview.rPresets = setup.rPresets;
    if (const auto m = args.value("--max-frames")) {
        const auto v = parseInt(*m);
        if (!v || *v < 1 || *v > 100'000'000)
            return usageError(cliText("opt.max-frames", {*m}));
        po.preview.maxFrames = *v;
    }
    po.preview.fromReferencePoint = args.has("--home");
    std::optional<stock::Blank> blank;
    if (!blankFor(args, setup.text, blank))
        return ExitUsage;
    proveout::Proof proof;
    try {
        proof = proveout::proveProgram(setup.profile, setup.store, setup.number, po.preview, blank);
    } catch (const plc::DescriptionError& e) {
        printDescriptionError(e, setup.lang);
        return ExitUsage;
    } catch (const profile::ToolError& e) {
        printToolError(e, setup.lang);
        return ExitUsage;
    }
    const toolpath::ProgrammedPath& path = proof.path;
    // The cycle time: the same program run on the simulated machine, unless
    // the preview already met an alarm or an endless program (its run would
    // end the same way).
    Cycle cycle;
    if (path.run.status == engine::PreviewStatus::Completed) {
        try {
            const machine::CycleTime t =
                machine::cycleTime(setup.profile, setup.store, setup.number, setup.rPresets);
            cycle.seconds = t.seconds;
            cycle.run = engine::runStatusName(t.run.status);
        } catch (const std::exception& e) { // the machine cannot run it as set up
            std::fprintf(stderr, "k528: %s\n", cliText("path.cycle-time", {e.what()}).c_str());
        }
    }
    if (asJson)
        printJson(path, proof.result, setup, cycle);
    else
        printPlain(path, proof.result, setup.lang, cycle);
    // Not flushed here: main() keeps the output whole and, flushing it at the
    // end, says why a write failed (a full disk, a closed pipe).
    return path.run.status == engine::PreviewStatus::Alarm ? ExitInputErrors : ExitOk;
}

} // namespace k528::cli
