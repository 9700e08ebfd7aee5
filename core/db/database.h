// The database of K528 Studio — an SQLite file on one PC, or a PostgreSQL
// database a shop's PCs share: machines with their constants C1..C152,
// R-parameter presets, programs (with revisions and SHA-256 checksums),
// technological messages, PLC message texts and simulation settings; every
// change as a revision with its author, time and old -> new values; an audit
// log of every write; programs released for the controllers; every transfer
// to and from a controller on record. docs/database.md describes the schema
// and the rules.
//
//   db::Database d = db::Database::open(db::defaultDatabasePath());
//   profile::MachineProfile p = d.loadMachine("grinder-205");
//   p.setC(22, 2133);
//   d.saveMachine("grinder-205", p, {.author = "Иванов"});      // revision N+1
//   auto old = d.loadMachine("grinder-205", 1);                 // as first stored
//   for (const auto& h : d.history("grinder-205", "C022")) ...  // who, when, old -> new
//
// Rules:
//   - open() checks the file before it changes anything: a file that is not
//     SQLite, another program's SQLite file (application_id), a schema newer
//     than this program's (user_version) or a file that fails
//     PRAGMA integrity_check (every table but the message history's, see
//     docs/database.md) is refused with a clear Error and left byte for
//     byte as it was. Older schemas are migrated in one transaction. A new
//     (empty) file gets the schema and the built-in machines.
//   - Every write is one transaction (BEGIN IMMEDIATE): it happens whole or
//     not at all, also when the process is killed. Two processes using one
//     file wait for each other up to the busy timeout.
//   - Every write is validated: values against their definitions (always),
//     the manual's cross-checks of the constants (errors reject the write
//     unless the machine already had that error or the caller allows errors).
//   - PostgreSQL (a Location "postgresql://…"): the same schema, rules and
//     results; every write serialised by the server (an advisory lock), the
//     other sessions told at commit (NOTIFY); the transfer log's user and a
//     release's author are the server's current_user. docs/database.md.
//   - One Database is one connection: use it from one thread at a
//     time. Several connections of one process to one file are safe (SQLite
//     shares its descriptors and locks), but a process should hold one
//     connection per file for its lifetime (the desktop: ShopDatabase) rather
//     than open one per operation. Nothing in core/ or app/ may open, read or
//     copy the database file (or its -shm) other than through SQLite: closing
//     any descriptor of the file drops every POSIX lock the process holds on
//     it, and another process may then delete a live -wal.
//   - A file the user may only read (permissions, folder, read-only mount)
//     opens for reading: open() writes nothing then, and every write is
//     refused with ReadOnlyError (the file and the reason, not the SQL).
//   - Timestamps come from an injectable clock (Unix seconds, UTC); the
//     default reads the system clock. The simulation never reads the clock;
//     only the history does.
#pragma once

#include "db/error.h"
#include "db/location.h"
#include "profile/diff.h"
#include "profile/profile.h"
#include "profile/validate.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace k528::db {

class Store;

// PRAGMA application_id of our files: "K528" in ASCII.
inline constexpr std::int32_t kApplicationId = 0x4B353238;

// Seconds since 1970-01-01 UTC.
using Clock = std::function<std::int64_t()>;
Clock systemClock();
// "2024-05-17T08:30:00Z"
std::string formatTimestamp(std::int64_t unixSeconds);

// The author recorded when none is given: the OS user name ($USER, else the
// password database, else "unknown").
std::string defaultAuthor();

// One step of the schema: run inside the migration transaction. `sql` is
// the same for both backends (written in SQLite's words; PostgreSQL runs it
// as postgresSchemaSql() renders it), the rest is what only one of them
// needs (triggers, row security).
struct Migration {
    int version;            // the schema version after this step (1, 2, ...)
    std::string_view title; // for the audit log
    std::string_view sql;   // statements
    std::string_view sqliteOnly = {};
    std::string_view postgresOnly = {};
};
// `sql` as PostgreSQL runs it: INTEGER columns are BIGINT (SQLite's integers
// are 64-bit), an INTEGER PRIMARY KEY an identity column, no WITHOUT ROWID.
std::string postgresSchemaSql(std::string_view sql);
// The schema's steps, in order; the last one's version is the current schema.
std::span<const Migration> schemaMigrations();
int latestSchemaVersion();

// One thing checkIntegrity() found wrong: what kind, and the names and
// numbers it concerns (never words of a language: the command line says it
// in its --lang from the kind, cli_texts.cpp `db.check.*`).
struct IntegrityProblem {
    enum class Kind {
        Pages,              // SQLite's integrity_check: its own line (args: the line)
        ForeignKey,         // a row whose key names no row (args: table, rowid)
        ProgramChecksum,    // a program's text is not its SHA-256 (machine, program number, revision)
        ChangeAuthors,      // changes that do not name their revision's author and time (machine, revision, count)
        ItemHistoryDiffers, // an item's row of item_history is not its changes (machine, key)
        ItemHistoryMissing, // an item with changes has no row in item_history (machine, key)
        Revisions,          // a machine's revision is not its history's (machine, revision, count, highest)
    };
    Kind kind;
    std::vector<std::string> args;
    bool operator==(const IntegrityProblem&) const = default;
};
// "pages", "foreign-key", "program-checksum", "change-authors",
// "item-history-differs", "item-history-missing", "revisions".
std::string_view integrityProblemName(IntegrityProblem::Kind kind);

struct OpenOptions {
    bool create = true;        // create the file when it does not exist
    int busyTimeoutMs = 10000; // how long to wait for another process
    Clock clock;               // default: systemClock()
    std::string author;        // recorded for the first start / migrations; default: OS user
    bool seedBuiltins = true;  // a new database gets profile::builtinNames()
    // Open for reading only: nothing is ever written (no settings, no
    // migration); every write is refused with ReadOnlyError. A file the user
    // may not write is opened this way by itself.
    bool readOnly = false;
    // The schema steps; tests pass a longer list to exercise a migration.
    std::span<const Migration> migrations = schemaMigrations();
    // Refuse a database that is not empty (Error Invalid): a copy's target.
    bool requireEmpty = false;
};

// What open() found and did.
struct OpenReport {
    bool created = false;            // the file was new or empty
    int fromVersion = 0;             // user_version found (0: new)
    int version = 0;                 // user_version now
    std::vector<std::string> seeded; // built-in machines loaded on the first start
    bool definitionsUpdated = false; // the C-parameter definitions were refreshed from the catalog
    bool recovered = false; // an unfinished transaction (hot -journal) was rolled back
};

struct MachineInfo {
    std::string name;
    std::string title;
    int revision = 0;      // current revision (1 = as first stored)
    std::string createdAt; // timestamps as formatTimestamp()
    std::string changedAt;
    std::string changedBy;
};

struct RevisionInfo {
    int revision = 0;
    std::string author;
    std::string at;
    std::string summary; // "import grinder.k528m", "set C022 R12", ...
    int changeCount = 0;
};

// One changed item of one revision. For programs, before/after are the
// SHA-256 of the texts (programText() gives the texts).
struct HistoryEntry {
    int revision = 0;
    std::string author;
    std::string at;
    profile::Change change;
};

struct ProgramVersion {
    int revision = 0;                // the machine revision that stored it
    std::optional<std::string> text; // nullopt: the program was deleted
    std::optional<std::string> sha256;
};

struct AuditEntry {
    std::int64_t id = 0;
    std::string at;
    std::string author;
    std::string
        action; // "create-database", "migrate", "create", "save", "set", "import", "delete", ...
    std::string machine; // "" when not about one machine
    int revision = 0;    // the revision written, 0 if none
    std::string detail;
};

struct WriteOptions {
    std::string author;          // default: defaultAuthor() (PostgreSQL: the session's user)
    std::string summary;         // recorded with the revision; default describes the write
    std::string action = "save"; // audit action
    // Accept cross-check errors of the constants (a trainer's deliberately
    // faulty machine). Values outside their definitions are never accepted.
    bool allowErrors = false;
    // Refuse (ErrorKind::Conflict) when the machine's revision is not this
    // one: someone else changed it since it was read.
    std::optional<int> expectedRevision;
    // Called inside the transaction after each changed item is written
    // (done, total): progress of long imports.
    std::function<void(std::size_t, std::size_t)> progress;
};

struct SaveResult {
    bool changed = false; // false: the stored machine already equalled the profile
    int revision = 0;     // the machine's revision after the write
    std::vector<profile::Change> changes;
    // Findings of the stored machine after the write: warnings, and errors
    // accepted because they existed before or allowErrors was set.
    std::vector<profile::Finding> findings;
};

// A change of single items, as `k528 db set` gives them.
struct Edit {
    std::optional<std::string> title;
    std::map<int, std::int64_t> c;                      // number -> value
    std::map<int, std::optional<std::int64_t>> r;       // nullopt: remove the preset
    std::map<int, std::optional<std::string>> messages; // nullopt: remove
    std::map<std::pair<catalog::PlcGroup, int>, std::optional<std::string>> plc;
    std::map<std::string, std::optional<std::string>> simulation;
    bool empty() const {
        return !title && c.empty() && r.empty() && messages.empty() && plc.empty() &&
               simulation.empty();
    }
    // "C022 R12 #3": the items, for summaries.
    std::string describe() const;
    // Applies the edit to a profile (no validation).
    void applyTo(profile::MachineProfile& p) const;
};

// The state of a program of a machine. Draft: its current version was never
// released (or was changed since); Released: the current version is the
// released one; Withdrawn: its last release was withdrawn (or the program
// was deleted from the machine since).
enum class ProgramState { Draft, Released, Withdrawn };
std::string_view programStateName(ProgramState s); // "draft", "released", "withdrawn"

// One release or withdrawal of a version of a program.
struct ReleaseEntry {
    int number = 0;
    int revision = 0;    // the version: the machine revision that stored its text
    std::string sha256;  // of that text
    bool released = true; // false: withdrawn
    std::string at;
    std::string author;  // PostgreSQL: the database user (current_user)
    std::string note;
    friend bool operator==(const ReleaseEntry&, const ReleaseEntry&) = default;
};

// A program's state now, and what a push to a controller takes.
struct ProgramRelease {
    int number = 0;
    ProgramState state = ProgramState::Draft;
    int revision = 0;                // its current version (0: deleted since its release)
    std::optional<ReleaseEntry> last; // the newest release or withdrawal
    // The version a push takes (the released one, also when a newer draft
    // exists); nullopt when nothing of it is released.
    std::optional<int> releasedRevision;
    std::optional<std::string> releasedSha256;
};

// One part of what moved in a transfer.
struct TransferItem {
    std::string kind;  // "program", "c" (the C block), "r" (the R block), "messages"
    int number = 0;    // the program's number; 0 for blocks
    std::string crc32; // "1a2b3c4d": CRC-32 of the bytes as the controller checks them
    std::optional<std::string> sha256; // of a program's text
    std::string state; // "new" (written and read back), "as-it-was", "in-doubt", "read" (pulled)
    friend bool operator==(const TransferItem&, const TransferItem&) = default;
};

// A push to or a pull from a controller, on record.
struct TransferEntry {
    std::int64_t id = 0;
    std::string at;
    std::string user;       // the OS user; PostgreSQL: the database user (current_user)
    std::string host;       // the PC
    std::string machine;    // the database's machine ("" when none was named)
    int revision = 0;       // its revision pushed, or kept from a pull (0: none)
    std::string controller; // the line and station, and what the controller said it is
    std::string direction;  // "push", "pull"
    std::string result;     // "ok", "partial" (some parts new), "failed"
    std::string detail;     // what the link said
    std::vector<TransferItem> items;
    friend bool operator==(const TransferEntry&, const TransferEntry&) = default;
};

struct TransferFilter {
    std::string machine;   // "" every machine
    std::string since;     // timestamps from this one on ("2024-05-17", "2024-05-17T08:30:00Z")
    int limit = 0;         // the newest N (0 all)
};

// One graded attempt of the training course (docs/training-course.md): who,
// which exercise, the program text graded and its grade.
struct AttemptEntry {
    std::int64_t id = 0;
    std::string at;         // filled from the clock when empty
    std::string recordedBy; // who graded it: the OS user; PostgreSQL: current_user
    std::string host;       // the PC (filled in when empty)
    std::string student;
    std::string exercise;   // the exercise's id ("lathe-03-step")
    std::string file;       // the file's name as given ("" for the editor's text)
    std::string program;    // the text graded
    std::string sha256;     // of the text (filled in)
    int score = 0;          // 0..100
    bool passed = false;
    std::string status;     // completed, alarm, interrupted, timeout, not_started, errors, procedure
    std::int64_t cycleTimeMs = 0;
    std::string grade;      // the whole grade as JSON (`k528 grade --json` of the file)
    friend bool operator==(const AttemptEntry&, const AttemptEntry&) = default;
};

struct AttemptFilter {
    std::string student;   // "" every student
    std::string exercise;  // "" every exercise
    std::int64_t afterId = 0; // only newer rows
    int limit = 0;         // the newest N (0 all)
};

// A role of the server (PostgreSQL) and who has it.
struct RoleInfo {
    std::string role;   // "k528_technologist", "k528_operator", "k528_viewer"
    std::string may;    // what it may, in words
    std::vector<std::string> members;
};

// What copyTo() copied.
struct CopyReport {
    std::string target;
    std::int64_t machines = 0, revisions = 0, programVersions = 0, releases = 0, messages = 0,
                 audit = 0, transfers = 0, attempts = 0, rows = 0;
};

class Database {
public:
    // Opens (and when needed creates or migrates) the database at `where`
    // (an SQLite file or a PostgreSQL database). Throws Error: Io, Foreign,
    // Corrupt, TooNew, Busy, Denied.
    static Database open(const Location& where, const OpenOptions& options = {});
    // An SQLite file.
    static Database open(const std::filesystem::path& path, const OpenOptions& options = {});

    Database(Database&&) noexcept;
    Database& operator=(Database&&) noexcept;
    ~Database();

    const Location& location() const;
    Backend backend() const;
    // The SQLite file; for PostgreSQL the URI as a path (for messages).
    const std::filesystem::path& path() const;
    const OpenReport& openReport() const;
    int schemaVersion() const;
    // The server's user of this session (PostgreSQL current_user); "" for SQLite.
    std::string sessionUser() const;

    // ReadOnlyReason::None when writes are possible.
    ReadOnlyReason readOnly() const;
    // Throws ReadOnlyError when the database can only be read.
    void requireWritable() const;
    // A read-only file whose folder does not let SQLite create the -shm
    // index is read as an immutable snapshot (it has no -wal then: every
    // commit is in the file). True when the file has changed or a -wal has
    // appeared since: open it again to see the changes.
    bool snapshotOutdated() const;

    // Machines.
    std::vector<MachineInfo> machines() const; // by name
    std::optional<MachineInfo> machine(std::string_view name) const;
    bool hasMachine(std::string_view name) const;
    // The current state. Throws NoMachine; Corrupt when a stored program no
    // longer matches its checksum or the rows are incomplete.
    profile::MachineProfile loadMachine(std::string_view name) const;
    // The state at `revision` (1..current), rebuilt from the history.
    profile::MachineProfile loadMachine(std::string_view name, int revision) const;

    // Stores a new machine as revision 1 (its name is p.name). Throws
    // MachineExists, ValidationError.
    SaveResult createMachine(const profile::MachineProfile& p, WriteOptions options = {});
    // Makes `p` the new state of machine `name` (p.name may differ: a
    // rename). Only what differs is written, as one new revision; an equal
    // profile writes nothing. Throws NoMachine, MachineExists (rename onto
    // another machine), Conflict, ValidationError.
    SaveResult saveMachine(std::string_view name, const profile::MachineProfile& p,
                           WriteOptions options = {});
    // Applies `edit` to the current state inside the write transaction.
    SaveResult applyEdit(std::string_view name, const Edit& edit, WriteOptions options = {});
    // Deletes a machine and its history (the audit log keeps a record).
    void removeMachine(std::string_view name, WriteOptions options = {});

    // History.
    std::vector<RevisionInfo> revisions(std::string_view name) const; // newest first
    // Changes, newest first; `key` ("C022", "R12", "L11", "#3", "A01",
    // "x.kv", "name", "title") restricts them to one item; `limit` > 0 keeps
    // the newest revisions only.
    std::vector<HistoryEntry> history(std::string_view name, std::optional<std::string> key = {},
                                      int limitRevisions = 0) const;
    std::vector<ProgramVersion> programHistory(std::string_view name, int number) const;
    // The text of program `number` as stored at `revision` (nullopt: none).
    std::optional<std::string> programText(std::string_view name, int number, int revision) const;

    std::vector<AuditEntry> audit(int limit = 0, std::string_view machine = {}) const;

    // Programs released for the controllers. release: the program's current
    // version becomes the released one (Error NoRevision: no such program;
    // an already released version is returned as it is, nothing written);
    // withdraw: the released version is withdrawn (Invalid when none is).
    // Both audited; on PostgreSQL they need the role k528_technologist.
    ReleaseEntry releaseProgram(std::string_view name, int number, const std::string& note = {},
                                WriteOptions options = {});
    ReleaseEntry withdrawProgram(std::string_view name, int number, const std::string& note = {},
                                 WriteOptions options = {});
    // Every program of the machine now (with those released and deleted
    // since), by number.
    std::vector<ProgramRelease> programReleases(std::string_view name) const;
    // Releases and withdrawals of one program, newest first.
    std::vector<ReleaseEntry> releaseHistory(std::string_view name, int number) const;

    // The transfer log. record: at (the clock), user (defaultAuthor(); on
    // PostgreSQL the server's current_user) and host (the PC) are filled in
    // when empty; returns the entry as stored. transfers: newest first.
    TransferEntry recordTransfer(TransferEntry entry);
    std::vector<TransferEntry> transfers(const TransferFilter& filter = {}) const;

    // The training course's attempts (schema version 4). record: validated
    // (a student and an exercise named, a score 0..100; Error Invalid, nothing
    // written), at, recordedBy, host and sha256 filled in when empty; on
    // PostgreSQL it needs the role k528_operator and recordedBy is the
    // server's current_user. attempts: newest first.
    AttemptEntry recordAttempt(AttemptEntry entry);
    std::vector<AttemptEntry> attempts(const AttemptFilter& filter = {}) const;

    // Whether another connection (another process or PC) committed since the
    // last call, and the machines it named (PostgreSQL: LISTEN/NOTIFY and
    // one short round trip; SQLite: PRAGMA data_version, names none: compare
    // machines()). The first call only starts watching.
    bool changedElsewhere(std::vector<std::string>* machines = nullptr);

    // Copies the whole database (machines, revisions, programs, releases,
    // message history, audit, transfers) into the empty database at
    // `target`, in one transaction of the target: all or nothing. Throws
    // Error (Invalid: the target is not empty).
    CopyReport copyTo(const Location& target, const OpenOptions& targetOptions = {}) const;

    // PostgreSQL's roles: k528_viewer (read), k528_operator (a viewer that
    // records transfers and messages, and pushes released programs),
    // k528_technologist (an operator that edits machines, releases programs
    // and pushes drafts where the machine allows). setUpRoles creates the
    // missing roles and grants them what they may on this database (the
    // owner of the tables with CREATEROLE runs it; again after an upgrade);
    // grantRole makes `user` a member ("technologist" or "k528_technologist").
    // SQLite has one user, who may everything: Error(Invalid).
    std::vector<RoleInfo> setUpRoles();
    void grantRole(const std::string& user, const std::string& role);
    std::vector<RoleInfo> roles() const;
    // Whether this session may do what `role` may (SQLite: always).
    bool mayActAs(std::string_view role) const;

    // Everything the database can check of itself (`k528 db check`):
    // SQLite's integrity_check of every page (the message history's too,
    // which an open skips) and foreign_key_check, and on both backends the
    // rules no server knows: programs against their SHA-256, each change
    // against its revision, item_history against the changes, each machine's
    // revision against its history. Empty when fine.
    std::vector<IntegrityProblem> checkIntegrity() const;

    // The storage, for the other parts of core/db on this database
    // (db::MessageLog); not for use outside core/db.
    Store& store() const;

private:
    struct Impl;
    explicit Database(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> d_;
};

} // namespace k528::db
