// The rows of a database in the SQL both backends speak (internal to
// core/db): SqlStore implements db::Store's rows once over the SQL seam
// (sql.h), and the backends add what differs — opening, checking, locking
// and transactions: SqliteStore (sqlite_store.h), PostgresStore
// (postgres_store.h).
//   sql_rows.cpp     the machines and their current state (profile rows);
//   sql_history.cpp  revisions, recorded changes, program versions;
//   sql_audit.cpp    the audit log, release states of programs, transfers;
//   sql_schema.cpp   the schema's steps and the C-parameter definitions.
#pragma once

#include "db/sql.h"
#include "db/store.h"

#include <functional>

namespace k528::db {

// Fills a new database inside the transaction that creates its schema (the
// built-in machines, or a copy's rows); returns the machines it loaded.
using Fill = std::function<std::vector<std::string>(Store&)>;

class SqlStore : public Store {
public:
    const std::filesystem::path& path() const override { return path_; }
    const OpenReport& openReport() const override { return report_; }
    ReadOnlyReason readOnly() const override { return readOnly_; }

    std::vector<MachineInfo> machines() override;
    std::optional<MachineRow> findMachine(std::string_view name) override;
    profile::MachineProfile loadCurrent(const MachineRow& row) override;
    std::optional<LoadedMachine> loadNamed(std::string_view name) override;
    std::optional<std::vector<ChangeRow>> historyNamed(
        std::string_view name, int limitRevisions, const std::optional<std::string>& key) override;
    std::int64_t insertMachine(const profile::MachineProfile& p, const std::string& at,
                               const std::string& author) override;
    void updateMachine(std::int64_t id, const profile::MachineProfile& p, int revision,
                       const std::string& at, const std::string& author) override;
    void deleteMachine(std::int64_t id) override;
    void writeItem(std::int64_t id, bool isNew, const profile::MachineProfile& p,
                   const profile::Change& c) override;
    void writeSettings(std::int64_t id, const profile::MachineProfile& p) override;

    void insertRevision(std::int64_t id, int revision, const std::string& author,
                        const std::string& at, const std::string& summary,
                        const std::string& settingsOrder) override;
    void insertProgramVersion(std::int64_t id, const ProgramRow& version) override;
    void insertChange(std::int64_t id, int revision, int seq, const std::string& author,
                      const std::string& at, const profile::Change& c) override;
    std::vector<ChangeRow> changesUpTo(std::int64_t id, int revision) override;
    std::optional<std::string> settingsOrder(std::int64_t id, int revision) override;
    std::vector<ProgramRow> programsAt(std::int64_t id, int revision) override;
    std::vector<RevisionInfo> revisions(std::int64_t id) override;
    std::vector<ChangeRow> history(std::int64_t id, int fromRevision,
                                   const std::optional<std::string>& key) override;
    std::vector<ProgramRow> programVersions(std::int64_t id, int number) override;
    std::optional<ProgramRow> programAt(std::int64_t id, int number, int revision) override;

    void insertAudit(const AuditEntry& e) override;
    std::vector<AuditEntry> audit(int limit, std::string_view machine) override;

    void insertProgramState(std::int64_t id, const ReleaseEntry& e) override;
    std::vector<ReleaseEntry> programStates(std::int64_t id, std::optional<int> number) override;
    std::int64_t insertTransfer(const TransferEntry& t) override;
    std::vector<TransferEntry> transfers(const TransferFilter& f) override;

protected:
    sql::Query& query(std::string_view text) { return connection()(text); }
    // The current state from the run queries of the machine's tables (sql_rows.cpp).
    profile::MachineProfile readCurrent(const MachineRow& row,
                                        std::span<sql::Query* const> queries);
    std::string now() const { return formatTimestamp(clock_()); }
    // Whether the recorded changes carry their revision's author and time
    // (schema version 7); an older database read as it is (read-only, or
    // opened with the older migrations) has them in its revisions only.
    bool changesKeepAuthors() const { return report_.version >= 7; }
    // Whether each item's whole history is kept in one row of item_history
    // too (schema version 9).
    bool itemHistoryKept() const { return report_.version >= 9; }
    // The machine's name and the database's path: the first arguments of
    // the catalog's texts about stored rows ("machine %1 in %2: …").
    std::vector<std::string> where(const MachineRow& row) const;
    // Runs the schema's steps above `from` up to the last of `migrations`
    // (inside the caller's transaction); a failing step is Error(Sql)
    // "migration to schema version N failed (…); nothing was changed".
    void migrate(std::span<const Migration> migrations, std::int64_t from);
    // Inside the caller's write transaction, on a database at schema version
    // `found`: the steps above it, the new version (stampSchema), and for a
    // new database its first rows — created_at, the audit entry, the
    // C-parameter definitions, then `fill`. Sets the report's versions.
    void upgrade(std::span<const Migration> migrations, std::int64_t found,
                 const std::string& author, const Fill& fill);
    // Records the schema version (SQLite: application_id and user_version).
    virtual void stampSchema(int version) = 0;
    // Writes the C-parameter definitions when the catalog differs from the
    // stored digest (inside the caller's transaction; audited).
    void syncDefinitions(const std::string& author);
    bool definitionsCurrent();
    // What no backend checks by itself: every program version's text
    // against its SHA-256, every machine's revision against its history.
    // Empty when fine.
    std::vector<IntegrityProblem> checkRows();

    std::filesystem::path path_;
    OpenReport report_;
    Clock clock_;
    ReadOnlyReason readOnly_ = ReadOnlyReason::None;
};

} // namespace k528::db
