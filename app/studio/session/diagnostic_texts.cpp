#include "session/diagnostic_texts.h"

#include "program/diagnostic.h"
#include "program/diagnostic_texts.h"
#include "proveout/rules.h"
#include "session/translated_texts.h"

#include <QCoreApplication>

#include <optional>
#include <string>
#include <vector>

namespace k528::studio {

namespace {

// core/program/diagnostic_texts.cpp's catalog, each text marked for the translators.
const TranslatedText kTexts[] = {
        {"unclosed-comment", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "comment not closed: no ')' before the end of the line")},
        {"cr-line-end", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "a CR without LF does not end a line: program text ends its lines with LF or CR LF; convert the file (e.g. tr '\\r' '\\n')")},
        {"invalid-utf8", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "invalid byte sequence %1: program text must be UTF-8")},
        {"frame-outside-program", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "frames before the first %L<n> header belong to no program: add a header above them")},
        {"header.unknown", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "unknown header '%1': expected %L<program number> or %MESSAGES")},
        {"header.no-number", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "program header without a number: expected %L<1..99>")},
        {"header.bad-number", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "program number '%1' is not a whole number 1..99")},
        {"program-number-range", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "program number L%1 is outside 1..99")},
        {"duplicate-program", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "program L%1 is already defined on line %2")},
        {"header.trailing", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "unexpected text after the program header: '%1'")},
        {"header.messages-trailing", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "unexpected text after %MESSAGES: '%1'")},
        {"message-syntax.line", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "a message table line must read #<1..99>=<text>")},
        {"message-number-range", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "message number #%1 is outside 1..99")},
        {"duplicate-message", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "message #%1 is already defined on line %2")},
        {"message-syntax.section", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "only #<1..99>=<text> lines and comments may stand in the %MESSAGES section")},
        {"address.no-number", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "address %1 is not followed by a number")},
        {"address.too-large", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "%1%2: number too large")},
        {"address.not-whole", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "%1: '%2' is not a whole number without sign or point")},
        {"address.no-value", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "address %1 has no value: expected a number or an R-parameter")},
        {"address.sign-before-r", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "%1: a sign before an R-parameter is not allowed; compute R<i>=0-R<j> in a frame of its own")},
        {"value.too-many-digits", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "%2'%1' has more than 18 significant digits")},
        {"value.too-fine", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "%2'%1' has more than 18 digits after the decimal point")},
        {"value.not-number", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "%2'%1' is not a number")},
        {"value-of.coordinate", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "%1 value: ")},
        {"value-of.address", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "%1: ")},
        {"unexpected-character", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "unexpected character '%1'")},
        {"cyrillic-letter", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "Cyrillic letter '%1': frame addresses are Latin letters")},
        {"cyrillic-letter.latin", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "Cyrillic letter '%1': frame addresses are Latin letters (%2)")},
        {"unknown-address", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "unknown address '%1': a frame may contain N, G, M, #, L, X, Z, FX, FZ")},
        {"duplicate-word", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "%1 is given twice in the frame")},
        {"goto-in-frame", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "GOTO makes an unconditional jump frame: it holds only [/][N] GOTO <frame number>")},
        {"too-many-g", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "more than three G functions in the frame: %1 is one too many")},
        {"too-many-m", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "more than three M functions in the frame: M%1 is one too many")},
        {"n-not-first", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "the frame number N must come first in the frame")},
        {"feed-without-axis", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "F without an axis: a bare F applies to the X or Z word directly before it; write FX or FZ")},
        {"r-outside-compute", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "R-parameter outside a computational frame: write R<i>=... as a frame of its own, and in X, Z, FX, FZ as X=R<i>")},
        {"if-in-frame", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "IF makes a conditional jump frame: it holds only [/][N] IF R<i>>0 GOTO <number>")},
        {"skip-not-first", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "the skip flag '/' may only stand at the start of the frame")},
        {"operand.missing", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "expected a whole number or an R-parameter")},
        {"operand.sign-before-r", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "a sign before an R-parameter is not allowed: write 0-R<j> instead of -R<j>")},
        {"decimal-in-compute", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "decimal point in a computational frame: R-parameters are whole numbers (discretes), '%1' is not allowed")},
        {"operand.not-number", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "'%1' is not a number")},
        {"literal-range", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "number %1 is outside the range of an R-parameter (-2147483648..2147483647)")},
        {"trailing.compute", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "unexpected text in a computational frame: '%1'")},
        {"trailing.if", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "unexpected text in a conditional jump frame: '%1'")},
        {"trailing.goto", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "unexpected text in an unconditional jump frame: '%1'")},
        {"compute.equals", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "computational frame: '=' expected after R%1")},
        {"compute.operation", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "computational frame: expected an operation + - * / or the end of the frame, not '%1'")},
        {"jump.with-n", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "the jump target is written without N: GOTO %1")},
        {"jump.with-n-only", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "the jump target is written without N: GOTO <frame number 1..999>")},
        {"jump.no-number", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "GOTO is not followed by a frame number")},
        {"jump.bad-number", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "jump target '%1' is not a whole number 1..999")},
        {"if.no-r", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "IF must be followed by an R-parameter: IF R<i>>0 GOTO <number>")},
        {"bad-condition", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "the only jump condition is %1>0 (manual 2.7.1.3); reduce another condition to it with a computational frame")},
        {"if.no-goto", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "the condition must be followed by GOTO <frame number>")},
        {"empty-program", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "program L%1 has no frames")},
        {"too-many-frames", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "program L%1 has %2 frames: at most 999 are allowed; this is frame 1000")},
        {"frame-number-range", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "frame number N%1 is outside 1..999")},
        {"duplicate-frame-number", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "duplicate frame numbers: N%1 is already used on line %2")},
        {"r-index-range", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "R-parameter R%1 does not exist: numbers are 0..299")},
        {"unknown-g.range", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "G?: %1 is outside 0..299")},
        {"unknown-g", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "G?: %1 is not a G function of table 5")},
        {"g-same-group", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "G?: %1 and %2 are both of group %3: a frame may hold one function of a group")},
        {"dwell-negative", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "X value: the dwell time G04 X%1 is negative")},
        {"dwell-range", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "X value: the dwell X%1 s is longer than 9999.999 s")},
        {"coordinate-range", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "%1 value: %1%2 is outside ±9999.999 mm")},
        {"feed-range", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "feed %1%2 is outside 0.001..10000 mm/min")},
        {"refusal.dwell-with-z", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "G04/X/Z: Z is given %2 with the dwell G04; the time goes in X only")},
        {"refusal.dwell-with-call", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "G04/L: subprogram %1 is called %2 with the dwell G04")},
        {"refusal.x-with-call", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "X/L: X is given %2 that calls subprogram %1")},
        {"refusal.z-with-call", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "Z/L: Z is given %2 that calls subprogram %1")},
        {"refusal.x-with-m17", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "X/M17: X is given %2 that ends the subprogram with M17")},
        {"refusal.z-with-m17", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "Z/M17: Z is given %2 that ends the subprogram with M17")},
        {"refusal.m30-call", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "M30/L: end of program M30 and a call of %1 %2")},
        {"refusal.m2-call", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "M2/L: end of program M02 and a call of %1 %2")},
        {"refusal.m17-call", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "M17/L: end of subprogram M17 and a call of %1 %2")},
        {"refusal.m30-m17", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "M30/M17: end of program M30 and end of subprogram M17 %2")},
        {"refusal.m2-m17", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "M2/M17: end of program M02 and end of subprogram M17 %2")},
        {"refusal.x-at-end", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "X/end of L: the last frame of subprogram %1 has no M17 and gives X")},
        {"refusal.z-at-end", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "Z/end of L: the last frame of subprogram %1 has no M17 and gives Z")},
        {"frame", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "in the frame")},
        {"frame.numbered", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "in frame N%1")},
        {"dwell-without-time", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "G04 without X: no dwell time is given (e.g. G04 X20.5 is 20.5 s)")},
        {"axis-function.set-position", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "%1 without %2: no position to set is given (e.g. %1 %212.324)")},
        {"axis-function.oscillation", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "%1 without %2: no oscillation stroke is given (e.g. %1 %2=-30.5 F%2=100)")},
        {"axis-function.signal", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "%1 without %2: there is no motion of axis %2 for signal %3 to interrupt")},
        {"m-range", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "M%1: M function number outside 0..99")},
        {"m-repeated", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "M%1 twice in the frame: the PLC gets it twice")},
        {"message-range", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "#%1: technological message number outside 1..99")},
        {"message-undefined", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "message #%1 is not in the message table: LCD line 2 will be blank")},
        {"call-range", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "L%1: called program number outside 1..99")},
        {"call-missing", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "L missing: there is no program L%1")},
        {"read-only-r", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "R%1 is read only (R232..R262, appendix Л): it cannot be written")},
        {"division-by-zero", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "overflow: division by zero")},
        {"constant-overflow", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "overflow: the result %1 is outside -2147483648..2147483647")},
        {"jump-target.range", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "jump error: frame number %1 is outside 1..999")},
        {"jump-target", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "jump error: there is no frame N%1 in program L%2")},
        {"unreachable", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "the frame on line %1 is never executed: an unconditional jump or an end of program precedes, and no jump leads here")},
        {"unreachable.lines", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "the frames on lines %1-%2 are never executed: an unconditional jump or an end of program precedes, and no jump leads here")},
        {"nesting-cycle", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "subprogram nesting: calls go round in a circle %2; unless a condition breaks it, nesting exceeds the limit of %1")},
        {"nesting-depth", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "subprogram nesting: the call chain %3 nests %1 levels deep, the limit is %2")},
        {"chain.call", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "L%1->%2")},
        {"chain.end", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "L%1")},
        {"axis-absent", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "%1: this machine has no %2 axis (C-parameter НАЛИЧ.ОСИ = 0)")},
        {"soft-limit.above", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "software limit (%2): %2%3%5%6 is beyond the + limit %4 mm")},
        {"soft-limit.below", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "software limit (%2): %2%3%5%6 is beyond the - limit %4 mm")},
        {"soft-limit.diameter", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", " (diameter)")},
        {"soft-limit.machine", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", ", %1 mm in the machine system,")},
        {"discrete-rounding", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "%1%2: the discrete of axis %1 is %3 mm, the value is rounded to %4")},
        {"discrete-rounding.feed", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "F%1%2: the discrete of axis %1 is %3 mm, the feed is rounded to %4")},
        {"feed-above-max", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "F%1%2 is above the axis' maximum program feed F УСК.АВТ. (%3 mm/min)")},
        {"message-too-long", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "message #%1 is longer than 20 characters (%2): the display shows 20")},
        {"message-character", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "control character in the text of message #%1")},
        {"message-charset", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "character '%1' in message #%2 may not show on the K923 (Latin, Cyrillic, digits and ASCII signs)")},
        {"no-program", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "the file holds no program (not a single frame)")},
        {"build.jump-target", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "a jump target is a frame number 1..999, not %1")},
        {"build.too-many-functions", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "at most 3 G and 3 M functions in a frame")},
        {"build.signal", QT_TRANSLATE_NOOP("k528::studio::DiagnosticTexts", "the signal number is 1..4")},
};

const TranslatedTexts kDiagnosticTexts("k528::studio::DiagnosticTexts", kTexts);

QString fromStd(const std::string& s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }

// A diagnostic or a part of one: its own arguments, then the texts of the
// parts it names.
template <class Part>
QString render(const Part& part, std::string_view id, const std::vector<std::string>& args,
               const std::vector<program::DiagnosticPart>& within) {
    if (id.empty())
        return {};
    return sayWithin({&kDiagnosticTexts}, id, args, within,
                     [](const program::DiagnosticPart& w) { return diagnosticText(w); },
                     [&] { return fromStd(program::diagnosticText(part, false)); });
}

} // namespace

QString diagnosticText(const program::Diagnostic& d) { return render(d, d.textId, d.args, d.within); }

QString diagnosticText(const program::DiagnosticPart& p) { return render(p, p.id, p.args, p.within); }

QString diagnosticWithManual(const program::Diagnostic& d) {
    const QString text = diagnosticText(d);
    if (d.manualNumber <= 0)
        return text;
    return QStringLiteral("[M%1] ").arg(d.manualNumber, 2, 10, QChar('0')) + text;
}

QString diagnosticLine(const program::Diagnostic& d) {
    return QCoreApplication::translate("k528::studio::DiagnosticTexts", "%1:%2: %3: %4")
        .arg(QString::number(d.line), QString::number(d.column),
             d.isError() ? QCoreApplication::translate("k528::studio::DiagnosticTexts", "error")
                         : QCoreApplication::translate("k528::studio::DiagnosticTexts", "warning"),
             diagnosticWithManual(d));
}

bool hasDiagnosticText(std::string_view id) { return kDiagnosticTexts.has(id); }

QString ruleName(program::Rule r) {
    using program::Rule;
    const char* name = nullptr;
    switch (r) {
    case Rule::InvalidUtf8: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "not UTF-8"); break;
    case Rule::UnclosedComment: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "unclosed comment"); break;
    case Rule::Syntax: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "frame syntax"); break;
    case Rule::CyrillicLetter: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "Cyrillic letter"); break;
    case Rule::UnknownAddress: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "unknown address"); break;
    case Rule::DuplicateWord: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "word given twice"); break;
    case Rule::TooManyG: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "too many G"); break;
    case Rule::TooManyM: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "too many M"); break;
    case Rule::FeedWithoutAxis: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "F without an axis"); break;
    case Rule::BadNumber: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "bad number"); break;
    case Rule::DecimalInCompute: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "point in an R frame"); break;
    case Rule::LiteralRange: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "number out of range"); break;
    case Rule::BadCondition: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "jump condition"); break;
    case Rule::BadHeader: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "bad header"); break;
    case Rule::ProgramNumberRange: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "program number"); break;
    case Rule::DuplicateProgram: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "program given twice"); break;
    case Rule::FrameOutsideProgram: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "frame outside a program"); break;
    case Rule::MessageSyntax: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "message line"); break;
    case Rule::MessageNumberRange: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "message number"); break;
    case Rule::MessageTooLong: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "message too long"); break;
    case Rule::DuplicateMessage: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "message given twice"); break;
    case Rule::MessageCharacter: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "control character"); break;
    case Rule::MessageCharset: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "K923 characters"); break;
    case Rule::FrameNumberRange: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "frame number"); break;
    case Rule::DuplicateFrameNumber: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "frame number twice"); break;
    case Rule::TooManyFrames: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "too many frames"); break;
    case Rule::EmptyProgram: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "empty program"); break;
    case Rule::NoProgram: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "no program"); break;
    case Rule::CoordinateRange: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "coordinate range"); break;
    case Rule::FeedRange: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "feed range"); break;
    case Rule::UnknownG: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "unknown G"); break;
    case Rule::GSameGroup: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "G of one group"); break;
    case Rule::MRange: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "M out of range"); break;
    case Rule::MRepeated: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "M given twice"); break;
    case Rule::MessageRange: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "message out of range"); break;
    case Rule::MessageUndefined: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "message not in the table"); break;
    case Rule::CallRange: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "call out of range"); break;
    case Rule::CallMissing: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "called program missing"); break;
    case Rule::RIndexRange: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "no such R"); break;
    case Rule::ReadOnlyR: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "read-only R"); break;
    case Rule::DivisionByZero: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "division by zero"); break;
    case Rule::ConstantOverflow: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "R overflow"); break;
    case Rule::JumpTarget: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "jump target"); break;
    case Rule::AxisWithCall: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "axis with a call"); break;
    case Rule::AxisWithM17: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "axis with M17"); break;
    case Rule::AxisAtSubprogramEnd: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "axis at the end of L"); break;
    case Rule::EndCombination: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "two ends in a frame"); break;
    case Rule::DwellWithZ: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "G04 with Z"); break;
    case Rule::DwellWithCall: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "G04 with a call"); break;
    case Rule::DwellNegative: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "negative dwell"); break;
    case Rule::DwellWithoutTime: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "G04 without time"); break;
    case Rule::AxisFunctionWithoutValue: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "G without its axis"); break;
    case Rule::Unreachable: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "unreachable frame"); break;
    case Rule::NestingCycle: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "calls in a circle"); break;
    case Rule::NestingDepth: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "nesting too deep"); break;
    case Rule::AxisAbsent: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "no such axis"); break;
    case Rule::SoftLimit: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "software limit"); break;
    case Rule::FeedAboveMax: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "feed above maximum"); break;
    case Rule::DiscreteRounding: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "rounded to a discrete"); break;
    }
    if (!name)
        return fromStd(std::string(program::ruleId(r)));
    return QCoreApplication::translate("k528::studio::RuleNames", name);
}

QString ruleName(proveout::Rule r) {
    using proveout::Rule;
    const char* name = nullptr;
    switch (r) {
    case Rule::RapidIntoMaterial: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "rapid into material"); break;
    case Rule::ToolIntoChuck: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "tool into chuck"); break;
    case Rule::TurretIntoChuck: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "turret into chuck"); break;
    case Rule::FeedSpindleStopped: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "feed, spindle stopped"); break;
    case Rule::FeedWheelStopped: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "feed, wheel stopped"); break;
    case Rule::CutTooDeep: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "cut too deep"); break;
    case Rule::ManualIntoMaterial: name = QT_TRANSLATE_NOOP("k528::studio::RuleNames", "manual move into material"); break;
    }
    if (!name)
        return fromStd(std::string(proveout::ruleId(r)));
    return QCoreApplication::translate("k528::studio::RuleNames", name);
}

} // namespace k528::studio
