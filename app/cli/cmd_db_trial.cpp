// k528 db trial MACHINE --tool N (--measured-x M --drawing-x D | --measured-z M
// --drawing-z D) [--dry-run] [--note TEXT]: the trial part (handbook 13.8) —
// the size measured on the part against the drawing's gives the change of
// the tool's offset R-parameter (profile/cutting.h; X measured as a
// diameter), kept as the machine's next revision (docs/cli-decisions.md).
#include "profile/error_text.h"
#include "args.h"
#include "cli.h"
#include "cli_texts.h"
#include "db/database.h"
#include "db_cli.h"
#include "db_cli_util.h"
#include "profile/cutting.h"
#include "profile/tools.h"

#include <cstdio>
#include <string>

namespace k528::cli::dbcli {

int cmdTrial(std::span<const std::string> argv) {
    const Args a(argv, {"--dry-run"},
                 {"--db", "--author", "--lang", "--tool", "--measured-x", "--drawing-x", "--measured-z", "--drawing-z",
                  "--note"});
    if (!a.ok())
        return usageError(a.error());
    if (a.positional().size() != 1)
        return usageError(cliText("trial.usage"));
    Lang lang;
    if (!parseLangOption(a, lang))
        return ExitUsage;
    const bool ru = lang == Lang::Ru;
    const auto station = a.value("--tool") ? parseInt(*a.value("--tool")) : std::nullopt;
    if (!station || *station < 1 || *station > profile::kMaxToolStations)
        return usageError(cliText("trial.tool"));
    const bool x = a.value("--measured-x") || a.value("--drawing-x");
    const bool z = a.value("--measured-z") || a.value("--drawing-z");
    if (x == z)
        return usageError(cliText("trial.axis"));
    const auto number = [&](const char* option) -> std::optional<double> {
        const auto v = a.value(option);
        if (!v)
            return std::nullopt;
        try {
            std::size_t used = 0;
            const double d = std::stod(*v, &used);
            if (used == v->size())
                return d;
        } catch (const std::exception&) {
        }
        return std::nullopt;
    };
    const auto measured = number(x ? "--measured-x" : "--measured-z");
    const auto drawing = number(x ? "--drawing-x" : "--drawing-z");
    if (!measured || !drawing)
        return usageError(cliText("trial.sizes", {x ? "x" : "z"}));
    DbTarget t;
    auto d = openDbOf(a, t, false, a.value("--author").value_or(""), lang);
    if (!d)
        return ExitUsage;
    const std::string machine = a.positional()[0];
    try {
        const profile::MachineProfile p = d->loadMachine(machine);
        std::optional<profile::Tool> tool;
        try {
            tool = profile::toolAt(profile::tools(p), static_cast<int>(*station));
        } catch (const profile::ToolError& e) {
            std::fprintf(stderr, "%s\n", cliText("machine.tools", {profile::errorText(e, ru)}, ru).c_str());
            return ExitUsage;
        }
        if (!tool) {
            std::fprintf(stderr, "%s\n",
                         cliText("trial.no-tool", {machine, std::to_string(static_cast<int>(*station))}, ru).c_str());
            return ExitUsage;
        }
        profile::cutting::TrialCorrection c;
        try {
            c = profile::cutting::trialCorrection(p, *tool, x ? catalog::Axis::X : catalog::Axis::Z, *measured,
                                                  *drawing);
        } catch (const profile::cutting::CuttingError& e) {
            std::fprintf(stderr, "k528: %s\n", profile::errorText(e, ru).c_str());
            return ExitUsage;
        }
        const auto mm = [](const char* format, double v) {
            char b[64];
            std::snprintf(b, sizeof b, format, v);
            return std::string(b);
        };
        out(cliText("trial.correction",
                    {std::to_string(tool->station), x ? "X" : "Z", mm("%.3f", *measured), mm("%.3f", *drawing),
                     mm("%+.3f", c.errorMm), std::to_string(c.rNumber), std::to_string(c.oldValue),
                     std::to_string(c.newValue), mm("%+.3f", c.changeMm)},
                    ru) +
            "\n");
        if (a.has("--dry-run") || c.newValue == c.oldValue)
            return ExitOk;
        db::Edit edit;
        edit.r[c.rNumber] = c.newValue;
        db::WriteOptions o;
        o.author = a.value("--author").value_or("");
        char summary[200];
        std::snprintf(summary, sizeof summary, "trial part: T%d %s measured %.3f for %.3f: R%d %lld -> %lld",
                      tool->station, x ? "X" : "Z", *measured, *drawing, c.rNumber,
                      static_cast<long long>(c.oldValue), static_cast<long long>(c.newValue));
        o.summary = a.value("--note").value_or(summary);
        const auto r = d->applyEdit(machine, edit, o);
        out(savedText(machine, r, lang));
        return ExitOk;
    } catch (const db::Error& e) {
        return dbFail(e, lang);
    }
}

} // namespace k528::cli::dbcli
