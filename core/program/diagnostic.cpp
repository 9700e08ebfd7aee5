#include "program/diagnostic.h"

#include "program/diagnostic_texts.h"

#include <algorithm>
#include <cstdio>

namespace k528::program {

std::string_view ruleId(Rule r) {
    switch (r) {
    case Rule::InvalidUtf8: return "invalid-utf8";
    case Rule::UnclosedComment: return "unclosed-comment";
    case Rule::Syntax: return "syntax";
    case Rule::CyrillicLetter: return "cyrillic-letter";
    case Rule::UnknownAddress: return "unknown-address";
    case Rule::DuplicateWord: return "duplicate-word";
    case Rule::TooManyG: return "too-many-g";
    case Rule::TooManyM: return "too-many-m";
    case Rule::FeedWithoutAxis: return "feed-without-axis";
    case Rule::BadNumber: return "bad-number";
    case Rule::DecimalInCompute: return "decimal-in-compute";
    case Rule::LiteralRange: return "literal-range";
    case Rule::BadCondition: return "bad-condition";
    case Rule::BadHeader: return "bad-header";
    case Rule::ProgramNumberRange: return "program-number-range";
    case Rule::DuplicateProgram: return "duplicate-program";
    case Rule::FrameOutsideProgram: return "frame-outside-program";
    case Rule::MessageSyntax: return "message-syntax";
    case Rule::MessageNumberRange: return "message-number-range";
    case Rule::MessageTooLong: return "message-too-long";
    case Rule::DuplicateMessage: return "duplicate-message";
    case Rule::MessageCharacter: return "message-character";
    case Rule::MessageCharset: return "message-charset";
    case Rule::FrameNumberRange: return "frame-number-range";
    case Rule::DuplicateFrameNumber: return "duplicate-frame-number";
    case Rule::TooManyFrames: return "too-many-frames";
    case Rule::EmptyProgram: return "empty-program";
    case Rule::CoordinateRange: return "coordinate-range";
    case Rule::FeedRange: return "feed-range";
    case Rule::UnknownG: return "unknown-g";
    case Rule::GSameGroup: return "g-same-group";
    case Rule::MRange: return "m-range";
    case Rule::NoProgram: return "no-program";
    case Rule::MRepeated: return "m-repeated";
    case Rule::MessageRange: return "message-range";
    case Rule::MessageUndefined: return "message-undefined";
    case Rule::CallRange: return "call-range";
    case Rule::CallMissing: return "call-missing";
    case Rule::RIndexRange: return "r-index-range";
    case Rule::ReadOnlyR: return "read-only-r";
    case Rule::DivisionByZero: return "division-by-zero";
    case Rule::ConstantOverflow: return "constant-overflow";
    case Rule::JumpTarget: return "jump-target";
    case Rule::AxisWithCall: return "axis-with-call";
    case Rule::AxisWithM17: return "axis-with-m17";
    case Rule::AxisAtSubprogramEnd: return "axis-at-subprogram-end";
    case Rule::EndCombination: return "end-combination";
    case Rule::DwellWithZ: return "dwell-with-z";
    case Rule::DwellWithCall: return "dwell-with-call";
    case Rule::DwellNegative: return "dwell-negative";
    case Rule::DwellWithoutTime: return "dwell-without-time";
    case Rule::AxisFunctionWithoutValue: return "axis-function-without-value";
    case Rule::Unreachable: return "unreachable";
    case Rule::NestingCycle: return "nesting-cycle";
    case Rule::NestingDepth: return "nesting-depth";
    case Rule::AxisAbsent: return "axis-absent";
    case Rule::SoftLimit: return "soft-limit";
    case Rule::FeedAboveMax: return "feed-above-max";
    case Rule::DiscreteRounding: return "discrete-rounding";
    }
    return "unknown";
}

void sortDiagnostics(std::vector<Diagnostic>& d) {
    std::stable_sort(d.begin(), d.end(), [](const Diagnostic& a, const Diagnostic& b) {
        if (a.line != b.line)
            return a.line < b.line;
        if (a.column != b.column)
            return a.column < b.column;
        return a.severity == Severity::Error && b.severity == Severity::Warning;
    });
}

bool hasErrors(const std::vector<Diagnostic>& d) {
    return std::any_of(d.begin(), d.end(), [](const Diagnostic& x) { return x.isError(); });
}

std::string formatDiagnostic(const Diagnostic& d, bool russian) {
    std::string s = std::to_string(d.line) + ":" + std::to_string(d.column) + ": " +
                    (d.isError() ? "error" : "warning") + ": ";
    if (d.manualNumber > 0) {
        char m[24];
        std::snprintf(m, sizeof m, "[M%02d] ", d.manualNumber);
        s += m;
    }
    return s + diagnosticText(d, russian);
}

std::size_t countErrors(const std::vector<Diagnostic>& d) {
    return static_cast<std::size_t>(
        std::count_if(d.begin(), d.end(), [](const Diagnostic& x) { return x.isError(); }));
}

} // namespace k528::program
