// db::Database: the rules of the store, the same for every backend — what a
// write checks, the one revision it makes and what that records, the audit
// entry, the state at a revision rebuilt from the history, releases of
// programs and the transfer log. The rows are the backend's (store.h;
// sqlite_store.h, postgres_store.h), the revision rules revisions.h's.
#include "db/database.h"
#include "db/notes.h"

#include "db/database_impl.h"
#include "db/postgres_store.h"
#include "db/revisions.h"
#include "db/sha256.h"
#include "db/sqlite_store.h"
#include "catalog/cparams.h"
#include "profile/builtin.h"
#include "profile/settings.h"


namespace k528::db {

namespace fs = std::filesystem;
using profile::Change;
using profile::DiffSection;
using profile::MachineProfile;

namespace {

// The machine's row: inserted for a new machine, updated (name, title,
// revision) otherwise. Returns its id.
std::int64_t writeMachineRow(Store& s, const std::optional<MachineRow>& row,
                             const MachineProfile& neu, int revision, const std::string& at,
                             const std::string& author) {
    if (!row) {
        if (s.findMachine(neu.name))
            throw Error(ErrorKind::MachineExists, ErrorText{"machine-exists", {neu.name, s.path().string()}});
        return s.insertMachine(neu, at, author);
    }
    if (neu.name != row->info.name && s.findMachine(neu.name))
        throw Error(ErrorKind::MachineExists, ErrorText{"rename-exists", {row->info.name, neu.name}});
    s.updateMachine(row->id, neu, revision, at, author);
    return row->id;
}

// The trainer's lock of a machine's constants for a class (the setting
// constants.lock, its value the class; docs/training-course.md): while the
// stored machine holds it, a write that changes a constant is refused —
// whoever writes, by whatever program (k528 db set/import, the studio);
// setting or clearing it is the trainer's (PostgreSQL: the role k528_trainer).
void checkConstantsLock(Store& s, const MachineProfile* old, const MachineProfile& neu,
                        const std::vector<Change>& changes) {
    const std::string locked = old ? old->simulation.getString(kConstantsLockKey, "") : std::string();
    bool lockChanged = false;
    std::string constants; // the constants the write changes: "C022, C040"
    for (const Change& c : changes) {
        if (c.section == DiffSection::Simulation && c.key == kConstantsLockKey)
            lockChanged = true;
        else if (c.section == DiffSection::C && constants.size() < 60)
            constants += (constants.empty() ? "" : ", ") + c.key;
    }
    if (lockChanged && !s.mayActAs(kTrainer))
        throw DeniedError(s.path().string(), DeniedAction::LockConstants, std::string(kTrainer), s.sessionUser(),
                          s.rolesOfUser(), "K528 Studio's rule: only a trainer locks and unlocks the constants");
    if (!locked.empty() && !constants.empty())
        throw ValidationError(
            ErrorText{"constants-locked", {neu.name, locked, std::string(kConstantsLockKey), constants}});
}

// Makes `neu` the state of the machine `row` (nullopt: a new machine) whose
// state was `old`, as one revision, inside the caller's write transaction.
SaveResult write(Store& s, const Clock& clock, const std::optional<MachineRow>& row,
                 const MachineProfile* old, const MachineProfile& neu, const WriteOptions& o) {
    const std::string author = authorOf(s, o.author);
    SaveResult result;
    result.findings = revision::checkWrite(old, neu, o.allowErrors);
    result.changes = revision::computeChanges(old, neu);
    checkConstantsLock(s, old, neu, result.changes);
    const int revision = row ? row->info.revision + 1 : 1;
    if (old && result.changes.empty()) {
        result.changed = false;
        result.revision = row->info.revision;
        return result;
    }
    result.changed = true;
    result.revision = revision;
    const std::string at = formatTimestamp(clock()); // one time for the whole write
    const std::int64_t id = writeMachineRow(s, row, neu, revision, at, author);
    const std::string summary =
        !o.summary.empty() ? o.summary
                           : noteText(row ? changedNote(result.changes) : Note{"created", {}});
    s.insertRevision(id, revision, author, at, summary, revision::joinKeys(neu.simulation, '\n'));
    bool settingsChanged = false;
    int seq = 0;
    for (const Change& c : result.changes) {
        Change recorded = c;
        if (c.section == DiffSection::Program) {
            // The texts are versions of their own; the change records their checksums.
            s.insertProgramVersion(id, ProgramRow{*revision::keyNumber(c.key), revision, c.after,
                                                  c.after ? std::optional(sha256Hex(*c.after))
                                                          : std::nullopt});
            if (recorded.before)
                recorded.before = sha256Hex(*recorded.before);
            if (recorded.after)
                recorded.after = sha256Hex(*recorded.after);
        } else if (c.section == DiffSection::Simulation) {
            settingsChanged = true;
        } else {
            s.writeItem(id, !row, neu, c);
        }
        s.insertChange(id, revision, seq++, author, at, recorded);
        if (o.progress)
            o.progress(static_cast<std::size_t>(seq), result.changes.size());
    }
    if (settingsChanged)
        s.writeSettings(id, neu);
    s.insertAudit(AuditEntry{0, at, author, o.action, neu.name, revision,
                             summary + " (" + std::to_string(result.changes.size()) +
                                 (result.changes.size() == 1 ? " change)" : " changes)")});
    s.notifyChange(neu.name, revision);
    return result;
}

// The state at `revision`, rebuilt forward from the recorded changes.
MachineProfile loadAt(Store& s, const MachineRow& row, int revision) {
    if (revision < 1 || revision > row.info.revision)
        throw Error(ErrorKind::NoRevision, ErrorText{"no-revision", {row.info.name, std::to_string(row.info.revision),
                                                                     std::to_string(revision)}});
    // The machine, the revision and the file, then what is wrong.
    const auto corrupt = [&](std::string id, std::vector<std::string> args) {
        args.insert(args.begin(), {row.info.name, std::to_string(revision), s.path().string()});
        return Error(ErrorKind::Corrupt, ErrorText{std::move(id), std::move(args)});
    };
    MachineProfile p;
    for (const ChangeRow& c : s.changesUpTo(row.id, revision)) {
        const auto section = revision::sectionFromName(c.section);
        if (!section || !revision::applyRecorded(p, *section, c.key, c.after))
            throw corrupt("corrupt.history-entry", {c.section, c.key, std::to_string(c.revision)});
    }
    const auto order = s.settingsOrder(row.id, revision);
    if (!order)
        throw corrupt("corrupt.revision-missing", {});
    if (auto [id, args] = revision::orderSettings(p, *order); !id.empty())
        throw corrupt(std::move(id), std::move(args));
    for (const ProgramRow& v : s.programsAt(row.id, revision)) {
        if (!v.text || sha256Hex(*v.text) != v.sha256.value_or(""))
            throw corrupt("corrupt.revision-program", {std::to_string(v.number), std::to_string(v.revision)});
        p.programs[v.number] = *v.text;
    }
    return p;
}

void requireRevision(const MachineRow& row, const WriteOptions& o, bool detailed) {
    if (!o.expectedRevision || *o.expectedRevision == row.info.revision)
        return;
    const std::string at = std::to_string(row.info.revision), read = std::to_string(*o.expectedRevision);
    throw Error(ErrorKind::Conflict,
                detailed ? ErrorText{"conflict.detailed", {row.info.name, at, row.info.changedBy, row.info.changedAt, read}}
                         : ErrorText{"conflict", {row.info.name, at, read}});
}

} // namespace

Database::Database(std::unique_ptr<Impl> impl) : d_(std::move(impl)) {}
Database::Database(Database&&) noexcept = default;
Database& Database::operator=(Database&&) noexcept = default;
Database::~Database() = default;

Database Database::open(const fs::path& path, const OpenOptions& options) {
    return open(Location(path), options);
}

Database Database::open(const Location& where, const OpenOptions& options) {
    auto impl = std::make_unique<Impl>();
    impl->clock = options.clock ? options.clock : systemClock();
    impl->location = where;
    const std::string author = options.author;
    const Clock clock = impl->clock;
    // A new database gets the built-in machines in the transaction that creates it.
    const Fill seed = [&](Store& s) {
        std::vector<std::string> seeded;
        if (!options.seedBuiltins)
            return seeded;
        for (const std::string& name : profile::builtinNames()) {
            WriteOptions wo;
            wo.author = author;
            wo.action = "seed";
            wo.summary = noteText({"seed", {name}});
            write(s, clock, std::nullopt, nullptr, profile::builtin(name), wo);
            seeded.push_back(name);
        }
        return seeded;
    };
    if (where.backend() == Backend::Postgres)
        impl->store = PostgresStore::open(where, options, seed);
    else
        impl->store = SqliteStore::open(where.file(), options, seed);
    return Database(std::move(impl));
}

const Location& Database::location() const {
    return d_->location;
}

Backend Database::backend() const {
    return d_->store->backend();
}

std::string Database::sessionUser() const {
    return d_->store->sessionUser();
}

Store& Database::store() const {
    return *d_->store;
}

const fs::path& Database::path() const {
    return d_->store->path();
}

const OpenReport& Database::openReport() const {
    return d_->store->openReport();
}

ReadOnlyReason Database::readOnly() const {
    return d_->store->readOnly();
}

void Database::requireWritable() const {
    if (const ReadOnlyReason r = d_->store->readOnly(); r != ReadOnlyReason::None)
        throw ReadOnlyError(path(), r);
}

bool Database::snapshotOutdated() const {
    return d_->store->snapshotOutdated();
}

int Database::schemaVersion() const {
    return d_->store->schemaVersion();
}

std::vector<MachineInfo> Database::machines() const {
    return d_->store->machines();
}

std::optional<MachineInfo> Database::machine(std::string_view name) const {
    auto r = d_->store->findMachine(name);
    if (!r)
        return std::nullopt;
    return r->info;
}

bool Database::hasMachine(std::string_view name) const {
    return d_->store->findMachine(name).has_value();
}

MachineProfile Database::loadMachine(std::string_view name) const {
    Store& s = *d_->store;
    // Read in one snapshot by the store (PostgreSQL: one statement, no
    // transaction around it).
    if (auto loaded = s.loadNamed(name))
        return std::move(loaded->profile);
    ReadSnapshot tx(s);
    return requireLoaded(s, name).profile; // no such machine: says which there are
}

MachineProfile Database::loadMachine(std::string_view name, int revision) const {
    Store& s = *d_->store;
    ReadSnapshot tx(s);
    return loadAt(s, requireMachine(s, name), revision);
}

SaveResult Database::createMachine(const MachineProfile& p, WriteOptions options) {
    if (options.action == "save")
        options.action = "create";
    Store& s = *d_->store;
    return asRole(s, DeniedAction::CreateMachine, kTechnologist, [&] {
        WriteTransaction tx(s);
        SaveResult r = write(s, d_->clock, std::nullopt, nullptr, p, options);
        tx.commit();
        return r;
    });
}

SaveResult Database::saveMachine(std::string_view name, const MachineProfile& p,
                                 WriteOptions options) {
    Store& s = *d_->store;
    return asRole(s, DeniedAction::ChangeMachine, kTechnologist, [&] {
        WriteTransaction tx(s);
        const LoadedMachine loaded = requireLoaded(s, name);
        const MachineRow& row = loaded.row;
        requireRevision(row, options, true);
        const MachineProfile& old = loaded.profile;
        SaveResult r = write(s, d_->clock, row, &old, p, options);
        tx.commit();
        return r;
    });
}

namespace {

// The item of `edit` its machine cannot hold (Edit::applyTo threw), as a
// problem: a C-parameter that does not exist, a simulation key or value that
// is not one.
profile::Problem editProblem(const Edit& edit) {
    profile::Problem item;
    for (const auto& [n, v] : edit.c)
        if (!catalog::findCParam(n)) {
            item = profile::problem("c.none", {std::to_string(n)});
            break;
        }
    for (const auto& [k, v] : edit.simulation) {
        if (!item.empty() || !v)
            break;
        if (profile::Problem e = profile::settingKeyProblem(k); !e.empty()) {
            item = profile::problem("setting.key");
            item.within.push_back(std::move(e));
        } else if (profile::Problem e2 = profile::settingValueProblem(*v); !e2.empty()) {
            item = profile::problem("setting.value", {k});
            item.within.push_back(std::move(e2));
        }
    }
    return item;
}

// The refusal of an edit the machine cannot hold: the item's problem, or the
// library's words when no item says it (an error without an id).
[[noreturn]] void throwEditRejection(const std::string& machine, const Edit& edit, const std::exception& e) {
    if (profile::Problem item = editProblem(edit); !item.empty())
        throw ValidationError(machine, std::move(item));
    throw Error(ErrorKind::Invalid, "machine " + machine + ": " + e.what(), e.what(), machine);
}

} // namespace

SaveResult Database::applyEdit(std::string_view name, const Edit& edit, WriteOptions options) {
    if (options.action == "save")
        options.action = "set";
    Store& s = *d_->store;
    return asRole(s, DeniedAction::ChangeMachine, kTechnologist, [&] {
        WriteTransaction tx(s);
        const LoadedMachine loaded = requireLoaded(s, name);
        const MachineRow& row = loaded.row;
        requireRevision(row, options, false);
        const MachineProfile& old = loaded.profile;
        MachineProfile neu = old;
        try {
            edit.applyTo(neu);
        } catch (const profile::SettingError& e) {
            throwEditRejection(row.info.name, edit, e);
        } catch (const std::out_of_range& e) {
            throwEditRejection(row.info.name, edit, e);
        }
        if (options.summary.empty())
            options.summary = noteText({"set", {edit.describe()}});
        SaveResult r = write(s, d_->clock, row, &old, neu, options);
        tx.commit();
        return r;
    });
}

void Database::removeMachine(std::string_view name, WriteOptions options) {
    Store& s = *d_->store;
    const std::string author = authorOf(s, options.author);
    asRole(s, DeniedAction::DeleteMachine, kTechnologist, [&] {
        WriteTransaction tx(s);
        const auto row = requireMachine(s, name);
        s.deleteMachine(row.id);
        s.insertAudit(AuditEntry{0, formatTimestamp(d_->clock()), author, "delete", row.info.name,
                                 row.info.revision,
                                 options.summary.empty() ? "machine deleted with its " +
                                                               std::to_string(row.info.revision) +
                                                               " revisions"
                                                         : options.summary});
        tx.commit();
    });
}

std::vector<RevisionInfo> Database::revisions(std::string_view name) const {
    Store& s = *d_->store;
    ReadSnapshot tx(s);
    return s.revisions(requireMachine(s, name).id);
}

std::vector<HistoryEntry> Database::history(std::string_view name, std::optional<std::string> key,
                                            int limitRevisions) const {
    Store& s = *d_->store;
    // Read in one snapshot by the store (PostgreSQL: one statement, no
    // transaction around it).
    auto changes = s.historyNamed(name, limitRevisions, key);
    if (!changes) { // no such machine (requireMachine says which there are), or no changes
        ReadSnapshot tx(s);
        const auto row = requireMachine(s, name);
        changes = s.history(row.id,
                            limitRevisions > 0 ? row.info.revision - limitRevisions + 1 : 1, key);
    }
    std::vector<HistoryEntry> out;
    for (ChangeRow& c : *changes) {
        const auto section = revision::sectionFromName(c.section);
        if (!section)
            throw Error(ErrorKind::Corrupt, ErrorText{"corrupt.history-section", {std::string(name), c.section}});
        out.push_back(HistoryEntry{c.revision, std::move(c.author), std::move(c.at),
                                   Change{*section, std::move(c.key), std::move(c.label),
                                          std::move(c.before), std::move(c.after)}});
    }
    return out;
}

std::vector<ProgramVersion> Database::programHistory(std::string_view name, int number) const {
    Store& s = *d_->store;
    ReadSnapshot tx(s);
    std::vector<ProgramVersion> out;
    for (ProgramRow& v : s.programVersions(requireMachine(s, name).id, number))
        out.push_back(ProgramVersion{v.revision, std::move(v.text), std::move(v.sha256)});
    return out;
}

std::optional<std::string> Database::programText(std::string_view name, int number,
                                                 int revision) const {
    Store& s = *d_->store;
    ReadSnapshot tx(s);
    const auto row = requireMachine(s, name);
    const auto v = s.programAt(row.id, number, revision);
    if (!v)
        return std::nullopt;
    if (v->text && sha256Hex(*v->text) != v->sha256.value_or(""))
        throw Error(ErrorKind::Corrupt, ErrorText{"corrupt.program", {row.info.name, std::to_string(number)}});
    return v->text;
}

std::vector<AuditEntry> Database::audit(int limit, std::string_view machine) const {
    return d_->store->audit(limit, machine);
}

std::string_view integrityProblemName(IntegrityProblem::Kind kind) {
    using K = IntegrityProblem::Kind;
    switch (kind) {
    case K::Pages: return "pages";
    case K::ForeignKey: return "foreign-key";
    case K::ProgramChecksum: return "program-checksum";
    case K::ChangeAuthors: return "change-authors";
    case K::ItemHistoryDiffers: return "item-history-differs";
    case K::ItemHistoryMissing: return "item-history-missing";
    case K::Revisions: return "revisions";
    }
    return "?";
}

std::vector<IntegrityProblem> Database::checkIntegrity() const {
    return d_->store->checkIntegrity();
}

} // namespace k528::db
