// The SQLite store of K528 Studio: machines with their constants C1..C152,
// R-parameter presets, programs (with revisions and SHA-256 checksums),
// technological messages, PLC message texts and simulation settings; every
// change as a revision with its author, time and old -> new values; an audit
// log of every write. docs/database.md describes the schema and the rules.
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
//   - One Database is one SQLite connection: use it from one thread at a
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

struct sqlite3;

namespace k528::db {

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

// One step of the schema: run inside the migration transaction.
struct Migration {
    int version;            // the user_version after this step (1, 2, ...)
    std::string_view title; // for the audit log
    std::string_view sql;   // statements
};
// The schema's steps, in order; the last one's version is the current schema.
std::span<const Migration> schemaMigrations();
int latestSchemaVersion();

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
    std::string author;          // default: defaultAuthor()
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

class Database {
public:
    // Opens (and when needed creates or migrates) the database at `path`.
    // Throws Error: Io, Foreign, Corrupt, TooNew, Busy.
    static Database open(const std::filesystem::path& path, const OpenOptions& options = {});

    Database(Database&&) noexcept;
    Database& operator=(Database&&) noexcept;
    ~Database();

    const std::filesystem::path& path() const;
    const OpenReport& openReport() const;
    int schemaVersion() const;

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

    // Runs PRAGMA integrity_check and foreign_key_check: "" when fine.
    std::string checkIntegrity() const;

    // The SQLite connection, for the other stores of core/db that share this
    // file and its rules (db::MessageLog); nullptr on another backend; not for
    // use outside core/db.
    sqlite3* connection() const;

private:
    struct Impl;
    explicit Database(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> d_;
};

} // namespace k528::db
