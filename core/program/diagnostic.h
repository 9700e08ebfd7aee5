// What the parser and the validator report about a program text.
//
// Every diagnostic names its program, its place (line and a column span in
// code points, 1-based, end exclusive — see model.h), its severity, the
// number of the K528-05 message (manual appendix М) when the controller has
// one for it, and a text in Russian and in English. The Russian texts start
// with the panel's wording where the manual has one («Ошибка перехода»,
// «G?») and then say exactly what is wrong.
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

struct Diagnostic {
    Rule rule = Rule::Syntax;
    Severity severity = Severity::Error;
    int program = 0;      // program number; 0 outside programs (file header, messages)
    int line = 0;         // 1-based
    int column = 0;       // 1-based, code points
    int endColumn = 0;    // exclusive, code points; always > column
    int manualNumber = 0; // appendix М number, 0 = none
    std::string messageRu;
    std::string messageEn;

    bool isError() const { return severity == Severity::Error; }
};

// Sorts by line, column, then errors before warnings (stable otherwise).
void sortDiagnostics(std::vector<Diagnostic>& d);
bool hasErrors(const std::vector<Diagnostic>& d);

// "LINE:COL: error|warning: [M<nn>] text" in Russian or English: the plain
// line of shared/spec/cli.md without its "FILE:" (the CLI and the desktop).
std::string formatDiagnostic(const Diagnostic& d, bool russian);
std::size_t countErrors(const std::vector<Diagnostic>& d);

} // namespace k528::program
