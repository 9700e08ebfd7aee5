// k528 db copy --to LOCATION (docs/database.md); helpers in db_cli_util.h.
#include "args.h"
#include "cli.h"
#include "cli_texts.h"
#include "db/database.h"
#include "db_cli_util.h"

namespace k528::cli::dbcli {

int cmdCopy(std::span<const std::string> argv) {
    const Args a(argv, {}, {"--db", "--lang", "--to"});
    if (!a.ok())
        return usageError(a.error());
    if (!a.positional().empty())
        return usageError(cliText("db.usage.copy-args"));
    const auto to = a.value("--to");
    if (!to || to->empty())
        return usageError(cliText("db.usage.copy-to"));
    db::Location target;
    try {
        target = db::Location::parse(*to);
    } catch (const db::Error& e) {
        return fail(e.text(langOf(a)));
    }
    DbTarget t;
    auto d = openDbOf(a, t, false);
    if (!d)
        return ExitUsage;
    try {
        const db::CopyReport r = d->copyTo(target);
        using std::to_string;
        std::string s = cliText("db.copy.copied", {t.path.string(), r.target}) + "\n";
        s += cliText("db.copy.machines", {to_string(r.machines), to_string(r.revisions), to_string(r.programVersions),
                                          to_string(r.releases)}) + "\n";
        s += cliText("db.copy.logs", {to_string(r.messages), to_string(r.audit), to_string(r.transfers)}) + "\n";
        s += cliText("db.copy.rows", {to_string(r.rows)}) + "\n";
        out(s);
        return ExitOk;
    } catch (const db::Error& e) {
        return dbFail(e, langOf(a));
    }
}

} // namespace k528::cli::dbcli
