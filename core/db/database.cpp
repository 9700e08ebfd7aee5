#include "db/database.h"

#include "catalog/cparams.h"
#include "catalog/messages.h"
#include "db/sha256.h"
#include "db/sqlite.h"
#include "profile/builtin.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <pwd.h>
#include <set>
#include <sqlite3.h>
#include <sstream>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

namespace k528::db {

namespace fs = std::filesystem;
namespace cat = k528::catalog;
using profile::Change;
using profile::DiffSection;
using profile::MachineProfile;

// ---------------------------------------------------------------------------
// Small helpers

Clock systemClock() {
    return [] {
        return static_cast<std::int64_t>(std::chrono::duration_cast<std::chrono::seconds>(
                                             std::chrono::system_clock::now().time_since_epoch())
                                             .count());
    };
}

std::string formatTimestamp(std::int64_t t) {
    // Days since the epoch -> civil date (H. Hinnant's algorithm).
    std::int64_t days = t >= 0 ? t / 86400 : -((-t + 86399) / 86400);
    std::int64_t secs = t - days * 86400;
    days += 719468;
    const std::int64_t era = (days >= 0 ? days : days - 146096) / 146097;
    const std::int64_t doe = days - era * 146097;
    const std::int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    std::int64_t y = yoe + era * 400;
    const std::int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const std::int64_t mp = (5 * doy + 2) / 153;
    const std::int64_t d = doy - (153 * mp + 2) / 5 + 1;
    const std::int64_t m = mp < 10 ? mp + 3 : mp - 9;
    if (m <= 2)
        ++y;
    char buf[128];
    std::snprintf(buf, sizeof buf, "%04lld-%02lld-%02lldT%02lld:%02lld:%02lldZ",
                  static_cast<long long>(y), static_cast<long long>(m), static_cast<long long>(d),
                  static_cast<long long>(secs / 3600), static_cast<long long>(secs / 60 % 60),
                  static_cast<long long>(secs % 60));
    return buf;
}

std::string defaultAuthor() {
    for (const char* var : {"USER", "LOGNAME"})
        if (const char* v = std::getenv(var); v && *v)
            return v;
    struct passwd pw {};
    struct passwd* result = nullptr;
    char buf[4096];
    if (getpwuid_r(geteuid(), &pw, buf, sizeof buf, &result) == 0 && result && pw.pw_name)
        return pw.pw_name;
    return "unknown";
}

std::string_view errorKindName(ErrorKind k) {
    switch (k) {
    case ErrorKind::Io:
        return "io";
    case ErrorKind::Foreign:
        return "foreign";
    case ErrorKind::Corrupt:
        return "corrupt";
    case ErrorKind::TooNew:
        return "too-new";
    case ErrorKind::Busy:
        return "busy";
    case ErrorKind::NoMachine:
        return "no-machine";
    case ErrorKind::MachineExists:
        return "machine-exists";
    case ErrorKind::NoRevision:
        return "no-revision";
    case ErrorKind::Conflict:
        return "conflict";
    case ErrorKind::Invalid:
        return "invalid";
    case ErrorKind::ReadOnly:
        return "read-only";
    case ErrorKind::Sql:
        return "sql";
    }
    return "";
}

std::string_view readOnlyReasonText(ReadOnlyReason r) {
    switch (r) {
    case ReadOnlyReason::None:
        return "";
    case ReadOnlyReason::Permission:
        return "permission denied";
    case ReadOnlyReason::Folder:
        return "no permission to create files in its folder";
    case ReadOnlyReason::FileSystem:
        return "read-only file system";
    case ReadOnlyReason::Requested:
        return "opened read-only";
    }
    return "";
}

namespace {

std::string readOnlyMessage(const fs::path& path, ReadOnlyReason reason, ReadOnlyRefusal refusal) {
    std::string s = "the database is read-only: " + path.string() + " (" +
                     std::string(readOnlyReasonText(reason)) + ")";
    switch (refusal) {
    case ReadOnlyRefusal::Write:
        return s + "; nothing was written";
    case ReadOnlyRefusal::Create:
        return s + "; a new database cannot be created there";
    case ReadOnlyRefusal::Upgrade:
        return s + "; its schema is older than this program's and cannot be upgraded";
    case ReadOnlyRefusal::Recover:
        return s + "; it has an unfinished transaction (a hot -journal) that only a user who "
                   "may write the file can roll back; the file was left untouched";
    }
    return s;
}

} // namespace

ReadOnlyError::ReadOnlyError(fs::path path, ReadOnlyReason reason, ReadOnlyRefusal refusal)
    : Error(ErrorKind::ReadOnly, readOnlyMessage(path, reason, refusal)), path_(std::move(path)),
      reason_(reason), refusal_(refusal) {}

namespace {

std::string two(int k) {
    return (k < 10 ? "0" : "") + std::to_string(k);
}

std::string plcKey(cat::PlcGroup g, int k) {
    return std::string(1, cat::plcGroupLetter(g)) + two(k);
}

std::optional<cat::PlcGroup> plcGroupOf(char letter) {
    for (cat::PlcGroup g : cat::kPlcGroups)
        if (cat::plcGroupLetter(g) == letter)
            return g;
    return std::nullopt;
}

std::optional<DiffSection> sectionFromName(std::string_view s) {
    for (DiffSection d :
         {DiffSection::Machine, DiffSection::C, DiffSection::R, DiffSection::Program,
          DiffSection::Message, DiffSection::PlcMessage, DiffSection::Simulation})
        if (profile::diffSectionName(d) == s)
            return d;
    return std::nullopt;
}

// The number after a one-character prefix ("C022" -> 22, "#3" -> 3).
std::optional<int> keyNumber(std::string_view key) {
    if (key.size() < 2)
        return std::nullopt;
    int n = 0;
    for (char ch : key.substr(1)) {
        if (ch < '0' || ch > '9' || n > 100000)
            return std::nullopt;
        n = n * 10 + (ch - '0');
    }
    return n;
}

std::optional<std::int64_t> toInt(const std::string& s) {
    if (s.empty())
        return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(s.c_str(), &end, 10);
    if (errno != 0 || end != s.c_str() + s.size())
        return std::nullopt;
    return v;
}

const std::string kOrderKey = "(order)"; // simulation keys that only moved

std::string joinKeys(const profile::Settings& s, char sep) {
    std::string out;
    for (const auto& [k, v] : s.entries()) {
        if (!out.empty())
            out += sep;
        out += k;
    }
    return out;
}

bool sameFinding(const profile::Finding& a, const profile::Finding& b) {
    return a.severity == b.severity && a.subject == b.subject && a.message == b.message;
}

// A finding about one item's own value (always rejected), as opposed to a
// cross-check between constants.
bool itemFinding(const profile::Finding& f, const MachineProfile& p) {
    if (f.cParams.empty())
        return f.severity == profile::Severity::Error;
    if (f.cParams.size() == 1) {
        const int n = f.cParams.front();
        return n >= 1 && n <= cat::kCParamCount && !profile::checkCValue(n, p.cValue(n)).empty();
    }
    return false;
}

std::string formatFindings(const std::vector<profile::Finding>& fs) {
    std::string s;
    for (const auto& f : fs)
        s += "\n  " + profile::formatFinding(f);
    return s;
}

// Checks `neu` before it is written: returns its findings (warnings and
// tolerated errors) or throws ValidationError.
std::vector<profile::Finding> checkWrite(const MachineProfile* old, const MachineProfile& neu,
                                         bool allowErrors) {
    std::vector<profile::Finding> found = profile::validate(neu);
    std::vector<profile::Finding> oldFound;
    if (old)
        oldFound = profile::validate(*old);
    std::vector<profile::Finding> rejected;
    for (const auto& f : found) {
        if (f.severity != profile::Severity::Error)
            continue;
        if (itemFinding(f, neu)) {
            rejected.push_back(f);
            continue;
        }
        const bool existed = std::any_of(oldFound.begin(), oldFound.end(),
                                         [&](const auto& o) { return sameFinding(o, f); });
        if (!existed && !allowErrors)
            rejected.push_back(f);
    }
    if (!rejected.empty())
        throw ValidationError("machine " + neu.name + ": rejected, nothing was written (" +
                                  std::to_string(rejected.size()) +
                                  (rejected.size() == 1 ? " error" : " errors") +
                                  "):" + formatFindings(rejected),
                              rejected);
    return found;
}

// The changes that turn `old` (nullptr: nothing) into `neu`. A new machine
// records its name, title and all 152 constants explicitly.
std::vector<Change> computeChanges(const MachineProfile* old, const MachineProfile& neu) {
    if (!old) {
        std::vector<Change> out;
        out.push_back(Change{DiffSection::Machine, "name", "", std::nullopt, neu.name});
        out.push_back(Change{DiffSection::Machine, "title", "", std::nullopt, neu.title});
        for (const cat::CParamDef& d : cat::cParams())
            out.push_back(Change{DiffSection::C, d.key(), std::string(d.name), std::nullopt,
                                 std::to_string(neu.cValue(d.number))});
        MachineProfile base;
        base.name = neu.name;
        base.title = neu.title;
        base.c = neu.c;
        const auto rest = profile::diff(base, neu);
        out.insert(out.end(), rest.begin(), rest.end());
        return out;
    }
    std::vector<Change> out = profile::diff(*old, neu);
    // Keys of the simulation section that only moved: diff() does not report
    // them, the history records the new order.
    std::vector<std::string> expected;
    for (const auto& [k, v] : old->simulation.entries())
        if (neu.simulation.has(k))
            expected.push_back(k);
    for (const auto& [k, v] : neu.simulation.entries())
        if (!old->simulation.has(k))
            expected.push_back(k);
    std::vector<std::string> actual;
    for (const auto& [k, v] : neu.simulation.entries())
        actual.push_back(k);
    if (expected != actual)
        out.push_back(Change{DiffSection::Simulation, kOrderKey, "", joinKeys(old->simulation, ' '),
                             joinKeys(neu.simulation, ' ')});
    return out;
}

std::string describeChanges(const std::vector<Change>& changes) {
    std::string s;
    std::size_t shown = 0;
    for (const auto& c : changes) {
        if (c.key == kOrderKey)
            continue;
        if (shown == 8) {
            s += " and " + std::to_string(changes.size() - shown) + " more";
            break;
        }
        s += (shown ? ", " : "") + c.key;
        ++shown;
    }
    return s.empty() ? "order of simulation settings" : s;
}

// The definition rows' content, for detecting a changed catalog.
std::string catalogDigest() {
    std::string s;
    const auto add = [&](std::string_view v) {
        s += v;
        s += '\x1f';
    };
    for (const cat::CParamDef& d : cat::cParams()) {
        add(std::to_string(d.number));
        add(cat::axisName(d.axis));
        add(cat::kindName(d.kind));
        add(cat::unitSymbol(d.unit));
        add(cat::unitRu(d.unit));
        add(cat::unitEn(d.unit));
        add(std::to_string(d.min));
        add(std::to_string(d.max));
        add(d.address.text());
        add(d.address.textEn());
        add(d.name);
        add(d.nameEn);
        add(d.descriptionRu);
        add(d.descriptionEn);
        add(d.hintRu);
        add(d.hintEn);
        add(d.note);
        s += '\x1e';
    }
    return sha256Hex(s);
}

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
};

// Whether something is at `path`, from stat() alone: the file is never opened
// here (see readHeader). Throws Io for a folder or anything but a regular file.
bool databaseFileExists(const fs::path& path) {
    std::error_code ec;
    const auto st = fs::status(path, ec);
    if (ec || !fs::exists(st)) {
        if (ec && ec != std::errc::no_such_file_or_directory)
            throw Error(ErrorKind::Io, path.string() + ": " + ec.message());
        return false;
    }
    if (fs::is_directory(st))
        throw Error(ErrorKind::Io, path.string() + ": is a directory, not a database file");
    if (!fs::is_regular_file(st))
        throw Error(ErrorKind::Io,
                    path.string() + ": is not a regular file (" +
                        (fs::is_character_file(st) ? "a character device"
                         : fs::is_block_file(st)   ? "a block device"
                         : fs::is_fifo(st)         ? "a FIFO"
                         : fs::is_socket(st)       ? "a socket"
                                                   : "not a file") +
                        "); a database is a regular file — give another --db path");
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
        throw Refusal{ErrorKind::Io, "cannot be read: SQLite did not open the file"};
    sqlite3_int64 size = 0;
    if (const int rc = f->pMethods->xFileSize(f, &size); rc != SQLITE_OK)
        throw Refusal{ErrorKind::Io, std::string("cannot be read: ") + sqlite3_errstr(rc)};
    FileHeader h;
    if (size == 0) {
        h.empty = true;
        return h;
    }
    unsigned char buf[100] = {};
    const int got = static_cast<int>(std::min<sqlite3_int64>(size, sizeof buf));
    if (const int rc = f->pMethods->xRead(f, buf, got, 0); rc != SQLITE_OK)
        throw Refusal{ErrorKind::Io, std::string("cannot be read: ") + sqlite3_errstr(rc)};
    static constexpr char kMagic[] = "SQLite format 3";
    if (got < 100 || std::memcmp(buf, kMagic, sizeof kMagic) != 0)
        throw Refusal{ErrorKind::Foreign,
                      "not a K528 Studio database: " +
                          (got < 100 ? "the file has only " + std::to_string(got) +
                                           " bytes, too few for an SQLite database"
                                     : std::string("the file does not start with the SQLite header "
                                                   "(another kind of file, or a database whose "
                                                   "first page is damaged)"))};
    h.userVersion = be32(buf + 60);
    h.applicationId = be32(buf + 68);
    if (h.applicationId != 0 && h.applicationId != static_cast<std::uint32_t>(kApplicationId))
        throw Refusal{ErrorKind::Foreign,
                      "not a K528 Studio database: it is another program's SQLite database "
                      "(application_id " +
                          hex32(h.applicationId) + ", ours is " +
                          hex32(static_cast<std::uint32_t>(kApplicationId)) + ")"};
    if (h.applicationId == static_cast<std::uint32_t>(kApplicationId) &&
        h.userVersion > static_cast<std::uint32_t>(latest))
        throw Refusal{ErrorKind::TooNew, "the database has schema version " +
                                             std::to_string(h.userVersion) +
                                             ", written by a newer K528 Studio; this program "
                                             "knows versions up to " +
                                             std::to_string(latest) + ". Use the newer program"};
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

struct Checked {
    std::int64_t appId = 0, version = 0, objects = 0;
};

// The checks of open(), on a connection with nothing set yet: what the file
// is (application_id, user_version, schema objects) and, when it is ours,
// PRAGMA integrity_check and foreign_key_check. They only read. Every failure
// is a Refusal.
Checked inspect(sqlite3* db, int latest) {
    Checked c;
    try {
        c.appId = sql::queryInt(db, "PRAGMA application_id");
        c.version = sql::queryInt(db, "PRAGMA user_version");
        c.objects = sql::queryInt(db, "SELECT count(*) FROM sqlite_schema");
    } catch (const Error& e) {
        const int code = sqlite3_extended_errcode(db);
        if (code == SQLITE_READONLY_ROLLBACK)
            throw Refusal{ErrorKind::Io, e.what(), true};
        if (code == SQLITE_READONLY_DIRECTORY || code == SQLITE_READONLY_CANTINIT ||
            code == SQLITE_READONLY_CANTLOCK || (code & 0xff) == SQLITE_CANTOPEN)
            throw Refusal{ErrorKind::ReadOnly, e.what(), false, true};
        if (e.kind() == ErrorKind::Busy)
            throw Refusal{ErrorKind::Busy, e.what()};
        throw Refusal{ErrorKind::Corrupt,
                      std::string("cannot be read as a database (") + e.what() + ")"};
    }
    if (c.appId == 0 && c.version == 0 && c.objects == 0)
        return c; // empty: ours to fill
    if (c.appId != kApplicationId)
        throw Refusal{ErrorKind::Foreign,
                      "not a K528 Studio database: it is another program's SQLite database "
                      "(application_id " +
                          hex32(static_cast<std::uint32_t>(c.appId)) + ", " +
                          std::to_string(c.objects) + " schema objects)"};
    if (c.version > latest)
        throw Refusal{ErrorKind::TooNew,
                      "the database has schema version " + std::to_string(c.version) +
                          ", written by a newer K528 Studio; this program knows versions up to " +
                          std::to_string(latest)};
    if (c.version < 1)
        throw Refusal{ErrorKind::Corrupt, "K528 Studio database without a schema version"};
    std::string problems;
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
        std::string fkFirst;
        for (const std::string& table : tables) {
            sql::Stmt fk(db, "PRAGMA foreign_key_check(\"" + table + "\")");
            while (fk.step())
                if (fkRows++ == 0)
                    fkFirst = fk.text(0) + " row " + std::to_string(fk.i64(1)) + " -> " + fk.text(2);
        }
        if (fkRows)
            problems += (problems.empty() ? "" : "; ") + std::to_string(fkRows) +
                        " rows break foreign keys (first: " + fkFirst + ")";
    } catch (const Error& e) {
        if (e.kind() == ErrorKind::Busy)
            throw Refusal{ErrorKind::Busy, e.what()};
        problems = e.what();
    }
    if (!problems.empty())
        throw Refusal{ErrorKind::Corrupt,
                      "the database is damaged (integrity check: " + problems + ")"};
    return c;
}

} // namespace

// ---------------------------------------------------------------------------
// Edit

std::string Edit::describe() const {
    std::string s;
    const auto add = [&](const std::string& k) { s += (s.empty() ? "" : " ") + k; };
    if (title)
        add("title");
    for (const auto& [n, v] : c)
        add(cat::cParam(n).key());
    for (const auto& [n, v] : r)
        add("R" + std::to_string(n));
    for (const auto& [n, v] : messages)
        add("#" + std::to_string(n));
    for (const auto& [gk, v] : plc)
        add(plcKey(gk.first, gk.second));
    for (const auto& [k, v] : simulation)
        add(k);
    return s;
}

void Edit::applyTo(MachineProfile& p) const {
    if (title)
        p.title = *title;
    for (const auto& [n, v] : c)
        p.setC(n, v);
    for (const auto& [n, v] : r) {
        if (v)
            p.r[n] = *v;
        else
            p.r.erase(n);
    }
    for (const auto& [n, v] : messages) {
        if (v)
            p.messages[n] = *v;
        else
            p.messages.erase(n);
    }
    for (const auto& [gk, v] : plc) {
        auto& m = p.plcTexts(gk.first);
        if (v)
            m[gk.second] = *v;
        else
            m.erase(gk.second);
    }
    for (const auto& [k, v] : simulation) {
        if (v)
            p.simulation.set(k, *v);
        else
            p.simulation.erase(k);
    }
}

// ---------------------------------------------------------------------------
// Database

struct Database::Impl {
    sqlite3* db = nullptr;
    fs::path path;
    OpenReport report;
    Clock clock;
    ReadOnlyReason readOnly = ReadOnlyReason::None;
    bool immutable = false;  // read as a snapshot (see snapshotOutdated)
    struct timespec snapshotTime {};
    off_t snapshotSize = 0;
    std::map<std::string, std::unique_ptr<sql::Stmt>, std::less<>> cache;

    ~Impl() {
        cache.clear();
        if (db)
            sqlite3_close_v2(db);
    }

    sql::Stmt& st(std::string_view text) {
        auto it = cache.find(text);
        if (it == cache.end())
            it = cache.emplace(std::string(text), std::make_unique<sql::Stmt>(db, text)).first;
        it->second->reset();
        return *it->second;
    }

    std::string now() const { return formatTimestamp(clock()); }

    void requireWritable() const {
        if (readOnly != ReadOnlyReason::None)
            throw ReadOnlyError(path, readOnly);
    }

    struct Row {
        std::int64_t id = 0;
        MachineInfo info;
    };

    std::optional<Row> findMachine(std::string_view name) {
        auto& q = st("SELECT id, name, title, revision, created_at, changed_at, changed_by "
                     "FROM machines WHERE name = ?1");
        q.bind(1, name);
        if (!q.step())
            return std::nullopt;
        Row r;
        r.id = q.i64(0);
        r.info = MachineInfo{q.text(1), q.text(2), q.i32(3), q.text(4), q.text(5), q.text(6)};
        q.reset();
        return r;
    }

    Row requireMachine(std::string_view name) {
        auto r = findMachine(name);
        if (!r) {
            std::string known;
            auto& q = st("SELECT name FROM machines ORDER BY name");
            while (q.step())
                known += (known.empty() ? "" : ", ") + q.text(0);
            throw Error(ErrorKind::NoMachine,
                        "no machine \"" + std::string(name) + "\" in " + path.string() +
                            " (machines: " + (known.empty() ? "none" : known) + ")");
        }
        return *r;
    }

    // `at` "": now.
    void audit(const std::string& author, std::string_view action, std::string_view machine,
               int revision, std::string_view detail, const std::string& at = {}) {
        auto& q = st("INSERT INTO audit (at, author, action, machine, revision, detail) "
                     "VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
        q.bind(1, at.empty() ? now() : at)
            .bind(2, author)
            .bind(3, action)
            .bind(4, machine)
            .bind(5, revision)
            .bind(6, detail);
        q.run();
    }

    MachineProfile loadCurrent(const Row& row);
    MachineProfile loadAt(const Row& row, int revision);
    SaveResult write(const std::optional<Row>& row, const MachineProfile* old,
                     const MachineProfile& neu, const WriteOptions& o);
    // The steps of write():
    std::int64_t writeMachineRow(const std::optional<Row>& row, const MachineProfile& neu,
                                 int revision, const std::string& at, const std::string& author);
    void writeRevisionRow(std::int64_t id, int revision, const std::string& author,
                          const std::string& at, const std::string& summary,
                          const MachineProfile& neu);
    // Applies one change to the tables of the current state and records it in
    // `changes` (a program's texts as their checksums); true for a
    // simulation setting (written whole by writeSettings).
    bool writeChange(std::int64_t id, bool update, int revision, int seq,
                     const MachineProfile& neu, const profile::Change& c);
    void writeSettings(std::int64_t id, const MachineProfile& neu);

    // The steps of Database::open():
    // Connects and inspects the file before anything is written; a hot
    // journal of ours is rolled back, anything else refused. A file this
    // process may only read gets a read-only connection.
    Checked connectAndInspect(const OpenOptions& options, int latest);
    sqlite3* connect(const std::string& target, int flags, int busyTimeoutMs, bool noCheckpoint,
                     const std::function<std::string()>& untouched) const;
    // Reconnects read-only to an immutable snapshot of the file.
    void connectSnapshot(int busyTimeoutMs, const std::function<std::string()>& untouched);
    void applyConnectionSettings();
    // WAL journal mode, retried up to the busy timeout.
    void switchToWal(int busyTimeoutMs);
    // Creates the schema (and seeds the built-ins) or migrates it, in one
    // transaction.
    void createOrMigrate(const OpenOptions& options, int latest, const std::string& author);
    // A newer catalog (e.g. a corrected description) refreshes the definitions.
    void refreshDefinitions(const std::string& author);
    void syncDefinitions(const std::string& author);
};

namespace {

// Resets statements left mid-iteration (an exception inside a loop), so no
// read snapshot outlives the call that made it.
void resetBusyStatements(sqlite3* db) {
    for (sqlite3_stmt* s = sqlite3_next_stmt(db, nullptr); s; s = sqlite3_next_stmt(db, s))
        if (sqlite3_stmt_busy(s))
            sqlite3_reset(s);
}

// Read-only snapshot: the SELECTs of one load see one state of the file.
class ReadTx {
public:
    template <typename D> explicit ReadTx(D& d) : db_(d.db) {
        if (sqlite3_get_autocommit(db_)) {
            sql::exec(db_, "BEGIN");
            own_ = true;
        }
    }
    ~ReadTx() {
        if (own_) {
            resetBusyStatements(db_);
            sqlite3_exec(db_, "COMMIT", nullptr, nullptr, nullptr);
        }
    }
    ReadTx(const ReadTx&) = delete;
    ReadTx& operator=(const ReadTx&) = delete;

private:
    sqlite3* db_;
    bool own_ = false;
};

// A write transaction: BEGIN IMMEDIATE takes the write lock at once (waiting
// up to the busy timeout), so two writers never deadlock.
class WriteTx {
public:
    template <typename D> explicit WriteTx(D& d) : db_(d.db) {
        d.requireWritable();
        try {
            sql::exec(db_, "BEGIN IMMEDIATE");
        } catch (const Error& e) {
            if (e.kind() == ErrorKind::ReadOnly)
                throw ReadOnlyError(d.path, whyReadOnly(d.path));
            if (e.kind() != ErrorKind::Busy)
                throw;
            throw Error(ErrorKind::Busy, d.path.string() +
                                             ": another process is writing to the database and "
                                             "kept it locked longer than the busy timeout; "
                                             "nothing was written, try again");
        }
    }
    void commit() {
        resetBusyStatements(db_);
        sql::exec(db_, "COMMIT");
        done_ = true;
    }
    ~WriteTx() {
        if (!done_) {
            resetBusyStatements(db_);
            sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
        }
    }
    WriteTx(const WriteTx&) = delete;
    WriteTx& operator=(const WriteTx&) = delete;

private:
    sqlite3* db_;
    bool done_ = false;
};

} // namespace

MachineProfile Database::Impl::loadCurrent(const Row& row) {
    MachineProfile p;
    p.name = row.info.name;
    p.title = row.info.title;
    const std::string where = "machine " + row.info.name + " in " + path.string();
    {
        auto& q = st("SELECT number, value FROM c_values WHERE machine_id = ?1");
        q.bind(1, row.id);
        int count = 0;
        while (q.step()) {
            const int n = q.i32(0);
            if (n < 1 || n > cat::kCParamCount)
                throw Error(ErrorKind::Corrupt,
                            where + ": C-parameter number " + std::to_string(n) + " is not 1..152");
            p.c[static_cast<std::size_t>(n)] = q.i64(1);
            ++count;
        }
        if (count != cat::kCParamCount)
            throw Error(ErrorKind::Corrupt, where + ": " + std::to_string(count) +
                                                " of the 152 C-parameter values are stored");
    }
    {
        auto& q = st("SELECT number, value FROM r_values WHERE machine_id = ?1");
        q.bind(1, row.id);
        while (q.step())
            p.r[q.i32(0)] = q.i64(1);
    }
    {
        auto& q = st("SELECT number, text, sha256, revision FROM programs WHERE machine_id = ?1");
        q.bind(1, row.id);
        while (q.step()) {
            std::string text = q.text(1);
            if (sha256Hex(text) != q.text(2))
                throw Error(ErrorKind::Corrupt,
                            where + ": program L" + std::to_string(q.i32(0)) + " of revision " +
                                std::to_string(q.i32(3)) +
                                " does not match its SHA-256 checksum (the text was altered "
                                "outside K528 Studio)");
            p.programs[q.i32(0)] = std::move(text);
        }
    }
    {
        auto& q = st("SELECT number, text FROM messages WHERE machine_id = ?1");
        q.bind(1, row.id);
        while (q.step())
            p.messages[q.i32(0)] = q.text(1);
    }
    {
        auto& q = st("SELECT grp, number, text FROM plc_messages WHERE machine_id = ?1");
        q.bind(1, row.id);
        while (q.step()) {
            const std::string g = q.text(0);
            const auto group = plcGroupOf(g.empty() ? '?' : g[0]);
            if (!group)
                throw Error(ErrorKind::Corrupt, where + ": unknown PLC message group " + g);
            p.plcTexts(*group)[q.i32(1)] = q.text(2);
        }
    }
    {
        auto& q = st("SELECT key, value FROM settings WHERE machine_id = ?1 ORDER BY position");
        q.bind(1, row.id);
        while (q.step()) {
            try {
                p.simulation.set(q.text(0), q.text(1));
            } catch (const profile::SettingError& e) {
                throw Error(ErrorKind::Corrupt, where + ": simulation setting: " + e.what());
            }
        }
    }
    return p;
}

MachineProfile Database::Impl::loadAt(const Row& row, int revision) {
    if (revision < 1 || revision > row.info.revision)
        throw Error(ErrorKind::NoRevision, "machine " + row.info.name + " has revisions 1.." +
                                               std::to_string(row.info.revision) +
                                               "; there is no revision " +
                                               std::to_string(revision));
    MachineProfile p;
    const std::string where = "machine " + row.info.name + " revision " + std::to_string(revision) +
                              " in " + path.string();
    const auto corrupt = [&](const std::string& what) {
        return Error(ErrorKind::Corrupt, where + ": " + what);
    };
    auto& q = st("SELECT section, key, after, revision FROM changes WHERE machine_id = ?1 AND "
                 "revision <= ?2 AND section <> 'program' ORDER BY revision, seq");
    q.bind(1, row.id).bind(2, revision);
    while (q.step()) {
        const std::string sectionName = q.text(0), key = q.text(1);
        const std::optional<std::string> after = q.optText(2);
        const auto section = sectionFromName(sectionName);
        const auto bad = [&] {
            return corrupt("history entry " + sectionName + " " + key + " of revision " +
                           std::to_string(q.i32(3)) + " cannot be read");
        };
        if (!section)
            throw bad();
        const auto num = keyNumber(key);
        std::optional<std::int64_t> value;
        switch (*section) {
        case DiffSection::Machine:
            if (!after)
                throw bad();
            if (key == "name")
                p.name = *after;
            else if (key == "title")
                p.title = *after;
            else
                throw bad();
            break;
        case DiffSection::C:
            if (!num || *num < 1 || *num > cat::kCParamCount || !after || !(value = toInt(*after)))
                throw bad();
            p.setC(*num, *value);
            break;
        case DiffSection::R:
            if (!num)
                throw bad();
            if (!after)
                p.r.erase(*num);
            else if ((value = toInt(*after)))
                p.r[*num] = *value;
            else
                throw bad();
            break;
        case DiffSection::Message:
            if (!num)
                throw bad();
            if (after)
                p.messages[*num] = *after;
            else
                p.messages.erase(*num);
            break;
        case DiffSection::PlcMessage: {
            const auto g = plcGroupOf(key.empty() ? '?' : key[0]);
            if (!g || !num)
                throw bad();
            if (after)
                p.plcTexts(*g)[*num] = *after;
            else
                p.plcTexts(*g).erase(*num);
            break;
        }
        case DiffSection::Simulation:
            if (key == kOrderKey)
                break;
            try {
                if (after)
                    p.simulation.set(key, *after);
                else
                    p.simulation.erase(key);
            } catch (const profile::SettingError&) {
                throw bad();
            }
            break;
        case DiffSection::Program:
            break;
        }
    }
    q.reset();
    // The order of the simulation keys at that revision.
    {
        auto& o =
            st("SELECT settings_order FROM revisions WHERE machine_id = ?1 AND revision = ?2");
        o.bind(1, row.id).bind(2, revision);
        if (!o.step())
            throw corrupt("the revision is missing from the revision table");
        const std::string order = o.text(0);
        o.reset();
        profile::Settings sorted;
        std::size_t pos = 0;
        while (pos < order.size()) {
            auto end = order.find('\n', pos);
            if (end == std::string::npos)
                end = order.size();
            const std::string key = order.substr(pos, end - pos);
            const auto v = p.simulation.find(key);
            if (!v)
                throw corrupt("simulation key " + key + " of the stored order has no value");
            sorted.set(key, *v);
            pos = end + 1;
        }
        if (sorted.size() != p.simulation.size())
            throw corrupt("the stored order of the simulation settings does not list every key");
        p.simulation = std::move(sorted);
    }
    {
        auto& pq = st("SELECT p.number, p.text, p.sha256, p.revision FROM program_revisions p "
                      "WHERE p.machine_id = ?1 AND p.revision = (SELECT max(q.revision) FROM "
                      "program_revisions q WHERE q.machine_id = p.machine_id AND q.number = "
                      "p.number AND q.revision <= ?2) AND p.text IS NOT NULL");
        pq.bind(1, row.id).bind(2, revision);
        while (pq.step()) {
            std::string text = pq.text(1);
            if (sha256Hex(text) != pq.text(2))
                throw corrupt("program L" + std::to_string(pq.i32(0)) + " of revision " +
                              std::to_string(pq.i32(3)) + " does not match its SHA-256 checksum");
            p.programs[pq.i32(0)] = std::move(text);
        }
    }
    return p;
}

// A machine's row: inserted for a new machine, updated (name, title,
// revision) otherwise. Returns its id.
std::int64_t Database::Impl::writeMachineRow(const std::optional<Row>& row,
                                             const MachineProfile& neu, int revision,
                                             const std::string& at, const std::string& author) {
    if (!row) {
        if (findMachine(neu.name))
            throw Error(ErrorKind::MachineExists,
                        "a machine named " + neu.name + " already exists in " + path.string());
        auto& q = st("INSERT INTO machines (name, title, revision, created_at, changed_at, "
                     "changed_by) VALUES (?1, ?2, 1, ?3, ?3, ?4)");
        q.bind(1, neu.name).bind(2, neu.title).bind(3, at).bind(4, author);
        q.run();
        return sqlite3_last_insert_rowid(db);
    }
    const std::int64_t id = row->id;
    if (neu.name != row->info.name && findMachine(neu.name))
        throw Error(ErrorKind::MachineExists, "cannot rename " + row->info.name + " to " +
                                                  neu.name + ": a machine of that name exists");
    auto& q = st("UPDATE machines SET name = ?2, title = ?3, revision = ?4, changed_at = ?5, "
                 "changed_by = ?6 WHERE id = ?1");
    q.bind(1, id)
        .bind(2, neu.name)
        .bind(3, neu.title)
        .bind(4, revision)
        .bind(5, at)
        .bind(6, author);
    q.run();
    return id;
}

void Database::Impl::writeRevisionRow(std::int64_t id, int revision, const std::string& author,
                                      const std::string& at, const std::string& summary,
                                      const MachineProfile& neu) {
    auto& q = st("INSERT INTO revisions (machine_id, revision, author, at, summary, "
                 "settings_order) VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
    q.bind(1, id)
        .bind(2, revision)
        .bind(3, author)
        .bind(4, at)
        .bind(5, summary)
        .bind(6, joinKeys(neu.simulation, '\n'));
    q.run();
}

bool Database::Impl::writeChange(std::int64_t id, bool update, int revision, int seq,
                                 const MachineProfile& neu, const Change& c) {
    std::optional<std::string> before = c.before, after = c.after;
    const auto num = keyNumber(c.key);
    bool setting = false;
    switch (c.section) {
    case DiffSection::Machine:
        break; // the machines row (writeMachineRow)
    case DiffSection::C: {
        auto& q =
            st(update ? "UPDATE c_values SET value = ?3 WHERE machine_id = ?1 AND number = ?2"
                      : "INSERT INTO c_values (machine_id, number, value) VALUES (?1, ?2, ?3)");
        q.bind(1, id).bind(2, *num).bind(3, neu.cValue(*num));
        q.run();
        break;
    }
    case DiffSection::R:
        if (c.after) {
            auto& q = st("INSERT INTO r_values (machine_id, number, value) VALUES (?1, ?2, ?3) "
                         "ON CONFLICT (machine_id, number) DO UPDATE SET value = excluded.value");
            q.bind(1, id).bind(2, *num).bind(3, neu.r.at(*num));
            q.run();
        } else {
            auto& q = st("DELETE FROM r_values WHERE machine_id = ?1 AND number = ?2");
            q.bind(1, id).bind(2, *num);
            q.run();
        }
        break;
    case DiffSection::Program: {
        auto& q = st("INSERT INTO program_revisions (machine_id, number, revision, text, "
                     "sha256) VALUES (?1, ?2, ?3, ?4, ?5)");
        q.bind(1, id).bind(2, *num).bind(3, revision).bind(4, c.after);
        if (c.after)
            q.bind(5, sha256Hex(*c.after));
        else
            q.bindNull(5);
        q.run();
        if (before)
            before = sha256Hex(*before);
        if (after)
            after = sha256Hex(*after);
        break;
    }
    case DiffSection::Message:
        if (c.after) {
            auto& q = st("INSERT INTO messages (machine_id, number, text) VALUES (?1, ?2, ?3) "
                         "ON CONFLICT (machine_id, number) DO UPDATE SET text = excluded.text");
            q.bind(1, id).bind(2, *num).bind(3, *c.after);
            q.run();
        } else {
            auto& q = st("DELETE FROM messages WHERE machine_id = ?1 AND number = ?2");
            q.bind(1, id).bind(2, *num);
            q.run();
        }
        break;
    case DiffSection::PlcMessage:
        if (c.after) {
            auto& q = st("INSERT INTO plc_messages (machine_id, grp, number, text) VALUES "
                         "(?1, ?2, ?3, ?4) ON CONFLICT (machine_id, grp, number) DO UPDATE "
                         "SET text = excluded.text");
            q.bind(1, id).bind(2, c.key.substr(0, 1)).bind(3, *num).bind(4, *c.after);
            q.run();
        } else {
            auto& q = st("DELETE FROM plc_messages WHERE machine_id = ?1 AND grp = ?2 AND "
                         "number = ?3");
            q.bind(1, id).bind(2, c.key.substr(0, 1)).bind(3, *num);
            q.run();
        }
        break;
    case DiffSection::Simulation:
        setting = true;
        break;
    }
    auto& ins = st("INSERT INTO changes (machine_id, revision, seq, section, key, label, before, "
                   "after) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)");
    ins.reset();
    ins.bind(1, id)
        .bind(2, revision)
        .bind(3, seq)
        .bind(4, profile::diffSectionName(c.section))
        .bind(5, c.key)
        .bind(6, c.label)
        .bind(7, before)
        .bind(8, after);
    ins.run();
    return setting;
}

void Database::Impl::writeSettings(std::int64_t id, const MachineProfile& neu) {
    auto& del = st("DELETE FROM settings WHERE machine_id = ?1");
    del.bind(1, id);
    del.run();
    auto& q = st("INSERT INTO settings (machine_id, position, key, value) VALUES (?1, ?2, ?3, ?4)");
    int pos = 0;
    for (const auto& [k, v] : neu.simulation.entries()) {
        q.reset();
        q.bind(1, id).bind(2, pos++).bind(3, k).bind(4, v);
        q.run();
    }
}

SaveResult Database::Impl::write(const std::optional<Row>& row, const MachineProfile* old,
                                 const MachineProfile& neu, const WriteOptions& o) {
    const std::string author = o.author.empty() ? defaultAuthor() : o.author;
    SaveResult result;
    result.findings = checkWrite(old, neu, o.allowErrors);
    result.changes = computeChanges(old, neu);
    const int revision = row ? row->info.revision + 1 : 1;
    if (old && result.changes.empty()) {
        result.changed = false;
        result.revision = row->info.revision;
        return result;
    }
    result.changed = true;
    result.revision = revision;
    const std::string at = now();
    const std::int64_t id = writeMachineRow(row, neu, revision, at, author);
    const std::string summary =
        !o.summary.empty() ? o.summary
                           : (row ? "changed " + describeChanges(result.changes) : "created");
    writeRevisionRow(id, revision, author, at, summary, neu);
    bool settingsChanged = false;
    int seq = 0;
    for (const Change& c : result.changes) {
        settingsChanged = writeChange(id, row.has_value(), revision, seq++, neu, c) || settingsChanged;
        if (o.progress)
            o.progress(static_cast<std::size_t>(seq), result.changes.size());
    }
    if (settingsChanged)
        writeSettings(id, neu);
    audit(author, o.action, neu.name, revision,
          summary + " (" + std::to_string(result.changes.size()) +
              (result.changes.size() == 1 ? " change)" : " changes)"),
          at);
    return result;
}

void Database::Impl::syncDefinitions(const std::string& author) {
    const std::string digest = catalogDigest();
    {
        auto& q = st("SELECT value FROM meta WHERE key = 'catalog_sha256'");
        if (q.step() && q.text(0) == digest) {
            q.reset();
            return;
        }
        q.reset();
    }
    auto& q = st(R"SQL(INSERT INTO c_definitions (number, axis, kind, unit, unit_ru, unit_en,
        min_value, max_value, address, address_en, name, name_en, description_ru, description_en,
        hint_ru, hint_en, note) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13,
        ?14, ?15, ?16, ?17) ON CONFLICT (number) DO UPDATE SET axis = excluded.axis,
        kind = excluded.kind, unit = excluded.unit, unit_ru = excluded.unit_ru,
        unit_en = excluded.unit_en, min_value = excluded.min_value, max_value = excluded.max_value,
        address = excluded.address, address_en = excluded.address_en, name = excluded.name,
        name_en = excluded.name_en, description_ru = excluded.description_ru,
        description_en = excluded.description_en, hint_ru = excluded.hint_ru,
        hint_en = excluded.hint_en, note = excluded.note)SQL");
    for (const cat::CParamDef& d : cat::cParams()) {
        q.reset();
        q.bind(1, d.number)
            .bind(2, cat::axisName(d.axis))
            .bind(3, cat::kindName(d.kind))
            .bind(4, cat::unitSymbol(d.unit))
            .bind(5, cat::unitRu(d.unit))
            .bind(6, cat::unitEn(d.unit))
            .bind(7, d.min)
            .bind(8, d.max)
            .bind(9, d.address.text())
            .bind(10, d.address.textEn())
            .bind(11, d.name)
            .bind(12, d.nameEn)
            .bind(13, d.descriptionRu)
            .bind(14, d.descriptionEn)
            .bind(15, d.hintRu)
            .bind(16, d.hintEn)
            .bind(17, d.note);
        q.run();
    }
    auto& m = st("INSERT INTO meta (key, value) VALUES ('catalog_sha256', ?1) ON CONFLICT (key) "
                 "DO UPDATE SET value = excluded.value");
    m.bind(1, digest);
    m.run();
    audit(author, "definitions", "", 0,
          "C-parameter definitions (appendix Е) written from the catalog, digest " +
              digest.substr(0, 12));
    report.definitionsUpdated = true;
}

Database::Database(std::unique_ptr<Impl> impl) : d_(std::move(impl)) {}
Database::Database(Database&&) noexcept = default;
Database& Database::operator=(Database&&) noexcept = default;
Database::~Database() = default;

sqlite3* Database::Impl::connect(const std::string& target, int flags, int busyTimeoutMs,
                                 bool noCheckpoint,
                                 const std::function<std::string()>& untouched) const {
    sqlite3* c = nullptr;
    const int rc = sqlite3_open_v2(target.c_str(), &c,
                                   flags | SQLITE_OPEN_NOMUTEX | SQLITE_OPEN_EXRESCODE, nullptr);
    if (rc != SQLITE_OK) {
        const std::string msg = c ? sqlite3_errmsg(c) : sqlite3_errstr(rc);
        sqlite3_close_v2(c);
        throw Error(ErrorKind::Io, "cannot open " + path.string() + ": " + msg + untouched());
    }
    sqlite3_extended_result_codes(c, 1);
    sqlite3_busy_timeout(c, busyTimeoutMs);
    if (noCheckpoint)
        sqlite3_db_config(c, SQLITE_DBCONFIG_NO_CKPT_ON_CLOSE, 1, nullptr);
    return c;
}

void Database::Impl::connectSnapshot(int busyTimeoutMs,
                                     const std::function<std::string()>& untouched) {
    // Without a -wal every commit is in the file; immutable=1 reads it with
    // no -shm index and no lock (a reader cannot create them here, and must
    // not leave files of its own beside the file for the writers). A writer
    // that starts meanwhile writes into a new -wal: snapshotOutdated() says so.
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) {
        snapshotTime = st.st_mtim;
        snapshotSize = st.st_size;
    }
    sqlite3_close_v2(db);
    db = nullptr;
    db = connect(immutableUri(path), SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, busyTimeoutMs, false,
                 untouched);
    immutable = true;
}

Checked Database::Impl::connectAndInspect(const OpenOptions& options, int latest) {
    std::error_code ec;
    const fs::path wal = path.string() + "-wal";
    const bool walExisted = fs::exists(wal, ec);
    const fs::path journal = path.string() + "-journal";
    const bool journalExisted = fs::exists(journal, ec) && fs::file_size(journal, ec) > 0 && !ec;
    const bool existed = fs::exists(path, ec);

    // The checks come before any setting or write. On a refusal the file is
    // closed without a checkpoint (a -wal stays as it was, not copied into
    // the refused file) and nothing else was written.
    bool recovered = false;
    const std::function<std::string()> untouched = [&] {
        if (!existed)
            return std::string();
        return recovered ? std::string("; only the unfinished transaction in ") + journal.string() +
                               " was rolled back (SQLite's crash recovery of a K528 Studio "
                               "database), nothing else was changed"
                         : std::string("; the file was left untouched");
    };
    const auto refused = [&](const Refusal& r) {
        return Error(r.kind, path.string() + ": " + r.what + untouched());
    };
    // One connection: read-write when the file may be written (SQLite falls
    // back to read-only when it may not), read-only when asked.
    const int flags = options.readOnly ? SQLITE_OPEN_READONLY
                                       : SQLITE_OPEN_READWRITE |
                                             (options.create ? SQLITE_OPEN_CREATE : 0);
    db = connect(path.string(), flags, options.busyTimeoutMs, walExisted, untouched);
    if (sqlite3_db_readonly(db, "main") == 1)
        readOnly = options.readOnly ? ReadOnlyReason::Requested : whyReadOnly(path);
    // A journal begun on an empty file (a first transaction that died) may
    // have left pages of the file without its first one: the header is not
    // there to read; rolling the journal back below gives the empty file.
    const std::int64_t startPages =
        journalExisted ? journalStartPages(journal).value_or(-1) : std::int64_t(-1);
    const bool newFileJournal = startPages == 0;
    FileHeader header;
    try {
        header = readHeader(db, latest);
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
            connect(path.string(), SQLITE_OPEN_READONLY, options.busyTimeoutMs, walExisted,
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
                throw refused(Refusal{
                    ErrorKind::Foreign,
                    "not a K528 Studio database: an SQLite database without K528 Studio's "
                    "application_id, with an unfinished transaction of another program (the "
                    "hot journal " +
                        journal.string() + ", begun on a file of " +
                        (startPages >= 0 ? std::to_string(startPages) + " pages"
                                         : std::string("unknown size")) +
                        "), which is not ours to roll back: let that program open it first"});
            if (readOnly != ReadOnlyReason::None)
                throw ReadOnlyError(path, readOnly, ReadOnlyRefusal::Recover);
            recovered = true;
        }
    }
    // A reader must not create a -wal and -shm of its own beside the file:
    // without a -wal, it reads an immutable snapshot.
    if (readOnly != ReadOnlyReason::None && !header.empty && !fs::exists(wal, ec)) {
        connectSnapshot(options.busyTimeoutMs, untouched);
        checked.reset();
    }
    if (!checked) {
        try {
            checked = inspect(db, latest);
        } catch (const Refusal& r) {
            // A file we may write in a folder we may not: SQLite cannot
            // create the -wal/-shm it needs to read a WAL database.
            if (!r.noIndex || immutable || fs::exists(wal, ec))
                throw refused(r);
            readOnly = whyReadOnly(path);
            connectSnapshot(options.busyTimeoutMs, untouched);
            try {
                checked = inspect(db, latest);
            } catch (const Refusal& again) {
                throw refused(again);
            }
        }
    }
    if (walExisted && !immutable)
        sqlite3_db_config(db, SQLITE_DBCONFIG_NO_CKPT_ON_CLOSE, 0, nullptr);
    report.recovered = recovered;
    return *checked;
}

void Database::Impl::applyConnectionSettings() {
    // Settings, now that the file is ours, intact and not newer.
    try {
        // Every commit reaches the disk before it is reported (independent
        // of how SQLite was compiled).
        sql::exec(db, "PRAGMA synchronous = FULL");
        sql::exec(db, "PRAGMA foreign_keys = ON");
    } catch (const Error& e) {
        throw Error(e.kind(), path.string() + ": " + e.what());
    }
}

void Database::Impl::switchToWal(int busyTimeoutMs) {
    // Switching to WAL needs the file to itself for a moment; SQLite does
    // not wait for that with the busy handler, so retry until the busy
    // timeout (another process starting at the same time switches it too).
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::milliseconds(busyTimeoutMs);
    std::string mode;
    for (int attempt = 0;; ++attempt) {
        try {
            {
                sql::Stmt jm(db, "PRAGMA journal_mode");
                mode = jm.step() ? jm.text(0) : "";
            }
            if (mode == "wal")
                return;
            sql::Stmt set(db, "PRAGMA journal_mode = WAL");
            mode = set.step() ? set.text(0) : "";
            if (mode == "wal")
                return;
        } catch (const Error& e) {
            if (e.kind() != ErrorKind::Busy)
                throw;
        }
        if (std::chrono::steady_clock::now() > deadline)
            throw Error(ErrorKind::Busy,
                        path.string() + ": cannot switch to WAL journal mode (mode \"" + mode +
                            "\"): another process kept the database busy longer than the "
                            "busy timeout");
        std::this_thread::sleep_for(std::chrono::milliseconds(attempt < 10 ? 2 : 20));
    }
}

void Database::Impl::createOrMigrate(const OpenOptions& options, int latest,
                                     const std::string& author) {
    WriteTx tx(*this);
    // Another process may have created or migrated it meanwhile.
    const std::int64_t now = sql::queryInt(db, "PRAGMA user_version");
    const std::int64_t nowObjects = sql::queryInt(db, "SELECT count(*) FROM sqlite_schema");
    if (now == 0 && nowObjects != 0)
        throw Error(ErrorKind::Foreign, path.string() + ": another program wrote into the "
                                                        "file while it was being created");
    for (const Migration& m : options.migrations) {
        if (m.version <= now)
            continue;
        try {
            sql::exec(db, m.sql);
        } catch (const Error& e) {
            throw Error(ErrorKind::Sql, path.string() + ": migration to schema version " +
                                            std::to_string(m.version) + " failed (" + e.what() +
                                            "); nothing was changed");
        }
    }
    if (now < latest) {
        sql::exec(db, "PRAGMA application_id = " + std::to_string(kApplicationId));
        sql::exec(db, "PRAGMA user_version = " + std::to_string(latest));
        if (now == 0) {
            auto& meta = st("INSERT INTO meta (key, value) VALUES (?1, ?2)");
            meta.bind(1, "created_at").bind(2, this->now());
            meta.run();
            audit(author, "create-database", "", 0,
                  "schema version " + std::to_string(latest) + " created");
            syncDefinitions(author);
            if (options.seedBuiltins)
                for (const std::string& name : profile::builtinNames()) {
                    WriteOptions wo;
                    wo.author = author;
                    wo.action = "seed";
                    wo.summary = "built-in profile " + name + " (first start)";
                    write(std::nullopt, nullptr, profile::builtin(name), wo);
                    report.seeded.push_back(name);
                }
        } else {
            audit(author, "migrate", "", 0,
                  "schema version " + std::to_string(now) + " -> " + std::to_string(latest));
        }
    }
    tx.commit();
    report.fromVersion = static_cast<int>(now);
    report.created = now == 0; // not when another process created it meanwhile
}

void Database::Impl::refreshDefinitions(const std::string& author) {
    auto& q = st("SELECT value FROM meta WHERE key = 'catalog_sha256'");
    const bool same = q.step() && q.text(0) == catalogDigest();
    q.reset();
    if (!same) {
        WriteTx tx(*this);
        syncDefinitions(author);
        tx.commit();
    }
}

Database Database::open(const fs::path& path, const OpenOptions& options) {
    const auto& migrations = options.migrations;
    if (migrations.empty())
        throw Error(ErrorKind::Sql, "no schema migrations given");
    const int latest = migrations.back().version;
    const bool exists = databaseFileExists(path);
    if (!exists && (!options.create || options.readOnly))
        throw Error(ErrorKind::Io, "no database at " + path.string());
    if (!exists) {
        std::error_code ec;
        const fs::path parent = path.parent_path();
        if (!parent.empty() && !fs::is_directory(parent, ec))
            throw Error(ErrorKind::Io, "cannot create the database " + path.string() +
                                           ": the folder " + parent.string() + " does not exist");
        if (::faccessat(AT_FDCWD, parent.empty() ? "." : parent.c_str(), W_OK, AT_EACCESS) != 0)
            throw ReadOnlyError(path,
                                errno == EROFS ? ReadOnlyReason::FileSystem : ReadOnlyReason::Folder,
                                ReadOnlyRefusal::Create);
    }
    auto impl = std::make_unique<Impl>();
    impl->path = path;
    impl->clock = options.clock ? options.clock : systemClock();
    const std::string author = options.author.empty() ? defaultAuthor() : options.author;

    const auto [appId, version, objects] = impl->connectAndInspect(options, latest);
    const bool empty = appId == 0 && version == 0 && objects == 0;
    impl->applyConnectionSettings();
    impl->report.created = empty;
    impl->report.fromVersion = static_cast<int>(version);
    if (impl->readOnly != ReadOnlyReason::None) {
        // Reading writes nothing: no journal mode, no migration, no
        // definitions. An older schema is read as it is (its tables are a
        // subset of ours; MessageLog needs schema 2).
        if (empty)
            throw ReadOnlyError(path, impl->readOnly, ReadOnlyRefusal::Create);
        impl->report.version = static_cast<int>(version);
        return Database(std::move(impl));
    }
    // Now ours, intact, not newer: WAL, then create or migrate in one transaction.
    impl->switchToWal(options.busyTimeoutMs);
    if (empty || version < latest)
        impl->createOrMigrate(options, latest, author);
    impl->report.version = latest;
    impl->refreshDefinitions(author);
    return Database(std::move(impl));
}

const fs::path& Database::path() const {
    return d_->path;
}

const OpenReport& Database::openReport() const {
    return d_->report;
}

sqlite3* Database::connection() const {
    return d_->db;
}

ReadOnlyReason Database::readOnly() const {
    return d_->readOnly;
}

void Database::requireWritable() const {
    d_->requireWritable();
}

bool Database::snapshotOutdated() const {
    if (!d_->immutable)
        return false;
    std::error_code ec;
    if (fs::exists(d_->path.string() + "-wal", ec))
        return true;
    struct stat st {};
    if (::stat(d_->path.c_str(), &st) != 0)
        return true;
    return st.st_size != d_->snapshotSize || st.st_mtim.tv_sec != d_->snapshotTime.tv_sec ||
           st.st_mtim.tv_nsec != d_->snapshotTime.tv_nsec;
}

int Database::schemaVersion() const {
    return static_cast<int>(sql::queryInt(d_->db, "PRAGMA user_version"));
}

std::vector<MachineInfo> Database::machines() const {
    std::vector<MachineInfo> out;
    auto& q = d_->st("SELECT name, title, revision, created_at, changed_at, changed_by FROM "
                     "machines ORDER BY name");
    while (q.step())
        out.push_back(MachineInfo{q.text(0), q.text(1), q.i32(2), q.text(3), q.text(4), q.text(5)});
    return out;
}

std::optional<MachineInfo> Database::machine(std::string_view name) const {
    auto r = d_->findMachine(name);
    if (!r)
        return std::nullopt;
    return r->info;
}

bool Database::hasMachine(std::string_view name) const {
    return d_->findMachine(name).has_value();
}

MachineProfile Database::loadMachine(std::string_view name) const {
    ReadTx tx(*d_);
    return d_->loadCurrent(d_->requireMachine(name));
}

MachineProfile Database::loadMachine(std::string_view name, int revision) const {
    ReadTx tx(*d_);
    return d_->loadAt(d_->requireMachine(name), revision);
}

SaveResult Database::createMachine(const MachineProfile& p, WriteOptions options) {
    if (options.action == "save")
        options.action = "create";
    WriteTx tx(*d_);
    SaveResult r = d_->write(std::nullopt, nullptr, p, options);
    tx.commit();
    return r;
}

SaveResult Database::saveMachine(std::string_view name, const MachineProfile& p,
                                 WriteOptions options) {
    WriteTx tx(*d_);
    const auto row = d_->requireMachine(name);
    if (options.expectedRevision && *options.expectedRevision != row.info.revision)
        throw Error(ErrorKind::Conflict, "machine " + row.info.name + " is at revision " +
                                             std::to_string(row.info.revision) + " (changed by " +
                                             row.info.changedBy + " at " + row.info.changedAt +
                                             "), not " + std::to_string(*options.expectedRevision) +
                                             " as read: load it again and repeat the change");
    const MachineProfile old = d_->loadCurrent(row);
    SaveResult r = d_->write(row, &old, p, options);
    tx.commit();
    return r;
}

SaveResult Database::applyEdit(std::string_view name, const Edit& edit, WriteOptions options) {
    if (options.action == "save")
        options.action = "set";
    WriteTx tx(*d_);
    const auto row = d_->requireMachine(name);
    if (options.expectedRevision && *options.expectedRevision != row.info.revision)
        throw Error(ErrorKind::Conflict, "machine " + row.info.name + " is at revision " +
                                             std::to_string(row.info.revision) + ", not " +
                                             std::to_string(*options.expectedRevision));
    const MachineProfile old = d_->loadCurrent(row);
    MachineProfile neu = old;
    try {
        edit.applyTo(neu);
    } catch (const profile::SettingError& e) {
        throw ValidationError("machine " + row.info.name + ": " + e.what(), {});
    } catch (const std::out_of_range& e) {
        throw ValidationError("machine " + row.info.name + ": " + e.what(), {});
    }
    if (options.summary.empty())
        options.summary = "set " + edit.describe();
    SaveResult r = d_->write(row, &old, neu, options);
    tx.commit();
    return r;
}

void Database::removeMachine(std::string_view name, WriteOptions options) {
    const std::string author = options.author.empty() ? defaultAuthor() : options.author;
    WriteTx tx(*d_);
    const auto row = d_->requireMachine(name);
    auto& q = d_->st("DELETE FROM machines WHERE id = ?1");
    q.bind(1, row.id);
    q.run();
    d_->audit(author, "delete", row.info.name, row.info.revision,
              options.summary.empty()
                  ? "machine deleted with its " + std::to_string(row.info.revision) + " revisions"
                  : options.summary);
    tx.commit();
}

std::vector<RevisionInfo> Database::revisions(std::string_view name) const {
    ReadTx tx(*d_);
    const auto row = d_->requireMachine(name);
    std::vector<RevisionInfo> out;
    auto& q =
        d_->st("SELECT r.revision, r.author, r.at, r.summary, (SELECT count(*) FROM changes c "
               "WHERE c.machine_id = r.machine_id AND c.revision = r.revision) FROM "
               "revisions r WHERE r.machine_id = ?1 ORDER BY r.revision DESC");
    q.bind(1, row.id);
    while (q.step())
        out.push_back(RevisionInfo{q.i32(0), q.text(1), q.text(2), q.text(3), q.i32(4)});
    return out;
}

std::vector<HistoryEntry> Database::history(std::string_view name, std::optional<std::string> key,
                                            int limitRevisions) const {
    ReadTx tx(*d_);
    const auto row = d_->requireMachine(name);
    const int from = limitRevisions > 0 ? row.info.revision - limitRevisions + 1 : 1;
    auto& q = d_->st(
        "SELECT c.revision, r.author, r.at, c.section, c.key, c.label, c.before, c.after FROM "
        "changes c JOIN revisions r ON r.machine_id = c.machine_id AND r.revision = c.revision "
        "WHERE c.machine_id = ?1 AND c.revision >= ?2 AND (?3 IS NULL OR c.key = ?3) "
        "ORDER BY c.revision DESC, c.seq");
    q.bind(1, row.id).bind(2, from).bind(3, key);
    std::vector<HistoryEntry> out;
    while (q.step()) {
        const auto section = sectionFromName(q.text(3));
        if (!section)
            throw Error(ErrorKind::Corrupt, "machine " + row.info.name +
                                                ": history has an unknown section " + q.text(3));
        out.push_back(
            HistoryEntry{q.i32(0), q.text(1), q.text(2),
                         Change{*section, q.text(4), q.text(5), q.optText(6), q.optText(7)}});
    }
    return out;
}

std::vector<ProgramVersion> Database::programHistory(std::string_view name, int number) const {
    ReadTx tx(*d_);
    const auto row = d_->requireMachine(name);
    auto& q = d_->st("SELECT revision, text, sha256 FROM program_revisions WHERE machine_id = ?1 "
                     "AND number = ?2 ORDER BY revision DESC");
    q.bind(1, row.id).bind(2, number);
    std::vector<ProgramVersion> out;
    while (q.step())
        out.push_back(ProgramVersion{q.i32(0), q.optText(1), q.optText(2)});
    return out;
}

std::optional<std::string> Database::programText(std::string_view name, int number,
                                                 int revision) const {
    ReadTx tx(*d_);
    const auto row = d_->requireMachine(name);
    auto& q = d_->st("SELECT text, sha256 FROM program_revisions WHERE machine_id = ?1 AND "
                     "number = ?2 AND revision <= ?3 ORDER BY revision DESC LIMIT 1");
    q.bind(1, row.id).bind(2, number).bind(3, revision);
    if (!q.step())
        return std::nullopt;
    auto text = q.optText(0);
    if (text && sha256Hex(*text) != q.text(1))
        throw Error(ErrorKind::Corrupt, "machine " + row.info.name + ": program L" +
                                            std::to_string(number) +
                                            " does not match its SHA-256 checksum");
    return text;
}

std::vector<AuditEntry> Database::audit(int limit, std::string_view machine) const {
    auto& q = d_->st("SELECT id, at, author, action, machine, revision, detail FROM audit WHERE "
                     "(?1 = '' OR machine = ?1) ORDER BY id DESC LIMIT ?2");
    q.bind(1, machine).bind(2, limit > 0 ? limit : -1);
    std::vector<AuditEntry> out;
    while (q.step())
        out.push_back(
            AuditEntry{q.i64(0), q.text(1), q.text(2), q.text(3), q.text(4), q.i32(5), q.text(6)});
    return out;
}

std::string Database::checkIntegrity() const {
    std::string problems;
    sql::Stmt ic(d_->db, "PRAGMA integrity_check");
    while (ic.step())
        if (const std::string line = ic.text(0); line != "ok")
            problems += (problems.empty() ? "" : "; ") + line;
    try {
        sql::Stmt fk(d_->db, "PRAGMA foreign_key_check");
        while (fk.step())
            problems += (problems.empty() ? "" : "; ") + std::string("foreign key: ") + fk.text(0) +
                        " row " + std::to_string(fk.i64(1));
    } catch (const Error& e) {
        // Damage the integrity check listed can stop the key check: say it.
        if (e.kind() == ErrorKind::Busy)
            throw;
        problems += (problems.empty() ? "" : "; ") + std::string(e.what());
    }
    return problems;
}

} // namespace k528::db
