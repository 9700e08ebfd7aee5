#include "constants/constants_editor.h"

#include "catalog/cparams.h"
#include "catalog/messages.h"
#include "engine/controller.h"
#include "language.h"
#include "profile/validate.h"
#include "session/simulation_session.h"

#include <QCoreApplication>
#include <QUndoCommand>
#include <QUndoStack>
#include <algorithm>
#include <set>
#include <vector>

namespace k528::studio {

namespace {

QString fromStd(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

using ErrorKey = std::pair<std::string, int>; // subject, message

std::set<ErrorKey> errorKeys(const std::vector<profile::Finding>& fs) {
    std::set<ErrorKey> keys;
    for (const profile::Finding& f : fs)
        if (f.severity == profile::Severity::Error)
            keys.insert({f.subject, f.message.value_or(15)});
    return keys;
}

// The mode of the moment of a change: F5 (one value) or F7 (all, the PC link).
template <class F>
QString inMode(engine::Controller& c, engine::Mode mode, F&& change) {
    if (engine::programActive(c.state()))
        return QCoreApplication::translate("k528::studio::ConstantsEditor", "a program is under way: the constants are changed when it has ended");
    for (engine::AxisId a : {engine::AxisId::X, engine::AxisId::Z})
        if (c.axisView(a).moving)
            return QCoreApplication::translate("k528::studio::ConstantsEditor", "an axis is moving: the constants are changed at standstill");
    const engine::Mode was = c.mode();
    if (was != mode) {
        const engine::OpResult r = c.selectMode(mode);
        if (!r.ok())
            return fromStd(r.detail);
    }
    const engine::OpResult r = change();
    if (was != mode)
        c.selectMode(was);
    return r.ok() ? QString() : fromStd(r.detail);
}

class SetCCommand : public QUndoCommand {
public:
    SetCCommand(ConstantsEditor& e, int number, std::int64_t before, std::int64_t after, QString note)
        : e_(e), number_(number), before_(before), after_(after), note_(std::move(note)) {
        setText(QStringLiteral("C%1 %2 → %3")
                    .arg(number, 3, 10, QChar('0'))
                    .arg(before)
                    .arg(after));
    }
    void redo() override { run(after_, note_); }
    void undo() override {
        run(before_, QCoreApplication::translate("k528::studio::ConstantsEditor", "undo: %1").arg(note_));
    }

private:
    void run(std::int64_t v, const QString& note) {
        const QString why = e_.applyAndKeep(number_, v, note);
        if (!why.isEmpty()) {
            setObsolete(true); // nothing happened: the stack forgets it
            emit e_.refused(why);
        }
    }
    ConstantsEditor& e_;
    int number_;
    std::int64_t before_, after_;
    QString note_;
};

} // namespace

CEditCheck checkCEdit(std::span<const std::int64_t> c, int number, std::int64_t value, bool russian) {
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
        const QString why = fromStd(russian ? f.textRu : f.textEn);
        if (f.severity == profile::Severity::Warning) {
            r.warnings << why;
            continue;
        }
        if (had.count({f.subject, f.message.value_or(15)}))
            continue; // the machine had it before; the change does not bring it
        if (r.ok) {
            r.ok = false;
            r.message = f.message.value_or(15);
            const catalog::PositionerMessage& m = catalog::positionerMessage(r.message);
            r.text = fromStd(m.panelText()) + QStringLiteral(" — ") + why;
        }
    }
    return r;
}

QString applyCToController(engine::Controller& controller, int number, std::int64_t value) {
    return inMode(controller, engine::Mode::MachineData,
                  [&] { return controller.setC(number, value); });
}

ConstantsEditor::ConstantsEditor(SimulationSession& session, QObject* parent)
    : QObject(parent), session_(session), store_(session.simulation().profile()),
      undo_(new QUndoStack(this)) {}

std::span<const std::int64_t> ConstantsEditor::values() const {
    return session_.controller().c();
}

CEditCheck ConstantsEditor::check(int number, std::int64_t value) const {
    return checkCEdit(values(), number, value, currentLanguage() == QLatin1String("ru"));
}

bool ConstantsEditor::set(int number, std::int64_t value, const QString& note) {
    const CEditCheck c = check(number, value);
    if (!c.ok) {
        emit refused(c.text);
        return false;
    }
    const std::int64_t before = values()[static_cast<std::size_t>(number)];
    if (before == value)
        return true;
    QString given = note.trimmed();
    if (given.isEmpty() && noteProvider_)
        given = noteProvider_().trimmed();
    const QString n = given.isEmpty()
                          ? QStringLiteral("set C%1 = %2 (K528 Studio)").arg(number, 3, 10, QChar('0')).arg(value)
                          : given;
    const int count = undo_->count();
    undo_->push(new SetCCommand(*this, number, before, value, n));
    return undo_->count() > count || values()[static_cast<std::size_t>(number)] == value;
}

QString ConstantsEditor::applyAndKeep(int number, std::int64_t value, const QString& note) {
    const QString why = applyCToController(session_.controller(), number, value);
    if (!why.isEmpty())
        return why;
    emit changed(number);
    db::Edit e;
    e.c[number] = value;
    const MachineStore::Kept k = store_.keep(e, note);
    if (k.revision == 0) {
        emit notKept(k.error);
    } else {
        lastRevision_ = k.revision;
        emit kept(k.revision, note);
    }
    session_.advance(0); // the views show it at once
    return {};
}

QString ConstantsEditor::applyAll(std::span<const std::int64_t> c) {
    engine::Controller& ctl = session_.controller();
    const QString why = inMode(ctl, engine::Mode::DataControl, [&] { return ctl.loadCParameters(c); });
    if (why.isEmpty()) {
        emit changed(0);
        session_.advance(0);
    }
    return why;
}

} // namespace k528::studio
