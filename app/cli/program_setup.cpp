#include "program_setup.h"

#include "cli.h"
#include "cli_texts.h"
#include "engine/program_check.h"
#include "engine/rparams.h"
#include "engine/self_test.h"
#include "machine_profile.h"
#include "profile/problem.h"
#include "profile/validate.h"

#include <set>

namespace k528::cli {

int applyParameterOptions(const Args& args, profile::MachineProfile& profile,
                          std::map<int, std::int64_t>& rPresets) {
    for (const std::string& p : args.values("--param")) {
        long long n = 0, v = 0;
        if (!parseAssignment(p, n, v))
            return usageError(cliText("opt.param", {p}));
        if (n < 1 || n > 152)
            return usageError(cliText("opt.param-range", {p}));
        if (const profile::Problem e = profile::cValueProblem(static_cast<int>(n), v); !e.empty())
            return usageError("--param " + p + ": " + profile::problemText(e, russianCommandLine()));
        profile.setC(static_cast<int>(n), v);
    }
    for (const std::string& p : args.values("--r")) {
        long long n = 0, v = 0;
        if (!parseAssignment(p, n, v))
            return usageError(cliText("opt.r", {p}));
        if (n < 0 || n > 299)
            return usageError(cliText("opt.r-range", {p}));
        if (engine::rReadOnly(static_cast<int>(n)))
            return usageError(cliText("opt.r-read-only", {p}));
        if (!engine::fitsR(v))
            return usageError(cliText("opt.r-value", {p}));
        rPresets[static_cast<int>(n)] = v;
    }
    return -1;
}

int readProgramOptions(const Args& args, Lang& lang, program::ParseOptions& parseOptions,
                       profile::MachineProfile& profile, std::map<int, std::int64_t>& rPresets) {
    if (const auto l = args.value("--lang"); l && !parseLang(*l, lang))
        return usageError(cliText("opt.lang", {*l}));
    if (!parseProgramNumber(args.value("--number"), parseOptions.programNumber))
        return ExitUsage;
    const std::optional<profile::MachineProfile> loaded = machineProfile(args);
    if (!loaded)
        return ExitUsage;
    profile = *loaded;
    return applyParameterOptions(args, profile, rPresets);
}

int loadProgramSetup(const Args& args, ProgramSetup& out, std::FILE* diagOut) {
    if (args.positional().size() != 1)
        return usageError(cliText("opt.one-file"));
    program::ParseOptions parseOptions;
    if (const int rc = readProgramOptions(args, out.lang, parseOptions, out.profile, out.rPresets); rc >= 0)
        return rc;
    const std::string path = args.positional().front();
    std::string text;
    if (!readProgramFile(path, text))
        return ExitUsage;
    bool intact = true;
    const engine::FileCheck checked = engine::checkFileForMachine(
        text, parseOptions, out.profile, engine::loadStore(out.profile, intact));
    const program::ParseResult& parsed = checked.parsed;
    if (parsed.hasErrors()) {
        printDiagnostics(diagOut, displayName(path), parsed.diagnostics, out.lang);
        return ExitInputErrors;
    }
    if (parsed.store.empty()) {
        std::fprintf(stderr, "k528: %s\n", cliText("file.no-program", {displayName(path)}).c_str());
        return ExitInputErrors;
    }
    if (checked.hasErrors()) {
        printDiagnostics(diagOut, displayName(path), checked.diagnostics, out.lang);
        return ExitInputErrors;
    }
    if (!checked.diagnostics.empty())
        printDiagnostics(stderr, displayName(path), checked.diagnostics, out.lang);
    if (const auto p = args.value("--program")) {
        const auto n = parseInt(*p);
        if (!n || *n < 1 || *n > 99)
            return usageError(cliText("opt.program", {*p}));
        if (!checked.programs.count(static_cast<int>(*n)))
            return usageError(cliText("opt.program-none", {*p, displayName(path)}));
        out.number = static_cast<int>(*n);
    } else {
        out.number = parsed.store.firstWritten(); // as `k528 run` starts it
    }
    out.store = parsed.store;
    out.text = std::move(text);
    return -1;
}

} // namespace k528::cli
