// k528 db check [--json] (docs/database.md): everything the database can
// check of itself, said in the command's language. The database is opened
// for reading only: a check writes nothing, not even an upgrade.
#include "args.h"
#include "cli.h"
#include "cli_texts.h"
#include "db/database.h"
#include "db/db_texts.h"
#include "db_cli_util.h"
#include "util/json.h"

namespace k528::cli::dbcli {

namespace {

std::string problemText(const db::IntegrityProblem& p, Lang lang) {
    return cliTexts().render("db.check." + std::string(db::integrityProblemName(p.kind)), p.args, lang == Lang::Ru);
}

} // namespace

int cmdCheck(std::span<const std::string> argv) {
    const Args a(argv, {"--json"}, {"--db", "--lang"});
    if (!a.ok())
        return usageError(a.error());
    Lang lang = Lang::Ru;
    if (!parseLangOption(a, lang))
        return ExitUsage;
    if (!a.positional().empty())
        return usageError(cliText("db.usage.no-args", {"check"}, lang == Lang::Ru));
    DbTarget t;
    if (!dbTarget(a, t))
        return ExitUsage;
    std::optional<db::Database> d;
    try {
        // Opened here, not by openDb: damage an open finds is the check's
        // finding (exit 1), not a database that cannot be used (exit 2).
        if (t.where.isFile() && !std::filesystem::exists(t.where.file()))
            return fail(db::dbText("open.no-database.init", std::vector<std::string>{t.where.file().string()},
                                   lang == Lang::Ru));
        db::OpenOptions o;
        o.readOnly = true;
        o.create = false;
        d.emplace(db::Database::open(t.where, o));
    } catch (const db::Error& e) {
        if (e.kind() == db::ErrorKind::Corrupt)
            return fail(e.text(lang), ExitInputErrors);
        return dbFail(e, lang);
    }
    std::vector<db::IntegrityProblem> problems;
    try {
        problems = d->checkIntegrity();
    } catch (const db::Error& e) {
        return fail(e.text(lang), e.kind() == db::ErrorKind::Corrupt ? ExitInputErrors : ExitUsage);
    }
    if (a.has("--json")) {
        Json list = Json::array();
        for (const db::IntegrityProblem& p : problems) {
            Json j;
            j["kind"] = std::string(db::integrityProblemName(p.kind));
            j["args"] = p.args;
            j["text"] = problemText(p, lang);
            list.push_back(std::move(j));
        }
        Json root;
        root["database"] = t.path.string();
        root["ok"] = problems.empty();
        root["problems"] = std::move(list);
        out(json::dump(root) + "\n");
    } else {
        const bool ru = lang == Lang::Ru;
        std::string s = cliText("db.database", {t.path.string()}, ru) + "\n";
        s += problems.empty() ? cliText("db.check.ok", {}, ru) : cliText("db.check.found", {std::to_string(problems.size())}, ru);
        s += "\n";
        for (const db::IntegrityProblem& p : problems)
            s += "  " + problemText(p, lang) + "\n";
        out(s);
    }
    return problems.empty() ? ExitOk : ExitInputErrors;
}

} // namespace k528::cli::dbcli
