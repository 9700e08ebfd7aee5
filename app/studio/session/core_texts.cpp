#include "session/core_texts.h"

#include "db/error.h"
#include "db/notes.h"
#include "language.h"
#include "profile/calculator.h"
#include "profile/problem.h"
#include "profile/tools.h"
#include "proveout/proveout.h"
#include "profile/validate.h"
#include "profile/text_format.h"
#include "session/shop_database.h"
#include "util/input_file.h"

#include <QCoreApplication>
#include <QFileInfo>

#include <optional>
#include <string>
#include <vector>

namespace k528::studio {

namespace {

struct Entry {
    const char* id;
    const char* text; // English, as core's catalog says it; translated by CoreTexts
};

// core/profile/problem.cpp's catalog, each text marked for the translators.
const Entry kProblems[] = {
        {"file.cannot-read", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "cannot read the file: %1")},
        {"file.cannot-create", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "cannot create the file")},
        {"file.cannot-write", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "cannot write the file")},
        {"file.utf8", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "not valid UTF-8")},
        {"file.bom", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "column %1: U+FEFF (byte-order mark), an invisible character; a byte-order mark may stand only at the very start of the file (files joined with `cat`?) — remove it")},
        {"file.twice", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1 is given twice (first on line %2)")},
        {"file.header-bracket", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "section header without ']': %1")},
        {"file.end-without-program", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "[end program] without [program N]")},
        {"file.unknown-section", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "unknown section [%1] (known: machine, c, r, program N, messages, plc-messages, simulation)")},
        {"file.program-number", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "[program N]: N must be a number 1..99, not '%1'")},
        {"file.program-empty", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program %1 is empty")},
        {"file.program-bracket", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "a program line may not start with '[' (missing [end program] for program %1 of line %2?)")},
        {"file.program-unended", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program %1 has no [end program]")},
        {"file.outside-section", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "line outside any section: %1")},
        {"file.no-equals", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "expected key=value: %1")},
        {"file.machine-key", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "unknown key '%1' in [machine] (format, name, title)")},
        {"file.format-nan", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "format: '%1' is not a number")},
        {"file.format-unknown", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "format %1 is not one this program reads (%2)")},
        {"file.c-key", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "unknown key '%1' in [c] (C001..C152)")},
        {"file.r-key", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "unknown key '%1' in [r] (R0..R299)")},
        {"file.not-integer", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1: '%2' is not a whole number")},
        {"file.message-key", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "expected #k=text in [messages], not '%1'")},
        {"file.message-number", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "message number %1 is outside #1..#99")},
        {"file.plc-key", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "expected A01..A32, W01..W32 or S01..S16 in [plc-messages], not '%1'")},
        {"file.plc-number", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "PLC message '%1': the number must be 1..%2")},
        {"file.no-machine", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "no [machine] section")},
        {"file.no-format", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "[machine] has no format=%1")},
        {"file.no-name", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "[machine] has no name=")},
        {"file.no-c", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "no [c] section (the 152 machine constants)")},
        {"file.c-lacks", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "[c] lacks %1 (all 152 are required)")},
        {"file.c-lacks-more", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "[c] lacks %1 and %2 more (all 152 are required)")},
        {"builtin.unknown", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "no built-in profile of this name (built-in: %1)")},
        {"builtin.none-given", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "no profile given (built-in: %1)")},
        {"builtin.neither", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "neither a built-in profile (%1) nor a machine file")},
        {"csv.header", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the first line must be the header '%1'")},
        {"csv.fields", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "expected 5 fields (number;axis;name;value;unit), found %1")},
        {"csv.number", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "number '%1' is not a C-parameter 1..152")},
        {"csv.axis", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1 belongs to axis '%2', the row says '%3'")},
        {"csv.twice", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1 is given twice")},
        {"csv.value", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1: value '%2' is not a whole number")},
        {"csv.empty", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "empty: no header line")},
        {"csv.missing", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1 is missing (all 152 are required)")},
        {"csv.quote-open", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "a quoted field is not closed")},
        {"csv.quote-text", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "text after a closing quote")},
        {"name.empty", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "name is empty")},
        {"name.long", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "name longer than 64 characters")},
        {"name.start", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "name '%1' does not start with a-z or 0-9")},
        {"name.char", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "name '%1' has a character other than a-z, 0-9, '-', '_', '.'")},
        {"title", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "title: %1")},
        {"text.empty", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "text is empty")},
        {"text.utf8", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "text is not valid UTF-8")},
        {"text.control", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "text has a control character or line break")},
        {"text.long", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "text has %1 characters, more than %2")},
        {"text.trailing-blank", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "text ends with a blank")},
        {"text.leading-blank", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "text starts with a blank")},
        {"c.none", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "no C-parameter %1 (1..152)")},
        {"c.range", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1 = %2 is outside the range %3 of «%4»")},
        {"r.none", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "no R-parameter %1 (0..299)")},
        {"r.read-only", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "R%1 is read-only (R232..R262): it cannot be preset")},
        {"r.range", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "R%1 = %2 is outside the 32-bit range")},
        {"program.number", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program number %1 is outside 1..99")},
        {"program.empty", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program L%1: empty")},
        {"program.utf8", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program L%1: not valid UTF-8")},
        {"program.no-line-break", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program L%1: the text does not end with a line break")},
        {"program.carriage-return", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program L%1: carriage return in the text (lines end with LF)")},
        {"program.bracket", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program L%1: line %2 starts with '[' (reserved for machine-file sections)")},
        {"program.header", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program L%1: line %2 is the header of program L%3 (one program per entry)")},
        {"program.messages", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program L%1: line %2: %MESSAGES belongs to the machine file's [messages] section")},
        {"program.blank", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program L%1: only blank lines")},
        {"message.number", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "technological message number %1 is outside 1..99")},
        {"message.text", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "message #%1: %2")},
        {"plc.number", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "PLC message %1 is outside 1..%2")},
        {"plc.text", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "PLC message %1: %2")},
        {"setting.key", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "simulation: %1")},
        {"setting.value", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "simulation %1: %2")},
        {"key.empty", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "empty key")},
        {"key.long", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "key longer than 64 characters")},
        {"key.start", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "key '%1' does not start with a letter a-z")},
        {"key.char", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "key '%1' has a character other than a-z, 0-9, '_', '.'")},
        {"value.utf8", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value is not valid UTF-8")},
        {"value.long", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value longer than 200 characters")},
        {"value.lines", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value spans lines")},
        {"value.control", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value has a control character")},
        {"value.semicolon", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value has a ';' (starts a comment in machine files)")},
        {"value.blank", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value starts or ends with a blank")},
        {"value.range", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value %1 is outside %2..%3")},
        {"value.integer", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value '%1' is not a whole number")},
        {"value.number", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value '%1' is not a number")},
        {"value.bool", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value '%1' is not true/false")},
        {"value.line", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1")},
        {"tool.kind", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "'%1' is not a tool kind (turning, facing, grooving, boring, drill, threading)")},
        {"tool.value", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1")},
        {"tool.orientation", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "'%1' is not one of +z+x, -z+x, +z-x, -z-x")},
        {"tool.tip-radius", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "needs 0..50 mm")},
        {"tool.size", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "needs more than 0, at most 1000 mm")},
        {"tool.depth", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "needs 0..100 mm (0: no limit)")},
        {"tool.offset", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "needs a user R-parameter 0..148 (X there, Z in the next)")},
        {"tool.key", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "a tool key is tool.<station 1..8>.<key>")},
        {"tool.field", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "'%1' is not a key of a tool")},
        {"tool.no-kind", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the tool of station %1 has no kind (tool.%1.kind)")},
        {"machine.item", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "machine %1: %2")},
        {"calc.vmax", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Vmax must be a positive number")},
        {"calc.run-up", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the run-up time must be a positive number")},
        {"calc.braking", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the braking distance must be a positive number")},
        {"calc.acceleration", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the acceleration must be a positive number")},
        {"calc.umax", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Umax must be a positive number")},
        {"calc.kv", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Kv must be a positive number")},
        {"calc.screw-lead", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the screw lead must be a positive number")},
        {"calc.gear-ratio", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the gear ratio must be a positive number")},
        {"calc.encoder-lines", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the encoder must have at least one line")},
        {"calc.lead-discretes", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the screw lead %1 mm is not a whole number of discretes (%2 mm)")},
        {"calc.gear-fraction", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the gear ratio %1 is not a fraction with a denominator up to 100000")},
        {"calc.speed", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "a speed must be zero or positive")},
        {"calc.feed-reach", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the fastest feed %1 mm/min is above what the drive reaches at DAC MAX (%2 mm/min)")},
};

// core/db/notes.cpp's catalog: the notes core and the desktop write.
const Entry kNotes[] = {
        {"seed", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "built-in profile %1 (first start)")},
        {"created", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "created")},
        {"set", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "set %1")},
        {"changed", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "changed %1")},
        {"changed-more", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "changed %1 and %2 more")},
        {"changed-order", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "changed order of simulation settings")},
        {"import", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "import %1")},
        {"studio.import", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "import %1 (K528 Studio)")},
        {"studio.loaded", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "the machine as K528 Studio loaded it")},
        {"studio.kept", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "kept from the simulated controller's memory (K528 Studio)")},
        {"studio.editor", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "programs and messages from the editor (K528 Studio)")},
        {"studio.set", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "set %1 = %2 (K528 Studio)")},
        {"studio.undo", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "undo: %1")},
};

// core/proveout's findings (proveout::texts()), each text marked for the translators.
const Entry kFindings[] = {
        {"rapid-into-material", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "A rapid (G00) enters the material of the blank: X%1 Z%2")},
        {"rapid-into-material.dogleg", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "A rapid (G00) enters the material at its dogleg: axis %3 arrives first (X%1 Z%2), although both end points are outside the blank")},
        {"rapid-into-material.ring", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "A rapid (G00) takes the wheel into the ring's material: X%1 Z%2")},
        {"tool-into-chuck.jaws", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "Tool T%3 runs into the chuck's jaws: X%1 Z%2")},
        {"tool-into-chuck.body", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "Tool T%3 runs into the chuck's body: X%1 Z%2")},
        {"turret-into-chuck.jaws", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "The turret runs into the chuck's jaws (tool T%3 at X%1 Z%2)")},
        {"turret-into-chuck.body", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "The turret runs into the chuck's body (tool T%3 at X%1 Z%2)")},
        {"feed-spindle-stopped", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "A feed into the material with the spindle stopped: X%1 Z%2")},
        {"feed-wheel-stopped", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "A feed into the ring's material with the wheel stopped: X%1 Z%2")},
        {"manual-into-material", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "A manual move takes the tool into the material of the blank: X%1 Z%2")},
        {"cut-too-deep", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "A cut %1 mm deep, deeper than tool T%2 takes (%3 mm)")},
};

// `pattern` with %1..%9 filled in one pass, as core fills its own texts
// (profile::fillPattern: an argument's own "%2" stays).
QString fill(const QString& pattern, const QStringList& args) {
    std::vector<std::string> a;
    a.reserve(static_cast<std::size_t>(args.size()));
    for (const QString& s : args)
        a.push_back(s.toStdString());
    return QString::fromStdString(profile::fillPattern(pattern.toStdString(), a));
}

const char* patternOf(std::string_view id) {
    for (const Entry& e : kProblems)
        if (id == e.id)
            return e.text;
    return nullptr;
}

QString fromStd(const std::string& s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }

} // namespace

bool hasProblemText(std::string_view id) { return patternOf(id) != nullptr; }

bool hasNoteText(std::string_view id) {
    for (const Entry& e : kNotes)
        if (id == e.id)
            return true;
    return false;
}

bool hasFindingText(std::string_view id) {
    for (const Entry& e : kFindings)
        if (id == e.id)
            return true;
    return false;
}

QString findingText(const proveout::Finding& f) {
    for (const Entry& e : kFindings) {
        if (f.text != e.id)
            continue;
        QStringList args;
        for (const std::string& a : f.args)
            args << fromStd(a);
        return fill(QCoreApplication::translate("k528::studio::ProveoutTexts", e.text), args);
    }
    return fromStd(f.message(false)); // an id without a translation: core's English
}

QString revisionNoteText(const std::string& summary) {
    const std::optional<db::Note> note = db::readNote(summary);
    if (!note)
        return fromStd(summary); // a user's own words
    for (const Entry& e : kNotes) {
        if (note->id != e.id)
            continue;
        QStringList args;
        for (const std::string& a : note->args)
            args << (note->id == "studio.undo" ? revisionNoteText(a) : fromStd(a)); // the note undone
        return fill(QCoreApplication::translate("k528::studio::RevisionNotes", e.text), args);
    }
    return fromStd(summary);
}

QString problemText(const profile::Problem& p) {
    const char* pattern = patternOf(p.id);
    if (!pattern)
        return fromStd(p.text()); // an id without a translation: core's English
    QString text = QCoreApplication::translate("k528::studio::CoreTexts", pattern);
    QStringList args;
    for (const std::string& a : p.args)
        args << fromStd(a);
    for (const profile::Problem& w : p.within)
        args << problemText(w);
    return fill(text, args);
}

QString fileErrorText(const profile::FileError& e) {
    const QString what = problemText(e.problem());
    const QString source = fromStd(e.source());
    if (source.isEmpty())
        return what;
    if (e.line() > 0)
        return QCoreApplication::translate("k528::studio::CoreTexts", "%1, line %2: %3")
            .arg(source, QString::number(e.line()), what);
    return QCoreApplication::translate("k528::studio::CoreTexts", "%1: %2").arg(source, what);
}

QString coreErrorText(const std::exception& e) {
    if (const auto* f = dynamic_cast<const profile::FileError*>(&e))
        return fileErrorText(*f);
    if (const auto* c = dynamic_cast<const profile::calc::CalcError*>(&e))
        return problemText(c->problem);
    if (const auto* t = dynamic_cast<const profile::ToolError*>(&e))
        return problemText(t->problem());
    if (const auto* v = dynamic_cast<const db::ValidationError*>(&e); v && v->findings().empty() && !v->problem().empty())
        return QCoreApplication::translate("k528::studio::CoreTexts", "rejected, nothing was written: %1")
            .arg(problemText(v->problem()));
    if (const auto* v = dynamic_cast<const db::ValidationError*>(&e); v && !v->findings().empty()) {
        // The cross-checks' findings: core says each in both languages.
        const bool ru = currentLanguage() == QLatin1String("ru");
        QString text = QCoreApplication::translate("k528::studio::CoreTexts",
                                                   "rejected, nothing was written (errors: %1):")
                           .arg(v->findings().size());
        for (const profile::Finding& f : v->findings()) {
            QString line = fromStd(f.subject);
            if (f.message)
                line += QCoreApplication::translate("k528::studio::CoreTexts", " (message %1)").arg(*f.message);
            text += QStringLiteral("\n") + line + QStringLiteral(": ") + fromStd(ru ? f.textRu : f.textEn);
        }
        return text;
    }
    return databaseErrorText(e);
}

bool readTextFile(const QString& path, std::string& text, QString& error) {
    const QFileInfo info(path);
    QString why;
    if (!info.exists())
        why = QCoreApplication::translate("k528::studio::CoreTexts", "there is no such file");
    else if (info.isDir())
        why = QCoreApplication::translate("k528::studio::CoreTexts", "it is a folder");
    else if (!info.isFile())
        why = QCoreApplication::translate("k528::studio::CoreTexts", "it is not a regular file (a device, a pipe or a socket)");
    else if (!info.isReadable())
        why = QCoreApplication::translate("k528::studio::CoreTexts", "this user may not read it");
    else if (static_cast<std::size_t>(info.size()) > util::kMaxInputBytes)
        why = QCoreApplication::translate("k528::studio::CoreTexts", "it is larger than 16 MiB");
    else {
        std::string err, reason;
        if (util::readInputFile(path.toStdString(), text, err, util::kMaxInputBytes, &reason))
            return true;
        why = fromStd(reason); // the system's own words (the C library's, in the window's language)
    }
    error = QCoreApplication::translate("k528::studio::CoreTexts", "%1 cannot be read: %2").arg(path, why);
    return false;
}

} // namespace k528::studio
