// k528 format [--number N] [--lang ru|en] [--in-place | --check] FILE
// (shared/spec/cli.md; extensions in docs/program-language.md).
#include <cstdio>

#include "args.h"
#include "cli.h"
#include "output_file.h"
#include "program/formatter.h"
#include "program/parser.h"
#include "program_cli.h"

namespace k528::cli {

int runFormat(std::span<const std::string> argv) {
    const Args args(argv, {"--in-place", "--check"}, {"--number", "--lang"});
    if (!args.ok())
        return usageError(args.error());
    if (args.positional().size() != 1)
        return usageError("format needs exactly one FILE");
    if (args.has("--in-place") && args.has("--check"))
        return usageError("--in-place and --check exclude each other");
    program::ParseOptions parseOptions;
    if (!parseProgramNumber(args.value("--number"), parseOptions.programNumber))
        return ExitUsage;
    Lang lang = Lang::Ru;
    if (const auto l = args.value("--lang"); l && !parseLang(*l, lang))
        return usageError("--lang is ru or en, not '" + *l + "'");
    const std::string& path = args.positional().front();
    if (args.has("--in-place") && path == "-")
        return usageError("--in-place needs a file, not standard input");

    std::string text;
    if (!readProgramFile(path, text))
        return ExitUsage;
    const program::ParseResult parsed = program::parse(text, parseOptions);
    if (parsed.hasErrors()) {
        // Formatting would lose what could not be read: say why and stop.
        printDiagnostics(stderr, displayName(path), parsed.diagnostics, lang);
        std::fprintf(stderr, "k528: %s: %s\n", displayName(path).c_str(),
                     lang == Lang::Ru ? "текст не отформатирован: исправьте синтаксические ошибки"
                                      : "not formatted: fix the syntax errors first");
        return ExitInputErrors;
    }
    const std::string canonical = program::format(parsed.store);
    if (args.has("--check")) {
        if (canonical == text)
            return ExitOk;
        std::fprintf(stderr, "k528: %s: %s\n", displayName(path).c_str(),
                     lang == Lang::Ru ? "текст не в каноническом виде" : "not in canonical form");
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
