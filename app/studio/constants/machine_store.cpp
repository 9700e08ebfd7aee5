#include "constants/machine_store.h"

#include "db/location.h"

#include <filesystem>

namespace k528::studio {

MachineStore::MachineStore(profile::MachineProfile base) : base_(std::move(base)) {}

db::Database MachineStore::open() const {
    const std::filesystem::path path = db::defaultDatabasePath();
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec); // open() says why if this failed
    return db::Database::open(path);
}

void MachineStore::ensureMachine(db::Database& d) const {
    if (d.hasMachine(base_.name))
        return;
    db::WriteOptions o;
    o.summary = "the machine as K528 Studio loaded it";
    o.action = "create";
    o.allowErrors = true; // a trainer's faulty machine is stored as it ran
    d.createMachine(base_, o);
}

MachineStore::Kept MachineStore::keep(const db::Edit& edit, const QString& note) const {
    Kept k;
    try {
        db::Database d = open();
        ensureMachine(d);
        db::WriteOptions o;
        o.summary = note.toStdString();
        o.action = "set";
        const db::SaveResult r = d.applyEdit(base_.name, edit, o);
        k.revision = r.revision;
        k.changes = static_cast<int>(r.changes.size());
    } catch (const std::exception& e) {
        k.error = QString::fromUtf8(e.what());
    }
    return k;
}

MachineStore::Kept MachineStore::keepProfile(profile::MachineProfile p, const QString& note,
                                             std::function<void(std::size_t, std::size_t)> progress) const {
    Kept k;
    try {
        db::Database d = open();
        ensureMachine(d);
        p.name = base_.name;
        db::WriteOptions o;
        o.summary = note.toStdString();
        o.action = "import";
        o.progress = std::move(progress);
        const db::SaveResult r = d.saveMachine(base_.name, p, o);
        k.revision = r.revision;
        k.changes = static_cast<int>(r.changes.size());
    } catch (const db::ValidationError& e) {
        std::string text = e.what();
        for (const profile::Finding& f : e.findings())
            text += "\n" + profile::formatFinding(f);
        k.error = QString::fromStdString(text);
    } catch (const std::exception& e) {
        k.error = QString::fromUtf8(e.what());
    }
    return k;
}

std::vector<db::RevisionInfo> MachineStore::revisions() const {
    db::Database d = open();
    if (!d.hasMachine(base_.name))
        return {};
    return d.revisions(base_.name);
}

std::vector<db::HistoryEntry> MachineStore::history(const std::string& key) const {
    db::Database d = open();
    if (!d.hasMachine(base_.name))
        return {};
    return d.history(base_.name, key);
}

profile::MachineProfile MachineStore::load(int revision) const {
    return open().loadMachine(base_.name, revision);
}

profile::MachineProfile MachineStore::current() const {
    db::Database d = open();
    return d.hasMachine(base_.name) ? d.loadMachine(base_.name) : base_;
}

} // namespace k528::studio
