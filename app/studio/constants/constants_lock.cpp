#include "constants/constants_lock.h"

#include "constants/machine_store.h"
#include "db/notes.h"
#include "session/shop_database.h"

#include <QCoreApplication>
#include <map>

namespace k528::studio {

namespace {
// The C-parameter mode of the K923 (F5): where the panel writes the constants.
constexpr int kCParameterMode = 5;
} // namespace

ConstantsLock::ConstantsLock(profile::MachineProfile machine)
    : machine_(std::make_unique<profile::MachineProfile>(std::move(machine))) {
    refresh();
}

ConstantsLock* ConstantsLock::of(const profile::MachineProfile& machine) {
    static std::map<std::string, ConstantsLock*> locks; // for the process's life
    auto& l = locks[machine.name];
    if (!l)
        l = new ConstantsLock(machine);
    return l;
}

void ConstantsLock::refresh() {
    QString now;
    try {
        const MachineStore store(*machine_);
        if (!store.revisions().empty())
            now = QString::fromStdString(store.current().simulation.getString(kSetting, "")).trimmed();
    } catch (const std::exception&) {
        return; // the database cannot be read now: the lock as last read
    }
    if (now != holder_) {
        holder_ = now;
        emit changed(holder_);
    }
}

QString ConstantsLock::set(const std::optional<std::string>& value, const QString& note) {
    db::Edit e;
    e.simulation[kSetting] = value;
    const MachineStore::Kept k = MachineStore(*machine_).keep(e, note, true);
    if (k.revision == 0)
        return k.error;
    refresh();
    return {};
}

QString ConstantsLock::lock(const QString& forClass) {
    const QString c = forClass.simplified();
    if (c.isEmpty())
        return tr("Name the class the constants are locked for");
    // Stored as core's note (its English), said in each reader's language.
    return set(c.toStdString(), QString::fromStdString(db::noteText({"studio.lock", {c.toStdString()}})));
}

QString ConstantsLock::unlock() {
    const QString was = holder_;
    return set(std::nullopt, QString::fromStdString(db::noteText({"studio.unlock", {was.toStdString()}})));
}

QString ConstantsLock::refusal() {
    refresh();
    if (!locked())
        return {};
    return tr("The machine constants are locked by the trainer for the class «%1»: they cannot be changed "
              "until the trainer unlocks them (Training course, Class tab)")
        .arg(holder_);
}

QString ConstantsLock::refusesKey(const ControllerState& state, panel::KeyPress k) {
    const bool entersMode = k.key == panel::Key::F5 && !k.shift && state.mode != kCParameterMode;
    const bool writes = k.key == panel::Key::Enter && state.mode == kCParameterMode;
    if (!entersMode && !writes)
        return {};
    return refusal();
}

} // namespace k528::studio
