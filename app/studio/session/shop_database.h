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
#include <map>
#include <set>
#include <string>
#include <memory>
#include <mutex>
#include <sys/types.h>
#include <utility>

namespace k528::studio {

class ShopDatabase {
public:
    // The connection to `path` (empty: current(), created with its folder
    // and the built-in machines on the first start). Throws db::Error (and
    // std::exception) when the database cannot be used (the next call tries
    // again) or the file was replaced under the connection.
    static std::shared_ptr<ShopDatabase> at(const std::filesystem::path& path = {});
    // The connection to an SQLite file or a PostgreSQL database (an empty
    // location: current()).
    static std::shared_ptr<ShopDatabase> at(const db::Location& where);
    // The same for a location as the user writes it ("": current()).
    static std::shared_ptr<ShopDatabase> atText(const QString& location);

    // The database the window works on: the one chosen (File > Database…,
    // --db, the one remembered), else db::defaultDatabaseLocation() ($K528_DB,
    // else the user's file), read again at each call until one is chosen.
    static db::Location current();
    static void choose(const db::Location& where);
    // The location as the window shows it (the file, or the URI).
    static QString currentText();

    // Runs fn(db::Database&) holding the connection: callers of every thread
    // take turns (a worker's import makes the others wait for its
    // transaction, as another process's would).
    template <typename F> decltype(auto) use(F&& fn) {
        std::lock_guard lock(mutex_);
        return std::forward<F>(fn)(db_);
    }
    // The same unless another caller holds the connection now (a worker's
    // import): then nothing runs and it returns false (the window's timers
    // try again on their next tick instead of waiting).
    template <typename F> bool tryUse(F&& fn) {
        std::unique_lock lock(mutex_, std::try_to_lock);
        if (!lock.owns_lock())
            return false;
        std::forward<F>(fn)(db_);
        return true;
    }
    // The same with the message history (schema 2) on this connection.
    template <typename F> decltype(auto) useLog(F&& fn) {
        std::lock_guard lock(mutex_);
        if (!log_)
            log_ = std::make_unique<db::MessageLog>(db_);
        return std::forward<F>(fn)(*log_);
    }

    // The SQLite file; for PostgreSQL the URI as a path (for messages).
    const std::filesystem::path& path() const { return path_; }
    const db::Location& location() const { return location_; }
    db::ReadOnlyReason readOnly() const { return readOnly_; }

    // The revisions this process wrote (every writer of the window says
    // so): the live watch tells only the others' (database/database_ui.h),
    // and a change is not refused as based on an old revision because of
    // the window's own newer ones. Any thread.
    void noteOwn(const std::string& machine, int revision);
    bool isOwn(const std::string& machine, int revision) const;
    // Whether every revision of `machine` after `from` up to `to` is this process's.
    bool allOwn(const std::string& machine, int from, int to) const;

    // Whether `file` is a database this process has open, or its -wal,
    // -shm or -journal: such a file must not be opened as a program or
    // written over (closing a descriptor of it would drop the connection's
    // locks; writing would destroy the database). stat() only.
    static bool isOpenDatabaseFile(const std::filesystem::path& file);

    ShopDatabase(const ShopDatabase&) = delete;
    ShopDatabase& operator=(const ShopDatabase&) = delete;
    ~ShopDatabase();

private:
    ShopDatabase(db::Location location, db::Database db);
    // The file at path() is still the one this connection reads.
    bool sameFile() const;

    std::recursive_mutex mutex_;
    db::Location location_;
    std::filesystem::path path_;
    db::Database db_;
    std::unique_ptr<db::MessageLog> log_;
    db::ReadOnlyReason readOnly_;
    mutable std::mutex ownMutex_;
    std::map<std::string, std::set<int>> own_;
    dev_t device_ = 0;
    ino_t inode_ = 0;
};

// The text of a database error for the window, in its language: an error
// of the database's catalog (a read-only file, a role refusal, a rejected
// write, …) by its id (databaseText); any other in English as core says
// it, in Russian a sentence naming the database and what is wrong
// (databaseErrorKindText), with the library's own words quoted
// (databaseErrorDetail).
QString databaseErrorText(const std::exception& e);
// What is wrong with a database, by the kind of its error («она повреждена…»).
QString databaseErrorKindText(db::ErrorKind kind);
// An error's details for the window: English, core's message; else the
// library's own words (db::Error::detail) in «», "" when core said it alone.
QString databaseErrorDetail(const std::exception& e);

} // namespace k528::studio
