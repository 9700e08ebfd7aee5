// The tokens of a program text for the editor's colouring. The
// word tokens come from the parser's own result — the column spans it
// recorded for every G, M, N, #, L, X/Z/FX/FZ, R and jump target — so a
// colour never disagrees with what the parser read; what lies between
// them (comments, headers, keywords, operators, the skip flag) is scanned
// with the parser's own trivia rules. Diagnostic spans are reported as
// Error tokens on top (the editor draws them as squiggles, not colours).
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "program/parser.h"

namespace k528::program {

enum class TokenKind : std::uint8_t {
    Default,
    Comment,      // "; ..." or "(...)"
    Header,       // "%L12", "%MESSAGES"
    Title,        // "(ring 205)" on a %L line
    Skip,         // "/"
    FrameNumber,  // "N12"
    GWord,        // "G1"
    MWord,        // "M30"
    MessageRef,   // "#5" in a frame
    Call,         // "L11"
    AxisValue,    // "X5.342", "Z=R12"
    Feed,         // "FX50"
    RParam,       // "R75" in a computational frame or IF
    Literal,      // an integer operand
    Keyword,      // "IF", "GOTO"
    JumpTarget,   // the target number of IF/GOTO
    Operator,     // "=", "+", "-", "*", "/", ">" 
    MessageNumber,// "#3=" of a %MESSAGES line
    MessageText,  // its text
};
inline constexpr int kTokenKindCount = 19;

struct Token {
    int line = 0;           // 1-based
    int column = 0;         // 1-based code points
    int endColumn = 0;      // exclusive
    std::size_t begin = 0;  // byte offset in the text
    std::size_t end = 0;    // exclusive
    TokenKind kind = TokenKind::Default;
};

struct TokenizeResult {
    ParseResult parse;          // what the tokens came from
    std::vector<Token> tokens;  // in text order, not overlapping
};

// Tokenizes the whole text (one parse).
TokenizeResult tokenize(std::string_view text, const ParseOptions& options = {});

// Tokens of an already parsed text (the parse of exactly this text).
std::vector<Token> tokensOf(std::string_view text, const ParseResult& parsed);

const char* tokenKindName(TokenKind k);

} // namespace k528::program
