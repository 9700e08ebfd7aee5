// The storage behind db::Database, internal to core/db: what a backend
// provides — SQLite (sqlite_store.h) and PostgreSQL (postgres_store.h), both
// over the rows of sql_store.h. The
// rules are Database's and the same for every backend (database.cpp,
// revisions.h): what a write validates, what a revision records, how the
// state at a revision is rebuilt, what the audit log says. A backend opens
// and checks its database, runs transactions, stores and finds rows, and says
// whether it may be written.
#pragma once

#include "db/database.h"
#include "db/sql.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace k528::db {

// A machine as stored: its row id and what MachineInfo shows.
struct MachineRow {
    std::int64_t id = 0;
    MachineInfo info;
};

// One recorded change read back (the section by its name, as stored).
struct ChangeRow {
    int revision = 0;
    std::string author, at; // of its revision (history() only)
    std::string section, key, label;
    std::optional<std::string> before, after;
};

// One version of a program.
struct ProgramRow {
    int number = 0;
    int revision = 0;
    std::optional<std::string> text; // nullopt: deleted at this revision
    std::optional<std::string> sha256;
};

// A machine's row and its current state, read together.
struct LoadedMachine {
    MachineRow row;
    profile::MachineProfile profile;
};

class Store {
public:
    virtual ~Store() = default;

    virtual const std::filesystem::path& path() const = 0;
    virtual const OpenReport& openReport() const = 0;
    virtual ReadOnlyReason readOnly() const = 0;
    virtual bool snapshotOutdated() const = 0;
    virtual int schemaVersion() = 0;
    virtual std::vector<IntegrityProblem> checkIntegrity() = 0;
    virtual Backend backend() const = 0;
    // The connection, for the other stores of core/db on this database
    // (db::MessageLog) and for copying.
    virtual sql::Connection& connection() = 0;
    // The server's name for this session's user (PostgreSQL current_user);
    // "" when the backend has none (SQLite).
    virtual std::string sessionUser() { return {}; }
    // Inside a write: tells other sessions that `machine` is at `revision`
    // now (PostgreSQL NOTIFY, delivered at commit; SQLite: nothing, readers
    // see data_version move).
    virtual void notifyChange(std::string_view /*machine*/, int /*revision*/) {}
    // Whether another connection committed since the last call, and the
    // machines it named (PostgreSQL LISTEN; SQLite data_version: names none).
    virtual bool changedElsewhere(std::vector<std::string>& machines) = 0;
    // After rows were copied in with their ids: the backend's counters of
    // ids follow them (PostgreSQL sequences; SQLite keeps its own).
    virtual void afterCopy() {}
    // Whether this session may do what `role` may (PostgreSQL: membership of
    // the role or ownership of the database; SQLite: always).
    virtual bool mayActAs(std::string_view /*role*/) { return true; }
    // The K528 Studio roles of this session's user, for messages ("" none).
    virtual std::string rolesOfUser() { return {}; }
    // The server's roles (Database::setUpRoles); SQLite: Error(Invalid).
    virtual std::vector<RoleInfo> roles(bool setUp);
    virtual void grantRole(const std::string& user, const std::string& role);

    // Transactions. beginRead(): one snapshot for the reads of a call; false
    // when a transaction is already open (a write's). beginWrite(): the write
    // lock first, waiting up to the busy timeout (Error Busy, ReadOnlyError).
    virtual bool beginRead() = 0;
    virtual void endRead() noexcept = 0;
    virtual void beginWrite() = 0;
    virtual void commit() = 0;
    virtual void rollback() noexcept = 0;

    // Machines and their current state.
    virtual std::vector<MachineInfo> machines() = 0; // by name
    virtual std::optional<MachineRow> findMachine(std::string_view name) = 0;
    // Throws Error(Corrupt) when the rows break their rules.
    virtual profile::MachineProfile loadCurrent(const MachineRow& row) = 0;
    // findMachine and loadCurrent at once, in one snapshot of its own
    // (PostgreSQL: one statement); nullopt when no machine has that name.
    virtual std::optional<LoadedMachine> loadNamed(std::string_view name) = 0;
    virtual std::int64_t insertMachine(const profile::MachineProfile& p, const std::string& at,
                                       const std::string& author) = 0;
    virtual void updateMachine(std::int64_t id, const profile::MachineProfile& p, int revision,
                               const std::string& at, const std::string& author) = 0;
    virtual void deleteMachine(std::int64_t id) = 0; // with its history
    // The current-state row of one changed C, R, message or PLC text as `p`
    // has it (programs are their versions; settings are written whole).
    virtual void writeItem(std::int64_t id, bool isNew, const profile::MachineProfile& p,
                           const profile::Change& c) = 0;
    virtual void writeSettings(std::int64_t id, const profile::MachineProfile& p) = 0;

    // History.
    virtual void insertRevision(std::int64_t id, int revision, const std::string& author,
                                const std::string& at, const std::string& summary,
                                const std::string& settingsOrder) = 0;
    virtual void insertProgramVersion(std::int64_t id, const ProgramRow& version) = 0;
    // A change of revision `revision`, with that revision's author and time.
    virtual void insertChange(std::int64_t id, int revision, int seq, const std::string& author,
                              const std::string& at, const profile::Change& c) = 0;
    // Every change but the programs' up to `revision`, in order.
    virtual std::vector<ChangeRow> changesUpTo(std::int64_t id, int revision) = 0;
    // The simulation keys' order at `revision` ("\n" between keys).
    virtual std::optional<std::string> settingsOrder(std::int64_t id, int revision) = 0;
    // The programs present at `revision` (each one's last version).
    virtual std::vector<ProgramRow> programsAt(std::int64_t id, int revision) = 0;
    virtual std::vector<RevisionInfo> revisions(std::int64_t id) = 0; // newest first
    // Changes of revisions >= fromRevision (of one key), newest first.
    virtual std::vector<ChangeRow> history(std::int64_t id, int fromRevision,
                                           const std::optional<std::string>& key) = 0;
    // The same of the machine `name`, of its last `limitRevisions` revisions
    // (<= 0: all), read in one snapshot of its own (PostgreSQL: one statement).
    // nullopt when no machine has that name, or (PostgreSQL, which cannot
    // tell the two apart in its one statement) when it has no such changes:
    // the caller then reads them by the machine's row.
    virtual std::optional<std::vector<ChangeRow>> historyNamed(
        std::string_view name, int limitRevisions, const std::optional<std::string>& key) = 0;
    virtual std::vector<ProgramRow> programVersions(std::int64_t id, int number) = 0; // newest first
    // The last version of program `number` at or before `revision`.
    virtual std::optional<ProgramRow> programAt(std::int64_t id, int number, int revision) = 0;

    // The audit log.
    virtual void insertAudit(const AuditEntry& e) = 0; // e.id is ignored
    virtual std::vector<AuditEntry> audit(int limit, std::string_view machine) = 0;

    // Releases and withdrawals of program versions (newest first; one
    // program's, or every program's).
    virtual void insertProgramState(std::int64_t id, const ReleaseEntry& e) = 0;
    virtual std::vector<ReleaseEntry> programStates(std::int64_t id, std::optional<int> number) = 0;
    // The transfer log. insertTransfer returns the entry's id; on
    // PostgreSQL the server records its user (current_user), not t.user.
    virtual std::int64_t insertTransfer(const TransferEntry& t) = 0;
    virtual std::vector<TransferEntry> transfers(const TransferFilter& f) = 0;
};

// A read snapshot for the reads of one call.
class ReadSnapshot {
public:
    explicit ReadSnapshot(Store& s) : s_(s), own_(s.beginRead()) {}
    ~ReadSnapshot() {
        if (own_)
            s_.endRead();
    }
    ReadSnapshot(const ReadSnapshot&) = delete;
    ReadSnapshot& operator=(const ReadSnapshot&) = delete;

private:
    Store& s_;
    bool own_;
};

// A write transaction: committed by commit(), rolled back otherwise.
class WriteTransaction {
public:
    explicit WriteTransaction(Store& s) : s_(s) { s_.beginWrite(); }
    void commit() {
        s_.commit();
        done_ = true;
    }
    ~WriteTransaction() {
        if (!done_)
            s_.rollback();
    }
    WriteTransaction(const WriteTransaction&) = delete;
    WriteTransaction& operator=(const WriteTransaction&) = delete;

private:
    Store& s_;
    bool done_ = false;
};

} // namespace k528::db
