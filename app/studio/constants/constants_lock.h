// The trainer's lock of a machine's constants for a class: the machine
// setting `constants.lock` (its value names the class), kept in the shop's
// database as the machine's next revision, so every window and PC that
// works the machine sees it. While it is set the dock «Machine constants»
// and the K923's РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ (F5) refuse changes with a
// message naming the lock; only the trainer's action (the Training pane's
// Class tab) lifts it.
#pragma once

#include "controller/controller.h"
#include "panel/keys.h"

#include <QObject>
#include <QString>
#include <memory>
#include <string>

namespace k528::studio {

class ConstantsLock : public QObject {
    Q_OBJECT
public:
    // The lock of `machine` (a profile as the window started with it: its
    // name is the machine's in the database). One object per machine name
    // in a process, shared by the docks, the panel and the trainer's view.
    static ConstantsLock* of(const profile::MachineProfile& machine);

    // The class the constants are locked for, "" when they are not (as last
    // read from the database: refresh()).
    QString holder() const { return holder_; }
    bool locked() const { return !holder_.isEmpty(); }
    // Reads the setting from the database again (changed() when it differs).
    void refresh();

    // The trainer's action: locks the constants for `forClass` (not empty),
    // unlocks them; kept in the database. "" or the error.
    QString lock(const QString& forClass);
    QString unlock();

    // The refusal a change of the constants gets while locked (reads the
    // database first: another PC may have locked or unlocked); "" when the
    // constants may be changed.
    QString refusal();
    // The same for a key of the K923: F5 (РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ) and
    // ENTER on its screen (the value written) while the controller is
    // `state`; "" for every other key, or when not locked.
    QString refusesKey(const ControllerState& state, panel::KeyPress k);

    static constexpr const char* kSetting = "constants.lock";

signals:
    void changed(const QString& holder);

private:
    explicit ConstantsLock(profile::MachineProfile machine);
    QString set(const std::optional<std::string>& value, const QString& note);
    std::unique_ptr<profile::MachineProfile> machine_;
    QString holder_;
};

} // namespace k528::studio
