// db::Database: programs released for the controllers, the transfer log and
// the notices of other sessions' changes — the same rules for every backend.
#include "db/database.h"
#include "db/database_impl.h"

#include <algorithm>
#include <map>

namespace k528::db {

std::string_view programStateName(ProgramState s) {
    switch (s) {
    case ProgramState::Draft: return "draft";
    case ProgramState::Released: return "released";
    case ProgramState::Withdrawn: return "withdrawn";
    }
    return "";
}

namespace {

// One program's state from its current version (0: none) and its newest
// release or withdrawal.
ProgramRelease stateOf(int number, int current, const std::optional<ReleaseEntry>& last) {
    ProgramRelease p;
    p.number = number;
    p.revision = current;
    p.last = last;
    if (last && last->released && current != 0) {
        p.releasedRevision = last->revision;
        p.releasedSha256 = last->sha256;
        p.state = last->revision == current ? ProgramState::Released : ProgramState::Draft;
    } else if (last) {
        // Withdrawn, or deleted from the machine since its release: nothing to push.
        p.state = ProgramState::Withdrawn;
    }
    return p;
}

} // namespace

ReleaseEntry Database::releaseProgram(std::string_view name, int number, const std::string& note,
                                      WriteOptions options) {
    Store& s = *d_->store;
    return asRole(s, DeniedAction::ReleaseProgram, kTechnologist, [&] {
        WriteTransaction tx(s);
        const MachineRow row = requireMachine(s, name);
        const auto v = s.programAt(row.id, number, row.info.revision);
        if (!v || !v->text)
            throw Error(ErrorKind::NoRevision,
                        ErrorText{"release.no-program", {row.info.name, std::to_string(number),
                                                         std::to_string(row.info.revision)}});
        const auto states = s.programStates(row.id, number);
        if (!states.empty() && states.front().released && states.front().revision == v->revision)
            return states.front(); // released already: nothing to write
        const std::string at = formatTimestamp(d_->clock());
        const std::string author = authorOf(s, options.author);
        s.insertProgramState(row.id, ReleaseEntry{number, v->revision, v->sha256.value_or(""), true,
                                                  at, author, note});
        s.insertAudit(AuditEntry{0, at, author, "release", row.info.name, row.info.revision,
                                 "L" + std::to_string(number) + " as of revision " +
                                     std::to_string(v->revision) + " released" +
                                     (note.empty() ? "" : ": " + note)});
        s.notifyChange(row.info.name, row.info.revision);
        ReleaseEntry stored = s.programStates(row.id, number).front();
        tx.commit();
        return stored;
    });
}

ReleaseEntry Database::withdrawProgram(std::string_view name, int number, const std::string& note,
                                       WriteOptions options) {
    Store& s = *d_->store;
    return asRole(s, DeniedAction::WithdrawProgram, kTechnologist, [&] {
        WriteTransaction tx(s);
        const MachineRow row = requireMachine(s, name);
        const auto states = s.programStates(row.id, number);
        if (states.empty() || !states.front().released)
            throw Error(ErrorKind::Invalid, ErrorText{states.empty() ? "release.never" : "release.withdrawn",
                                                      {row.info.name, std::to_string(number)}});
        const std::string at = formatTimestamp(d_->clock());
        const std::string author = authorOf(s, options.author);
        const ReleaseEntry& released = states.front();
        s.insertProgramState(row.id, ReleaseEntry{number, released.revision, released.sha256, false,
                                                  at, author, note});
        s.insertAudit(AuditEntry{0, at, author, "withdraw", row.info.name, row.info.revision,
                                 "L" + std::to_string(number) + " as of revision " +
                                     std::to_string(released.revision) + " withdrawn" +
                                     (note.empty() ? "" : ": " + note)});
        s.notifyChange(row.info.name, row.info.revision);
        ReleaseEntry stored = s.programStates(row.id, number).front();
        tx.commit();
        return stored;
    });
}

std::vector<ProgramRelease> Database::programReleases(std::string_view name) const {
    Store& s = *d_->store;
    ReadSnapshot tx(s);
    const MachineRow row = requireMachine(s, name);
    std::map<int, int> current; // number -> its current version
    for (const ProgramRow& p : s.programsAt(row.id, row.info.revision))
        current[p.number] = p.revision;
    std::map<int, ReleaseEntry> last; // number -> its newest state
    for (ReleaseEntry& e : s.programStates(row.id, std::nullopt))
        last.try_emplace(e.number, std::move(e));
    std::vector<ProgramRelease> out;
    for (const auto& [n, rev] : current) {
        const auto it = last.find(n);
        out.push_back(stateOf(n, rev, it == last.end() ? std::nullopt : std::optional(it->second)));
    }
    for (const auto& [n, e] : last)
        if (!current.contains(n))
            out.push_back(stateOf(n, 0, e));
    std::sort(out.begin(), out.end(),
              [](const ProgramRelease& a, const ProgramRelease& b) { return a.number < b.number; });
    return out;
}

std::vector<ReleaseEntry> Database::releaseHistory(std::string_view name, int number) const {
    Store& s = *d_->store;
    ReadSnapshot tx(s);
    return s.programStates(requireMachine(s, name).id, number);
}

TransferEntry Database::recordTransfer(TransferEntry entry) {
    Store& s = *d_->store;
    if (entry.direction != "push" && entry.direction != "pull")
        throw Error(ErrorKind::Invalid, ErrorText{"transfer.direction", {entry.direction}});
    if (entry.result != "ok" && entry.result != "partial" && entry.result != "failed")
        throw Error(ErrorKind::Invalid, ErrorText{"transfer.result", {entry.result}});
    if (entry.at.empty())
        entry.at = formatTimestamp(d_->clock());
    if (entry.user.empty())
        entry.user = authorOf(s, {});
    if (entry.host.empty())
        entry.host = hostName();
    return asRole(s, DeniedAction::RecordTransfer, kOperator, [&] {
        WriteTransaction tx(s);
        entry.id = s.insertTransfer(entry);
        TransferFilter f;
        f.limit = 1;
        auto stored = s.transfers(f);
        tx.commit();
        return stored.empty() ? entry : stored.front();
    });
}

std::vector<TransferEntry> Database::transfers(const TransferFilter& filter) const {
    Store& s = *d_->store;
    ReadSnapshot tx(s);
    return s.transfers(filter);
}

std::vector<RoleInfo> Store::roles(bool) {
    throw Error(ErrorKind::Invalid, ErrorText{"roles.sqlite", {path().string()}});
}

void Store::grantRole(const std::string&, const std::string&) {
    roles(false);
}

std::vector<RoleInfo> Database::setUpRoles() {
    return d_->store->roles(true);
}

void Database::grantRole(const std::string& user, const std::string& role) {
    d_->store->grantRole(user, role);
}

std::vector<RoleInfo> Database::roles() const {
    return d_->store->roles(false);
}

bool Database::mayActAs(std::string_view role) const {
    return d_->store->mayActAs(role);
}

bool Database::changedElsewhere(std::vector<std::string>* machines) {
    std::vector<std::string> names;
    const bool changed = d_->store->changedElsewhere(names);
    if (machines)
        *machines = std::move(names);
    return changed;
}

} // namespace k528::db
