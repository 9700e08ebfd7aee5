// Program text -> ProgramStore (shared/spec/program-language.md).
//
// The parser reads the whole text in one pass and never stops at an error:
// each line is parsed on its own, a bad word inside a frame is reported and
// the parser carries on with the next word, a bad header or message line is
// reported and the next line is read as usual. It reports only what makes
// the text unreadable (syntax); the validator judges what was read. A frame
// with a syntax error is kept (marked `malformed`, with whatever words could
// be read) so that its number still counts for jumps and duplicates.
//
// Performance: no regex, no allocation per character; plain words and values
// are read as they are scanned. A 99 x 999-frame store parses and validates
// in about 40 ms (bench/program_bench.cpp, target 50 ms).
#pragma once

#include <string_view>
#include <vector>

#include "program/diagnostic.h"
#include "program/model.h"

namespace k528::program {

struct ParseOptions {
    // The number of the program of a text without a %L header (1..99); the
    // command line's --number, or the editor's current program.
    int programNumber = 1;
};

struct ParseResult {
    ProgramStore store;
    std::vector<Diagnostic> diagnostics; // syntax errors, in text order
    // True if the parser reported an error: the text cannot be formatted
    // without losing something, and must not be run.
    bool hasErrors() const { return program::hasErrors(diagnostics); }
};

ParseResult parse(std::string_view text, const ParseOptions& options = {});

} // namespace k528::program
