// k528 db init (docs/database.md); helpers in db_cli_util.h.
#include "db_cli_util.h"
#include "args.h"
#include "catalog/cparams.h"
#include "cli.h"
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

int cmdInit(std::span<const std::string> argv) {
    const Args a(argv, {}, {"--db"});
    if (!a.ok())
        return usageError(a.error());
    if (!a.positional().empty())
        return usageError("db init takes no arguments");
    DbTarget t;
    auto d = openDbOf(a, t, true);
    if (!d)
        return ExitUsage;
    const auto& r = d->openReport();
    std::string s = "database  " + t.path.string() + "\n";
    s += "schema    version " + std::to_string(r.version);
    if (r.created)
        s += " (created)";
    else if (r.fromVersion < r.version)
        s += " (upgraded from version " + std::to_string(r.fromVersion) + ")";
    else
        s += " (up to date)";
    s += "\n";
    if (!r.seeded.empty()) {
        s += "loaded    ";
        for (std::size_t i = 0; i < r.seeded.size(); ++i)
            s += (i ? ", " : "") + r.seeded[i];
        s += " (built-in machines)\n";
    }
    s += "machines  " + std::to_string(d->machines().size()) + "\n";
    out(s);
    return ExitOk;
}

} // namespace k528::cli::dbcli
