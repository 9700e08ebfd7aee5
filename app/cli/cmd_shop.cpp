// k528 shop status|publish (cli.md, docs/shop.md), k528's half: the machines
// of the database that have a line (the `line` setting: tcp://HOST:PORT/UNIT
// or serial:DEVICE?…), then k528-link (cmd_shop_qt.cpp, Qt: the plugins,
// the pollers, MQTT) with one `--line MACHINE=LINE` each. k528 itself stays
// plain C++ (docs/link.md, *Why k528-link*).
#include "args.h"
#include "cli.h"
#include "cli_texts.h"
#include "db_cli_util.h"
#include "profile/line.h"

#include <algorithm>
#include <cstdio>

namespace k528::cli {

int forwardToLink(const char* command, std::span<const std::string> args); // cmd_link_forward.cpp

int runShop(std::span<const std::string> argv) {
    const Args a(argv, {"--json", "--watch"},
                 {"--db", "--timeout-ms", "--interval-ms", "--seconds", "--mqtt", "--client-id", "--lang"});
    if (!a.ok())
        return usageError(a.error());
    if (a.positional().empty() || (a.positional()[0] != "status" && a.positional()[0] != "publish"))
        return usageError(cliText("shop.usage"));
    const std::string sub = a.positional()[0];
    if (sub == "publish" && !a.value("--mqtt"))
        return usageError(cliText("shop.usage.mqtt"));
    dbcli::DbTarget t;
    auto d = dbcli::openDbOf(a, t, false);
    if (!d)
        return ExitUsage;
    std::vector<std::string> names;
    std::vector<std::string> lines;
    try {
        const std::vector<db::MachineInfo> all = d->machines();
        const std::vector<std::string> asked(a.positional().begin() + 1, a.positional().end());
        for (const std::string& m : asked)
            if (std::none_of(all.begin(), all.end(), [&](const db::MachineInfo& i) { return i.name == m; }))
                return usageError(cliText("shop.no-machine", {m}));
        for (const db::MachineInfo& i : all) {
            const bool wanted = asked.empty() || std::find(asked.begin(), asked.end(), i.name) != asked.end();
            if (!wanted)
                continue;
            const auto line = d->loadMachine(i.name).simulation.find("line");
            if (!line) {
                if (!asked.empty())
                    return usageError(cliText("shop.no-line", {i.name}));
                continue;
            }
            profile::Problem error;
            if (!profile::parseLine(*line, error))
                return usageError(cliText("shop.bad-line", {i.name, profile::problemText(error, russianCommandLine())}));
            names.push_back(i.name);
            lines.push_back(*line);
        }
    } catch (const db::Error& e) {
        std::fprintf(stderr, "k528: %s\n", e.text(russianCommandLine() ? db::Lang::Ru : db::Lang::En).c_str());
        return ExitUsage;
    }
    if (names.empty()) {
        std::fprintf(stderr, "%s\n", cliText("shop.no-lines").c_str());
        if (sub == "status" && !a.has("--watch")) {
            if (a.has("--json"))
                std::printf("[]\n");
            return ExitOk;
        }
        return ExitUsage;
    }
    std::vector<std::string> out = {sub};
    for (const char* flag : {"--json", "--watch"})
        if (a.has(flag))
            out.emplace_back(flag);
    for (const char* option : {"--timeout-ms", "--interval-ms", "--seconds", "--mqtt", "--client-id", "--lang"})
        if (const auto v = a.value(option)) {
            out.emplace_back(option);
            out.push_back(*v);
        }
    for (std::size_t i = 0; i < names.size(); ++i) {
        out.emplace_back("--line");
        out.push_back(names[i] + "=" + lines[i]);
    }
    if (sub == "publish" || a.has("--watch")) {
        // Polling over time keeps each machine's time in each state there (docs/shop.md).
        out.emplace_back("--db");
        out.push_back(d->location().text());
    }
    d.reset(); // closed before k528-link takes the process's place
    return forwardToLink("shop", out);
}

} // namespace k528::cli
