// The SQLite backend of db::Database (internal to core/db): opening,
// checks, read-only files, locking (transactions), WAL, migrations and the
// whole-file integrity check (sqlite_open.cpp); the rows are SqlStore's
// (sql_store.h). docs/database.md says what each does and why.
#pragma once

#include "db/sql_store.h"
#include "db/sqlite.h"

#include <functional>
#include <memory>
#include <sys/types.h>
#include <time.h>

namespace k528::db {

struct Checked; // what open() found (sqlite_open.cpp)

class SqliteStore final : public SqlStore {
public:
    // Opens (checks, creates or migrates) the database at `path`. Throws
    // Error: Io, Foreign, Corrupt, TooNew, Busy; ReadOnlyError.
    static std::unique_ptr<SqliteStore> open(const std::filesystem::path& path,
                                             const OpenOptions& options, const Fill& fill);
    ~SqliteStore() override;

    bool snapshotOutdated() const override;
    int schemaVersion() override;
    std::vector<IntegrityProblem> checkIntegrity() override;
    Backend backend() const override { return Backend::Sqlite; }
    sql::Connection& connection() override { return conn_; }
    bool changedElsewhere(std::vector<std::string>& machines) override;

    bool beginRead() override;
    void endRead() noexcept override;
    void beginWrite() override;
    void commit() override;
    void rollback() noexcept override;

private:
    SqliteStore() = default;
    void requireWritable() const;

    // The steps of open() (sqlite_open.cpp).
    Checked connectAndInspect(const OpenOptions& options, int latest);
    sqlite3* connect(const std::string& target, int flags, int busyTimeoutMs, bool noCheckpoint,
                     const std::function<void(ErrorText&)>& untouched) const;
    void connectSnapshot(int busyTimeoutMs, const std::function<void(ErrorText&)>& untouched);
    void applyConnectionSettings();
    void switchToWal(int busyTimeoutMs);
    void createOrMigrate(const OpenOptions& options, int latest, const std::string& author,
                         const Fill& fill);
    void refreshDefinitions(const std::string& author);
    void stampSchema(int version) override;

    sqlite3* db_ = nullptr;
    sql::SqliteConnection conn_;
    bool immutable_ = false; // read as a snapshot (see snapshotOutdated)
    struct timespec snapshotTime_ {};
    off_t snapshotSize_ = 0;
    std::int64_t dataVersion_ = -1; // PRAGMA data_version seen last (changedElsewhere)
};

} // namespace k528::db
