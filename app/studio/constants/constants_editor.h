// Editing the machine constants of the simulated controller from the desktop
// (the dock «Machine constants»), as the technologist does at the K923 in
// РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ, with the checks the controller would make
// afterwards made before:
//   - check(): the value against its definition and the cross-checks of
//     profile::checkCParams over the controller's other constants. An error
//     the change would bring (messages 13/29, 15, 37, 38, 39 of appendix М)
//     refuses it with the manual's text of that message and the reason;
//     nothing changes. Warnings are told, the change is allowed.
//   - set(): a change that passes goes onto the undo stack; doing it (and
//     undoing it) applies the value to the controller (F5 for the moment of
//     the change, the mode the operator had after it; refused while a program
//     is under way or an axis moves) and keeps it in the database as the
//     machine's next revision with the note given (MachineStore).
#pragma once

#include "constants/machine_store.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <cstdint>
#include <functional>
#include <span>

class QUndoStack;

namespace k528::engine {
class Controller;
}

namespace k528::studio {

class SimulationSession;

struct CEditCheck {
    bool ok = true;
    int message = 0;     // appendix М number of the refusal, 0 if none
    QString text;        // the refusal: the manual's message text, then why
    QStringList warnings;
};

// The check of C`number` = `value` over the constants `c` (indexed by
// number). `russian`: the reason in Russian (the message text is the
// manual's Russian always).
CEditCheck checkCEdit(std::span<const std::int64_t> c, int number, std::int64_t value, bool russian);

// Sets C`number` on the controller as the K923 does (F5 for the moment of
// the change); "" when done, otherwise why not (English from the engine).
QString applyCToController(engine::Controller& controller, int number, std::int64_t value);

class ConstantsEditor : public QObject {
    Q_OBJECT
public:
    ConstantsEditor(SimulationSession& session, QObject* parent = nullptr);

    SimulationSession& session() const { return session_; }
    const MachineStore& store() const { return store_; }
    QUndoStack* undoStack() const { return undo_; }

    std::span<const std::int64_t> values() const;
    CEditCheck check(int number, std::int64_t value) const;
    // Checks, then pushes the change (which applies and keeps it). `note`:
    // the revision's summary ("" -> "set C022 = 2133 (K528 Studio)").
    // Returns false (and emits refused()) when refused.
    bool set(int number, std::int64_t value, const QString& note = QString());

    // Used by the undo commands: apply and keep, no undo entry. "" or why not.
    QString applyAndKeep(int number, std::int64_t value, const QString& note);
    // All 152 (imports): checked as a whole, applied to the controller.
    QString applyAll(std::span<const std::int64_t> c);

    int lastRevision() const { return lastRevision_; }
    // Where set() takes the note when it is given none (the dock's note field).
    void setNoteProvider(std::function<QString()> f) { noteProvider_ = std::move(f); }

signals:
    void changed(int number);           // the controller's C`number` changed
    void refused(const QString& why);   // a change was not made
    void kept(int revision, const QString& note);
    void notKept(const QString& why);   // applied to the controller, not to the database

private:
    SimulationSession& session_;
    MachineStore store_;
    QUndoStack* undo_;
    int lastRevision_ = 0;
    std::function<QString()> noteProvider_;
};

} // namespace k528::studio
