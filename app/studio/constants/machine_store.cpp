#include "constants/machine_store.h"

#include "session/shop_database.h"

namespace k528::studio {

MachineStore::MachineStore(profile::MachineProfile base) : base_(std::move(base)) {}

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
        ShopDatabase::at()->use([&](db::Database& d) {
            ensureMachine(d);
            db::WriteOptions o;
            o.summary = note.toStdString();
            o.action = "set";
            const db::SaveResult r = d.applyEdit(base_.name, edit, o);
            k.revision = r.revision;
            k.changes = static_cast<int>(r.changes.size());
        });
    } catch (const std::exception& e) {
        k.error = databaseErrorText(e);
    }
    return k;
}

MachineStore::Kept MachineStore::keepProfile(profile::MachineProfile p, const QString& note,
                                             std::function<void(std::size_t, std::size_t)> progress) const {
    Kept k;
    try {
        ShopDatabase::at()->use([&](db::Database& d) {
            ensureMachine(d);
            p.name = base_.name;
            db::WriteOptions o;
            o.summary = note.toStdString();
            o.action = "import";
            o.progress = std::move(progress);
            const db::SaveResult r = d.saveMachine(base_.name, p, o);
            k.revision = r.revision;
            k.changes = static_cast<int>(r.changes.size());
        });
    } catch (const db::ValidationError& e) {
        std::string text = e.what();
        for (const profile::Finding& f : e.findings())
            text += "\n" + profile::formatFinding(f);
        k.error = QString::fromStdString(text);
    } catch (const std::exception& e) {
        k.error = databaseErrorText(e);
    }
    return k;
}

std::vector<db::RevisionInfo> MachineStore::revisions() const {
    return ShopDatabase::at()->use([&](db::Database& d) {
        return d.hasMachine(base_.name) ? d.revisions(base_.name) : std::vector<db::RevisionInfo>{};
    });
}

std::vector<db::HistoryEntry> MachineStore::history(const std::string& key) const {
    return ShopDatabase::at()->use([&](db::Database& d) {
        return d.hasMachine(base_.name) ? d.history(base_.name, key) : std::vector<db::HistoryEntry>{};
    });
}

profile::MachineProfile MachineStore::load(int revision) const {
    return ShopDatabase::at()->use([&](db::Database& d) { return d.loadMachine(base_.name, revision); });
}

profile::MachineProfile MachineStore::current() const {
    return ShopDatabase::at()->use(
        [&](db::Database& d) { return d.hasMachine(base_.name) ? d.loadMachine(base_.name) : base_; });
}

} // namespace k528::studio
