#include "training/training_texts.h"

#include "window_language.h"
#include "profile/problem.h"

#include <QCoreApplication>

namespace k528::studio {

namespace {

struct TrainingTexts {
    Q_DECLARE_TR_FUNCTIONS(TrainingTexts)
public:
    // One entry per id of catalog::trainingTexts(), its English the catalog's.
    static QString pattern(const std::string& id) {
        struct Entry {
            const char* id;
            QString text;
        };
        const Entry table[] = {
            {"program-errors", tr("the machine does not take the program: %1 errors, the first on line %2: %3")},
            {"no-program", tr("the file holds no program: the machine has nothing to run")},
            {"procedure-error", tr("line %1: the operator's step '%2' is not understood: %3")},
            {"procedure.hold", tr("HOLD:BUTTON:S holds a button for S seconds (0..3600)")},
            {"procedure.estop", tr("the E-stop latches: PUSH:ESTOP, PULL:ESTOP")},
            {"procedure.button", tr("no such button; the machine's buttons: DRIVES_ON START STOP RESET X+ X- Z+ Z- RAPID CHUCK ESTOP")},
            {"procedure.wait", tr("WAIT:S waits S seconds (0..36000)")},
            {"procedure.program", tr("PROGRAM:N takes a program number 1..99")},
            {"procedure.handwheel", tr("HANDWHEEL:X, HANDWHEEL:Z or HANDWHEEL:OFF")},
            {"procedure.step", tr("STEP:1, STEP:10 or STEP:100: the handwheel's multiplier")},
            {"procedure.turn", tr("TURN:N turns the handwheel by N detents (±1..100000)")},
            {"procedure.override", tr("OVERRIDE:P takes a step of the override: 0 1 2 5 10 20 35 50 75 90 100")},
            {"procedure.preset", tr("R<n>=<value>: a writable R-parameter 0..231 and a whole value")},
            {"procedure.unknown", tr("expected one of: %2")},
            {"note.program-refused", tr("program L%1 was not selected (ACK, number, ENTER in АВТОМАТ)")},
            {"note.override-refused", tr("the override %1 %% was not set: the machine has no such step")},
            {"note.new-wheel-refused", tr("the wheel was not changed: stop the wheel spindle first")},
            {"note.door-refused", tr("the door did not open: it is locked")},
            {"note.home-failed", tr("the reference-point cycle did not complete: %1")},
            {"note.preset-refused", tr("%1 = %2 was not written (РУЧНОЙ, screen 3; not while a program runs)")},
            {"note.not-started", tr("the program did not start after «Пуск»")},
            {"overcut", tr("over-cut: metal removed %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4 — frame %5, line %6")},
            {"overcut.manual", tr("over-cut by a manual move: metal removed %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4")},
            {"overcut.unknown", tr("over-cut: metal missing %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4")},
            {"undercut", tr("under-cut: %1 µm of metal left beyond the tolerance (area %2 mm²) at Ø%3 near Z%4; the nearest pass is frame %5, line %6")},
            {"undercut.untouched", tr("under-cut: %1 µm of metal left beyond the tolerance (area %2 mm²) at Ø%3 near Z%4: no pass came here")},
            {"collision.rapid-into-material", tr("a rapid (G00) into the metal at X%1 Z%2, %3 mm into the blank — frame %4, line %5: the tool is broken")},
            {"collision.manual-into-material", tr("a manual move into the metal at X%1 Z%2, %3 mm into the blank: the tool is broken")},
            {"collision.feed-spindle-stopped", tr("cutting with the spindle stopped at X%1 Z%2 — frame %4, line %5: start the spindle (M3) before the feed")},
            {"collision.feed-wheel-stopped", tr("a feed of the wheel into the ring with the wheel stopped: its edge at Ø%1 near Z%2 — frame %4, line %5: start the wheel before the feed")},
            {"collision.tool-into-chuck.jaws", tr("the tool into the chuck's jaws at X%1 Z%2 — frame %4, line %5")},
            {"collision.tool-into-chuck.body", tr("the tool into the chuck's body at X%1 Z%2 — frame %4, line %5")},
            {"collision.tool-into-chuck", tr("the tool into the chuck or its jaws at X%1 Z%2 — frame %4, line %5")},
            {"collision.tool-into-chuck.manual", tr("the tool into the chuck or its jaws by a manual move at X%1 Z%2")},
            {"collision.rapid-into-material.ring", tr("the wheel into the ring at rapid: its edge at Ø%1 near Z%2, %3 mm into the wall — frame %4, line %5")},
            {"message", tr("message %1 «%2» — frame %3, line %4: it must not come in this exercise")},
            {"message.machine", tr("message %1 «%2»: it must not come in this exercise")},
            {"not-started", tr("the program was never started")},
            {"not-started.why", tr("the program did not start: %1")},
            {"not-completed.alarm", tr("a message stopped the program before its end — frame %1, line %2")},
            {"not-completed.interrupted", tr("the program was interrupted before its end — frame %1, line %2")},
            {"not-completed.timeout", tr("the program did not end in the time given — frame %1, line %2")},
            {"cycle-time", tr("cycle time %1 s is over the limit of %2 s")},
            {"step.home", tr("the reference-point cycle (ПБТ) of X and Z was not done before the program started")},
            {"step.preset", tr("R%1 was %2 when the program started; the task asks for %3 (РУЧНОЙ, screen 3)")},
            {"step.acknowledge", tr("messages not acknowledged (ESC): %1")},
            {"step.position", tr("the tool stopped at X%1 Z%2; the task asks for X%3 Z%4 (±%5 mm)")},
            {"step.new_wheel", tr("the worn wheel was not changed (NEW WHEEL)")},
            {"step.completed", tr("the program did not run to its end")},
            {"end.spindle_stopped", tr("the spindle still turns after the program (M5)")},
            {"end.coolant_off", tr("the coolant is still on after the program (M9)")},
            {"end.gauge_out", tr("the in-process gauge is still in the bore after the program (M21)")},
            {"end.r", tr("R%1 is %2 after the program; %3 was expected")},
        };
        for (const Entry& e : table)
            if (id == e.id)
                return e.text;
        return {};
    }
};

// An argument of two languages (a message of the positioner) is data: it is
// shown in the desktop's language.
training::Language argumentLanguage() {
    return russianWindow() ? training::Language::Ru : training::Language::En;
}

} // namespace

QString trainingTextPattern(const std::string& id) {
    return TrainingTexts::pattern(id);
}

QString trainingText(const training::Text& t) {
    const QString pattern = TrainingTexts::pattern(t.id);
    if (pattern.isEmpty())
        return QString::fromStdString(training::render(t, argumentLanguage()));
    return QString::fromStdString(
        profile::fillPattern(pattern.toStdString(), training::argsIn(t.args, argumentLanguage())));
}

} // namespace k528::studio
