// k528 db init|machines|show|set|export|import|diff|calc|audit — the database
// of machines (docs/database.md).
#include "args.h"
#include "catalog/cparams.h"
#include "catalog/messages.h"
#include "catalog/rparams.h"
#include "cli.h"
#include "db/database.h"
#include "db/explain.h"
#include "db/location.h"
#include "db/sha256.h"
#include "db_cli.h"
#include "output_file.h"
#include "profile/builtin.h"
#include "profile/csv.h"
#include "profile/diff.h"
#include "profile/text_format.h"
#include "profile/validate.h"
#include "units/units.h"
#include "util/input_file.h"
#include "util/json.h"
#include "util/utf8.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <sstream>

namespace k528::cli {

namespace fs = std::filesystem;
namespace cat = k528::catalog;
using db::Lang;
using profile::MachineProfile;

const char* const kDbDetails =
    "Subcommands (each takes --db PATH; default $K528_DB, else\n"
    "$XDG_DATA_HOME/k528studio/k528.db, created with the built-in machines on first use):\n"
    "  init                         create or upgrade the database; print its schema version\n"
    "  machines [--json]            list machines: name, revision, last change, title\n"
    "  show MACHINE[@REV] [--c N | --r N | --programs | --program N | --messages]\n"
    "       [--history [N]] [--lang ru|en] [--json]\n"
    "                               constants with their meaning; one constant or R-parameter\n"
    "                               in full; programs; messages; the last N revisions' changes\n"
    "  set MACHINE ITEM=VALUE... [--author NAME] [--allow-errors] [--lang ru|en]\n"
    "                               change items as one revision: C022=2133, R12=5, R12= "
    "(remove),\n"
    "                               #3=TEXT, A01=TEXT (W.., S..), title=TEXT, x.kv=1.2; checked\n"
    "                               against the definitions and the manual's cross-checks\n"
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
    "--allow-errors accepts cross-check errors (a deliberately faulty training machine);\n"
    "values outside their definitions are never accepted.\n"
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
    "Exit codes: 0 ok; 1 rejected input (validation, a bad file); 2 usage, unknown machine,\n"
    "or a database that cannot be used (damaged, another program's, newer, locked).\n";

namespace {

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
    std::string s = f.severity == profile::Severity::Error ? "error" : "warning";
    if (f.message)
        s += " [M" + std::to_string(*f.message) + "]";
    if (!f.subject.empty())
        s += " " + f.subject;
    return s + ": " + (lang == Lang::Ru ? f.textRu : f.textEn);
}

json::Value findingJson(const profile::Finding& f) {
    json::Value j;
    j.set("severity", f.severity == profile::Severity::Error ? "error" : "warning");
    j.set("subject", f.subject);
    j.set("manual_number", f.message ? json::Value(*f.message) : json::Value(nullptr));
    json::Array cs;
    for (int n : f.cParams)
        cs.push_back(n);
    j.set("c", std::move(cs));
    j.set("message_ru", f.textRu);
    j.set("message_en", f.textEn);
    return j;
}

json::Value optJson(const std::optional<std::string>& s) {
    return s ? json::Value(*s) : json::Value(nullptr);
}

json::Value changeJson(const profile::Change& c) {
    json::Value j;
    j.set("section", profile::diffSectionName(c.section));
    j.set("key", c.key);
    j.set("label", c.label);
    j.set("before", optJson(c.before));
    j.set("after", optJson(c.after));
    return j;
}

int fail(const std::string& message, int code = ExitUsage) {
    std::fprintf(stderr, "k528: %s\n", message.c_str());
    return code;
}

int dbFail(const db::Error& e) {
    if (const auto* v = dynamic_cast<const db::ValidationError*>(&e); v && !v->findings().empty())
        return fail(e.what(), ExitInputErrors);
    return fail(e.what(), e.kind() == db::ErrorKind::Invalid ? ExitInputErrors : ExitUsage);
}

bool parseLangOption(const Args& a, Lang& lang) {
    lang = Lang::Ru;
    if (const auto l = a.value("--lang")) {
        if (*l == "ru")
            lang = Lang::Ru;
        else if (*l == "en")
            lang = Lang::En;
        else {
            usageError("--lang is ru or en, not '" + *l + "'");
            return false;
        }
    }
    return true;
}

// --------------------------------------------------------------------------
// Opening the database

struct DbTarget {
    fs::path path;
    bool explicitPath = false;
};

// "--db PATH" of the subcommand, else the default location.
bool dbTarget(const Args& a, DbTarget& t) {
    if (const auto p = a.value("--db")) {
        if (p->empty()) {
            usageError("--db needs a file path");
            return false;
        }
        t.path = *p;
        t.explicitPath = true;
        return true;
    }
    try {
        t.path = db::defaultDatabasePath();
    } catch (const db::Error& e) {
        fail(e.what());
        return false;
    }
    t.explicitPath = std::getenv("K528_DB") && *std::getenv("K528_DB");
    return true;
}

// Opens the database. The default location is created on first use (with its
// folder); an explicit --db path only by init and import.
std::optional<db::Database> openDb(const DbTarget& t, bool mayCreate,
                                   const std::string& author = {}) {
    std::error_code ec;
    const bool exists = fs::exists(t.path, ec);
    if (!exists && t.explicitPath && !mayCreate) {
        fail("no database at " + t.path.string() + " (create one with: k528 db init --db " +
             t.path.string() + ")");
        return std::nullopt;
    }
    if (!exists && !t.explicitPath) {
        fs::create_directories(t.path.parent_path(), ec);
        if (ec) {
            fail("cannot create the folder " + t.path.parent_path().string() + ": " + ec.message());
            return std::nullopt;
        }
    }
    try {
        db::OpenOptions o;
        o.author = author;
        return db::Database::open(t.path, o);
    } catch (const db::Error& e) {
        fail(e.what());
        return std::nullopt;
    }
}

// "grinder-205@3" -> name, revision.
struct MachineRef {
    std::string name;
    std::optional<int> revision;
};

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
        usageError("'" + s + "': the revision after @ must be a positive number");
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
        return "= " + units::formatDisc(v, s) + (ru ? " мм" : " mm");
    case cat::RUnit::DiscXPerMin:
    case cat::RUnit::DiscZPerMin:
        return "= " + units::formatDisc(v, s) + (ru ? " мм/мин" : " mm/min");
    case cat::RUnit::Ms: {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.3f", static_cast<double>(v) / 1000.0);
        return std::string("= ") + buf + (ru ? " с" : " s");
    }
    default:
        return {};
    }
}

std::string machineHeader(const db::MachineInfo& m, std::optional<int> revision) {
    std::string s = "machine   " + m.name + (m.title.empty() ? "" : " — " + m.title) + "\n";
    if (revision && *revision != m.revision)
        s += "revision  " + std::to_string(*revision) + " (current " + std::to_string(m.revision) +
             ")\n";
    else
        s += "revision  " + std::to_string(m.revision) + ", changed " + m.changedAt + " by " +
             m.changedBy + "\n";
    return s;
}

std::string programSummary(int n, const std::string& text) {
    const auto lines = std::count(text.begin(), text.end(), '\n');
    const std::string title = db::programTitle(text);
    return "L" + pad(std::to_string(n), 3) + pad(title, 40) + " " +
           padLeft(std::to_string(lines), 4) + " lines  sha256 " +
           db::sha256Hex(text).substr(0, 16) + "\n";
}

// Changes of one revision, for --history and set.
std::string changeLines(const std::vector<profile::Change>& changes, const db::Database* d,
                        const std::string& machine, int revision) {
    std::string s;
    for (const auto& c : changes) {
        if (c.section == profile::DiffSection::Program) {
            s += "  " + c.key + ": " + (!c.before ? "added" : !c.after ? "removed" : "changed");
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
             c.before.value_or("(none)") + " -> " + c.after.value_or("(none)") + "\n";
    }
    return s;
}

// --------------------------------------------------------------------------
// init

int cmdInit(std::span<const std::string> argv) {
    const Args a(argv, {}, {"--db"});
    if (!a.ok())
        return usageError(a.error());
    if (!a.positional().empty())
        return usageError("db init takes no arguments");
    DbTarget t;
    if (!dbTarget(a, t))
        return ExitUsage;
    auto d = openDb(t, true);
    if (!d)
        return ExitUsage;
    const auto& r = d->openReport();
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
    s += "machines  " + std::to_string(d->machines().size()) + "\n";
    out(s);
    return ExitOk;
}

// --------------------------------------------------------------------------
// machines

int cmdMachines(std::span<const std::string> argv) {
    const Args a(argv, {"--json"}, {"--db"});
    if (!a.ok())
        return usageError(a.error());
    if (!a.positional().empty())
        return usageError("db machines takes no arguments");
    DbTarget t;
    if (!dbTarget(a, t))
        return ExitUsage;
    auto d = openDb(t, false);
    if (!d)
        return ExitUsage;
    const auto ms = d->machines();
    if (a.has("--json")) {
        json::Array arr;
        for (const auto& m : ms) {
            json::Value j;
            j.set("name", m.name);
            j.set("title", m.title);
            j.set("revision", m.revision);
            j.set("created_at", m.createdAt);
            j.set("changed_at", m.changedAt);
            j.set("changed_by", m.changedBy);
            arr.push_back(std::move(j));
        }
        json::Value root;
        root.set("database", t.path.string());
        root.set("machines", std::move(arr));
        out(root.dump() + "\n");
        return ExitOk;
    }
    std::size_t w = 7;
    for (const auto& m : ms)
        w = std::max(w, utf8::length(m.name));
    std::string s = pad("MACHINE", w) + "  REV  CHANGED               BY          TITLE\n";
    for (const auto& m : ms)
        s += pad(m.name, w) + "  " + padLeft(std::to_string(m.revision), 3) + "  " +
             pad(m.changedAt, 20) + "  " + pad(m.changedBy, 10) + "  " + m.title + "\n";
    if (ms.empty())
        s += "(no machines: k528 db import FILE adds one)\n";
    out(s);
    return ExitOk;
}

// --------------------------------------------------------------------------
// show

// "--history" may be followed by a number: "--history 5" -> "--history=5",
// "--history" alone -> "--history=0" (all).
std::vector<std::string> normalizeHistory(std::span<const std::string> argv) {
    std::vector<std::string> v;
    for (std::size_t i = 0; i < argv.size(); ++i) {
        if (argv[i] == "--history") {
            if (i + 1 < argv.size() && parseInt(argv[i + 1])) {
                v.push_back("--history=" + argv[i + 1]);
                ++i;
            } else {
                v.push_back("--history=0");
            }
            continue;
        }
        v.push_back(argv[i]);
    }
    return v;
}

std::optional<int> parseCNumber(const std::string& s) {
    std::string t = s;
    if (!t.empty() && (t[0] == 'C' || t[0] == 'c'))
        t = t.substr(1);
    const auto n = parseInt(t);
    if (!n || *n < 1 || *n > cat::kCParamCount)
        return std::nullopt;
    return static_cast<int>(*n);
}

std::optional<int> parseRNumber(const std::string& s) {
    std::string t = s;
    if (!t.empty() && (t[0] == 'R' || t[0] == 'r'))
        t = t.substr(1);
    const auto n = parseInt(t);
    if (!n || *n < 0 || *n >= cat::kRParamCount)
        return std::nullopt;
    return static_cast<int>(*n);
}

std::string historyText(const db::Database& d, const std::string& machine,
                        const std::optional<std::string>& key, int limit) {
    std::string s;
    if (key) {
        const auto h = d.history(machine, key, limit);
        s += "history of " + *key + (h.empty() ? ": no changes recorded\n" : ":\n");
        for (const auto& e : h) {
            s += "  revision " + std::to_string(e.revision) + "  " + e.at + "  " + e.author + ": ";
            if (e.change.section == profile::DiffSection::Program)
                s += std::string(!e.change.before  ? "added"
                                 : !e.change.after ? "removed"
                                                   : "changed") +
                     "\n";
            else
                s += e.change.before.value_or("(none)") + " -> " +
                     e.change.after.value_or("(none)") + "\n";
        }
        return s;
    }
    const auto revs = d.revisions(machine);
    const auto all = d.history(machine, std::nullopt, limit);
    int shown = 0;
    for (const auto& r : revs) {
        if (limit > 0 && shown >= limit)
            break;
        ++shown;
        s += "revision " + std::to_string(r.revision) + "  " + r.at + "  " + r.author + "  " +
             r.summary + " (" + std::to_string(r.changeCount) +
             (r.changeCount == 1 ? " change" : " changes") + ")\n";
        if (r.revision == 1 && r.changeCount > 20) {
            s += "  (the machine as first stored: k528 db export " + machine + "@1)\n";
            continue;
        }
        std::vector<profile::Change> cs;
        for (const auto& e : all)
            if (e.revision == r.revision)
                cs.push_back(e.change);
        s += changeLines(cs, &d, machine, r.revision);
    }
    return s;
}

json::Value historyJson(const db::Database& d, const std::string& machine,
                        const std::optional<std::string>& key, int limit) {
    json::Array arr;
    const auto all = d.history(machine, key, limit);
    int shown = 0;
    for (const auto& r : d.revisions(machine)) {
        if (limit > 0 && shown >= limit)
            break;
        ++shown;
        json::Array cs;
        for (const auto& e : all)
            if (e.revision == r.revision)
                cs.push_back(changeJson(e.change));
        if (key && cs.empty())
            continue;
        json::Value j;
        j.set("revision", r.revision);
        j.set("author", r.author);
        j.set("at", r.at);
        j.set("summary", r.summary);
        j.set("changes", std::move(cs));
        arr.push_back(std::move(j));
    }
    return arr;
}

json::Value cJson(const MachineProfile& p, const cat::CParamDef& d, bool full) {
    json::Value j;
    j.set("number", d.number);
    j.set("key", d.key());
    j.set("axis", cat::axisName(d.axis));
    j.set("name", d.name);
    j.set("name_en", d.nameEn);
    j.set("value", p.cValue(d.number));
    j.set("unit", cat::unitSymbol(d.unit));
    j.set("explanation_ru", db::explainCValue(p, d.number, Lang::Ru));
    j.set("explanation_en", db::explainCValue(p, d.number, Lang::En));
    if (full) {
        j.set("kind", cat::kindName(d.kind));
        j.set("min", d.min);
        j.set("max", d.max);
        j.set("address", d.address.text());
        j.set("description_ru", d.descriptionRu);
        j.set("description_en", d.descriptionEn);
        j.set("hint_ru", d.hintRu);
        j.set("hint_en", d.hintEn);
        j.set("note", d.note);
    }
    return j;
}

int cmdShow(std::span<const std::string> argvIn) {
    const auto argv = normalizeHistory(argvIn);
    const Args a(argv, {"--programs", "--messages", "--json"},
                 {"--db", "--c", "--r", "--program", "--history", "--lang"});
    if (!a.ok())
        return usageError(a.error());
    if (a.positional().size() != 1)
        return usageError("db show needs one MACHINE (or MACHINE@REV)");
    Lang lang;
    if (!parseLangOption(a, lang))
        return ExitUsage;
    const auto ref = parseRef(a.positional()[0]);
    if (!ref)
        return ExitUsage;
    int views = 0;
    for (const char* o : {"--c", "--r", "--program"})
        views += a.value(o) ? 1 : 0;
    views += a.has("--programs") + a.has("--messages");
    if (views > 1)
        return usageError("db show takes one of --c, --r, --programs, --program, --messages");
    std::optional<int> cNumber, rNumber, programNumber;
    if (const auto v = a.value("--c"); v && !(cNumber = parseCNumber(*v)))
        return usageError("--c: '" + *v + "' is not a C-parameter number 1..152");
    if (const auto v = a.value("--r"); v && !(rNumber = parseRNumber(*v)))
        return usageError("--r: '" + *v + "' is not an R-parameter number 0..299");
    if (const auto v = a.value("--program")) {
        const auto n = parseInt(*v);
        if (!n || *n < 1 || *n > 99)
            return usageError("--program: '" + *v + "' is not a program number 1..99");
        programNumber = static_cast<int>(*n);
    }
    std::optional<int> historyLimit;
    if (const auto v = a.value("--history")) {
        const auto n = parseInt(*v);
        if (!n || *n < 0)
            return usageError("--history N: N must be a number of revisions (0 = all)");
        historyLimit = static_cast<int>(*n);
    }
    DbTarget t;
    if (!dbTarget(a, t))
        return ExitUsage;
    auto d = openDb(t, false);
    if (!d)
        return ExitUsage;
    try {
        const MachineProfile p = loadRef(*d, *ref);
        const db::MachineInfo info = *d->machine(ref->name);
        const bool ru = lang == Lang::Ru;
        std::optional<std::string> historyKey;
        if (cNumber)
            historyKey = cat::cParam(*cNumber).key();
        else if (rNumber)
            historyKey = "R" + std::to_string(*rNumber);
        else if (programNumber)
            historyKey = "L" + std::to_string(*programNumber);

        if (a.has("--json")) {
            json::Value root;
            root.set("name", p.name);
            root.set("title", p.title);
            root.set("revision", ref->revision ? *ref->revision : info.revision);
            root.set("current_revision", info.revision);
            root.set("changed_at", info.changedAt);
            root.set("changed_by", info.changedBy);
            root.set("created_at", info.createdAt);
            json::Array cs;
            for (const auto& def : cat::cParams())
                if (!cNumber || *cNumber == def.number)
                    cs.push_back(cJson(p, def, cNumber.has_value()));
            root.set("c", std::move(cs));
            json::Array rs;
            for (const auto& [n, v] : p.r)
                if (!rNumber || *rNumber == n) {
                    json::Value j;
                    j.set("number", n);
                    j.set("value", v);
                    j.set("meaning_ru", rMeaning(n, Lang::Ru));
                    j.set("meaning_en", rMeaning(n, Lang::En));
                    rs.push_back(std::move(j));
                }
            root.set("r", std::move(rs));
            json::Array ps;
            for (const auto& [n, text] : p.programs)
                if (!programNumber || *programNumber == n) {
                    json::Value j;
                    j.set("number", n);
                    j.set("title", db::programTitle(text));
                    j.set("lines",
                          static_cast<long long>(std::count(text.begin(), text.end(), '\n')));
                    j.set("sha256", db::sha256Hex(text));
                    if (programNumber)
                        j.set("text", text);
                    ps.push_back(std::move(j));
                }
            root.set("programs", std::move(ps));
            json::Value ms = json::Object{};
            for (const auto& [n, text] : p.messages)
                ms.set("#" + std::to_string(n), text);
            root.set("messages", std::move(ms));
            json::Value plc = json::Object{};
            for (cat::PlcGroup g : cat::kPlcGroups)
                for (const auto& [k, text] : p.plcTexts(g))
                    plc.set(std::string(1, cat::plcGroupLetter(g)) + (k < 10 ? "0" : "") +
                                std::to_string(k),
                            text);
            root.set("plc_messages", std::move(plc));
            json::Array fs;
            for (const auto& f : profile::validate(p))
                fs.push_back(findingJson(f));
            root.set("findings", std::move(fs));
            if (historyLimit)
                root.set("history", historyJson(*d, info.name, historyKey, *historyLimit));
            out(root.dump() + "\n");
            return ExitOk;
        }

        std::string s = machineHeader(info, ref->revision);
        if (cNumber) {
            const auto& def = cat::cParam(*cNumber);
            s += "\n" + def.key() + " " + std::string(ru ? def.name : def.nameEn);
            if (def.axis != cat::Axis::Common)
                s += std::string(ru ? " (ось " : " (axis ") + std::string(cat::axisName(def.axis)) +
                     ")";
            s += " = " + std::to_string(p.cValue(*cNumber)) + "\n";
            const std::string ex = db::explainCValue(p, *cNumber, lang);
            if (!ex.empty())
                s += std::string(ru ? "  значение:  " : "  meaning:   ") + ex + "\n";
            s += std::string(ru ? "  единица:   " : "  unit:      ") + unitText(def.unit, lang) +
                 "\n";
            s += std::string(ru ? "  диапазон:  " : "  range:     ") + std::to_string(def.min) +
                 "..." + std::to_string(def.max) + "\n";
            s += std::string(ru ? "  тип:       " : "  kind:      ") +
                 std::string(cat::kindName(def.kind)) + "\n";
            if (!def.address.text().empty())
                s += std::string(ru ? "  адрес в БП: " : "  address:   ") +
                     (ru ? def.address.text() : def.address.textEn()) + "\n";
            const std::string hint(ru ? def.hintRu : def.hintEn);
            if (!hint.empty())
                s += std::string(ru ? "  подсказка: " : "  hint:      ") + hint + "\n";
            s += "  " + std::string(ru ? def.descriptionRu : def.descriptionEn) + "\n";
            if (!def.note.empty())
                s += "  note: " + std::string(def.note) + "\n";
            for (const auto& f : profile::validate(p))
                if (std::find(f.cParams.begin(), f.cParams.end(), *cNumber) != f.cParams.end())
                    s += "  " + findingText(f, lang) + "\n";
            s += historyText(*d, info.name, historyKey, historyLimit.value_or(0));
        } else if (rNumber) {
            const cat::RParamDef& def = cat::rParam(*rNumber);
            const auto it = p.r.find(*rNumber);
            s += "\nR" + std::to_string(*rNumber) + " = " +
                 (it == p.r.end() ? std::string(ru ? "(не задан)" : "(not preset)")
                                  : std::to_string(it->second) + " " +
                                        rValueText(p, *rNumber, it->second, lang)) +
                 "\n";
            const std::string meaning = rMeaning(*rNumber, lang);
            if (!meaning.empty())
                s += "  " + meaning + "\n";
            s += std::string("  ") +
                 (def.readOnly() ? (ru ? "только чтение (R232..R262)" : "read only (R232..R262)")
                  : def.user() ? (ru ? "параметр пользователя" : "user parameter")
                               : (ru ? "системный параметр" : "system parameter")) +
                 ", " + std::string(ru ? cat::rUnitRu(def.unit) : cat::rUnitEn(def.unit)) + "\n";
            if (def.group > 0)
                s += std::string(ru ? "  УСТАНОВОЧНЫЕ ДАННЫЕ " : "  preset screen ") +
                     std::to_string(def.group) + " " +
                     std::string(ru ? cat::rGroupNameRu(def.group) : cat::rGroupNameEn(def.group)) +
                     "\n";
            s += historyText(*d, info.name, historyKey, historyLimit.value_or(0));
        } else if (programNumber) {
            const auto it = p.programs.find(*programNumber);
            if (it == p.programs.end())
                return fail("machine " + p.name + " has no program L" +
                            std::to_string(*programNumber));
            if (historyLimit) {
                out(s + historyText(*d, info.name, historyKey, *historyLimit));
                return ExitOk;
            }
            out(it->second);
            return ExitOk;
        } else if (historyLimit) {
            s += "\n" + historyText(*d, info.name, std::nullopt, *historyLimit);
            out(s);
            return ExitOk;
        } else if (a.has("--programs")) {
            s += "\n";
            for (const auto& [n, text] : p.programs)
                s += programSummary(n, text);
            if (p.programs.empty())
                s += ru ? "(нет программ)\n" : "(no programs)\n";
        } else if (a.has("--messages")) {
            s += ru ? "\nТехнологические сообщения:\n" : "\nTechnological messages:\n";
            for (const auto& [n, text] : p.messages)
                s += "  #" + pad(std::to_string(n), 3) + text + "\n";
            for (cat::PlcGroup g : cat::kPlcGroups) {
                s += "\n" + std::string(ru ? cat::plcGroupNameRu(g) : cat::plcGroupNameEn(g)) +
                     ":\n";
                for (const auto& [k, text] : p.plcTexts(g))
                    s += "  " + std::string(1, cat::plcGroupLetter(g)) + (k < 10 ? "0" : "") +
                         std::to_string(k) + "  " + pad(cat::plcMessageAddress(g, k), 8) + "  " +
                         text + "\n";
            }
        } else {
            s += "\n";
            for (const auto& def : cat::cParams()) {
                if (def.number == 1)
                    s += ru ? "; ось X\n" : "; axis X\n";
                else if (def.number == 53)
                    s += ru ? "; ось Z\n" : "; axis Z\n";
                else if (def.number == 105)
                    s += ru ? "; общие\n" : "; common\n";
                s += cLine(p, def, lang);
            }
            s += ru ? "\nR-параметры (предустановки):\n" : "\nR-parameter presets:\n";
            for (const auto& [n, v] : p.r) {
                const std::string vt = rValueText(p, n, v, lang);
                s += "R" + pad(std::to_string(n), 4) + " " + padLeft(std::to_string(v), 11) + "  " +
                     pad(vt, 18) + " " + rMeaning(n, lang) + "\n";
            }
            if (p.r.empty())
                s += ru ? "(нет)\n" : "(none)\n";
            s += (ru ? "\nпрограммы: " : "\nprograms: ") + std::to_string(p.programs.size());
            if (!p.programs.empty()) {
                s += " (";
                bool first = true;
                for (const auto& [n, text] : p.programs) {
                    s += (first ? "L" : ", L") + std::to_string(n);
                    first = false;
                }
                s += ")";
            }
            s += (ru ? "; сообщения: " : "; messages: ") + std::to_string(p.messages.size()) +
                 (ru ? "; тексты ПЛК: " : "; PLC texts: ") +
                 std::to_string(p.plcAlarm.size() + p.plcWork.size() + p.plcSystem.size()) + "\n";
        }
        if (!cNumber) {
            const auto findings = profile::validate(p);
            if (!findings.empty()) {
                s += ru ? "\nпроверка:\n" : "\nchecks:\n";
                for (const auto& f : findings)
                    s += "  " + findingText(f, lang) + "\n";
            }
        }
        if (historyLimit && (a.has("--programs") || a.has("--messages")))
            s += "\n" + historyText(*d, info.name, std::nullopt, *historyLimit);
        out(s);
        return ExitOk;
    } catch (const db::Error& e) {
        return dbFail(e);
    }
}

// --------------------------------------------------------------------------
// set

// The item an ITEM=VALUE names, the same for C22, c022 and C022.
std::string itemKey(const std::string& item) {
    std::string key = item.substr(0, item.find('='));
    if (key.size() < 2 || std::string_view("CcRr#AWS").find(key[0]) == std::string_view::npos)
        return key;
    const std::size_t nz = key.find_first_not_of('0', 1);
    const std::string digits = nz == std::string::npos ? "0" : key.substr(nz);
    return std::string(1, static_cast<char>(std::toupper(static_cast<unsigned char>(key[0])))) + digits;
}

// One ITEM=VALUE of `set` into the edit; "" or what is wrong.
std::string parseItem(const std::string& item, db::Edit& e) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
        return "'" + item + "' is not ITEM=VALUE (e.g. C022=2133, R12=5, #3=TEXT, A01=TEXT)";
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    const auto digits = [](const std::string& s) {
        return !s.empty() &&
               std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    const std::string rest = key.substr(1);
    if ((key[0] == 'C' || key[0] == 'c') && digits(rest)) {
        const auto n = parseInt(rest);
        if (!n || *n < 1 || *n > cat::kCParamCount)
            return key + ": no such C-parameter (1..152)";
        const auto v = parseInt(value);
        if (!v)
            return key + ": '" + value + "' is not a whole number";
        e.c[static_cast<int>(*n)] = *v;
        return {};
    }
    if ((key[0] == 'R' || key[0] == 'r') && digits(rest)) {
        const auto n = parseInt(rest);
        if (!n || *n < 0 || *n >= cat::kRParamCount)
            return key + ": no such R-parameter (0..299)";
        if (value.empty()) {
            e.r[static_cast<int>(*n)] = std::nullopt;
            return {};
        }
        const auto v = parseInt(value);
        if (!v)
            return key + ": '" + value + "' is not a whole number";
        e.r[static_cast<int>(*n)] = *v;
        return {};
    }
    if (key[0] == '#' && digits(rest)) {
        const auto n = parseInt(rest);
        if (!n || *n < 1 || *n > cat::kTechMessageCount)
            return key + ": no such technological message (#1..#99)";
        e.messages[static_cast<int>(*n)] =
            value.empty() ? std::nullopt : std::optional<std::string>(value);
        return {};
    }
    if ((key[0] == 'A' || key[0] == 'W' || key[0] == 'S') && digits(rest)) {
        const cat::PlcGroup g = key[0] == 'A'   ? cat::PlcGroup::Alarm
                                : key[0] == 'W' ? cat::PlcGroup::Work
                                                : cat::PlcGroup::System;
        const auto n = parseInt(rest);
        if (!n || *n < 1 || *n > cat::plcMessageCount(g))
            return key + ": no such PLC message (" + std::string(1, key[0]) + "01.." +
                   std::string(1, key[0]) + std::to_string(cat::plcMessageCount(g)) + ")";
        e.plc[{g, static_cast<int>(*n)}] =
            value.empty() ? std::nullopt : std::optional<std::string>(value);
        return {};
    }
    if (key == "title") {
        e.title = value;
        return {};
    }
    if (profile::Settings::keyError(key).empty()) {
        e.simulation[key] = value.empty() ? std::nullopt : std::optional<std::string>(value);
        return {};
    }
    return "'" + key +
           "' is not an item: C<n>, R<n>, #<n>, A<nn>, W<nn>, S<nn>, title or a "
           "simulation key";
}

void printRejection(const db::ValidationError& e, Lang lang, const std::string& where) {
    const std::string first = std::string(e.what()).substr(0, std::string(e.what()).find('\n'));
    std::fprintf(stderr, "k528: %s\n", first.c_str());
    for (const auto& f : e.findings())
        std::fprintf(stderr, "%s%s\n", where.c_str(), findingText(f, lang).c_str());
}

std::string savedText(const std::string& machine, const db::SaveResult& r, Lang lang) {
    std::string s;
    if (!r.changed)
        return machine + ": no changes (revision " + std::to_string(r.revision) + ")\n";
    s = machine + ": revision " + std::to_string(r.revision) + " (" +
        std::to_string(r.changes.size()) + (r.changes.size() == 1 ? " change" : " changes") + ")\n";
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

int cmdSet(std::span<const std::string> argv) {
    const Args a(argv, {"--allow-errors"}, {"--db", "--author", "--lang"});
    if (!a.ok())
        return usageError(a.error());
    if (a.positional().size() < 2)
        return usageError("db set needs MACHINE and at least one ITEM=VALUE (e.g. C022=2133)");
    Lang lang;
    if (!parseLangOption(a, lang))
        return ExitUsage;
    db::Edit edit;
    std::map<std::string, std::string> given; // item key -> the ITEM=VALUE that set it
    for (std::size_t i = 1; i < a.positional().size(); ++i) {
        const std::string& item = a.positional()[i];
        if (const auto err = parseItem(item, edit); !err.empty())
            return usageError(err);
        const auto [it, fresh] = given.emplace(itemKey(item), item);
        if (!fresh)
            return usageError(item.substr(0, item.find('=')) + " is given twice ('" + it->second +
                              "' and '" + item + "'); give each item once");
    }
    DbTarget t;
    if (!dbTarget(a, t))
        return ExitUsage;
    auto d = openDb(t, false, a.value("--author").value_or(""));
    if (!d)
        return ExitUsage;
    const std::string machine = a.positional()[0];
    try {
        db::WriteOptions o;
        o.author = a.value("--author").value_or("");
        o.allowErrors = a.has("--allow-errors");
        const auto r = d->applyEdit(machine, edit, o);
        out(savedText(machine, r, lang));
        return ExitOk;
    } catch (const db::ValidationError& e) {
        printRejection(e, lang, "  ");
        return ExitInputErrors;
    } catch (const db::Error& e) {
        return dbFail(e);
    }
}

// --------------------------------------------------------------------------
// export

int cmdExport(std::span<const std::string> argv) {
    const Args a(argv, {}, {"--db", "--format", "--out"});
    if (!a.ok())
        return usageError(a.error());
    if (a.positional().size() != 1)
        return usageError("db export needs one MACHINE (or MACHINE@REV)");
    const std::string format = a.value("--format").value_or("k528m");
    if (format != "k528m" && format != "csv")
        return usageError("--format is k528m or csv, not '" + format + "'");
    const auto ref = parseRef(a.positional()[0]);
    if (!ref)
        return ExitUsage;
    DbTarget t;
    if (!dbTarget(a, t))
        return ExitUsage;
    auto d = openDb(t, false);
    if (!d)
        return ExitUsage;
    try {
        const MachineProfile p = loadRef(*d, *ref);
        const std::string text =
            format == "csv" ? profile::writeCParamsCsv(p.cValues()) : profile::writeMachineText(p);
        return writeOutput(a.value("--out"), text) ? ExitOk : ExitUsage;
    } catch (const db::Error& e) {
        return dbFail(e);
    }
}

// --------------------------------------------------------------------------
// import

// The line of `key` ("C017") in the [c] section of a machine file, 0 if none.
int lineOfC(const std::string& text, int number) {
    std::istringstream in(text);
    std::string line;
    int n = 0;
    bool inC = false;
    while (std::getline(in, line)) {
        ++n;
        std::string s = line;
        while (!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t'))
            s.pop_back();
        const auto b = s.find_first_not_of(" \t");
        if (b == std::string::npos)
            continue;
        s = s.substr(b);
        if (s[0] == '[') {
            inC = s == "[c]";
            continue;
        }
        if (!inC || (s[0] != 'C' && s[0] != 'c'))
            continue;
        const auto eq = s.find('=');
        if (eq == std::string::npos)
            continue;
        std::string k = s.substr(1, eq - 1);
        while (!k.empty() && (k.back() == ' ' || k.back() == '\t'))
            k.pop_back();
        if (const auto v = parseInt(k); v && *v == number)
            return n;
    }
    return 0;
}

bool looksLikeCsv(const std::string& path, const std::string& text) {
    if (path.size() > 4 && path.substr(path.size() - 4) == ".csv")
        return true;
    std::string t = text.substr(0, 64);
    if (t.rfind("\xEF\xBB\xBF", 0) == 0)
        t = t.substr(3);
    return t.rfind("number;", 0) == 0;
}

int cmdImport(std::span<const std::string> argv) {
    const Args a(argv, {"--replace", "--allow-errors"},
                 {"--db", "--as", "--author", "--format", "--lang"});
    if (!a.ok())
        return usageError(a.error());
    if (a.positional().size() != 1)
        return usageError("db import needs one FILE (a machine file .k528m, or CSV with --as)");
    Lang lang;
    if (!parseLangOption(a, lang))
        return ExitUsage;
    const std::string file = a.positional()[0];
    std::string text, err;
    if (file == "-") {
        if (!util::readInputStream(stdin, "standard input", text, err))
            return fail(err);
    } else if (!readFile(file, text, err)) {
        return fail(err);
    }
    const std::string source = file == "-" ? "<stdin>" : file;
    std::string format = a.value("--format").value_or("");
    if (!format.empty() && format != "k528m" && format != "csv")
        return usageError("--format is k528m or csv, not '" + format + "'");
    if (format.empty())
        format = looksLikeCsv(file, text) ? "csv" : "k528m";
    const auto asName = a.value("--as");
    if (asName) {
        if (const auto e = profile::checkName(*asName); !e.empty())
            return usageError("--as " + *asName + ": " + e);
    }
    db::WriteOptions o;
    o.author = a.value("--author").value_or("");
    o.allowErrors = a.has("--allow-errors");
    o.action = "import";
    o.summary = "import " + fs::path(source).filename().string();

    // Read and check the whole file before the database is touched.
    MachineProfile p;
    profile::CValues csv{};
    try {
        if (format == "csv") {
            if (!asName)
                return usageError("a CSV file holds only the constants: name the machine whose "
                                  "constants it replaces with --as NAME");
            csv = profile::readCParamsCsv(text, source);
        } else {
            p = profile::readMachineText(text, source);
            if (asName)
                p.name = *asName;
        }
    } catch (const profile::FileError& e) {
        return fail(std::string(e.what()) + " (nothing was imported)", ExitInputErrors);
    }
    DbTarget t;
    if (!dbTarget(a, t))
        return ExitUsage;
    auto d = openDb(t, true, o.author);
    if (!d)
        return ExitUsage;
    const std::string machine = format == "csv" ? *asName : p.name;
    try {
        db::SaveResult r;
        if (format == "csv") {
            db::Edit e;
            for (int n = 1; n <= cat::kCParamCount; ++n)
                e.c[n] = csv[static_cast<std::size_t>(n)];
            r = d->applyEdit(machine, e, o);
        } else if (d->hasMachine(machine)) {
            if (!a.has("--replace")) {
                const auto info = *d->machine(machine);
                return fail("machine " + machine + " already exists in " + t.path.string() +
                            " (revision " + std::to_string(info.revision) +
                            "): --replace stores the file as its next revision, --as NAME "
                            "imports it under another name; nothing was imported");
            }
            r = d->saveMachine(machine, p, o);
        } else {
            r = d->createMachine(p, o);
        }
        out(savedText(machine, r, lang));
        return ExitOk;
    } catch (const db::ValidationError& e) {
        const std::string first = std::string(e.what()).substr(0, std::string(e.what()).find('\n'));
        std::fprintf(stderr, "k528: %s\n", first.c_str());
        for (const auto& f : e.findings()) {
            int line = 0;
            if (format == "k528m")
                for (int n : f.cParams)
                    if (const int l = lineOfC(text, n); l && (!line || l < line))
                        line = l;
            std::fprintf(stderr, "%s:%s %s\n", source.c_str(),
                         line ? (std::to_string(line) + ":").c_str() : "",
                         findingText(f, lang).c_str());
        }
        return ExitInputErrors;
    } catch (const db::Error& e) {
        return dbFail(e);
    }
}

// --------------------------------------------------------------------------
// diff

// A side of a diff: MACHINE@REV, a machine of the database, a machine file,
// or a built-in profile.
bool resolveSide(const db::Database& d, const std::string& s, MachineProfile& p,
                 std::string& label) {
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
            label = s + " (built-in)";
            return true;
        }
        fail("'" + s + "' is neither a machine of " + d.path().string() +
             ", MACHINE@REV, a machine file nor a built-in profile");
        return false;
    } catch (const profile::FileError& e) {
        fail(e.what(), ExitInputErrors);
        return false;
    } catch (const db::Error& e) {
        dbFail(e);
        return false;
    }
}

int cmdDiff(std::span<const std::string> argv) {
    const Args a(argv, {"--json"}, {"--db"});
    if (!a.ok())
        return usageError(a.error());
    if (a.positional().size() != 2)
        return usageError("db diff needs two sides: MACHINE, MACHINE@REV or FILE");
    DbTarget t;
    if (!dbTarget(a, t))
        return ExitUsage;
    auto d = openDb(t, false);
    if (!d)
        return ExitUsage;
    MachineProfile pa, pb;
    std::string la, lb;
    if (!resolveSide(*d, a.positional()[0], pa, la) || !resolveSide(*d, a.positional()[1], pb, lb))
        return ExitUsage;
    const auto changes = profile::diff(pa, pb);
    if (a.has("--json")) {
        json::Value root;
        root.set("a", la);
        root.set("b", lb);
        json::Array cs;
        for (const auto& c : changes)
            cs.push_back(changeJson(c));
        root.set("changes", std::move(cs));
        out(root.dump() + "\n");
        return ExitOk;
    }
    std::string s = "--- " + la + "\n+++ " + lb + "\n";
    s += changes.empty() ? "no differences\n" : profile::formatDiff(changes);
    out(s);
    return ExitOk;
}

// --------------------------------------------------------------------------
// audit

int cmdAudit(std::span<const std::string> argv) {
    const Args a(argv, {"--json"}, {"--db", "--limit", "--machine"});
    if (!a.ok())
        return usageError(a.error());
    if (!a.positional().empty())
        return usageError("db audit takes no arguments");
    int limit = 50;
    if (const auto v = a.value("--limit")) {
        const auto n = parseInt(*v);
        if (!n || *n < 0)
            return usageError("--limit N: N must be 0 (all) or more");
        limit = static_cast<int>(*n);
    }
    DbTarget t;
    if (!dbTarget(a, t))
        return ExitUsage;
    auto d = openDb(t, false);
    if (!d)
        return ExitUsage;
    const auto entries = d->audit(limit, a.value("--machine").value_or(""));
    if (a.has("--json")) {
        json::Array arr;
        for (const auto& e : entries) {
            json::Value j;
            j.set("id", e.id);
            j.set("at", e.at);
            j.set("author", e.author);
            j.set("action", e.action);
            j.set("machine", e.machine);
            j.set("revision", e.revision);
            j.set("detail", e.detail);
            arr.push_back(std::move(j));
        }
        json::Value root;
        root.set("audit", std::move(arr));
        out(root.dump() + "\n");
        return ExitOk;
    }
    std::string s;
    for (const auto& e : entries)
        s += e.at + "  " + pad(e.author, 10) + "  " + pad(e.action, 15) + "  " +
             (e.machine.empty()
                  ? ""
                  : e.machine + (e.revision ? "@" + std::to_string(e.revision) : "") + "  ") +
             e.detail + "\n";
    out(s);
    return ExitOk;
}

} // namespace

int runDb(std::span<const std::string> args) {
    std::vector<std::string> rest(args.begin(), args.end());
    // "--db PATH" may also come before the subcommand.
    std::vector<std::string> dbOpt;
    while (!rest.empty() && (rest[0] == "--db" || rest[0].rfind("--db=", 0) == 0)) {
        if (rest[0] == "--db") {
            if (rest.size() < 2)
                return usageError("option --db needs a value");
            dbOpt = {"--db", rest[1]};
            rest.erase(rest.begin(), rest.begin() + 2);
        } else {
            dbOpt = {rest[0]};
            rest.erase(rest.begin());
        }
    }
    if (rest.empty())
        return usageError(
            "db needs a subcommand: init, machines, show, set, export, import, diff, calc, audit");
    const std::string sub = rest[0];
    std::vector<std::string> subArgs(rest.begin() + 1, rest.end());
    subArgs.insert(subArgs.end(), dbOpt.begin(), dbOpt.end());
    if (sub == "init")
        return cmdInit(subArgs);
    if (sub == "machines")
        return cmdMachines(subArgs);
    if (sub == "show")
        return cmdShow(subArgs);
    if (sub == "set")
        return cmdSet(subArgs);
    if (sub == "export")
        return cmdExport(subArgs);
    if (sub == "import")
        return cmdImport(subArgs);
    if (sub == "diff")
        return cmdDiff(subArgs);
    if (sub == "calc")
        return runDbCalc(subArgs);
    if (sub == "audit")
        return cmdAudit(subArgs);
    return usageError("unknown db subcommand '" + sub +
                      "' (init, machines, show, set, export, import, diff, calc, audit)");
}

} // namespace k528::cli
