// k528 db roles [grant USER ROLE] (docs/database.md): PostgreSQL's roles.
#include "args.h"
#include "cli.h"
#include "db/database.h"
#include "db_cli_util.h"

namespace k528::cli::dbcli {

int cmdRoles(std::span<const std::string> argv) {
    const Args a(argv, {}, {"--db", "--lang"});
    if (!a.ok())
        return usageError(a.error());
    const auto& pos = a.positional();
    const bool grant = !pos.empty() && pos[0] == "grant";
    if (!(pos.empty() || (grant && pos.size() == 3)))
        return usageError(russianCommandLine()
                              ? "db roles не принимает аргументов, кроме: k528 db roles grant ПОЛЬЗОВАТЕЛЬ technologist|operator|viewer"
                              : "db roles takes nothing, or: k528 db roles grant USER technologist|operator|viewer");
    DbTarget t;
    auto d = openDbOf(a, t, false);
    if (!d)
        return ExitUsage;
    if (d->backend() == db::Backend::Sqlite) {
        out("database  " + t.path.string() +
            "\nroles     none: an SQLite database has one user, who may do everything (the roles "
            "k528_technologist, k528_operator and k528_viewer are PostgreSQL's)\n");
        return grant ? ExitUsage : ExitOk;
    }
    try {
        auto roles = d->setUpRoles();
        if (grant) {
            d->grantRole(pos[1], pos[2]);
            roles = d->roles();
        }
        std::string s = "database  " + t.path.string() + "\n";
        for (const db::RoleInfo& r : roles) {
            std::string members;
            for (const auto& m : r.members)
                members += (members.empty() ? "" : ", ") + m;
            s += pad(r.role, 18) + "  " + r.may + "\n" + std::string(20, ' ') + "members: " +
                 (members.empty() ? "none" : members) + "\n";
        }
        out(s);
        return ExitOk;
    } catch (const db::Error& e) {
        return dbFail(e, langOf(a));
    }
}

} // namespace k528::cli::dbcli
