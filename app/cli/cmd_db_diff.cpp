// k528 db diff (docs/database.md); helpers in db_cli_util.h.
#include "db_cli_util.h"
#include "args.h"
#include "catalog/cparams.h"
#include "cli.h"
#include "cli_texts.h"
#include "db/database.h"
#include "db/explain.h"
#include "db_cli.h"
#include "profile/builtin.h"
#include "profile/diff.h"
#include "profile/text_format.h"
#include "profile/validate.h"
#include "util/json.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace k528::cli::dbcli {

namespace {

// A side of a diff: MACHINE@REV, a machine of the database, a machine file,
// or a built-in profile.
bool resolveSide(const db::Database& d, const std::string& s, MachineProfile& p,
                 std::string& label, Lang lang) {
    try {
        const auto at = s.rfind('@');
        if (at != std::string::npos && at > 0 && parseInt(s.substr(at + 1)) &&
            d.hasMachine(s.substr(0, at))) {
            const auto ref = parseRef(s);
            if (!ref)
                return false;
            p = loadRef(d, *ref);
            label = s;
            return true;
        }
        if (d.hasMachine(s)) {
            p = d.loadMachine(s);
            label = s + "@" + std::to_string(d.machine(s)->revision);
            return true;
        }
        std::error_code ec;
        if (fs::is_regular_file(s, ec)) {
            p = profile::readMachineFile(s);
            label = s;
            return true;
        }
        if (profile::isBuiltin(s)) {
            p = profile::builtin(s);
            label = cliText("db.diff.builtin", {s});
            return true;
        }
        fail(cliText("db.diff.neither", {s, d.path().string()}));
        return false;
    } catch (const profile::FileError& e) {
        fail(e.what(), ExitInputErrors);
        return false;
    } catch (const db::Error& e) {
        dbFail(e, lang);
        return false;
    }
}

} // namespace

int cmdDiff(std::span<const std::string> argv) {
    const Args a(argv, {"--json"}, {"--db", "--lang"});
    if (!a.ok())
        return usageError(a.error());
    if (a.positional().size() != 2)
        return usageError(cliText("db.usage.diff"));
    DbTarget t;
    auto d = openDbOf(a, t, false);
    if (!d)
        return ExitUsage;
    MachineProfile pa, pb;
    std::string la, lb;
    if (!resolveSide(*d, a.positional()[0], pa, la, langOf(a)) || !resolveSide(*d, a.positional()[1], pb, lb, langOf(a)))
        return ExitUsage;
    const auto changes = profile::diff(pa, pb);
    if (a.has("--json")) {
        Json root;
        root["a"] = la;
        root["b"] = lb;
        Json cs = Json::array();
        for (const auto& c : changes)
            cs.push_back(changeJson(c));
        root["changes"] = std::move(cs);
        out(json::dump(root) + "\n");
        return ExitOk;
    }
    std::string s = "--- " + la + "\n+++ " + lb + "\n";
    s += changes.empty() ? cliText("db.diff.none") + "\n" : profile::formatDiff(changes);
    out(s);
    return ExitOk;
}

} // namespace k528::cli::dbcli
