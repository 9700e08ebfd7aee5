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
#include <atomic>
#include <memory>
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
        // Refused because another process or PC made a newer revision than
        // the one this window knew (error: the database's words: who, when).
        bool conflict = false;
        int known = 0;      // the revision the change was based on
        int newest = 0;     // the machine's revision in the database now
        QString newer;      // the revisions after `known`, a line each: who, when, what
    };
    // Stores `edit` as the machine's next revision with `note` as its summary,
    // based on known(): refused (conflict) when another process or PC made a
    // newer one since. `onNewest`: based on the newest revision instead (the
    // user's change applied again on top of the other's).
    Kept keep(const db::Edit& edit, const QString& note, bool onNewest = false) const;

    // The revision this window's view of the machine is based on (0: none
    // read yet, nothing refused); copies of the store share it.
    int known() const { return *known_; }
    void setKnown(int revision) const { *known_ = revision; }
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

    // After File > Database…: the machine as the window's database holds it
    // now, and known() its revision there (0 and the profile the window
    // started with when that database has no such machine).
    struct Reloaded {
        profile::MachineProfile profile;
        int revision = 0; // 0: not in this database
    };
    Reloaded reload() const;

private:
    void ensureMachine(db::Database& d) const;
    profile::MachineProfile base_;
    std::shared_ptr<std::atomic<int>> known_ = std::make_shared<std::atomic<int>>(0);
};

} // namespace k528::studio
