// The SQLite backend of db::Database (internal to core/db):
//   sqlite_open.cpp     opening, checks, read-only files, locking (transactions),
//                       WAL, migrations, the C-parameter definitions;
//   sqlite_rows.cpp     the machines and their current state (profile rows);
//   sqlite_history.cpp  revisions, recorded changes, program versions;
//   sqlite_audit.cpp    the audit log and the integrity check.
// docs/database.md says what each does and why.
#pragma once

#include "db/sqlite.h"
#include "db/store.h"

#include <functional>
#include <memory>
#include <sys/types.h>
#include <time.h>

namespace k528::db {

struct Checked; // what open() found (sqlite_open.cpp)

class SqliteStore final : public Store {
public:
    // Fills a new database inside the transaction that creates its schema
    // (the built-in machines); returns what it loaded.
    using Fill = std::function<std::vector<std::string>(Store&)>;

    // Opens (checks, creates or migrates) the database at `path`. Throws
    // Error: Io, Foreign, Corrupt, TooNew, Busy; ReadOnlyError.
    static std::unique_ptr<SqliteStore> open(const std::filesystem::path& path,
                                             const OpenOptions& options, const Fill& fill);
    ~SqliteStore() override;

    const std::filesystem::path& path() const override { return path_; }
    const OpenReport& openReport() const override { return report_; }
    ReadOnlyReason readOnly() const override { return readOnly_; }
    bool snapshotOutdated() const override;
    int schemaVersion() override;
    std::string checkIntegrity() override;
    sqlite3* sqliteConnection() const override { return db_; }

    bool beginRead() override;
    void endRead() noexcept override;
    void beginWrite() override;
    void commit() override;
    void rollback() noexcept override;

    std::vector<MachineInfo> machines() override;
    std::optional<MachineRow> findMachine(std::string_view name) override;
    profile::MachineProfile loadCurrent(const MachineRow& row) override;
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
    void insertChange(std::int64_t id, int revision, int seq, const profile::Change& c) override;
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

private:
    SqliteStore() = default;
    std::string now() const { return formatTimestamp(clock_()); }
    void requireWritable() const;
    // "machine NAME in PATH", for messages about stored rows.
    std::string where(const MachineRow& row) const;

    // The steps of open() (sqlite_open.cpp).
    Checked connectAndInspect(const OpenOptions& options, int latest);
    sqlite3* connect(const std::string& target, int flags, int busyTimeoutMs, bool noCheckpoint,
                     const std::function<std::string()>& untouched) const;
    void connectSnapshot(int busyTimeoutMs, const std::function<std::string()>& untouched);
    void applyConnectionSettings();
    void switchToWal(int busyTimeoutMs);
    void createOrMigrate(const OpenOptions& options, int latest, const std::string& author,
                         const Fill& fill);
    void refreshDefinitions(const std::string& author);
    void syncDefinitions(const std::string& author);

    sqlite3* db_ = nullptr;
    std::filesystem::path path_;
    OpenReport report_;
    Clock clock_;
    ReadOnlyReason readOnly_ = ReadOnlyReason::None;
    bool immutable_ = false; // read as a snapshot (see snapshotOutdated)
    struct timespec snapshotTime_ {};
    off_t snapshotSize_ = 0;
    sql::StatementCache st_;
};

} // namespace k528::db
