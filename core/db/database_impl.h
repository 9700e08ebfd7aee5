// What db::Database's parts share (internal to core/db): its state, the
// roles an action needs, who writes, the machine a call names.
#pragma once

#include "db/database.h"
#include "db/store.h"

#include <unistd.h>

namespace k528::db {

struct Database::Impl {
    std::unique_ptr<Store> store;
    Clock clock;
    Location location;
};

// The roles of docs/database.md (PostgreSQL): who may do what.
inline constexpr std::string_view kTechnologist = "k528_technologist";
inline constexpr std::string_view kOperator = "k528_operator";
inline constexpr std::string_view kTrainer = "k528_trainer"; // a technologist who locks the constants
// The machine setting of the trainer's lock of the constants (its value: the class).
inline constexpr std::string_view kConstantsLockKey = "constants.lock";

// Runs `f`; a refusal of the server's privileges becomes a DeniedError that
// names the action and the role it needs.
template <typename F>
decltype(auto) asRole(Store& s, DeniedAction action, std::string_view role, F&& f) {
    try {
        return f();
    } catch (const DeniedError&) {
        throw;
    } catch (const Error& e) {
        if (e.kind() != ErrorKind::Denied)
            throw;
        throw DeniedError(s.path().string(), action, std::string(role), s.sessionUser(), s.rolesOfUser(),
                          e.what());
    }
}

// The author of a write: the one given, else PostgreSQL's user, else the OS user's.
// A name, not a text: at most kMaxAuthorBytes (PostgreSQL keeps it in the
// index of the revisions' authors, whose rows have a size limit).
inline constexpr std::size_t kMaxAuthorBytes = 256;
inline std::string authorOf(Store& s, const std::string& given) {
    if (given.size() > kMaxAuthorBytes)
        throw Error(ErrorKind::Invalid, ErrorText{"author-too-long", {std::to_string(given.size()),
                                                                      std::to_string(kMaxAuthorBytes)}});
    if (!given.empty())
        return given;
    std::string user = s.sessionUser();
    return user.empty() ? defaultAuthor() : user;
}

// Refuses a database whose schema is older than `version`, the one that
// brought `what` ("attempts", "messages", "state-times": the end of the
// catalog's id "schema-lacks.…"): a file only read keeps the schema it has.
inline void requireSchema(Store& s, int version, std::string_view what) {
    if (s.schemaVersion() < version)
        throw Error(ErrorKind::Invalid,
                    ErrorText{"schema-lacks." + std::string(what),
                              {s.path().string(), std::to_string(s.schemaVersion()), std::to_string(version)}});
}

inline std::string hostName() {
    char buf[256] = {};
    if (::gethostname(buf, sizeof buf - 1) != 0 || !buf[0])
        return "unknown";
    return buf;
}

inline MachineRow requireMachine(Store& s, std::string_view name) {
    auto r = s.findMachine(name);
    if (!r) {
        std::string known;
        for (const MachineInfo& m : s.machines())
            known += (known.empty() ? "" : ", ") + m.name;
        throw Error(ErrorKind::NoMachine,
                    known.empty() ? ErrorText{"no-machine.none", {std::string(name), s.path().string()}}
                                  : ErrorText{"no-machine", {std::string(name), s.path().string(), known}});
    }
    return *r;
}

// The machine's row and current state (one round trip on PostgreSQL).
inline LoadedMachine requireLoaded(Store& s, std::string_view name) {
    if (auto loaded = s.loadNamed(name))
        return std::move(*loaded);
    const MachineRow row = requireMachine(s, name); // throws: no such machine
    return LoadedMachine{row, s.loadCurrent(row)};
}

} // namespace k528::db
