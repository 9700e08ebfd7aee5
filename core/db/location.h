// Where the database lives — an SQLite file or a PostgreSQL database — and
// the profile the engine runs.
#pragma once

#include "profile/profile.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace k528::db {

enum class Backend { Sqlite, Postgres };
std::string_view backendName(Backend b); // "sqlite", "postgresql"

// A database location as every command and the desktop take it: a path or
// `sqlite:PATH` (an SQLite file), or a libpq URI `postgresql://…` /
// `postgres://…` (`postgresql://` alone takes everything from the PG*
// variables: PGHOST, PGPORT, PGDATABASE, PGUSER, PGSERVICE…). A password
// never goes into a location: libpq reads it from ~/.pgpass (PGPASSFILE), a
// service file (PGSERVICEFILE, `postgresql://?service=shop`) or PGPASSWORD.
class Location {
public:
    Location() = default;
    // An SQLite file.
    explicit Location(std::filesystem::path file);
    // Throws Error(Invalid): an empty text, a URI with a password
    // (`postgresql://user:secret@host/db`, `?password=…`), another scheme
    // (`mysql://…`).
    static Location parse(std::string_view text);

    Backend backend() const { return backend_; }
    bool isFile() const { return backend_ == Backend::Sqlite; }
    bool empty() const { return backend_ == Backend::Sqlite && file_.empty(); }
    // The SQLite file ("" for PostgreSQL).
    const std::filesystem::path& file() const { return file_; }
    // The libpq URI as given ("" for SQLite).
    const std::string& uri() const { return uri_; }
    // What messages and the desktop show: the file, or the URI.
    std::string text() const;

    friend bool operator==(const Location&, const Location&) = default;

private:
    Backend backend_ = Backend::Sqlite;
    std::filesystem::path file_;
    std::string uri_;
};

// The database of the command line and the desktop: $K528_DB if set and not
// empty (a path or a URI), else $XDG_DATA_HOME/k528studio/k528.db, else
// $HOME/.local/share/k528studio/k528.db. Throws Error(Io) when neither
// $XDG_DATA_HOME nor $HOME is set, Error(Invalid) for a bad $K528_DB.
Location defaultDatabaseLocation();
// The same when it is a file; Error(Invalid) when $K528_DB names a server.
std::filesystem::path defaultDatabasePath();

// The profile the engine should run for `nameOrPath`:
//   1. a machine of that name in the database at `db` (default:
//      defaultDatabaseLocation()), when the database exists (a file that
//      exists; a server is asked);
//   2. otherwise profile::load(nameOrPath): a built-in profile or a machine file.
// A missing database file is not an error (nothing is created); a damaged,
// foreign or newer one is (db::Error), rather than silently running another
// profile. profile::FileError when nothing fits.
profile::MachineProfile loadProfile(std::string_view nameOrPath, const Location& db = {});
// `dbText` as --db gives it ("" for the default).
profile::MachineProfile loadProfile(std::string_view nameOrPath, const std::string& dbText);

} // namespace k528::db
