// k528 db roles [grant USER ROLE] (docs/database.md): PostgreSQL's roles.
#include "args.h"
#include "cli.h"
#include "cli_texts.h"
#include "db/database.h"
#include "db_cli_util.h"

namespace k528::cli::dbcli {

namespace {

// What a role may, in the command's language (the database says it in English).
std::string roleMay(const db::RoleInfo& r) {
    if (r.role == "k528_viewer")
        return cliText("db.role.viewer");
    if (r.role == "k528_operator")
        return cliText("db.role.operator");
    if (r.role == "k528_technologist")
        return cliText("db.role.technologist");
    if (r.role == "k528_trainer")
        return cliText("db.role.trainer");
    return r.may;
}

} // namespace

int cmdRoles(std::span<const std::string> argv) {
    const Args a(argv, {}, {"--db", "--lang"});
    if (!a.ok())
        return usageError(a.error());
    const auto& pos = a.positional();
    const bool grant = !pos.empty() && pos[0] == "grant";
    if (!(pos.empty() || (grant && pos.size() == 3)))
        return usageError(cliText("db.usage.roles"));
    DbTarget t;
    auto d = openDbOf(a, t, false);
    if (!d)
        return ExitUsage;
    if (d->backend() == db::Backend::Sqlite) {
        out(cliText("db.database", {t.path.string()}) + "\n" + cliText("db.roles.sqlite") + "\n");
        return grant ? ExitUsage : ExitOk;
    }
    try {
        auto roles = d->setUpRoles();
        if (grant) {
            d->grantRole(pos[1], pos[2]);
            roles = d->roles();
        }
        std::string s = cliText("db.database", {t.path.string()}) + "\n";
        for (const db::RoleInfo& r : roles) {
            std::string members;
            for (const auto& m : r.members)
                members += (members.empty() ? "" : ", ") + m;
            s += pad(r.role, 18) + "  " + roleMay(r) + "\n" + std::string(20, ' ') +
                 cliText("db.roles.members", {members.empty() ? cliText("db.roles.no-members") : members}) + "\n";
        }
        out(s);
        return ExitOk;
    } catch (const db::Error& e) {
        return dbFail(e, langOf(a));
    }
}

} // namespace k528::cli::dbcli
