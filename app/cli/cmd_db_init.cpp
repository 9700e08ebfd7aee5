// k528 db init (docs/database.md); helpers in db_cli_util.h.
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

int cmdInit(std::span<const std::string> argv) {
    const Args a(argv, {}, {"--db", "--lang"});
    if (!a.ok())
        return usageError(a.error());
    if (!a.positional().empty())
        return usageError(cliText("db.usage.no-args", {"init"}));
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
    const bool ru = lang == Lang::Ru;
    std::string s = cliText("db.database", {t.path.string()}, ru) + "\n";
    const std::string version = std::to_string(r.version);
    if (r.created)
        s += cliText("db.init.created", {version}, ru);
    else if (r.fromVersion < r.version)
        s += cliText("db.init.upgraded", {version, std::to_string(r.fromVersion)}, ru);
    else
        s += cliText("db.init.current", {version}, ru);
    s += "\n";
    if (!r.seeded.empty()) {
        std::string names;
        for (std::size_t i = 0; i < r.seeded.size(); ++i)
            names += (i ? ", " : "") + r.seeded[i];
        s += cliText("db.init.loaded", {names}, ru) + "\n";
    }
    if (r.recovered)
        s += cliText("db.init.recovered", {t.path.string()}, ru) + "\n";
    if (d->readOnly() != db::ReadOnlyReason::None)
        s += cliText("db.init.read-only", {std::string(db::readOnlyReasonText(d->readOnly(), lang))}, ru) + "\n";
    s += cliText("db.init.machines", {std::to_string(d->machines().size())}, ru) + "\n";
    out(s);
    return ExitOk;
}

} // namespace k528::cli::dbcli
