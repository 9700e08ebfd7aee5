// What the parser and the validator report about a program text.
//
// Every diagnostic names its program, its place (line and a column span in
// code points, 1-based, end exclusive — see model.h), its severity, the
// number of the K528-05 message (manual appendix М) when the controller has
// one for it, and its text as an id of diagnostic_texts.h's catalog with its
// arguments (numbers already written out, as the texts show them). The
// command line says it in Russian or English from that catalog
// (formatDiagnostic), the desktop through its translators by the id. The
// Russian texts start with the panel's wording where the manual has one
// («Ошибка перехода», «G?») and then say exactly what is wrong.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace k528::program {

enum class Severity : std::uint8_t { Error, Warning };

// One value per rule; ruleId() gives its stable name ("jump-target"), used in
// docs/program-language.md and by the editor.
enum class Rule : std::uint16_t {
    // Text and syntax (parser). A frame with one of these is `malformed`.
    InvalidUtf8,
    UnclosedComment,
    Syntax,
    CyrillicLetter,
    UnknownAddress,
    DuplicateWord,
    TooManyG,
    TooManyM,
    FeedWithoutAxis,
    BadNumber,
    DecimalInCompute,
    LiteralRange,
    BadCondition,
    BadHeader,
    ProgramNumberRange,
    DuplicateProgram,
    FrameOutsideProgram,
    MessageSyntax,
    MessageNumberRange,
    MessageTooLong,
    DuplicateMessage,
    MessageCharacter,
    MessageCharset, // warning
    // Frames (validator).
    FrameNumberRange,
    DuplicateFrameNumber, // 54
    TooManyFrames,
    EmptyProgram, // warning
    NoProgram,    // warning: a file without any program
    CoordinateRange, // 33 / 49
    FeedRange,
    UnknownG,     // 47
    GSameGroup,   // 47
    MRange,
    MRepeated, // warning
    MessageRange,
    MessageUndefined, // warning
    CallRange,
    CallMissing, // 45
    RIndexRange,
    ReadOnlyR,
    DivisionByZero,   // 46
    ConstantOverflow, // 46
    JumpTarget,       // 53
    AxisWithCall,     // 34 / 50
    AxisWithM17,      // 35 / 51
    AxisAtSubprogramEnd, // 36 / 52
    EndCombination,   // 58..62
    DwellWithZ,       // 63
    DwellWithCall,    // 64
    DwellNegative,    // 33
    DwellWithoutTime, // warning
    AxisFunctionWithoutValue, // warning
    Unreachable,      // warning
    NestingCycle,     // 48, warning
    NestingDepth,     // 48, warning
    // Against a machine's constants (validator, warnings).
    AxisAbsent,
    SoftLimit,        // 12 / 28
    FeedAboveMax,
    DiscreteRounding,
};

std::string_view ruleId(Rule r);

// A text of the catalog inside another one (the frame «в кадре N5» / "in
// frame N5", a chain of calls): its id ("" says nothing), its arguments and
// its own parts, which fill the arguments after its own.
struct DiagnosticPart {
    std::string id;
    std::vector<std::string> args;
    std::vector<DiagnosticPart> within;
};

struct Diagnostic {
    Rule rule = Rule::Syntax;
    Severity severity = Severity::Error;
    int program = 0;      // program number; 0 outside programs (file header, messages)
    int line = 0;         // 1-based
    int column = 0;       // 1-based, code points
    int endColumn = 0;    // exclusive, code points; always > column
    int manualNumber = 0; // appendix М number, 0 = none
    std::string textId;             // diagnostic_texts.h
    std::vector<std::string> args;  // %1..: words of the program and numbers, the same in both languages
    std::vector<DiagnosticPart> within; // texts of the catalog, the arguments after `args`

    bool isError() const { return severity == Severity::Error; }
};

// Sorts by line, column, then errors before warnings (stable otherwise).
void sortDiagnostics(std::vector<Diagnostic>& d);
bool hasErrors(const std::vector<Diagnostic>& d);

// "LINE:COL: error|warning: [M<nn>] text" in Russian or English: the plain
// line of shared/spec/cli.md without its "FILE:" (the command line).
std::string formatDiagnostic(const Diagnostic& d, bool russian);
std::size_t countErrors(const std::vector<Diagnostic>& d);

} // namespace k528::program
