// k528 check [--json] [--number N] [--lang ru|en] [--profile NAME|PATH] FILE...
// (shared/spec/cli.md; extensions in docs/program-language.md).
#include "profile/error_text.h"
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <optional>
#include <sstream>

#include "args.h"
#include "cli.h"
#include "cli_texts.h"
#include "engine/program_check.h"
#include "program/diagnostic_texts.h"
#include "machine_profile.h"
#include "profile/builtin.h"
#include "profile/text_format.h"
#include "program/validator.h"
#include "program_cli.h"
#include "proveout_cli.h"
#include "util/json.h"

namespace k528::cli {

namespace {


// The constants of a machine profile that a program is checked against.
// The machine's limits and feeds (--profile, --db) as validation options.
bool machineOptions(const Args& args, program::ValidateOptions& options,
                    std::optional<profile::MachineProfile>& machine) {
    machine = machineProfile(args);
    if (!machine)
        return false;
    options = engine::validateOptionsFor(*machine);
    return true;
}

Json fileJson(const std::string& file, const program::CheckResult& r) {
    Json f;
    f["file"] = file;
    Json programs = Json::array();
    for (const int n : r.store.numbers())
        programs.emplace_back(n);
    f["programs"] = std::move(programs);
    Json diags = Json::array();
    for (const auto& d : r.diagnostics) {
        Json j;
        j["line"] = d.line;
        j["column"] = d.column;
        j["end_column"] = d.endColumn;
        j["severity"] = d.isError() ? "error" : "warning";
        j["manual_number"] = d.manualNumber > 0 ? Json(d.manualNumber) : Json();
        j["message_ru"] = program::diagnosticText(d, true);
        j["message_en"] = program::diagnosticText(d, false);
        j["rule"] = std::string(program::ruleId(d.rule));
        diags.push_back(std::move(j));
    }
    f["diagnostics"] = std::move(diags);
    return f;
}

} // namespace

void printDescriptionError(const plc::DescriptionError& e, Lang lang) {
    const bool ru = lang == Lang::Ru;
    std::fprintf(stderr, "%s\n", cliText("machine.description", {e.text(ru)}, ru).c_str());
}

void printToolError(const std::exception& e, Lang lang) {
    const bool ru = lang == Lang::Ru;
    std::fprintf(stderr, "%s\n", cliText("machine.tools", {profile::errorText(e, ru)}, ru).c_str());
}

bool parseLang(const std::string& text, Lang& lang) {
    if (text == "ru")
        lang = Lang::Ru;
    else if (text == "en")
        lang = Lang::En;
    else
        return false;
    return true;
}

std::string displayName(const std::string& path) { return path == "-" ? "<stdin>" : path; }

bool readProgramFile(const std::string& path, std::string& contents) {
    if (path == "-") {
        std::string error;
        if (!readStandardInput(contents, error)) {
            std::fprintf(stderr, "k528: %s\n", error.c_str());
            return false;
        }
        return true;
    }
    std::string error;
    if (!readFile(path, contents, error)) {
        std::fprintf(stderr, "k528: %s\n", error.c_str());
        return false;
    }
    return true;
}

void printDiagnostics(std::FILE* out, const std::string& file,
                      const std::vector<program::Diagnostic>& diagnostics, Lang lang) {
    for (const auto& d : diagnostics)
        std::fprintf(out, "%s:%s\n", file.c_str(),
                     program::formatDiagnostic(d, lang == Lang::Ru).c_str());
}

bool parseProgramNumber(const std::optional<std::string>& value, int& number) {
    if (!value)
        return true;
    const auto n = parseInt(*value);
    if (!n || *n < 1 || *n > program::kMaxPrograms) {
        usageError(cliText("opt.number", {*value}));
        return false;
    }
    number = static_cast<int>(*n);
    return true;
}

int runCheck(std::span<const std::string> argv) {
    const Args args(argv, {"--json"}, {"--number", "--lang", "--profile", "--db", "--blank"});
    if (!args.ok())
        return usageError(args.error());
    if (args.positional().empty())
        return usageError(cliText("check.usage"));
    program::ParseOptions parseOptions;
    if (!parseProgramNumber(args.value("--number"), parseOptions.programNumber))
        return ExitUsage;
    Lang lang = Lang::Ru;
    if (const auto l = args.value("--lang"); l && !parseLang(*l, lang))
        return usageError(cliText("opt.lang", {*l}));
    program::ValidateOptions options;
    std::optional<profile::MachineProfile> machine;
    if (args.value("--profile") && !machineOptions(args, options, machine))
        return ExitUsage;
    if (args.value("--blank") && !machine)
        return usageError(cliText("opt.blank-profile"));

    const bool asJson = args.has("--json");
    bool ioError = false;
    bool errors = false;
    Json files = Json::array();
    for (const std::string& path : args.positional()) {
        std::string text;
        if (!readProgramFile(path, text)) {
            ioError = true;
            continue;
        }
        const program::CheckResult r = program::check(text, parseOptions, options);
        errors = errors || r.hasErrors();
        // With the machine: the prove-out of a file without errors.
        std::vector<proveout::Finding> findings;
        if (machine && !r.hasErrors()) {
            std::optional<stock::Blank> blank;
            if (!blankFor(args, text, blank))
                return ExitUsage;
            const bool proved = withMachineData(lang, [&] {
                engine::PreviewOptions po;
                po.fromReferencePoint = true; // as `k528 run` starts, after homing
                findings = proveout::proveStore(*machine, r.store, po, blank).findings;
            });
            if (!proved)
                return ExitUsage;
            errors = errors || std::any_of(findings.begin(), findings.end(),
                                           [](const proveout::Finding& f) { return f.isError(); });
        }
        const auto inFile = [&](const proveout::Finding& f) {
            return r.store.find(f.program) != nullptr;
        };
        if (asJson) {
            Json f = fileJson(displayName(path), r);
            for (const proveout::Finding& x : findings)
                f["diagnostics"].push_back(findingJson(x, text, inFile(x)));
            files.push_back(std::move(f));
        } else {
            printDiagnostics(stdout, displayName(path), r.diagnostics, lang);
            for (const proveout::Finding& x : findings)
                printFinding(stdout, displayName(path), x, inFile(x), lang);
        }
    }
    if (asJson) {
        Json root;
        root["files"] = std::move(files);
        std::printf("%s\n", json::dump(root).c_str());
    }
    if (ioError)
        return ExitUsage;
    return errors ? ExitInputErrors : ExitOk;
}

} // namespace k528::cli
