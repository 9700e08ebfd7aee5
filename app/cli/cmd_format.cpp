// k528 format [--number N] [--lang ru|en] [--renumber [--start N] [--step K]]
//             [--in-place | --check] FILE
// (shared/spec/cli.md; extensions in docs/program-language.md).
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <filesystem>
#include <fstream>

#include "args.h"
#include "cli.h"
#include "cli_texts.h"
#include "output_file.h"
#include "program/formatter.h"
#include "program/parser.h"
#include "program/refactor.h"
#include "program_cli.h"

namespace k528::cli {

int runFormat(std::span<const std::string> argv) {
    const Args args(argv, {"--in-place", "--check", "--renumber"}, {"--number", "--lang", "--start", "--step"});
    if (!args.ok())
        return usageError(args.error());
    if (args.positional().size() != 1)
        return usageError(cliText("format.usage"));
    if (args.has("--in-place") && args.has("--check"))
        return usageError(cliText("format.in-place-check"));
    program::ParseOptions parseOptions;
    if (!parseProgramNumber(args.value("--number"), parseOptions.programNumber))
        return ExitUsage;
    Lang lang = Lang::Ru;
    if (const auto l = args.value("--lang"); l && !parseLang(*l, lang))
        return usageError(cliText("opt.lang", {*l}));
    // --renumber: every program's frames become start, start+step, ... and
    // every IF/GOTO target follows its frame (program/refactor.h).
    int renumberStart = 1;
    int renumberStep = 1;
    for (const auto& [name, target] : {std::pair<const char*, int*>{"--start", &renumberStart},
                                       std::pair<const char*, int*>{"--step", &renumberStep}}) {
        const auto v = args.value(name);
        if (!v)
            continue;
        if (!args.has("--renumber"))
            return usageError(std::string(name) + " needs --renumber");
        char* end = nullptr;
        const long n = std::strtol(v->c_str(), &end, 10);
        if (v->empty() || *end != '\0' || n < 1 || n > program::kMaxFrameNumber)
            return usageError(std::string(name) + " is a number 1..999, not '" + *v + "'");
        *target = static_cast<int>(n);
    }
    const std::string& path = args.positional().front();
    if (args.has("--in-place") && path == "-")
        return usageError(cliText("format.in-place-stdin"));

    std::string text;
    if (!readProgramFile(path, text))
        return ExitUsage;
    const program::ParseResult parsed = program::parse(text, parseOptions);
    if (parsed.hasErrors()) {
        // Formatting would lose what could not be read: say why and stop.
        printDiagnostics(stderr, displayName(path), parsed.diagnostics, lang);
        std::fprintf(stderr, "k528: %s: %s\n", displayName(path).c_str(),
                     cliText("format.not-formatted", {}, lang == Lang::Ru).c_str());
        return ExitInputErrors;
    }
    program::ProgramStore store = parsed.store;
    if (args.has("--renumber")) {
        for (program::Program& p : store.programs()) {
            const program::RefactorResult r = program::renumber(p, renumberStart, renumberStep);
            if (!r.ok) {
                std::fprintf(stderr, "k528: %s: L%d: %s\n", displayName(path).c_str(), p.number,
                             r.text(lang == Lang::Ru).c_str());
                return ExitInputErrors;
            }
        }
    }
    const std::string canonical = program::format(store);
    if (args.has("--check")) {
        if (canonical == text)
            return ExitOk;
        std::fprintf(stderr, "k528: %s: %s\n", displayName(path).c_str(),
                     cliText("format.not-canonical", {}, lang == Lang::Ru).c_str());
        return ExitInputErrors;
    }
    if (args.has("--in-place")) {
        if (canonical == text)
            return ExitOk;
        // The file itself is replaced, not a link to it, and it keeps its
        // permissions (output_file.h).
        std::string error;
        if (!writeOutputFile(path, canonical, error)) {
            std::fprintf(stderr, "k528: %s\n", error.c_str());
            return ExitUsage;
        }
        return ExitOk;
    }
    std::fwrite(canonical.data(), 1, canonical.size(), stdout);
    return ExitOk;
}

} // namespace k528::cli
