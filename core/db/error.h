// Errors of the database module. Every message says what is wrong and where
// (the file, the machine, the item).
#pragma once

#include "profile/problem.h"
#include "profile/validate.h"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace k528::db {

// The language of texts core renders itself (explanations, findings, the
// command line's messages).
enum class Lang { Ru, En };

enum class ErrorKind {
    Io,            // the file cannot be opened, created, read or written
    Foreign,       // not a K528 Studio database (another program's SQLite file, or not SQLite)
    Corrupt,       // integrity_check failed, or stored data break their own rules
    TooNew,        // written by a newer K528 Studio (schema version above ours)
    Busy,          // another process held the database longer than the busy timeout
    NoMachine,     // no machine of that name
    MachineExists, // a machine of that name already exists
    NoRevision,    // the machine has no such revision
    Conflict,      // the machine changed since the caller read it (expected revision)
    Invalid,       // a value, an edit or a file is rejected (see ValidationError)
    ReadOnly,      // a write to a database this process may only read (see ReadOnlyError)
    Sql,           // an unexpected database error (a bug: please report it)
    Denied,        // the database's server refused: this user's roles do not allow it (see DeniedError)
};

std::string_view errorKindName(ErrorKind k); // "io", "foreign", ...

// What an error says: an id of the database's catalog (db/db_texts.h) and its
// arguments (names, numbers, paths: never words of a language).
struct ErrorText {
    ErrorText() = default;
    ErrorText(std::string id_, std::vector<std::string> args_ = {}) : id(std::move(id_)), args(std::move(args_)) {}
    std::string id;
    std::vector<std::string> args;
    // What it concerns, said before it ("PATH: …"): a path or a name, "" if none.
    std::string at;
    // A text said after it ("; the file was left untouched"), "" if none.
    std::string tail;
    std::vector<std::string> tailArgs;
    // Texts of the catalog it holds (the reason of a read-only database, the
    // action a role refusal was about): each said in the same language and
    // added after `args` (%N+1, %N+2, …).
    std::vector<ErrorText> within;
};
// `t` in a language (Russian or English).
std::string renderText(const ErrorText& t, bool russian);

class Error : public std::runtime_error {
public:
    // An error whose message has no id: what() in English; in Russian, text()
    // says what kind of error it is, where (`at`: a path or a location, ""
    // if none) and the library's own words (detail) quoted.
    Error(ErrorKind kind, const std::string& message, std::string detail = {}, std::string at = {})
        : std::runtime_error(message), kind_(kind), detail_(std::move(detail)) {
        text_.at = std::move(at);
    }
    // The same with a text said after it in every language (`after`: its
    // at and tail; its id empty).
    Error(ErrorKind kind, const std::string& message, std::string detail, ErrorText after)
        : std::runtime_error(message), kind_(kind), detail_(std::move(detail)), text_(std::move(after)) {
        text_.id.clear();
    }
    // An error said by the catalog: what() is its English.
    Error(ErrorKind kind, ErrorText text, std::string detail = {});
    // The same with what() given (the English of a text longer than the
    // catalog's: a rejection with its findings).
    Error(const std::string& what, ErrorKind kind, ErrorText text, std::string detail = {});
    ErrorKind kind() const { return kind_; }
    // The catalog's id and arguments ("" when the message has no id).
    const std::string& textId() const { return text_.id; }
    const std::vector<std::string>& textArgs() const { return text_.args; }
    const ErrorText& catalogText() const { return text_; }
    // The message in `lang`: the catalog's text; without an id what() in
    // English, in Russian the kind of error, where and the library's words.
    virtual std::string text(Lang lang) const;
    // Where it happened ("" if not said): the `at` of its text.
    const std::string& at() const { return text_.at; }
    // The library's or the system's own words inside the message, as it
    // said them (SQLite's errmsg, libpq's, strerror's), "" if none: the
    // desktop quotes them in a sentence of its language.
    const std::string& detail() const { return detail_; }

private:
    ErrorKind kind_;
    std::string detail_;
    ErrorText text_;
};

// Why a database can only be read.
enum class ReadOnlyReason {
    None,       // it can be written
    Permission, // the user may not write the file
    Folder,     // the user may not create files in its folder (SQLite's -wal/-shm/-journal)
    FileSystem, // the file system is mounted read-only
    Requested,  // opened read-only on purpose (OpenOptions::readOnly)
};
// "permission denied", "no permission to create files in its folder",
// "read-only file system", "opened read-only" ("" for None): the catalog's
// text of the reason (readOnlyReasonId).
std::string readOnlyReasonText(ReadOnlyReason r, Lang lang = Lang::En);
// The catalog's id of a reason ("read-only.permission", …; "" for None).
std::string_view readOnlyReasonId(ReadOnlyReason r);

// What a read-only database refused.
enum class ReadOnlyRefusal {
    Write,   // a change: nothing was written
    Create,  // a new database cannot be created (an empty file, a folder it may not write)
    Upgrade, // the schema is older than this program's and cannot be upgraded
    Recover, // an unfinished transaction (a hot -journal) cannot be rolled back
};

// A write refused because the database can only be read: names the file and
// why ("the database is read-only: /srv/k528.db (permission denied);
// nothing was written"), never the SQL that failed. Said by the catalog:
// the refusal's id ("read-only.write", …) holding the reason's.
class ReadOnlyError : public Error {
public:
    ReadOnlyError(std::filesystem::path path, ReadOnlyReason reason,
                  ReadOnlyRefusal refusal = ReadOnlyRefusal::Write);
    const std::filesystem::path& path() const { return path_; }
    ReadOnlyReason reason() const { return reason_; }
    ReadOnlyRefusal refusal() const { return refusal_; }

private:
    std::filesystem::path path_;
    ReadOnlyReason reason_;
    ReadOnlyRefusal refusal_;
};

// What a role refusal was about (DeniedError::action).
enum class DeniedAction {
    CreateMachine,
    ChangeMachine,
    DeleteMachine,
    ReleaseProgram,
    WithdrawProgram,
    RecordTransfer,
    RecordMessages,
    RecordAttempt,
    CreateTables,
    SetUpRoles,
    GrantRole,
    LockConstants,
    RecordStateTimes,
};
// Who may do it when that is no role's name (DeniedError's role()).
enum class DeniedHolder {
    Role,            // the role role() (k528_technologist, …)
    DatabaseOwner,   // the owner of the database
    TablesCreator,   // the owner of the database's tables with CREATEROLE
    RoleAdmin,       // the role's admin (its creator, or CREATEROLE)
};

// An action the server refused for this user (PostgreSQL's privileges):
// names the database, the user, the action and the role that may do it
// ("the database postgresql:///shop refused the user ivanov: releasing a
// program needs the role k528_technologist; the user has k528_operator;
// nothing was written"). Said by the catalog ("denied", its action and
// holder ids within); what() adds the server's own words (detail()), which
// the texts leave out: they may be in any language (the server's
// lc_messages) and say nothing the user can act on.
class DeniedError : public Error {
public:
    DeniedError(std::string database, DeniedAction action, std::string role, std::string user,
                std::string userRoles, const std::string& serverMessage);
    DeniedError(std::string database, DeniedAction action, DeniedHolder holder, std::string user,
                std::string userRoles, const std::string& serverMessage);
    DeniedAction action() const { return action_; }
    DeniedHolder holder() const { return holder_; }
    // The role it needs ("" when the holder is not a role).
    const std::string& role() const { return role_; }
    const std::string& user() const { return user_; }

private:
    DeniedError(const std::string& database, DeniedAction action, DeniedHolder holder, std::string role,
                std::string user, const std::string& userRoles, const std::string& serverMessage);
    DeniedAction action_;
    DeniedHolder holder_;
    std::string role_, user_;
};

// A write rejected by validation: values outside their definitions, or
// cross-check errors of the machine constants (with the manual's message
// numbers). Nothing was written.
class ValidationError : public Error {
public:
    // The machine's findings of severity Error rejected the write: "machine
    // NAME: rejected, nothing was written (N errors):" and a line a finding.
    ValidationError(const std::string& machine, std::vector<profile::Finding> findings);
    // An item the machine cannot even hold (a C-parameter that does not
    // exist, a simulation key or value that is not one): "machine NAME:
    // rejected, nothing was written: " and the problem.
    ValidationError(const std::string& machine, profile::Problem problem);
    // A rejection the catalog says whole (its id and arguments).
    explicit ValidationError(ErrorText text) : Error(ErrorKind::Invalid, std::move(text)) {}
    // The errors that caused the rejection (severity Error).
    const std::vector<profile::Finding>& findings() const { return findings_; }
    // A rejection without findings: what is wrong, as core's problem ids say
    // it; empty when the findings or the catalog's text say it.
    const profile::Problem& problem() const { return problem_; }
    // The first line in `lang`: the catalog's sentence, with the problem when
    // there is one (the command line puts its own finding lines after it).
    std::string head(Lang lang) const;
    // head() and a line a finding ("  error [M37] C017,C069: …").
    std::string text(Lang lang) const override;

private:
    std::vector<profile::Finding> findings_;
    profile::Problem problem_;
};

} // namespace k528::db
