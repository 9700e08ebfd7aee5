// k528 db release / withdraw MACHINE L<n> [--note TEXT] (docs/database.md).
#include "args.h"
#include "cli.h"
#include "cli_texts.h"
#include "db/database.h"
#include "db_cli_util.h"

namespace k528::cli::dbcli {

int cmdRelease(std::span<const std::string> argv, bool release) {
    const Args a(argv, {}, {"--db", "--lang", "--note", "--author"});
    if (!a.ok())
        return usageError(a.error());
    if (a.positional().size() != 2)
        return usageError(cliText("db.usage.release", {release ? "release" : "withdraw"}));
    const std::string& machine = a.positional()[0];
    std::string prog = a.positional()[1];
    if (!prog.empty() && (prog[0] == 'L' || prog[0] == 'l'))
        prog = prog.substr(1);
    const auto n = parseInt(prog);
    if (!n || *n < 1 || *n > 99)
        return usageError(cliText("db.usage.program", {a.positional()[1]}));
    DbTarget t;
    auto d = openDbOf(a, t, false);
    if (!d)
        return ExitUsage;
    try {
        db::WriteOptions o;
        o.author = a.value("--author").value_or("");
        const std::string note = a.value("--note").value_or("");
        const int number = static_cast<int>(*n);
        const db::ReleaseEntry e = release ? d->releaseProgram(machine, number, note, o)
                                           : d->withdrawProgram(machine, number, note, o);
        const std::initializer_list<std::string> said = {machine, std::to_string(number), std::to_string(e.revision),
                                                          e.sha256.substr(0, 12), e.author, e.at,
                                                          e.note.empty() ? "" : ": " + e.note};
        out((release ? cliText("db.released", said) : cliText("db.withdrawn", said)) + "\n");
        return ExitOk;
    } catch (const db::Error& e) {
        return dbFail(e, langOf(a));
    }
}

} // namespace k528::cli::dbcli
