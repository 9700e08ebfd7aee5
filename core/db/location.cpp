#include "db/location.h"

#include "db/database.h"
#include "profile/builtin.h"

#include <cstdlib>

namespace k528::db {

namespace fs = std::filesystem;

std::filesystem::path defaultDatabasePath() {
    if (const char* p = std::getenv("K528_DB"); p && *p)
        return fs::path(p);
    if (const char* x = std::getenv("XDG_DATA_HOME"); x && *x && fs::path(x).is_absolute())
        return fs::path(x) / "k528studio" / "k528.db";
    if (const char* h = std::getenv("HOME"); h && *h)
        return fs::path(h) / ".local" / "share" / "k528studio" / "k528.db";
    throw Error(ErrorKind::Io, "no database location: set K528_DB, XDG_DATA_HOME or HOME");
}

profile::MachineProfile loadProfile(std::string_view nameOrPath, const fs::path& dbPath) {
    const fs::path path = dbPath.empty() ? defaultDatabasePath() : dbPath;
    std::error_code ec;
    if (profile::checkName(nameOrPath).empty() && fs::exists(path, ec)) {
        OpenOptions o;
        o.create = false;
        Database d = Database::open(path, o);
        if (d.hasMachine(nameOrPath))
            return d.loadMachine(nameOrPath);
    }
    return profile::load(nameOrPath);
}

} // namespace k528::db
