// Opening and locking of the SQLite backend: the checks before anything is
// written (the header through SQLite's own file handle, hot journals, damage,
// foreign and newer files), read-only files, the connection's settings, WAL,
// migrations and the C-parameter definitions; transactions; a snapshot's
// freshness. docs/database.md: Opening, Connections and locks, Read-only files.
#include "db/sqlite_store.h"

#include "db/db_texts.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sqlite3.h>
#include <sys/stat.h>
#include <optional>
#include <thread>
#include <unistd.h>

namespace k528::db {

namespace fs = std::filesystem;
namespace cat = k528::catalog;

// What open() found: application_id, user_version, schema objects.
struct Checked {
    std::int64_t appId = 0, version = 0, objects = 0;
};

namespace {

struct FileHeader {
    bool empty = false;
    std::uint32_t applicationId = 0;
    std::uint32_t userVersion = 0;
};

std::uint32_t be32(const unsigned char* p) {
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) |
           std::uint32_t(p[3]);
}

std::string hex32(std::uint32_t v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%08X", v);
    return buf;
}

// Why open() refuses a file (the caller adds the path and what became of it).
struct Refusal {
    ErrorKind kind;
    std::string what;
    bool hotJournal = false; // a read-only connection met a hot journal it cannot roll back
    bool noIndex = false;    // SQLite could not create the -wal/-shm it needs to read
    std::string detail = {}; // SQLite's own words (Error::detail)
    ErrorText text = {};     // what `what` says, when the catalog says it
};

// A refusal the catalog says (`what` its English); `detail`: SQLite's words.
Refusal refusal(ErrorKind kind, ErrorText text, std::string detail = {}) {
    std::string what = renderText(text, false);
    return Refusal{kind, std::move(what), false, false, std::move(detail), std::move(text)};
}

// SQLite's own words of an error (its detail), else its message.
std::string saidBy(const Error& e) {
    return e.detail().empty() ? std::string(e.what()) : e.detail();
}

// Whether something is at `path`, from stat() alone: the file is never opened
// here (see readHeader). Throws Io for a folder or anything but a regular file.
bool databaseFileExists(const fs::path& path) {
    std::error_code ec;
    const auto st = fs::status(path, ec);
    if (ec || !fs::exists(st)) {
        if (ec && ec != std::errc::no_such_file_or_directory)
            throw Error(ErrorKind::Io, path.string() + ": " + ec.message(), ec.message(), path.string());
        return false;
    }
    if (fs::is_directory(st))
        throw Error(ErrorKind::Io, ErrorText{"open.directory", {path.string()}});
    if (!fs::is_regular_file(st))
        throw Error(ErrorKind::Io,
                    ErrorText{std::string("open.not-regular.") +
                                  (fs::is_character_file(st) ? "character-device"
                                   : fs::is_block_file(st)   ? "block-device"
                                   : fs::is_fifo(st)         ? "fifo"
                                   : fs::is_socket(st)       ? "socket"
                                                             : "other"),
                              {path.string()}});
    return true;
}

// The file's first 100 bytes, read through the connection's own file handle
// before any SQL runs: what is certainly not ours is refused without SQLite
// interpreting it (no journal rollback, no WAL recovery, nothing written).
// Never through a descriptor of our own (an ifstream): closing it would drop
// every POSIX lock this process holds on the file — those of its other
// connections too — and another process could then take itself for the last
// user and delete the -wal under them (SQLite's "How To Corrupt", 2.2).
// SQLite's unix VFS keeps its descriptors per file and process and closes
// none while a lock is held.
FileHeader readHeader(sqlite3* db, int latest) {
    sqlite3_file* f = nullptr;
    if (sqlite3_file_control(db, "main", SQLITE_FCNTL_FILE_POINTER, &f) != SQLITE_OK || !f ||
        !f->pMethods)
        throw refusal(ErrorKind::Io, ErrorText{"open.no-handle"});
    sqlite3_int64 size = 0;
    if (const int rc = f->pMethods->xFileSize(f, &size); rc != SQLITE_OK)
        throw refusal(ErrorKind::Io, ErrorText{"open.unreadable", {sqlite3_errstr(rc)}}, sqlite3_errstr(rc));
    FileHeader h;
    if (size == 0) {
        h.empty = true;
        return h;
    }
    unsigned char buf[100] = {};
    const int got = static_cast<int>(std::min<sqlite3_int64>(size, sizeof buf));
    if (const int rc = f->pMethods->xRead(f, buf, got, 0); rc != SQLITE_OK)
        throw refusal(ErrorKind::Io, ErrorText{"open.unreadable", {sqlite3_errstr(rc)}}, sqlite3_errstr(rc));
    static constexpr char kMagic[] = "SQLite format 3";
    if (got < 100 || std::memcmp(buf, kMagic, sizeof kMagic) != 0)
        throw refusal(ErrorKind::Foreign, got < 100 ? ErrorText{"open.foreign-short", {std::to_string(got)}}
                                                    : ErrorText{"open.foreign-header", {}});
    h.userVersion = be32(buf + 60);
    h.applicationId = be32(buf + 68);
    if (h.applicationId != 0 && h.applicationId != static_cast<std::uint32_t>(kApplicationId))
        throw refusal(ErrorKind::Foreign,
                      ErrorText{"open.foreign-program",
                                {hex32(h.applicationId), hex32(static_cast<std::uint32_t>(kApplicationId))}});
    if (h.applicationId == static_cast<std::uint32_t>(kApplicationId) &&
        h.userVersion > static_cast<std::uint32_t>(latest))
        throw refusal(ErrorKind::TooNew,
                      ErrorText{"open.too-new", {std::to_string(h.userVersion), std::to_string(latest)}});
    return h;
}

// The size in pages the database had when the transaction of a rollback
// journal began (its header, bytes 16..19); nullopt when the file is not a
// journal SQLite would play back. Read with a descriptor of our own: SQLite
// keeps no lock on a -journal (a rollback journal's locks are all on the
// database file), so closing it drops none.
std::optional<std::uint32_t> journalStartPages(const fs::path& journal) {
    const int fd = ::open(journal.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return std::nullopt;
    unsigned char buf[28] = {};
    const ssize_t n = ::pread(fd, buf, sizeof buf, 0);
    ::close(fd);
    static constexpr unsigned char kJournalMagic[8] = {0xd9, 0xd5, 0x05, 0xf9,
                                                       0x20, 0xa1, 0x63, 0xd7};
    if (n != static_cast<ssize_t>(sizeof buf) || std::memcmp(buf, kJournalMagic, 8) != 0)
        return std::nullopt;
    return be32(buf + 16);
}

// Why this process cannot write `path` (access(2) with the effective ids:
// no open).
ReadOnlyReason whyReadOnly(const fs::path& path) {
    const auto denied = [](const fs::path& p) -> std::optional<ReadOnlyReason> {
        if (::faccessat(AT_FDCWD, p.c_str(), W_OK, AT_EACCESS) == 0)
            return std::nullopt;
        return errno == EROFS ? ReadOnlyReason::FileSystem : ReadOnlyReason::Permission;
    };
    if (const auto r = denied(path))
        return *r;
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    if (const auto r = denied(folder))
        return *r == ReadOnlyReason::Permission ? ReadOnlyReason::Folder : *r;
    return ReadOnlyReason::Permission; // SQLite refused, for a reason stat() cannot see
}

// "file:/a%20b/k528.db?mode=ro&immutable=1"
std::string immutableUri(const fs::path& path) {
    std::string uri = "file:";
    for (const char ch : fs::absolute(path).string()) {
        if (ch == '%' || ch == '?' || ch == '#' || ch == ' ') {
            char buf[4];
            std::snprintf(buf, sizeof buf, "%%%02X", static_cast<unsigned char>(ch));
            uri += buf;
        } else {
            uri += ch;
        }
    }
    return uri + "?mode=ro&immutable=1";
}

// The checks of open(), on a connection with nothing set yet: what the file
// is (application_id, user_version, schema objects) and, when it is ours,
// PRAGMA integrity_check and foreign_key_check. They only read. Every failure
// is a Refusal.
Checked inspect(sqlite3* db, int latest) {
    Checked c;
    try {
        // One statement, one snapshot: read one by one, another process's
        // creation committed between them showed "application_id 0 with 33
        // schema objects" — a database being created taken for another
        // program's.
        sql::Stmt what(db, "SELECT (SELECT application_id FROM pragma_application_id), "
                           "(SELECT user_version FROM pragma_user_version), "
                           "(SELECT count(*) FROM sqlite_schema)");
        // Scalar subqueries without FROM: one row whatever the file holds
        // (a file SQLite cannot read fails in step() with its own words).
        if (!what.step())
            throw sql::internalError("the header's query returned no row");
        c.appId = what.i64(0);
        c.version = what.i64(1);
        c.objects = what.i64(2);
    } catch (const Error& e) {
        const int code = sqlite3_extended_errcode(db);
        if (code == SQLITE_READONLY_ROLLBACK) {
            Refusal r = refusal(ErrorKind::Io, ErrorText{"open.unreadable", {saidBy(e)}}, e.detail());
            r.hotJournal = true;
            throw r;
        }
        if (code == SQLITE_READONLY_DIRECTORY || code == SQLITE_READONLY_CANTINIT ||
            code == SQLITE_READONLY_CANTLOCK || (code & 0xff) == SQLITE_CANTOPEN) {
            Refusal r = refusal(ErrorKind::ReadOnly, ErrorText{"open.unreadable", {saidBy(e)}}, e.detail());
            r.noIndex = true;
            throw r;
        }
        if (e.kind() == ErrorKind::Busy)
            throw refusal(ErrorKind::Busy, ErrorText{"open.busy", {saidBy(e)}}, e.detail());
        throw refusal(ErrorKind::Corrupt, ErrorText{"open.not-database", {saidBy(e)}}, e.detail());
    }
    if (c.appId == 0 && c.version == 0 && c.objects == 0)
        return c; // empty: ours to fill
    if (c.appId != kApplicationId)
        throw refusal(ErrorKind::Foreign,
                      ErrorText{"open.foreign-objects",
                                {hex32(static_cast<std::uint32_t>(c.appId)), std::to_string(c.objects)}});
    if (c.version > latest)
        throw refusal(ErrorKind::TooNew,
                      ErrorText{"open.too-new", {std::to_string(c.version), std::to_string(latest)}});
    if (c.version < 1)
        throw refusal(ErrorKind::Corrupt, ErrorText{"open.no-version"});
    std::string problems; // SQLite's words
    std::optional<ErrorText> keys; // rows that break foreign keys
    try {
        // Every table with its indexes, except the message history (schema
        // 2): a log that grows without bound would make every open as slow
        // as its size. Its pages are checked by checkIntegrity() (`k528 db
        // check`), and damage met while reading or writing it is an
        // Error(Corrupt) then; the machines are checked here, always.
        std::vector<std::string> tables;
        {
            sql::Stmt t(db, "SELECT name FROM sqlite_schema WHERE type = 'table' AND name NOT IN "
                            "('message_history', 'sqlite_sequence') ORDER BY name");
            while (t.step())
                tables.push_back(t.text(0));
        }
        for (const std::string& table : tables) {
            sql::Stmt ic(db, "PRAGMA integrity_check(\"" + table + "\")");
            while (ic.step())
                if (const std::string line = ic.text(0); line != "ok")
                    problems += (problems.empty() ? "" : "; ") + line;
        }
        int fkRows = 0;
        std::string fkTable, fkParent;
        std::int64_t fkRow = 0;
        for (const std::string& table : tables) {
            sql::Stmt fk(db, "PRAGMA foreign_key_check(\"" + table + "\")");
            while (fk.step())
                if (fkRows++ == 0) {
                    fkTable = fk.text(0);
                    fkRow = fk.i64(1);
                    fkParent = fk.text(2);
                }
        }
        if (fkRows)
            keys = ErrorText{"open.damaged-keys", {std::to_string(fkRows), fkTable, std::to_string(fkRow), fkParent}};
    } catch (const Error& e) {
        if (e.kind() == ErrorKind::Busy)
            throw refusal(ErrorKind::Busy, ErrorText{"open.busy", {saidBy(e)}}, e.detail());
        problems = saidBy(e);
    }
    if (!problems.empty())
        throw refusal(ErrorKind::Corrupt, ErrorText{"open.damaged", {problems}}, problems);
    if (keys)
        throw refusal(ErrorKind::Corrupt, *keys);
    return c;
}

} // namespace

std::unique_ptr<SqliteStore> SqliteStore::open(const fs::path& path, const OpenOptions& options,
                                               const Fill& fill) {
    const auto& migrations = options.migrations;
    if (migrations.empty())
        throw sql::internalError("no schema migrations given");
    const int latest = migrations.back().version;
    const bool exists = databaseFileExists(path);
    if (!exists && (!options.create || options.readOnly))
        throw Error(ErrorKind::Io, ErrorText{"open.no-database", {path.string()}});
    if (!exists) {
        std::error_code ec;
        const fs::path parent = path.parent_path();
        if (!parent.empty() && !fs::is_directory(parent, ec))
            throw Error(ErrorKind::Io, ErrorText{"open.no-folder", {path.string(), parent.string()}});
        if (::faccessat(AT_FDCWD, parent.empty() ? "." : parent.c_str(), W_OK, AT_EACCESS) != 0)
            throw ReadOnlyError(path,
                                errno == EROFS ? ReadOnlyReason::FileSystem : ReadOnlyReason::Folder,
                                ReadOnlyRefusal::Create);
    }
    std::unique_ptr<SqliteStore> s(new SqliteStore);
    s->path_ = path;
    s->clock_ = options.clock ? options.clock : systemClock();
    const std::string author = options.author.empty() ? defaultAuthor() : options.author;

    const auto [appId, version, objects] = s->connectAndInspect(options, latest);
    const bool empty = appId == 0 && version == 0 && objects == 0;
    if (options.requireEmpty && !empty)
        throw Error(ErrorKind::Invalid, ErrorText{"open.not-empty", {path.string(), std::to_string(version)}});
    s->applyConnectionSettings();
    s->report_.created = empty;
    s->report_.fromVersion = static_cast<int>(version);
    if (s->readOnly_ != ReadOnlyReason::None) {
        // Reading writes nothing: no journal mode, no migration, no
        // definitions. An older schema is read as it is (its tables are a
        // subset of ours; MessageLog needs schema 2).
        if (empty)
            throw ReadOnlyError(path, s->readOnly_, ReadOnlyRefusal::Create);
        s->report_.version = static_cast<int>(version);
        return s;
    }
    // Now ours, intact, not newer: WAL, then create or migrate in one transaction.
    s->switchToWal(options.busyTimeoutMs);
    if (empty || version < latest)
        s->createOrMigrate(options, latest, author, fill);
    s->report_.version = latest;
    s->refreshDefinitions(author);
    return s;
}

SqliteStore::~SqliteStore() {
    conn_.reset(nullptr);
    if (db_)
        sqlite3_close_v2(db_);
}

void SqliteStore::requireWritable() const {
    if (readOnly_ != ReadOnlyReason::None)
        throw ReadOnlyError(path_, readOnly_);
}

bool SqliteStore::snapshotOutdated() const {
    if (!immutable_)
        return false;
    std::error_code ec;
    if (fs::exists(path_.string() + "-wal", ec))
        return true;
    struct stat st {};
    if (::stat(path_.c_str(), &st) != 0)
        return true;
    return st.st_size != snapshotSize_ || st.st_mtim.tv_sec != snapshotTime_.tv_sec ||
           st.st_mtim.tv_nsec != snapshotTime_.tv_nsec;
}

int SqliteStore::schemaVersion() {
    return static_cast<int>(sql::queryInt(db_, "PRAGMA user_version"));
}

// Transactions. A read snapshot: the SELECTs of one call see one state of the
// file. A write: BEGIN IMMEDIATE takes the write lock at once (waiting up to
// the busy timeout), so two writers never deadlock.

bool SqliteStore::beginRead() {
    if (!sqlite3_get_autocommit(db_))
        return false;
    sql::exec(db_, "BEGIN");
    return true;
}

void SqliteStore::endRead() noexcept {
    sql::resetBusyStatements(db_);
    sqlite3_exec(db_, "COMMIT", nullptr, nullptr, nullptr);
}

void SqliteStore::beginWrite() {
    requireWritable();
    try {
        sql::exec(db_, "BEGIN IMMEDIATE");
    } catch (const Error& e) {
        if (e.kind() == ErrorKind::ReadOnly)
            throw ReadOnlyError(path_, whyReadOnly(path_));
        if (e.kind() != ErrorKind::Busy)
            throw;
        throw Error(ErrorKind::Busy, ErrorText{"busy.write", {path_.string()}});
    }
}

void SqliteStore::commit() {
    sql::resetBusyStatements(db_);
    sql::exec(db_, "COMMIT");
}

void SqliteStore::rollback() noexcept {
    sql::resetBusyStatements(db_);
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
}

sqlite3* SqliteStore::connect(const std::string& target, int flags, int busyTimeoutMs,
                                 bool noCheckpoint,
                                 const std::function<void(ErrorText&)>& untouched) const {
    sqlite3* c = nullptr;
    const int rc = sqlite3_open_v2(target.c_str(), &c,
                                   flags | SQLITE_OPEN_NOMUTEX | SQLITE_OPEN_EXRESCODE, nullptr);
    if (rc != SQLITE_OK) {
        const std::string msg = c ? sqlite3_errmsg(c) : sqlite3_errstr(rc);
        sqlite3_close_v2(c);
        ErrorText text{"open.cannot", {msg}};
        text.at = path_.string();
        untouched(text);
        throw Error(ErrorKind::Io, std::move(text), msg);
    }
    sqlite3_extended_result_codes(c, 1);
    sqlite3_busy_timeout(c, busyTimeoutMs);
    if (noCheckpoint)
        sqlite3_db_config(c, SQLITE_DBCONFIG_NO_CKPT_ON_CLOSE, 1, nullptr);
    return c;
}

void SqliteStore::connectSnapshot(int busyTimeoutMs,
                                     const std::function<void(ErrorText&)>& untouched) {
    // Without a -wal every commit is in the file; immutable=1 reads it with
    // no -shm index and no lock (a reader cannot create them here, and must
    // not leave files of its own beside the file for the writers). A writer
    // that starts meanwhile writes into a new -wal: snapshotOutdated() says so.
    struct stat st {};
    if (::stat(path_.c_str(), &st) == 0) {
        snapshotTime_ = st.st_mtim;
        snapshotSize_ = st.st_size;
    }
    sqlite3_close_v2(db_);
    db_ = nullptr;
    db_ = connect(immutableUri(path_), SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, busyTimeoutMs, false,
                 untouched);
    immutable_ = true;
}

Checked SqliteStore::connectAndInspect(const OpenOptions& options, int latest) {
    std::error_code ec;
    const fs::path wal = path_.string() + "-wal";
    const bool walExisted = fs::exists(wal, ec);
    const fs::path journal = path_.string() + "-journal";
    const bool journalExisted = fs::exists(journal, ec) && fs::file_size(journal, ec) > 0 && !ec;
    const bool existed = fs::exists(path_, ec);

    // The checks come before any setting or write. On a refusal the file is
    // closed without a checkpoint (a -wal stays as it was, not copied into
    // the refused file) and nothing else was written.
    bool recovered = false;
    const std::function<void(ErrorText&)> untouched = [&](ErrorText& text) {
        if (!existed)
            return;
        text.tail = recovered ? "open.recovered" : "open.untouched";
        if (recovered)
            text.tailArgs = {journal.string()};
    };
    const auto refused = [&](const Refusal& r) {
        ErrorText text = r.text;
        text.at = path_.string();
        untouched(text);
        if (text.id.empty()) // said in Russian by its kind, the path and SQLite's words
            return Error(r.kind, path_.string() + ": " + r.what + dbText(text.tail, text.tailArgs, false), r.detail,
                         std::move(text));
        return Error(r.kind, std::move(text), r.detail);
    };
    // One connection: read-write when the file may be written (SQLite falls
    // back to read-only when it may not), read-only when asked.
    const int flags = options.readOnly ? SQLITE_OPEN_READONLY
                                       : SQLITE_OPEN_READWRITE |
                                             (options.create ? SQLITE_OPEN_CREATE : 0);
    db_ = connect(path_.string(), flags, options.busyTimeoutMs, walExisted, untouched);
    if (sqlite3_db_readonly(db_, "main") == 1)
        readOnly_ = options.readOnly ? ReadOnlyReason::Requested : whyReadOnly(path_);
    // A journal begun on an empty file (a first transaction that died) may
    // have left pages of the file without its first one: the header is not
    // there to read; rolling the journal back below gives the empty file.
    const std::int64_t startPages =
        journalExisted ? journalStartPages(journal).value_or(-1) : std::int64_t(-1);
    const bool newFileJournal = startPages == 0;
    FileHeader header;
    try {
        header = readHeader(db_, latest);
    } catch (const Refusal& r) {
        if (!newFileJournal || r.kind != ErrorKind::Foreign)
            throw refused(r);
    }

    std::optional<Checked> checked;
    if (journalExisted) {
        // A rollback journal: if it is hot (its writer died), a read-write
        // connection would roll it back at the first read. A read-only one
        // cannot: the checks run there, and another program's unfinished
        // transaction stays where it is.
        std::unique_ptr<sqlite3, int (*)(sqlite3*)> ro(
            connect(path_.string(), SQLITE_OPEN_READONLY, options.busyTimeoutMs, walExisted,
                    untouched),
            sqlite3_close_v2);
        try {
            checked = inspect(ro.get(), latest);
        } catch (const Refusal& r) {
            if (!r.hotJournal)
                throw refused(r);
            // Ours to roll back: a file with our application_id (not newer,
            // see readHeader), or one that was empty when the transaction
            // began — rolling back gives the empty file again, and nothing
            // committed is lost (an interrupted `k528 db init`).
            if (header.applicationId != static_cast<std::uint32_t>(kApplicationId) &&
                !newFileJournal)
                throw refused(refusal(ErrorKind::Foreign,
                                      startPages >= 0 ? ErrorText{"open.foreign-journal",
                                                                  {journal.string(), std::to_string(startPages)}}
                                                      : ErrorText{"open.foreign-journal.size", {journal.string()}}));
            if (readOnly_ != ReadOnlyReason::None)
                throw ReadOnlyError(path_, readOnly_, ReadOnlyRefusal::Recover);
            recovered = true;
        }
    }
    // A reader must not create a -wal and -shm of its own beside the file:
    // without a -wal, it reads an immutable snapshot.
    if (readOnly_ != ReadOnlyReason::None && !header.empty && !fs::exists(wal, ec)) {
        connectSnapshot(options.busyTimeoutMs, untouched);
        checked.reset();
    }
    if (!checked) {
        try {
            checked = inspect(db_, latest);
        } catch (const Refusal& r) {
            // A file we may write in a folder we may not: SQLite cannot
            // create the -wal/-shm it needs to read a WAL database.
            if (!r.noIndex || immutable_ || fs::exists(wal, ec))
                throw refused(r);
            readOnly_ = whyReadOnly(path_);
            connectSnapshot(options.busyTimeoutMs, untouched);
            try {
                checked = inspect(db_, latest);
            } catch (const Refusal& again) {
                throw refused(again);
            }
        }
    }
    if (walExisted && !immutable_)
        sqlite3_db_config(db_, SQLITE_DBCONFIG_NO_CKPT_ON_CLOSE, 0, nullptr);
    report_.recovered = recovered;
    conn_.reset(db_);
    return *checked;
}

void SqliteStore::applyConnectionSettings() {
    // Settings, now that the file is ours, intact and not newer.
    try {
        // Every commit reaches the disk before it is reported (independent
        // of how SQLite was compiled).
        sql::exec(db_, "PRAGMA synchronous = FULL");
        sql::exec(db_, "PRAGMA foreign_keys = ON");
    } catch (const Error& e) {
        throw Error(e.kind(), path_.string() + ": " + e.what(), e.detail(), path_.string());
    }
}

void SqliteStore::switchToWal(int busyTimeoutMs) {
    // Switching to WAL needs the file to itself for a moment; SQLite does
    // not wait for that with the busy handler, so retry until the busy
    // timeout (another process starting at the same time switches it too).
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::milliseconds(busyTimeoutMs);
    std::string mode;
    for (int attempt = 0;; ++attempt) {
        try {
            {
                sql::Stmt jm(db_, "PRAGMA journal_mode");
                mode = jm.step() ? jm.text(0) : "";
            }
            if (mode == "wal")
                return;
            sql::Stmt set(db_, "PRAGMA journal_mode = WAL");
            mode = set.step() ? set.text(0) : "";
            if (mode == "wal")
                return;
        } catch (const Error& e) {
            if (e.kind() != ErrorKind::Busy)
                throw;
        }
        if (std::chrono::steady_clock::now() > deadline) {
            ErrorText text{"open.wal", {mode}};
            text.at = path_.string();
            throw Error(ErrorKind::Busy, std::move(text));
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(attempt < 10 ? 2 : 20));
    }
}

void SqliteStore::createOrMigrate(const OpenOptions& options, int /*latest*/,
                                  const std::string& author, const Fill& fill) {
    WriteTransaction tx(*this);
    // Another process may have created or migrated it meanwhile.
    const std::int64_t found = sql::queryInt(db_, "PRAGMA user_version");
    const std::int64_t nowObjects = sql::queryInt(db_, "SELECT count(*) FROM sqlite_schema");
    if (found == 0 && nowObjects != 0) {
        ErrorText text{"open.foreign-writer"};
        text.at = path_.string();
        throw Error(ErrorKind::Foreign, std::move(text));
    }
    upgrade(options.migrations, found, author, fill);
    tx.commit();
}

void SqliteStore::stampSchema(int version) {
    sql::exec(db_, "PRAGMA application_id = " + std::to_string(kApplicationId));
    sql::exec(db_, "PRAGMA user_version = " + std::to_string(version));
}

void SqliteStore::refreshDefinitions(const std::string& author) {
    if (!definitionsCurrent()) {
        WriteTransaction tx(*this);
        syncDefinitions(author);
        tx.commit();
    }
}

std::vector<IntegrityProblem> SqliteStore::checkIntegrity() {
    using K = IntegrityProblem::Kind;
    std::vector<IntegrityProblem> problems;
    sql::Stmt ic(db_, "PRAGMA integrity_check");
    while (ic.step())
        if (const std::string line = ic.text(0); line != "ok")
            problems.push_back({K::Pages, {line}});
    try {
        sql::Stmt fk(db_, "PRAGMA foreign_key_check");
        while (fk.step())
            problems.push_back({K::ForeignKey, {fk.text(0), std::to_string(fk.i64(1))}});
    } catch (const Error& e) {
        // Damage the integrity check listed can stop the key check: say
        // SQLite's words of it.
        if (e.kind() == ErrorKind::Busy)
            throw;
        problems.push_back({K::Pages, {e.detail().empty() ? std::string(e.what()) : e.detail()}});
    }
    // Rows read from damaged pages would add findings of the damage itself.
    if (problems.empty())
        problems = checkRows();
    return problems;
}

bool SqliteStore::changedElsewhere(std::vector<std::string>& /*machines*/) {
    // PRAGMA data_version moves when another connection committed (our own
    // commits leave it as it is).
    const std::int64_t v = sql::queryInt(db_, "PRAGMA data_version");
    const bool changed = dataVersion_ >= 0 && v != dataVersion_;
    dataVersion_ = v;
    return changed;
}

} // namespace k528::db
