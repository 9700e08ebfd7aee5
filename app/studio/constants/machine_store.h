// The shop's database as the machine-data docks use it (constants, R presets):
// the machine the window simulates, its next revision for every change kept,
// its revisions, the history of one item and the state at a revision. Every
// call uses the process's connection (ShopDatabase), from any thread: a
// worker thread may call these while the window goes on.
// When the database has no machine of that name yet (a built-in profile or a
// machine file was loaded), the first change creates it from the profile the
// window started with, then stores the change as revision 2.
#pragma once

#include "db/database.h"
#include "profile/profile.h"

#include <QString>
#include <functional>
#include <string>
#include <vector>

namespace k528::studio {

class MachineStore {
public:
    // `base`: the machine as the window started with it (its name is the
    // machine's name in the database).
    explicit MachineStore(profile::MachineProfile base);

    const std::string& name() const { return base_.name; }
    QString qName() const { return QString::fromStdString(base_.name); }

    struct Kept {
        int revision = 0;   // 0: not kept (error says why)
        int changes = 0;    // items this revision changed
        QString error;
    };
    // Stores `edit` as the machine's next revision with `note` as its summary.
    Kept keep(const db::Edit& edit, const QString& note) const;
    // Stores `p` (renamed to this machine) as the next revision; `progress`
    // (done, total) is called inside the transaction. Cross-check errors are
    // refused (db::ValidationError) as `k528 db import` refuses them.
    Kept keepProfile(profile::MachineProfile p, const QString& note,
                     std::function<void(std::size_t, std::size_t)> progress = {}) const;

    // Throw db::Error (the database cannot be used, no such revision).
    std::vector<db::RevisionInfo> revisions() const; // newest first; empty: not in the database
    std::vector<db::HistoryEntry> history(const std::string& key) const;
    profile::MachineProfile load(int revision) const;
    profile::MachineProfile current() const; // the stored state (base when not stored)

private:
    void ensureMachine(db::Database& d) const;
    profile::MachineProfile base_;
};

} // namespace k528::studio
