#include "training/training_texts.h"

#include "session/translated_texts.h"
#include "window_language.h"

#include <QCoreApplication>

#include <optional>

namespace k528::studio {

namespace {

// One entry per id of catalog::trainingTexts(), its English the catalog's.
const TranslatedText kTexts[] = {
    {"program-errors", QT_TRANSLATE_NOOP("TrainingTexts", "the machine does not take the program: %1 errors, the first on line %2: %3")},
    {"no-program", QT_TRANSLATE_NOOP("TrainingTexts", "the file holds no program: the machine has nothing to run")},
    {"procedure-error", QT_TRANSLATE_NOOP("TrainingTexts", "line %1: the operator's step '%2' is not understood: %3")},
    {"procedure.hold", QT_TRANSLATE_NOOP("TrainingTexts", "HOLD:BUTTON:S holds a button for S seconds (0..3600)")},
    {"procedure.estop", QT_TRANSLATE_NOOP("TrainingTexts", "the E-stop latches: PUSH:ESTOP, PULL:ESTOP")},
    {"procedure.button", QT_TRANSLATE_NOOP("TrainingTexts", "no such button; the machine's buttons: DRIVES_ON START STOP RESET X+ X- Z+ Z- RAPID CHUCK ESTOP")},
    {"procedure.wait", QT_TRANSLATE_NOOP("TrainingTexts", "WAIT:S waits S seconds (0..36000)")},
    {"procedure.program", QT_TRANSLATE_NOOP("TrainingTexts", "PROGRAM:N takes a program number 1..99")},
    {"procedure.handwheel", QT_TRANSLATE_NOOP("TrainingTexts", "HANDWHEEL:X, HANDWHEEL:Z or HANDWHEEL:OFF")},
    {"procedure.step", QT_TRANSLATE_NOOP("TrainingTexts", "STEP:1, STEP:10 or STEP:100: the handwheel's multiplier")},
    {"procedure.turn", QT_TRANSLATE_NOOP("TrainingTexts", "TURN:N turns the handwheel by N detents (±1..100000)")},
    {"procedure.override", QT_TRANSLATE_NOOP("TrainingTexts", "OVERRIDE:P takes a step of the override: 0 1 2 5 10 20 35 50 75 90 100")},
    {"procedure.preset", QT_TRANSLATE_NOOP("TrainingTexts", "R<n>=<value>: a writable R-parameter 0..231 and a whole value")},
    {"procedure.unknown", QT_TRANSLATE_NOOP("TrainingTexts", "expected one of: %2")},
    {"note.program-refused", QT_TRANSLATE_NOOP("TrainingTexts", "program L%1 was not selected (ACK, number, ENTER in АВТОМАТ)")},
    {"note.override-refused", QT_TRANSLATE_NOOP("TrainingTexts", "the override %1 %% was not set: the machine has no such step")},
    {"note.new-wheel-refused", QT_TRANSLATE_NOOP("TrainingTexts", "the wheel was not changed: stop the wheel spindle first")},
    {"note.door-refused", QT_TRANSLATE_NOOP("TrainingTexts", "the door did not open: it is locked")},
    {"note.home-failed", QT_TRANSLATE_NOOP("TrainingTexts", "the reference-point cycle did not complete: %1")},
    {"note.preset-refused", QT_TRANSLATE_NOOP("TrainingTexts", "%1 = %2 was not written (РУЧНОЙ, screen 3; not while a program runs)")},
    {"note.not-started", QT_TRANSLATE_NOOP("TrainingTexts", "the program did not start after CYCLE START")},
    {"overcut", QT_TRANSLATE_NOOP("TrainingTexts", "over-cut: metal removed %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4 — frame %5, line %6")},
    {"overcut.manual", QT_TRANSLATE_NOOP("TrainingTexts", "over-cut by a manual move: metal removed %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4")},
    {"overcut.unknown", QT_TRANSLATE_NOOP("TrainingTexts", "over-cut: metal missing %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4")},
    {"undercut", QT_TRANSLATE_NOOP("TrainingTexts", "under-cut: %1 µm of metal left beyond the tolerance (area %2 mm²) at Ø%3 near Z%4; the nearest pass is frame %5, line %6")},
    {"undercut.untouched", QT_TRANSLATE_NOOP("TrainingTexts", "under-cut: %1 µm of metal left beyond the tolerance (area %2 mm²) at Ø%3 near Z%4: no pass came here")},
    {"collision.rapid-into-material", QT_TRANSLATE_NOOP("TrainingTexts", "a rapid (G00) into the metal at X%1 Z%2, %3 mm into the blank — frame %4, line %5: the tool is broken")},
    {"collision.manual-into-material", QT_TRANSLATE_NOOP("TrainingTexts", "a manual move into the metal at X%1 Z%2, %3 mm into the blank: the tool is broken")},
    {"collision.feed-spindle-stopped", QT_TRANSLATE_NOOP("TrainingTexts", "cutting with the spindle stopped at X%1 Z%2 — frame %4, line %5: start the spindle (M3) before the feed")},
    {"collision.feed-wheel-stopped", QT_TRANSLATE_NOOP("TrainingTexts", "a feed of the wheel into the ring with the wheel stopped: its edge at Ø%1 near Z%2 — frame %4, line %5: start the wheel before the feed")},
    {"collision.tool-into-chuck.jaws", QT_TRANSLATE_NOOP("TrainingTexts", "the tool into the chuck's jaws at X%1 Z%2 — frame %4, line %5")},
    {"collision.tool-into-chuck.body", QT_TRANSLATE_NOOP("TrainingTexts", "the tool into the chuck's body at X%1 Z%2 — frame %4, line %5")},
    {"collision.tool-into-chuck", QT_TRANSLATE_NOOP("TrainingTexts", "the tool into the chuck or its jaws at X%1 Z%2 — frame %4, line %5")},
    {"collision.tool-into-chuck.manual", QT_TRANSLATE_NOOP("TrainingTexts", "the tool into the chuck or its jaws by a manual move at X%1 Z%2")},
    {"collision.rapid-into-material.ring", QT_TRANSLATE_NOOP("TrainingTexts", "the wheel into the ring at rapid: its edge at Ø%1 near Z%2, %3 mm into the wall — frame %4, line %5")},
    {"message", QT_TRANSLATE_NOOP("TrainingTexts", "message %1 «%2» — frame %3, line %4: it must not come in this exercise")},
    {"message.machine", QT_TRANSLATE_NOOP("TrainingTexts", "message %1 «%2»: it must not come in this exercise")},
    {"not-started", QT_TRANSLATE_NOOP("TrainingTexts", "the program was never started")},
    {"not-started.why", QT_TRANSLATE_NOOP("TrainingTexts", "the program did not start: %1")},
    {"not-completed.alarm", QT_TRANSLATE_NOOP("TrainingTexts", "a message stopped the program before its end — frame %1, line %2")},
    {"not-completed.interrupted", QT_TRANSLATE_NOOP("TrainingTexts", "the program was interrupted before its end — frame %1, line %2")},
    {"not-completed.timeout", QT_TRANSLATE_NOOP("TrainingTexts", "the program did not end in the time given — frame %1, line %2")},
    {"cycle-time", QT_TRANSLATE_NOOP("TrainingTexts", "cycle time %1 s is over the limit of %2 s")},
    {"step.home", QT_TRANSLATE_NOOP("TrainingTexts", "the reference-point cycle (ПБТ) of X and Z was not done before the program started")},
    {"step.preset", QT_TRANSLATE_NOOP("TrainingTexts", "R%1 was %2 when the program started; the task asks for %3 (РУЧНОЙ, screen 3)")},
    {"step.acknowledge", QT_TRANSLATE_NOOP("TrainingTexts", "messages not acknowledged (ESC): %1")},
    {"step.position", QT_TRANSLATE_NOOP("TrainingTexts", "the tool stopped at X%1 Z%2; the task asks for X%3 Z%4 (±%5 mm)")},
    {"step.new_wheel", QT_TRANSLATE_NOOP("TrainingTexts", "the worn wheel was not changed (NEW WHEEL)")},
    {"step.completed", QT_TRANSLATE_NOOP("TrainingTexts", "the program did not run to its end")},
    {"end.spindle_stopped", QT_TRANSLATE_NOOP("TrainingTexts", "the spindle still turns after the program (M5)")},
    {"end.coolant_off", QT_TRANSLATE_NOOP("TrainingTexts", "the coolant is still on after the program (M9)")},
    {"end.gauge_out", QT_TRANSLATE_NOOP("TrainingTexts", "the in-process gauge is still in the bore after the program (M21)")},
    {"end.r", QT_TRANSLATE_NOOP("TrainingTexts", "R%1 is %2 after the program; %3 was expected")},
};

const TranslatedTexts kTrainingTexts("TrainingTexts", kTexts);

// An argument of two languages (a message of the positioner) is data: it is
// shown in the desktop's language.
training::Language argumentLanguage() {
    return inWindowLanguage(training::Language::Ru, training::Language::En);
}

} // namespace

QString trainingTextPattern(const std::string& id) { return kTrainingTexts.pattern(id); }

QString trainingText(const training::Text& t) {
    if (const std::optional<QString> text = kTrainingTexts.text(t.id, training::argsIn(t.args, argumentLanguage())))
        return *text;
    return QString::fromStdString(training::render(t, argumentLanguage()));
}

} // namespace k528::studio
