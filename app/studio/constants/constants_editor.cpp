#include "constants/constants_editor.h"

#include "constants/constants_lock.h"

#include "catalog/cparams.h"
#include "catalog/messages.h"
#include "engine/positioner.h"
#include "db/notes.h"
#include "session/catalog_texts.h"
#include "session/core_texts.h"
#include "window_language.h"
#include "profile/validate.h"
#include "controller/controller.h"

#include <QCoreApplication>
#include <QUndoCommand>
#include <QPointer>
#include <QUndoStack>
#include <memory>
#include <utility>
#include <algorithm>
#include <set>
#include <vector>

namespace k528::studio {

namespace {

using ErrorKey = std::pair<std::string, int>; // subject, message

std::set<ErrorKey> errorKeys(const std::vector<profile::Finding>& fs) {
    std::set<ErrorKey> keys;
    for (const profile::Finding& f : fs)
        if (f.severity == profile::Severity::Error)
            keys.insert({f.subject, f.message.value_or(15)});
    return keys;
}

// One change of a constant on the undo stack. The first redo() only keeps
// it (the controller took it before it was pushed); every other undo or
// redo asks the controller again. A controller that refuses at once (the
// simulation answers at once) makes the command obsolete; one on the link
// answers later: a refusal then puts the stack's index back without asking.
class SetCCommand : public QUndoCommand {
public:
    SetCCommand(ConstantsEditor& e, int number, std::int64_t before, std::int64_t after, QString note)
        : e_(e), number_(number), before_(before), after_(after), note_(std::move(note)) {
        setText(QStringLiteral("C%1 %2 → %3")
                    .arg(number, 3, 10, QChar('0'))
                    .arg(before)
                    .arg(after));
    }
    void redo() override {
        if (std::exchange(first_, false)) {
            e_.keep(number_, after_, note_);
            return;
        }
        run(after_, note_, false);
    }
    void undo() override {
        // Stored as core's note (English), said in each reader's language.
        run(before_, QString::fromStdString(db::noteText({"studio.undo", {note_.toStdString()}})), true);
    }
    static bool replaying; // the stack's index put back: nothing asked

private:
    void run(std::int64_t v, const QString& note, bool undoing) {
        if (replaying)
            return;
        auto answered = std::make_shared<bool>(false);
        auto inside = std::make_shared<bool>(true);
        QUndoStack* stack = e_.undoStack();
        ConstantsEditor* editor = &e_;
        const int number = number_;
        QPointer<QUndoStack> guard(stack);
        const auto answer = [=, this](bool ok, const QString& why) {
            *answered = true;
            if (!guard)
                return;
            if (ok) {
                editor->keep(number, v, note);
                return;
            }
            emit editor->refused(why);
            if (*inside) {
                setObsolete(true); // nothing happened: the stack forgets it
                return;
            }
            replaying = true; // the index back where the controller is
            if (undoing)
                stack->redo();
            else
                stack->undo();
            replaying = false;
        };
        // The trainer's lock refuses undo and redo too.
        if (const QString locked = e_.lockRefusal(); !locked.isEmpty())
            answer(false, locked);
        else
            e_.controller().setC(number_, v, answer);
        *inside = false;
    }
    ConstantsEditor& e_;
    int number_;
    std::int64_t before_, after_;
    QString note_;
    bool first_ = true;
};

bool SetCCommand::replaying = false;

} // namespace

CEditCheck checkCEdit(std::span<const std::int64_t> c, int number, std::int64_t value) {
    CEditCheck r;
    const catalog::CParamDef* d = catalog::findCParam(number);
    if (!d || c.size() < static_cast<std::size_t>(catalog::kCParamCount + 1)) {
        r.ok = false;
        r.message = 15;
        r.text = QCoreApplication::translate("k528::studio::ConstantsEditor", "No C-parameter %1 (1..152)").arg(number);
        return r;
    }
    const std::vector<profile::Finding> before = profile::checkCParams(c);
    std::vector<std::int64_t> next(c.begin(), c.end());
    next[static_cast<std::size_t>(number)] = value;
    const std::vector<profile::Finding> after = profile::checkCParams(next);
    const std::set<ErrorKey> had = errorKeys(before);
    for (const profile::Finding& f : after) {
        const bool involves =
            std::find(f.cParams.begin(), f.cParams.end(), number) != f.cParams.end();
        if (!involves)
            continue;
        const QString why = problemText(f.problem);
        if (f.severity == profile::Severity::Warning) {
            r.warnings << why;
            continue;
        }
        if (had.count({f.subject, f.message.value_or(15)}))
            continue; // the machine had it before; the change does not bring it
        if (r.ok) {
            r.ok = false;
            r.message = f.message.value_or(15);
            // The controller's message as the window says it (in Russian the
            // panel's text letter by letter), then why.
            r.text = positionerMessageLine(r.message) + QStringLiteral(" — ") + why;
        }
    }
    return r;
}

ConstantsEditor::ConstantsEditor(ViewedController& viewed, const profile::MachineProfile& machine, QObject* parent)
    : QObject(parent), viewed_(viewed), store_(machine), undo_(new QUndoStack(this)),
      lock_(ConstantsLock::of(machine)) {
    // Another controller shown: the undo steps were of the other one's memory.
    connect(&viewed_, &ViewedController::changed, undo_, &QUndoStack::clear);
}

Controller& ConstantsEditor::controller() const { return viewed_.current(); }

std::span<const std::int64_t> ConstantsEditor::values() const {
    return controller().cValues();
}

CEditCheck ConstantsEditor::check(int number, std::int64_t value) const {
    return checkCEdit(values(), number, value);
}

QString ConstantsEditor::lockRefusal() const {
    return lock_->refusal();
}

bool ConstantsEditor::set(int number, std::int64_t value, const QString& note) {
    if (const QString why = lockRefusal(); !why.isEmpty()) {
        emit refused(why);
        return false;
    }
    const CEditCheck c = check(number, value);
    if (!c.ok) {
        emit refused(c.text);
        return false;
    }
    if (const QString why = controller().whyNotWritable(MemoryArea::C, number); !why.isEmpty()) {
        emit refused(why);
        return false;
    }
    const std::int64_t before = values()[static_cast<std::size_t>(number)];
    if (before == value)
        return true;
    QString given = note.trimmed();
    if (given.isEmpty() && noteProvider_)
        given = noteProvider_().trimmed();
    const QString n = given.isEmpty()
                          ? QString::fromStdString(db::noteText(
                                {"studio.set", {QStringLiteral("C%1").arg(number, 3, 10, QChar('0')).toStdString(),
                                                std::to_string(value)}}))
                          : given;
    // Asked of the controller first: only what it took goes onto the stack.
    auto result = std::make_shared<int>(-1); // -1 no answer yet, 0 refused, 1 taken
    QPointer<ConstantsEditor> self(this);
    Controller* asked = &controller();
    controller().setC(number, value, [=](bool ok, const QString& why) {
        *result = ok ? 1 : 0;
        if (!self)
            return;
        if (!ok) {
            emit self->refused(why);
            return;
        }
        if (&self->controller() == asked) // still the controller shown
            self->undo_->push(new SetCCommand(*self, number, before, value, n));
        else
            self->keep(number, value, n);
    });
    return *result != 0;
}

void ConstantsEditor::keep(int number, std::int64_t value, const QString& note, bool onNewest) {
    emit changed(number);
    db::Edit e;
    e.c[number] = value;
    const MachineStore::Kept k = store_.keep(e, note, onNewest);
    if (k.conflict) {
        emit conflicted(number, value, note, k.error + QStringLiteral("\n") + k.newer.trimmed(), k.known, k.newest);
    } else if (k.revision == 0) {
        emit notKept(k.error);
    } else {
        lastRevision_ = k.revision;
        emit kept(k.revision, note);
    }
}

void ConstantsEditor::applyAll(std::vector<std::int64_t> c, std::function<void(const QString& why)> done) {
    QPointer<ConstantsEditor> self(this);
    controller().setAllC(std::move(c), [self, done](bool ok, const QString& why) {
        if (self && ok)
            emit self->changed(0);
        if (done)
            done(ok ? QString() : why);
    });
}

} // namespace k528::studio
