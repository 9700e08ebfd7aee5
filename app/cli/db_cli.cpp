// Helpers shared by the `k528 db` subcommands (db_cli_util.h) and the
// `k528 db` dispatcher.
#include "profile/error_text.h"
#include "db_cli_util.h"
#include "args.h"
#include "catalog/cparams.h"
#include "catalog/messages.h"
#include "catalog/rparams.h"
#include "cli.h"
#include "cli_texts.h"
#include "db/database.h"
#include "db/db_texts.h"
#include "db/explain.h"
#include "db/location.h"
#include "db/sha256.h"
#include "db_cli.h"
#include "output_file.h"
#include "profile/diff.h"
#include "profile/validate.h"
#include "units/units.h"
#include "util/json.h"
#include "util/utf8.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace k528::cli {

const char* const kDbDetails =
    "Subcommands (each takes --db LOCATION: a file path, sqlite:PATH, or a PostgreSQL URI\n"
    "postgresql://[user@]host[:port]/dbname (postgresql:// alone: the PG* variables; the\n"
    "password from ~/.pgpass or a service file, never in the URI); default $K528_DB, else\n"
    "$XDG_DATA_HOME/k528studio/k528.db, created with the built-in machines on first use):\n"
    "  init                         create or upgrade the database; print its schema version\n"
    "  machines [--json]            list machines: name, revision, last change, title\n"
    "  show MACHINE[@REV] [--c N | --r N | --programs | --program N | --messages]\n"
    "       [--history [N]] [--lang ru|en] [--json]\n"
    "                               constants with their meaning; one constant or R-parameter\n"
    "                               in full; programs; messages; the last N revisions' changes\n"
    "  set MACHINE ITEM=VALUE... [--author NAME] [--allow-errors] [--allow-unknown] [--lang ru|en]\n"
    "                               change items as one revision: C022=2133, R12=5, R12= "
    "(remove),\n"
    "                               #3=TEXT, A01=TEXT (W.., S..), title=TEXT, x.kv=1.2; checked\n"
    "                               against the definitions and the manual's cross-checks\n"
    "  trial MACHINE --tool N --measured-x M --drawing-x D [--dry-run] [--note TEXT]\n"
    "                               the trial part: the size measured against the drawing's\n"
    "                               changes the tool's offset R-parameter (X a diameter; or\n"
    "                               --measured-z/--drawing-z), kept as one revision\n"
    "  export MACHINE[@REV] [--format k528m|csv] [--out FILE]\n"
    "                               the machine file (docs/profile-format.md) or CSV of C1..C152\n"
    "  import FILE [--as NAME] [--replace] [--author NAME] [--allow-errors] [--format k528m|csv]\n"
    "                               a machine file as a new machine (or, with --replace, as a new\n"
    "                               revision of the existing one); CSV sets the constants of\n"
    "                               machine --as NAME. A bad file is rejected whole, naming its "
    "line\n"
    "  diff A B [--json]            differences of two machines, revisions (MACHINE@REV) or files\n"
    "  calc [OPTIONS] [--json]      C-constants of an axis from physical data (below)\n"
    "  audit [--limit N] [--machine NAME] [--json]\n"
    "                               the audit log: every write, newest first\n"
    "  copy --to LOCATION           the whole database into an empty one, in one transaction\n"
    "  release MACHINE L<n> [--note TEXT]\n"
    "                               the program's current version becomes the released one:\n"
    "                               what a push to the controller takes\n"
    "  withdraw MACHINE L<n> [--note TEXT]\n"
    "                               the released version is withdrawn\n"
    "  log [MACHINE] [--since TIME] [--limit N] [--json]\n"
    "                               the transfers to and from controllers, newest first\n"
    "  roles [grant USER ROLE]      PostgreSQL: create the roles k528_technologist,\n"
    "                               k528_operator, k528_viewer with their GRANTs; list members\n"
    "  check [--json]               everything the database can check of itself: every page\n"
    "                               (SQLite), keys, program checksums, the history against the\n"
    "                               revisions; opened read-only. Exit 1 when it finds a problem\n"
    "--allow-errors accepts cross-check errors (a deliberately faulty training machine);\n"
    "values outside their definitions are never accepted. set refuses a simulation key\n"
    "not in the registry (a typo), naming the known keys close to it; --allow-unknown\n"
    "stores it anyway (a key a newer version reads).\n"
    "calc options (speeds in mm/min of the slide; --machine supplies what is not given):\n"
    "  --machine NAME       physical data (simulation settings), discrete, feeds and\n"
    "                       accelerations of a machine; prints its current values beside\n"
    "  --axis X|Z           the axis (numbers of the printed constants; default X)\n"
    "  --discrete MM        0.01, 0.001 or 0.0001 (default 0.001)   --diameter  diameter display\n"
    "  --screw-lead MM  --gear MOTOR_REV_PER_SCREW_REV (1)  --encoder-lines N\n"
    "  --drive-volts V (10)  --drive-speed MM/MIN: the drive's speed at that voltage\n"
    "  --kv (M/MIN)/MM (1)  --dac-max N (2047)  --dac-limit-percent P (17)\n"
    "  --feed --rapid --auto-rapid --home-start --home-creep MM/MIN   (C40..44)\n"
    "  --accel SPEC, --accel2 SPEC  ACCELERATION 1/2: runup:MM/MIN:MS (formula 1),\n"
    "                       braking:MM/MIN:MM (formula 2) or value:M/S2 (formula 3)\n"
    "  --as-printed         enter formulas 1/2 as printed (formula 1 then doubles the\n"
    "                       acceleration, as appendix Ж does; see docs/machine-constants.md)\n"
    "Every subcommand takes --lang ru|en: the language of its messages (default ru).\n"
    "Exit codes: 0 ok; 1 rejected input (validation, a bad file); 2 usage, unknown machine,\n"
    "or a database that cannot be used (damaged, another program's, newer, locked).\n";


namespace dbcli {


// --------------------------------------------------------------------------
// Output helpers

void out(const std::string& s) {
    std::fwrite(s.data(), 1, s.size(), stdout);
}

std::string pad(const std::string& s, std::size_t width) {
    const std::size_t len = utf8::length(s);
    return len >= width ? s : s + std::string(width - len, ' ');
}

std::string padLeft(const std::string& s, std::size_t width) {
    const std::size_t len = utf8::length(s);
    return len >= width ? s : std::string(width - len, ' ') + s;
}

std::string findingText(const profile::Finding& f, Lang lang) {
    return profile::formatFinding(f, lang == Lang::Ru);
}

Json findingJson(const profile::Finding& f) {
    Json j;
    j["severity"] = f.severity == profile::Severity::Error ? "error" : "warning";
    j["subject"] = f.subject;
    j["manual_number"] = f.message ? Json(*f.message) : Json();
    Json cs = Json::array();
    for (int n : f.cParams)
        cs.push_back(n);
    j["c"] = std::move(cs);
    j["message_ru"] = f.textRu;
    j["message_en"] = f.textEn;
    return j;
}

Json optJson(const std::optional<std::string>& s) {
    return s ? Json(*s) : Json();
}

Json changeJson(const profile::Change& c) {
    Json j;
    j["section"] = profile::diffSectionName(c.section);
    j["key"] = c.key;
    j["label"] = c.label;
    j["before"] = optJson(c.before);
    j["after"] = optJson(c.after);
    return j;
}

int fail(const std::string& message, int code) {
    std::fprintf(stderr, "k528: %s\n", message.c_str());
    return code;
}

int dbFail(const db::Error& e, Lang lang) {
    // A rejection with its findings, a read-only refusal: core's text in `lang` (Error::text).
    return fail(e.text(lang), e.kind() == db::ErrorKind::Invalid ? ExitInputErrors : ExitUsage);
}

Lang langOf(const Args& a) {
    return a.value("--lang") == std::optional<std::string>("en") ? Lang::En : Lang::Ru;
}

bool parseLangOption(const Args& a, Lang& lang) {
    lang = Lang::Ru;
    if (const auto l = a.value("--lang")) {
        if (*l == "ru")
            lang = Lang::Ru;
        else if (*l == "en")
            lang = Lang::En;
        else {
            usageError(cliText("opt.lang", {*l}));
            return false;
        }
    }
    return true;
}

// --------------------------------------------------------------------------
// Opening the database


// "--db PATH" of the subcommand, else the default location.
bool dbTarget(const Args& a, DbTarget& t) {
    if (Lang lang; !parseLangOption(a, lang))
        return false;
    try {
        if (const auto p = a.value("--db")) {
            if (p->empty()) {
                usageError(cliText("db.usage.db", {}, langOf(a) == Lang::Ru));
                return false;
            }
            t.where = db::Location::parse(*p);
            t.explicitPath = true;
        } else {
            t.where = db::defaultDatabaseLocation();
            t.explicitPath = std::getenv("K528_DB") && *std::getenv("K528_DB");
        }
    } catch (const db::Error& e) {
        fail(e.text(langOf(a)));
        return false;
    }
    t.path = t.where.text();
    return true;
}

// Opens the database. The default location is created on first use (with its
// folder); an explicit --db path only by init and import.
std::optional<db::Database> openDbOf(const Args& a, DbTarget& t, bool mayCreate, const std::string& author,
                                     std::optional<Lang> lang) {
    if (!dbTarget(a, t))
        return std::nullopt;
    return openDb(t, mayCreate, author, lang.value_or(langOf(a)));
}

std::optional<db::Database> openDb(const DbTarget& t, bool mayCreate,
                                   const std::string& author, Lang lang, bool readOnly) {
    db::OpenOptions o;
    o.author = author;
    o.readOnly = readOnly;
    if (t.where.isFile()) {
        const fs::path& file = t.where.file();
        std::error_code ec;
        const bool exists = fs::exists(file, ec);
        if (!exists && t.explicitPath && !mayCreate) {
            fail(db::dbText("open.no-database.init", std::vector<std::string>{file.string()}, lang == Lang::Ru));
            return std::nullopt;
        }
        if (!exists && !t.explicitPath) {
            fs::create_directories(file.parent_path(), ec);
            if (ec) {
                fail(cliText("db.no-folder", {file.parent_path().string(), ec.message()}, lang == Lang::Ru));
                return std::nullopt;
            }
        }
    } else {
        // A server's database that holds nothing yet gets its tables from init only.
        o.create = mayCreate;
    }
    try {
        return db::Database::open(t.where, o);
    } catch (const db::Error& e) {
        dbFail(e, lang);
        return std::nullopt;
    }
}


std::optional<MachineRef> parseRef(const std::string& s) {
    MachineRef r;
    const auto at = s.rfind('@');
    if (at == std::string::npos) {
        r.name = s;
        return r;
    }
    r.name = s.substr(0, at);
    const auto n = parseInt(s.substr(at + 1));
    if (!n || *n < 1 || *n > 1000000000) {
        usageError(cliText("db.usage.revision", {s}));
        return std::nullopt;
    }
    r.revision = static_cast<int>(*n);
    return r;
}

MachineProfile loadRef(const db::Database& d, const MachineRef& r) {
    return r.revision ? d.loadMachine(r.name, *r.revision) : d.loadMachine(r.name);
}

bool writeOutput(const std::optional<std::string>& outPath, const std::string& text) {
    if (!outPath || *outPath == "-") {
        out(text);
        return true;
    }
    std::string error;
    if (!writeOutputFile(*outPath, text, error)) {
        fail(error);
        return false;
    }
    return true;
}

// --------------------------------------------------------------------------
// Explanations

std::string unitText(cat::Unit u, Lang lang) {
    return std::string(lang == Lang::Ru ? cat::unitRu(u) : cat::unitEn(u));
}

std::size_t unitWidth(Lang lang) {
    std::size_t w = 0;
    for (const auto& d : cat::cParams())
        w = std::max(w, utf8::length(unitText(d.unit, lang)));
    return w;
}

std::string cLine(const MachineProfile& p, const cat::CParamDef& d, Lang lang) {
    static const std::size_t widthRu = unitWidth(Lang::Ru), widthEn = unitWidth(Lang::En);
    const std::string name(lang == Lang::Ru ? d.name : d.nameEn);
    std::string s = d.key() + "  " + pad(name, 20) + " " +
                    padLeft(std::to_string(p.cValue(d.number)), 9) + "  " +
                    pad(unitText(d.unit, lang), lang == Lang::Ru ? widthRu : widthEn);
    std::string ex = db::explainCValue(p, d.number, lang);
    // The panel's hint line says what 1 means for a flag, or gives the formula
    // of a gain; other hints repeat the unit.
    const std::string hint(lang == Lang::Ru ? d.hintRu : d.hintEn);
    if (!hint.empty() && (d.unit == cat::Unit::Flag || ex.empty()) && d.unit != cat::Unit::None)
        ex += (ex.empty() ? "" : "; ") + hint;
    s += " " + ex;
    while (!s.empty() && s.back() == ' ')
        s.pop_back();
    return s + "\n";
}

std::string rMeaning(int n, Lang lang) {
    const cat::RParamDef* d = cat::findRParam(n);
    if (!d)
        return {};
    if (lang == Lang::En)
        return std::string(d->meaningEn);
    return std::string(d->panelHint.empty() ? d->meaningRu : d->panelHint);
}

std::string rValueText(const MachineProfile& p, int n, std::int64_t v, Lang lang) {
    const cat::RParamDef* d = cat::findRParam(n);
    if (!d)
        return {};
    const bool ru = lang == Lang::Ru;
    const auto axis = cat::rUnitAxis(d->unit);
    const units::AxisScale s =
        profile::axisScale(p, axis == cat::Axis::Z ? cat::Axis::Z : cat::Axis::X);
    switch (d->unit) {
    case cat::RUnit::DiscX:
    case cat::RUnit::DiscZ:
        return "= " + units::formatDisc(v, s) + " " + cliText("unit.mm", {}, ru);
    case cat::RUnit::DiscXPerMin:
    case cat::RUnit::DiscZPerMin:
        return "= " + units::formatDisc(v, s) + " " + cliText("unit.mm-per-min", {}, ru);
    case cat::RUnit::Ms: {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.3f", static_cast<double>(v) / 1000.0);
        return std::string("= ") + buf + " " + cliText("unit.s", {}, ru);
    }
    default:
        return {};
    }
}

std::string machineHeader(const db::MachineInfo& m, std::optional<int> revision) {
    std::string s = cliText("db.show.machine", {m.name + (m.title.empty() ? "" : " — " + m.title)}) + "\n";
    if (revision && *revision != m.revision)
        s += cliText("db.show.revision-of", {std::to_string(*revision), std::to_string(m.revision)}) + "\n";
    else
        s += cliText("db.show.revision", {std::to_string(m.revision), m.changedAt, m.changedBy}) + "\n";
    return s;
}

std::string programSummary(int n, const std::string& text) {
    const auto lines = std::count(text.begin(), text.end(), '\n');
    const std::string title = db::programTitle(text);
    return "L" + pad(std::to_string(n), 3) + pad(title, 40) + " " +
           cliText("db.show.program-lines", {padLeft(std::to_string(lines), 4), db::sha256Hex(text).substr(0, 16)}) +
           "\n";
}

// Changes of one revision, for --history and set.
std::string changeLines(const std::vector<profile::Change>& changes, const db::Database* d,
                        const std::string& machine, int revision) {
    std::string s;
    for (const auto& c : changes) {
        if (c.section == profile::DiffSection::Program) {
            s += "  " + c.key + ": " + changeWord(c.before.has_value(), c.after.has_value());
            if (c.before && c.before->size() == 64 && c.after && c.after->size() == 64)
                s += " (sha256 " + c.before->substr(0, 12) + " -> " + c.after->substr(0, 12) + ")";
            s += "\n";
            if (d) {
                const int n = std::stoi(c.key.substr(1));
                const auto before = revision > 1 ? d->programText(machine, n, revision - 1)
                                                 : std::optional<std::string>();
                const auto after = d->programText(machine, n, revision);
                std::istringstream lines(
                    profile::lineDiff(before.value_or(""), after.value_or("")));
                for (std::string line; std::getline(lines, line);)
                    if (line.rfind("  ", 0) != 0)
                        s += "      " + line + "\n";
            }
            continue;
        }
        s += "  " + c.key + (c.label.empty() ? "" : " " + c.label) + ": " +
             c.before.value_or(cliText("db.change.none")) + " -> " + c.after.value_or(cliText("db.change.none")) + "\n";
    }
    return s;
}

std::string changeWord(bool before, bool after) {
    return !before ? cliText("db.change.added") : !after ? cliText("db.change.removed") : cliText("db.change.changed");
}

std::string changeCount(std::size_t n) {
    return n == 1 ? cliText("db.changes.one") : cliText("db.changes.many", {std::to_string(n)});
}


std::string savedText(const std::string& machine, const db::SaveResult& r, Lang lang) {
    std::string s;
    if (!r.changed)
        return cliText("db.saved.nothing", {machine, std::to_string(r.revision)}, lang == Lang::Ru) + "\n";
    s = cliText("db.saved", {machine, std::to_string(r.revision), changeCount(r.changes.size())}, lang == Lang::Ru) +
        "\n";
    if (r.changes.size() <= 40) {
        for (const auto& c : r.changes) {
            if (c.section != profile::DiffSection::Program) {
                s += changeLines({c}, nullptr, machine, r.revision);
                continue;
            }
            // The texts are at hand: checksums and the changed lines.
            auto x = c;
            x.before = c.before ? std::optional(db::sha256Hex(*c.before)) : std::nullopt;
            x.after = c.after ? std::optional(db::sha256Hex(*c.after)) : std::nullopt;
            s += changeLines({x}, nullptr, machine, r.revision);
            std::istringstream lines(
                profile::lineDiff(c.before.value_or(""), c.after.value_or("")));
            for (std::string line; std::getline(lines, line);)
                if (line.rfind("  ", 0) != 0)
                    s += "      " + line + "\n";
        }
    }
    for (const auto& f : r.findings)
        s += findingText(f, lang) + "\n";
    return s;
}

} // namespace dbcli

namespace {

// The subcommands of `k528 db`, in the order its usage line and its errors
// name them: the one list both are made of.
struct DbSubcommand {
    std::string_view name;
    int (*run)(std::span<const std::string> args);
};

constexpr DbSubcommand kDbSubcommands[] = {
    {"init", dbcli::cmdInit},
    {"machines", dbcli::cmdMachines},
    {"show", dbcli::cmdShow},
    {"set", dbcli::cmdSet},
    {"trial", dbcli::cmdTrial},
    {"export", dbcli::cmdExport},
    {"import", dbcli::cmdImport},
    {"diff", dbcli::cmdDiff},
    {"calc", runDbCalc},
    {"audit", dbcli::cmdAudit},
    {"copy", dbcli::cmdCopy},
    {"release", [](std::span<const std::string> a) { return dbcli::cmdRelease(a, true); }},
    {"withdraw", [](std::span<const std::string> a) { return dbcli::cmdRelease(a, false); }},
    {"log", dbcli::cmdLog},
    {"roles", dbcli::cmdRoles},
    {"check", dbcli::cmdCheck},
};

std::string dbSubcommandNames(std::string_view separator) {
    std::string names;
    for (const DbSubcommand& c : kDbSubcommands)
        names += (names.empty() ? "" : std::string(separator)) + std::string(c.name);
    return names;
}

} // namespace

std::string_view dbUsage() {
    static const std::string usage = "db " + dbSubcommandNames("|") + " [--db LOCATION] ...";
    return usage;
}

int runDb(std::span<const std::string> args) {
    std::vector<std::string> rest(args.begin(), args.end());
    // "--db PATH" may also come before the subcommand.
    std::vector<std::string> dbOpt;
    while (!rest.empty() && (rest[0] == "--db" || rest[0].rfind("--db=", 0) == 0)) {
        if (rest[0] == "--db") {
            if (rest.size() < 2)
                return usageError(cliText("opt.needs-value", {"--db"}));
            dbOpt = {"--db", rest[1]};
            rest.erase(rest.begin(), rest.begin() + 2);
        } else {
            dbOpt = {rest[0]};
            rest.erase(rest.begin());
        }
    }
    if (rest.empty())
        return usageError(cliText("db.no-subcommand", {dbSubcommandNames(", ")}));
    const std::string sub = rest[0];
    std::vector<std::string> subArgs(rest.begin() + 1, rest.end());
    subArgs.insert(subArgs.end(), dbOpt.begin(), dbOpt.end());
    for (const DbSubcommand& c : kDbSubcommands)
        if (c.name == sub)
            return c.run(subArgs);
    return usageError(cliText("db.unknown-subcommand", {sub, dbSubcommandNames(", ")}));
}

} // namespace k528::cli
