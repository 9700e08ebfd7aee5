#include "db/location.h"

#include "db/database.h"
#include "profile/builtin.h"

#include <cstdlib>

namespace k528::db {

namespace fs = std::filesystem;

std::string_view backendName(Backend b) {
    return b == Backend::Postgres ? "postgresql" : "sqlite";
}

Location::Location(fs::path file) : backend_(Backend::Sqlite), file_(std::move(file)) {}

namespace {

bool startsWith(std::string_view s, std::string_view prefix) {
    return s.substr(0, prefix.size()) == prefix;
}

[[noreturn]] void invalid(std::string_view text, std::string id, std::vector<std::string> more = {}) {
    more.insert(more.begin(), std::string(text));
    throw Error(ErrorKind::Invalid, ErrorText{std::move(id), std::move(more)});
}

// A libpq URI: postgresql://[user[:password]@][host][:port][/dbname][?param=value&…].
void checkUri(std::string_view text) {
    const std::string_view rest = text.substr(text.find("://") + 3);
    const auto query = rest.find('?');
    const std::string_view authority = rest.substr(0, rest.find_first_of("/?"));
    if (const auto at = authority.rfind('@'); at != std::string_view::npos &&
                                              authority.substr(0, at).find(':') != std::string_view::npos)
        invalid(text, "location.password");
    if (query != std::string_view::npos) {
        std::string_view params = rest.substr(query + 1);
        while (!params.empty()) {
            const auto amp = params.find('&');
            const std::string_view p = params.substr(0, amp);
            if (startsWith(p, "password="))
                invalid(text, "location.password");
            params = amp == std::string_view::npos ? std::string_view() : params.substr(amp + 1);
        }
    }
}

} // namespace

Location Location::parse(std::string_view text) {
    if (text.empty())
        invalid(text, "location.empty");
    Location l;
    if (startsWith(text, "postgresql://") || startsWith(text, "postgres://")) {
        checkUri(text);
        l.backend_ = Backend::Postgres;
        l.uri_ = std::string(text);
        return l;
    }
    if (startsWith(text, "sqlite:")) {
        std::string_view p = text.substr(7);
        if (startsWith(p, "//"))
            p = p.substr(2); // sqlite:///abs/path
        if (p.empty())
            invalid(text, "location.sqlite-path");
        l.file_ = fs::path(std::string(p));
        return l;
    }
    if (const auto scheme = text.find("://"); scheme != std::string_view::npos &&
                                              text.find('/') > scheme)
        invalid(text, "location.unknown-kind", {std::string(text.substr(0, scheme))});
    l.file_ = fs::path(std::string(text));
    return l;
}

std::string Location::text() const {
    return backend_ == Backend::Postgres ? uri_ : file_.string();
}

Location defaultDatabaseLocation() {
    if (const char* p = std::getenv("K528_DB"); p && *p)
        return Location::parse(p);
    if (const char* x = std::getenv("XDG_DATA_HOME"); x && *x && fs::path(x).is_absolute())
        return Location(fs::path(x) / "k528studio" / "k528.db");
    if (const char* h = std::getenv("HOME"); h && *h)
        return Location(fs::path(h) / ".local" / "share" / "k528studio" / "k528.db");
    throw Error(ErrorKind::Io, ErrorText{"location.none", {}});
}

fs::path defaultDatabasePath() {
    const Location l = defaultDatabaseLocation();
    if (!l.isFile())
        throw Error(ErrorKind::Invalid, ErrorText{"location.postgres", {l.text()}});
    return l.file();
}

profile::MachineProfile loadProfile(std::string_view nameOrPath, const Location& given) {
    const Location where = given.empty() ? defaultDatabaseLocation() : given;
    std::error_code ec;
    if (profile::checkName(nameOrPath).empty() && (!where.isFile() || fs::exists(where.file(), ec))) {
        OpenOptions o;
        o.create = false;
        Database d = Database::open(where, o);
        if (d.hasMachine(nameOrPath))
            return d.loadMachine(nameOrPath);
    }
    return profile::load(nameOrPath);
}

profile::MachineProfile loadProfile(std::string_view nameOrPath, const std::string& dbText) {
    return loadProfile(nameOrPath, dbText.empty() ? Location() : Location::parse(dbText));
}

} // namespace k528::db
