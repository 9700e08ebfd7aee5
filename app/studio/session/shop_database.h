// The workstation's one owner of its database connections: one connection
// to each database file for the whole process, opened at its first use and
// kept, shared by every part of the window that reads or writes the shop's
// database — where the machines come from and *Keep in the database*
// (machine_source), the constants and R-parameter docks (machine_store), the
// editor's database programs, the controller dock's pull, the message
// history (recording, the dock, its CSV export) — and by their worker
// threads, one caller at a time.
//
//   ShopDatabase::at()->use([&](db::Database& d) { return d.loadMachine(name); });
//   shop->useLog([&](db::MessageLog& log) { log.write(run, events); });
//
// Why one: each open checks the whole file (integrity_check), and a process
// that opens and closes connections beside one it keeps invites the lock
// pitfall of docs/database.md (Connections and locks). A read-only
// snapshot is opened again when the file changed. A file replaced or removed
// under the connection (another inode at the path) is refused until the
// program starts again: a second connection would take the old file's
// -wal and -shm for the new file's.
#pragma once

#include "db/database.h"
#include "db/message_log.h"

#include <QString>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <sys/types.h>
#include <utility>

namespace k528::studio {

class ShopDatabase {
public:
    // The connection to `path` (empty: db::defaultDatabasePath(), created
    // with its folder and the built-in machines on the first start). Throws
    // db::Error (and std::exception) when the database cannot be used (the
    // next call tries again) or the file was replaced under the connection.
    static std::shared_ptr<ShopDatabase> at(const std::filesystem::path& path = {});

    // Runs fn(db::Database&) holding the connection: callers of every thread
    // take turns (a worker's import makes the others wait for its
    // transaction, as another process's would).
    template <typename F> decltype(auto) use(F&& fn) {
        std::lock_guard lock(mutex_);
        return std::forward<F>(fn)(db_);
    }
    // The same with the message history (schema 2) on this connection.
    template <typename F> decltype(auto) useLog(F&& fn) {
        std::lock_guard lock(mutex_);
        if (!log_)
            log_ = std::make_unique<db::MessageLog>(db_);
        return std::forward<F>(fn)(*log_);
    }

    const std::filesystem::path& path() const { return path_; }
    db::ReadOnlyReason readOnly() const { return readOnly_; }

    // Whether `file` is a database this process has open, or its -wal,
    // -shm or -journal: such a file must not be opened as a program or
    // written over (closing a descriptor of it would drop the connection's
    // locks; writing would destroy the database). stat() only.
    static bool isOpenDatabaseFile(const std::filesystem::path& file);

    ShopDatabase(const ShopDatabase&) = delete;
    ShopDatabase& operator=(const ShopDatabase&) = delete;
    ~ShopDatabase();

private:
    ShopDatabase(std::filesystem::path path, db::Database db);
    // The file at path() is still the one this connection reads.
    bool sameFile() const;

    std::recursive_mutex mutex_;
    std::filesystem::path path_;
    db::Database db_;
    std::unique_ptr<db::MessageLog> log_;
    db::ReadOnlyReason readOnly_;
    dev_t device_ = 0;
    ino_t inode_ = 0;
};

// The text of a database error for the window: a read-only database in the
// window's language («База данных доступна только для чтения: …»), anything
// else as core says it.
QString databaseErrorText(const std::exception& e);

} // namespace k528::studio
