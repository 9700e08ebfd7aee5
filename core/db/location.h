// Where the database lives, and the profile the engine runs.
#pragma once

#include "profile/profile.h"

#include <filesystem>
#include <string_view>

namespace k528::db {

// The database of the command line and the desktop: $K528_DB if set and not
// empty, else $XDG_DATA_HOME/k528studio/k528.db, else
// $HOME/.local/share/k528studio/k528.db. Throws Error(Io) when neither
// $XDG_DATA_HOME nor $HOME is set.
std::filesystem::path defaultDatabasePath();

// The profile the engine should run for `nameOrPath`:
//   1. a machine of that name in the database at `dbPath` (default:
//      defaultDatabasePath()), when the file exists;
//   2. otherwise profile::load(nameOrPath): a built-in profile or a machine file.
// A missing database file is not an error (nothing is created); a damaged,
// foreign or newer one is (db::Error), rather than silently running another
// profile. profile::FileError when nothing fits.
profile::MachineProfile loadProfile(std::string_view nameOrPath,
                                    const std::filesystem::path& dbPath = {});

} // namespace k528::db
