// Shared by the `k528 db` subcommands (cmd_db_<sub>.cpp): output helpers,
// opening the database, machine references, the texts that explain
// constants and changes. Not for cmd_db_calc.cpp, which stands alone.
#pragma once

#include "args.h"
#include "catalog/cparams.h"
#include "cli.h"
#include "db/database.h"
#include "db/explain.h"
#include "profile/diff.h"
#include "profile/profile.h"
#include "profile/validate.h"
#include "util/json_fwd.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace k528::cli::dbcli {

namespace fs = std::filesystem;
namespace cat = k528::catalog;
using db::Lang;
using profile::MachineProfile;

struct DbTarget {
    db::Location where; // a file or a PostgreSQL database
    fs::path path;      // where.text(), for messages
    bool explicitPath = false;
};

// "grinder-205@3" -> name, revision.
struct MachineRef {
    std::string name;
    std::optional<int> revision;
};

void out(const std::string& s);

std::string pad(const std::string& s, std::size_t width);

std::string padLeft(const std::string& s, std::size_t width);

std::string findingText(const profile::Finding& f, Lang lang);

Json findingJson(const profile::Finding& f);

Json optJson(const std::optional<std::string>& s);

Json changeJson(const profile::Change& c);

int fail(const std::string& message, int code = ExitUsage);

// Prints the error in `lang` (a rejected write with its findings); returns
// the exit code.
int dbFail(const db::Error& e, Lang lang = Lang::Ru);

bool parseLangOption(const Args& a, Lang& lang);
// The language of a command's messages: English for --lang en, else Russian
// (a wrong --lang is said by parseLangOption).
Lang langOf(const Args& a);

// "--db LOCATION" of the subcommand (a path, sqlite:PATH or a postgresql://
// URI), else the default location ($K528_DB, else the file of the data folder).
bool dbTarget(const Args& a, DbTarget& t);

// Opens the database. The default location is created on first use (with its
// folder); an explicit --db path only by init and import. `readOnly`: never
// written, not even upgraded (db check).
std::optional<db::Database> openDb(const DbTarget& t, bool mayCreate,
                                   const std::string& author = {}, Lang lang = Lang::Ru, bool readOnly = false);

// dbTarget and openDb together: the database the command's --db names (its
// path into `t`), or nullopt after printing why (exit ExitUsage).
std::optional<db::Database> openDbOf(const Args& a, DbTarget& t, bool mayCreate,
                                     const std::string& author = {}, std::optional<Lang> lang = std::nullopt);

// "grinder-205@3" -> name, revision; a usage error printed when bad.
std::optional<MachineRef> parseRef(const std::string& s);

MachineProfile loadRef(const db::Database& d, const MachineRef& r);

bool writeOutput(const std::optional<std::string>& outPath, const std::string& text);

std::string unitText(cat::Unit u, Lang lang);

std::size_t unitWidth(Lang lang);

std::string cLine(const MachineProfile& p, const cat::CParamDef& d, Lang lang);

std::string rMeaning(int n, Lang lang);

std::string rValueText(const MachineProfile& p, int n, std::int64_t v, Lang lang);

std::string machineHeader(const db::MachineInfo& m, std::optional<int> revision);

std::string programSummary(int n, const std::string& text);

// Changes of one revision, for --history and set.
std::string changeLines(const std::vector<profile::Change>& changes, const db::Database* d,
                        const std::string& machine, int revision);

// A program's change in a word ("added", "removed", "changed") and a count
// of changes ("1 change", "3 changes"), in the command line's language.
std::string changeWord(bool before, bool after);
std::string changeCount(std::size_t n);

std::string savedText(const std::string& machine, const db::SaveResult& r, Lang lang);

// The subcommands (args after the subcommand's name).
int cmdInit(std::span<const std::string> argv);
int cmdMachines(std::span<const std::string> argv);
int cmdShow(std::span<const std::string> argv);
int cmdSet(std::span<const std::string> argv);
int cmdTrial(std::span<const std::string> argv); // cmd_db_trial.cpp
int cmdExport(std::span<const std::string> argv);
int cmdImport(std::span<const std::string> argv);
int cmdDiff(std::span<const std::string> argv);
int cmdAudit(std::span<const std::string> argv);
int cmdCopy(std::span<const std::string> argv);
int cmdCheck(std::span<const std::string> argv); // cmd_db_check.cpp
int cmdRelease(std::span<const std::string> argv, bool release);
int cmdLog(std::span<const std::string> argv);
int cmdRoles(std::span<const std::string> argv);

} // namespace k528::cli::dbcli
