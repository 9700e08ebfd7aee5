// The PostgreSQL backend of db::Database (internal to core/db): connecting,
// the checks before anything is written (another program's tables, a newer
// schema), creating and migrating the schema, transactions (a write holds
// the database's advisory lock: one writer at a time, as on SQLite), the
// notices of other sessions' revisions (LISTEN/NOTIFY), roles. The rows are
// SqlStore's (sql_store.h). docs/database.md: PostgreSQL.
#pragma once

#include "db/postgres.h"
#include "db/sql_store.h"

#include <memory>

namespace k528::db {

class PostgresStore final : public SqlStore {
public:
    static std::unique_ptr<PostgresStore> open(const Location& where, const OpenOptions& options,
                                               const Fill& fill);

    bool snapshotOutdated() const override { return false; }
    int schemaVersion() override;
    std::vector<IntegrityProblem> checkIntegrity() override;
    Backend backend() const override { return Backend::Postgres; }
    sql::Connection& connection() override { return *conn_; }
    std::string sessionUser() override { return user_; }
    void notifyChange(std::string_view machine, int revision) override;
    bool changedElsewhere(std::vector<std::string>& machines) override;
    void afterCopy() override;
    bool mayActAs(std::string_view role) override;

    bool beginRead() override;
    void endRead() noexcept override;
    void beginWrite() override;
    void commit() override;
    void rollback() noexcept override;

    std::string rolesOfUser() override;
    std::vector<RoleInfo> roles(bool setUp) override;
    void grantRole(const std::string& user, const std::string& role) override;

private:
    PostgresStore() = default;
    void stampSchema(int version) override;
    // VACUUM (ANALYZE) of the recorded changes after an upgrade; a failure
    // is left to autovacuum.
    void vacuumChanges();
    void reconnect();
    void listen();

    std::unique_ptr<sql::PgConnection> conn_;
    std::string uri_;
    std::string user_;
    int busyTimeoutMs_ = 10000;
    bool watching_ = false;
};

// The channel of the revisions' notices.
inline constexpr std::string_view kRevisionChannel = "k528_revisions";

} // namespace k528::db
