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
    const Args a(argv, {}, {"--db", "--lang"});
    if (!a.ok())
        return usageError(a.error());
    if (!a.positional().empty())
        return usageError(russianCommandLine() ? "db init не принимает аргументов" : "db init takes no arguments");
    Lang lang;
    if (!parseLangOption(a, lang))
        return ExitUsage;
    DbTarget t;
    auto d = openDbOf(a, t, true, {}, lang);
    if (!d)
        return ExitUsage;
    const auto& r = d->openReport();
    // A file this user may only read: nothing to do when it is up to date,
    // an upgrade it cannot make is said.
    if (d->readOnly() != db::ReadOnlyReason::None && r.version < db::latestSchemaVersion())
        return dbFail(db::ReadOnlyError(t.path, d->readOnly(), db::ReadOnlyRefusal::Upgrade), lang);
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
    if (r.recovered)
        s += "recovered " + t.path.string() + "-journal: an interrupted transaction was rolled back\n";
    if (d->readOnly() != db::ReadOnlyReason::None)
        s += "access    read-only (" + std::string(db::readOnlyReasonText(d->readOnly())) + ")\n";
    s += "machines  " + std::to_string(d->machines().size()) + "\n";
    out(s);
    return ExitOk;
}

} // namespace k528::cli::dbcli
