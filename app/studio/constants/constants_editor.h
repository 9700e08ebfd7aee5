// Editing the machine constants of the controller the window shows (the
// dock «Machine constants»: the simulated one, or a real one on the link),
// as the technologist does at the K923 in РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ,
// with the checks the controller would make afterwards made before:
//   - check(): the value against its definition and the cross-checks of
//     profile::checkCParams over the controller's other constants. An error
//     the change would bring (messages 13/29, 15, 37, 38, 39 of appendix М)
//     refuses it with the manual's text of that message and the reason;
//     nothing changes. Warnings are told, the change is allowed.
//   - set(): a change that passes is asked of the controller with its own
//     rules (Controller::setC: the simulation's panel — F5 for the moment
//     of the change, refused while a program is under way or an axis moves;
//     the link's F7 «РАБОТА С ПЭВМ»); once it took it, the change goes onto
//     the undo stack and is kept in the database as the machine's next
//     revision with the note given (MachineStore). Undo and redo ask the
//     controller again; one it refuses leaves the stack where it was.
//   - while the trainer has locked the constants for a class (ConstantsLock)
//     set(), undo and redo are refused with the lock's message.
#pragma once

#include "constants/machine_store.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

class QUndoStack;

namespace k528::studio {

class ConstantsLock;
class Controller;
class ViewedController;

struct CEditCheck {
    bool ok = true;
    int message = 0;     // appendix М number of the refusal, 0 if none
    QString text;        // the refusal: the manual's message text, then why
    QStringList warnings;
};

// The check of C`number` = `value` over the constants `c` (indexed by
// number): the reason in the window's language (the message text is the
// manual's Russian always).
CEditCheck checkCEdit(std::span<const std::int64_t> c, int number, std::int64_t value);

class ConstantsEditor : public QObject {
    Q_OBJECT
public:
    // Edits the constants of `viewed`'s controller, kept in the database as
    // revisions of `machine` (the window's machine).
    ConstantsEditor(ViewedController& viewed, const profile::MachineProfile& machine, QObject* parent = nullptr);

    Controller& controller() const;
    const MachineStore& store() const { return store_; }
    QUndoStack* undoStack() const { return undo_; }

    std::span<const std::int64_t> values() const;
    CEditCheck check(int number, std::int64_t value) const;
    // Checks, then asks the controller; once it took the value the change
    // goes onto the undo stack and is kept. `note`: the revision's summary
    // ("" -> "set C022 = 2133 (K528 Studio)"). Returns false (and emits
    // refused()) when refused now; true when done or asked of a controller
    // on the link (refused() or changed() follow).
    bool set(int number, std::int64_t value, const QString& note = QString());

    // Used by the undo commands: keep in the database, no undo entry.
    // `onNewest`: on the database's newest revision even when another PC
    // made it after the one this window knew (the user chose to apply the
    // change again on top of it).
    void keep(int number, std::int64_t value, const QString& note, bool onNewest = false);
    // All 152 (imports): applied to the controller as a whole (Controller::setAllC).
    void applyAll(std::vector<std::int64_t> c, std::function<void(const QString& why)> done);

    int lastRevision() const { return lastRevision_; }
    // The trainer's lock of the machine's constants (constants_lock.h):
    // the refusal every change gets while it is set, "" otherwise.
    QString lockRefusal() const;
    ConstantsLock* lock() const { return lock_; }
    // Where set() takes the note when it is given none (the dock's note field).
    void setNoteProvider(std::function<QString()> f) { noteProvider_ = std::move(f); }

signals:
    void changed(int number);           // the controller's C`number` changed
    void refused(const QString& why);   // a change was not made
    void kept(int revision, const QString& note);
    void notKept(const QString& why);   // applied to the controller, not to the database
    // Not kept because another process or PC made revision `newest` after
    // `known`, the one this change was based on (`why`: the refusal, then
    // the newer revisions, a line each: who, when, what).
    void conflicted(int number, qint64 value, const QString& note, const QString& why, int known, int newest);

private:
    ViewedController& viewed_;
    MachineStore store_;
    QUndoStack* undo_;
    int lastRevision_ = 0;
    std::function<QString()> noteProvider_;
    ConstantsLock* lock_;
};

} // namespace k528::studio
