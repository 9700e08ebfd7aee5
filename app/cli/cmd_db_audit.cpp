// k528 db audit (docs/database.md); helpers in db_cli_util.h.
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

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace k528::cli::dbcli {

int cmdAudit(std::span<const std::string> argv) {
    const Args a(argv, {"--json"}, {"--db", "--lang", "--limit", "--machine"});
    if (!a.ok())
        return usageError(a.error());
    if (!a.positional().empty())
        return usageError(cliText("db.usage.no-args", {"audit"}));
    int limit = 50;
    if (const auto v = a.value("--limit")) {
        const auto n = parseInt(*v);
        if (!n || *n < 0)
            return usageError(cliText("db.usage.limit"));
        limit = static_cast<int>(*n);
    }
    DbTarget t;
    auto d = openDbOf(a, t, false);
    if (!d)
        return ExitUsage;
    const auto entries = d->audit(limit, a.value("--machine").value_or(""));
    if (a.has("--json")) {
        Json arr = Json::array();
        for (const auto& e : entries) {
            Json j;
            j["id"] = e.id;
            j["at"] = e.at;
            j["author"] = e.author;
            j["action"] = e.action;
            j["machine"] = e.machine;
            j["revision"] = e.revision;
            j["detail"] = e.detail;
            arr.push_back(std::move(j));
        }
        Json root;
        root["audit"] = std::move(arr);
        out(json::dump(root) + "\n");
        return ExitOk;
    }
    std::string s;
    for (const auto& e : entries)
        s += e.at + "  " + pad(e.author, 10) + "  " + pad(e.action, 15) + "  " +
             (e.machine.empty()
                  ? ""
                  : e.machine + (e.revision ? "@" + std::to_string(e.revision) : "") + "  ") +
             e.detail + "\n";
    out(s);
    return ExitOk;
}

} // namespace k528::cli::dbcli
