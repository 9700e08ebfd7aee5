#include "constants/machine_store.h"
#include "db/notes.h"
#include "session/core_texts.h"

#include "session/shop_database.h"

#include <QCoreApplication>
#include <algorithm>

namespace k528::studio {

MachineStore::MachineStore(profile::MachineProfile base) : base_(std::move(base)) {
    // The window's view of the machine is the database's revision now.
    try {
        ShopDatabase::at()->use([&](db::Database& d) {
            if (const auto m = d.machine(base_.name))
                setKnown(m->revision);
        });
    } catch (const std::exception&) {
        // told where the database is used
    }
}

void MachineStore::ensureMachine(db::Database& d) const {
    if (d.hasMachine(base_.name))
        return;
    db::WriteOptions o;
    o.summary = db::noteText({"studio.loaded", {}});
    o.action = "create";
    o.allowErrors = true; // a trainer's faulty machine is stored as it ran
    const db::SaveResult r = d.createMachine(base_, o);
    ShopDatabase::at()->noteOwn(base_.name, r.revision);
}

MachineStore::Kept MachineStore::keep(const db::Edit& edit, const QString& note, bool onNewest) const {
    Kept k;
    try {
        const auto shop = ShopDatabase::at();
        shop->use([&](db::Database& d) {
            ensureMachine(d);
            db::WriteOptions o;
            o.summary = note.toStdString();
            o.action = "set";
            const int now = d.machine(base_.name)->revision;
            k.known = known();
            // Newer revisions this window made itself (a program saved, the
            // memory kept) are no one else's change.
            if (k.known > 0 && !onNewest)
                o.expectedRevision = shop->allOwn(base_.name, k.known, now) ? now : k.known;
            const db::SaveResult r = d.applyEdit(base_.name, edit, o);
            k.revision = r.revision;
            k.changes = static_cast<int>(r.changes.size());
            if (r.changed)
                shop->noteOwn(base_.name, r.revision);
            setKnown(r.revision);
        });
    } catch (const db::Error& e) {
        k.error = coreErrorText(e);
        if (e.kind() == db::ErrorKind::Conflict) {
            k.conflict = true;
            try {
                ShopDatabase::at()->use([&](db::Database& d) {
                    for (const db::RevisionInfo& r : d.revisions(base_.name)) {
                        if (r.revision <= k.known)
                            break;
                        k.newest = std::max(k.newest, r.revision);
                        k.newer += QCoreApplication::translate("k528::studio::MachineStore",
                                                               "revision %1 by %2 at %3: %4\n")
                                       .arg(r.revision)
                                       .arg(QString::fromStdString(r.author), QString::fromStdString(r.at),
                                            revisionNoteText(r.summary));
                    }
                });
            } catch (const std::exception&) {
            }
        }
    } catch (const std::exception& e) {
        k.error = coreErrorText(e);
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
            if (r.changed)
                ShopDatabase::at()->noteOwn(base_.name, r.revision);
            setKnown(r.revision);
        });
    } catch (const std::exception& e) {
        k.error = coreErrorText(e); // a file's or the cross-checks' refusal, or the database's
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

MachineStore::Reloaded MachineStore::reload() const {
    Reloaded r;
    setKnown(0); // the other database's revision means nothing here
    ShopDatabase::at()->use([&](db::Database& d) {
        // The revision before the load: a revision made between the two is
        // then one this window does not know (a change is refused and offered
        // again on top of it, never made over it unseen).
        const auto m = d.machine(base_.name);
        if (!m)
            return;
        r.profile = d.loadMachine(base_.name);
        r.revision = m->revision;
    });
    if (r.revision == 0)
        r.profile = base_;
    setKnown(r.revision);
    return r;
}

} // namespace k528::studio
