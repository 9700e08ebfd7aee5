// k528 db export (docs/database.md); helpers in db_cli_util.h.
#include "db_cli_util.h"
#include "args.h"
#include "catalog/cparams.h"
#include "cli.h"
#include "cli_texts.h"
#include "db/database.h"
#include "db/explain.h"
#include "db_cli.h"
#include "profile/csv.h"
#include "profile/diff.h"
#include "profile/text_format.h"
#include "profile/validate.h"
#include "util/json.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace k528::cli::dbcli {

int cmdExport(std::span<const std::string> argv) {
    const Args a(argv, {}, {"--db", "--lang", "--format", "--out"});
    if (!a.ok())
        return usageError(a.error());
    if (a.positional().size() != 1)
        return usageError(cliText("db.usage.one-machine", {"export"}));
    const std::string format = a.value("--format").value_or("k528m");
    if (format != "k528m" && format != "csv")
        return usageError(cliText("db.usage.format", {format}));
    const auto ref = parseRef(a.positional()[0]);
    if (!ref)
        return ExitUsage;
    DbTarget t;
    auto d = openDbOf(a, t, false);
    if (!d)
        return ExitUsage;
    try {
        const MachineProfile p = loadRef(*d, *ref);
        const std::string text =
            format == "csv" ? profile::writeCParamsCsv(p.cValues()) : profile::writeMachineText(p);
        return writeOutput(a.value("--out"), text) ? ExitOk : ExitUsage;
    } catch (const db::Error& e) {
        return dbFail(e, langOf(a));
    }
}

} // namespace k528::cli::dbcli
