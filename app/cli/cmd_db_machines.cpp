// k528 db machines (docs/database.md); helpers in db_cli_util.h.
#include "db_cli_util.h"
#include "args.h"
#include "catalog/cparams.h"
#include "cli.h"
#include "cli_texts.h"
#include "db/database.h"
#include "db/explain.h"
#include "db_cli.h"
#include "profile/diff.h"
#include "profile/validate.h"
#include "util/json.h"
#include "util/utf8.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace k528::cli::dbcli {

int cmdMachines(std::span<const std::string> argv) {
    const Args a(argv, {"--json"}, {"--db", "--lang"});
    if (!a.ok())
        return usageError(a.error());
    if (!a.positional().empty())
        return usageError(cliText("db.usage.no-args", {"machines"}));
    DbTarget t;
    auto d = openDbOf(a, t, false);
    if (!d)
        return ExitUsage;
    const auto ms = d->machines();
    if (a.has("--json")) {
        Json arr = Json::array();
        for (const auto& m : ms) {
            Json j;
            j["name"] = m.name;
            j["title"] = m.title;
            j["revision"] = m.revision;
            j["created_at"] = m.createdAt;
            j["changed_at"] = m.changedAt;
            j["changed_by"] = m.changedBy;
            arr.push_back(std::move(j));
        }
        Json root;
        root["database"] = t.path.string();
        root["machines"] = std::move(arr);
        out(json::dump(root) + "\n");
        return ExitOk;
    }
    const std::string machineColumn = cliText("db.machines.machine");
    std::size_t w = utf8::length(machineColumn);
    for (const auto& m : ms)
        w = std::max(w, utf8::length(m.name));
    std::string s = pad(machineColumn, w) + "  " + padLeft(cliText("db.machines.revision"), 3) + "  " +
                    pad(cliText("db.machines.changed"), 20) + "  " + pad(cliText("db.machines.by"), 10) + "  " +
                    cliText("db.machines.title") + "\n";
    for (const auto& m : ms)
        s += pad(m.name, w) + "  " + padLeft(std::to_string(m.revision), 3) + "  " +
             pad(m.changedAt, 20) + "  " + pad(m.changedBy, 10) + "  " + m.title + "\n";
    if (ms.empty())
        s += cliText("db.machines.none") + "\n";
    out(s);
    return ExitOk;
}

} // namespace k528::cli::dbcli
