#include "program/parser.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <iterator>
#include <string>

#include "program/gfunctions.h"
#include "program/iso_frame.h"
#include "program/text_util.h"
#include "util/utf8.h"

namespace k528::program {

namespace {

using text::isDigit;
using text::isSpace;
using text::upper;

// At most this many errors are reported on one line; the rest of a line
// that bad is noise (documented in docs/program-language.md).
constexpr int kMaxErrorsPerLine = 8;

// Input text as a diagnostic's argument (quoted by the catalog's texts):
// whole UTF-8 characters, bad bytes as \xHH (a text is valid UTF-8 whatever
// the input).
std::string quoted(std::string_view s) { return text::printable(s); }

// The bytes skipTriviaAndComments() reads past: blanks and comment starts
// (one load where skipTrivia() tested each of them on every word).
constexpr std::array<bool, 256> kTriviaStart = [] {
    std::array<bool, 256> a{};
    for (int c = 0; c < 256; ++c)
        a[static_cast<std::size_t>(c)] = isSpace(static_cast<char>(c)) || c == ';' || c == '(';
    return a;
}();

class Parser {
public:
    Parser(std::string_view text, const ParseOptions& options, ParseResult& out)
        : text_(text), options_(options), out_(out) {}

    void run();

private:
    enum class Section { Implicit, Program, Scratch, Messages };

    // --- input -----------------------------------------------------------------
    std::string_view text_;
    ParseOptions options_;
    ParseResult& out_;

    // --- the current line --------------------------------------------------------
    std::string_view line_;
    int lineNo_ = 0;
    bool lineAscii_ = true;
    std::size_t asciiPrefix_ = 0; // bytes before the line's first non-ASCII one (a column each)
    std::size_t colPos_ = 0; // column cache: byte offset ...
    int colCol_ = 1;         // ... and its column
    int lineErrors_ = 0;
    bool crHintGiven_ = false; // the "CR alone is no line end" hint, once a text
    std::size_t invalidUtf8At_ = std::string_view::npos; // the byte reported as invalid-utf8

    // --- state ---------------------------------------------------------------------
    Section section_ = Section::Implicit;
    Program current_;                  // the program being read (Implicit, Program, Scratch)
    int currentDiagProgram_ = 0;       // program number for diagnostics
    std::vector<TriviaLine> pending_;  // trivia since the last frame / entry / header
    bool sawProgramHeader_ = false;
    bool implicitStored_ = false;  // the headerless program went into the store
    bool anythingRead_ = false;    // a non-blank line was read
    SourceSpan implicitFirst_;     // the first frame of the headerless part
    std::array<int, kMaxPrograms + 1> programLine_{}; // header line of each program read
    std::array<int, kMaxMessages + 1> messageLine_{};

    // --- positions and diagnostics ---------------------------------------------------
    int col(std::size_t pos) {
        if (lineAscii_ || pos <= asciiPrefix_)
            return static_cast<int>(pos) + 1;
        if (pos < colPos_) {
            colPos_ = 0;
            colCol_ = 1;
        }
        colCol_ += static_cast<int>(utf8::length(line_.substr(colPos_, pos - colPos_)));
        colPos_ = pos;
        return colCol_;
    }

    [[gnu::always_inline]] ColSpan span(std::size_t b, std::size_t e) {
        if (!lineAscii_ && std::max(b, e > line_.size() ? line_.size() : e) > asciiPrefix_)
            return spanCounted(b, e);
        // A column is a byte: no cache to walk.
        ColSpan s;
        s.column = static_cast<int>(b) + 1;
        s.endColumn = static_cast<int>(e > line_.size() ? line_.size() : e) + 1;
        if (s.endColumn <= s.column)
            s.endColumn = s.column + 1;
        return s;
    }
    // span() of a word read whole: b < e <= line_.size(). (An ASCII line's
    // prefix is all of it, so one test says a column is a byte.)
    [[gnu::always_inline]] ColSpan wordSpan(std::size_t b, std::size_t e) {
        if (e > asciiPrefix_)
            return spanCounted(b, e);
        return {static_cast<int>(b) + 1, static_cast<int>(e) + 1};
    }
    [[gnu::noinline]] ColSpan spanCounted(std::size_t b, std::size_t e) {
        ColSpan s;
        s.column = col(b);
        s.endColumn = col(e > line_.size() ? line_.size() : e);
        if (s.endColumn <= s.column)
            s.endColumn = s.column + 1;
        return s;
    }

    // An error of the text: `id` of diagnostic_texts.h with its arguments.
    void report(Rule rule, int manual, std::size_t b, std::size_t e, std::string_view id,
                std::vector<std::string> args = {}, std::vector<DiagnosticPart> within = {}) {
        if (++lineErrors_ > kMaxErrorsPerLine)
            return;
        Diagnostic d;
        d.rule = rule;
        d.severity = Severity::Error;
        d.program = currentDiagProgram_;
        d.line = lineNo_;
        const ColSpan s = span(b, e);
        d.column = s.column;
        d.endColumn = s.endColumn;
        d.manualNumber = manual;
        d.textId = id;
        d.args = std::move(args);
        d.within = std::move(within);
        out_.diagnostics.push_back(std::move(d));
    }

    // --- lexing helpers ----------------------------------------------------------------
    char at(std::size_t i) const { return i < line_.size() ? line_[i] : '\0'; }
    // The end of the character at i (whole UTF-8 sequences; i + 1 at the end).
    std::size_t charEnd(std::size_t i) const {
        return i < line_.size() ? i + text::sequenceLength(line_, i) : i + 1;
    }
    void skipSpaces(std::size_t& i) const {
        while (i < line_.size() && isSpace(line_[i]))
            ++i;
    }
    bool keyword(std::size_t i, std::string_view kw) const {
        if (i + kw.size() > line_.size())
            return false;
        for (std::size_t k = 0; k < kw.size(); ++k)
            if (upper(line_[i + k]) != kw[k])
                return false;
        return true;
    }
    // Skips spaces and comments; comments are appended to `comments`.
    // Returns false if an unclosed '(' was met (reported; the rest of the
    // line is taken as its text).
    void skipTrivia(std::size_t& i, std::vector<Comment>& comments) {
        // Most calls meet a word or a single blank: no call for them.
        while (i < line_.size() && line_[i] == ' ')
            ++i;
        if (i < line_.size() && kTriviaStart[static_cast<unsigned char>(line_[i])])
            skipTriviaAndComments(i, comments);
    }
    void skipTriviaAndComments(std::size_t& i, std::vector<Comment>& comments);
    // A number at i as one scan reads it: [sign] digits [. digits], the
    // digits gathered into one integer on the way. Every word's number is
    // read by it (intWord, value, operand); what it does not take whole
    // (ends false, too many digits, a second point) goes to numberEnd() and
    // the general lexeme's checks.
    struct NumberScan {
        std::uint64_t digits = 0; // the digits read, the point left out (below 10^19: no overflow)
        std::size_t end = 0;      // where the scan stopped
        int count = 0;            // digits read, leading zeros too (at most kMaxDigits + 1)
        int fraction = -1;        // digits after the point; -1: no point
        bool sign = false;        // a '+' or '-' first
        bool negative = false;    // ... a '-'
        bool ends = false;        // the number lexeme (numberEnd) ends at `end`
        // Digits only, fewer than 10 significant: a whole number as parseUnsigned reads it.
        bool whole() const { return count > 0 && ends && !sign && fraction < 0 && digits < 1000000000; }
    };
    [[gnu::always_inline]] NumberScan scanNumber(std::size_t i) const {
        NumberScan s;
        const char* const p = line_.data();
        const std::size_t n = line_.size();
        std::size_t k = i;
        if (k < n && (p[k] == '-' || p[k] == '+')) {
            s.sign = true;
            s.negative = p[k] == '-';
            ++k;
        }
        // At most kMaxDigits + 1 digits in all: the loops stop at a limit
        // set before them (one test a digit) and count by position.
        constexpr std::size_t kScanDigits = Decimal::kMaxDigits + 1;
        std::uint64_t v = 0;
        const std::size_t first = k;
        for (const std::size_t stop = std::min(n, k + kScanDigits); k < stop && isDigit(p[k]); ++k)
            v = v * 10 + static_cast<std::uint64_t>(p[k] - '0');
        int count = static_cast<int>(k - first);
        if (k < n && p[k] == '.' && count <= Decimal::kMaxDigits) {
            ++k;
            const std::size_t point = k;
            for (const std::size_t stop = std::min(n, k + (kScanDigits - static_cast<std::size_t>(count)));
                 k < stop && isDigit(p[k]); ++k)
                v = v * 10 + static_cast<std::uint64_t>(p[k] - '0');
            s.fraction = static_cast<int>(k - point);
            count += s.fraction;
        }
        s.digits = v;
        s.count = count;
        s.end = k;
        s.ends = k >= n || (!isDigit(p[k]) && p[k] != '.');
        return s;
    }
    // The end of a number lexeme: sign, digits and points.
    std::size_t numberEnd(std::size_t i) const {
        if (i < line_.size() && (line_[i] == '+' || line_[i] == '-'))
            ++i;
        while (i < line_.size() && (isDigit(line_[i]) || line_[i] == '.'))
            ++i;
        return i;
    }
    // Moves past an unreadable word to the next plausible word start.
    // (A byte that is not UTF-8 counts as one character.)
    std::size_t resync(std::size_t i) const {
        auto step = [&](std::size_t k) { return std::max<std::size_t>(1, text::validSequenceLength(line_, k)); };
        if (i < line_.size())
            i += step(i);
        while (i < line_.size()) {
            const char c = line_[i];
            if ((upper(c) >= 'A' && upper(c) <= 'Z') || c == '#' || c == '(' || c == ';' ||
                isSpace(c))
                break;
            i += step(i);
        }
        return i;
    }

    // --- lines ------------------------------------------------------------------------
    std::size_t pos_ = 0; // start of the next line in text_
    // Lines from here to the next header: room for the program's frames.
    std::size_t estimateFrames() const {
        std::size_t n = 1;
        for (std::size_t p = pos_; p < text_.size() && n <= static_cast<std::size_t>(kMaxFrames);) {
            const std::size_t eol = text_.find('\n', p);
            if (eol == std::string_view::npos || eol + 1 >= text_.size() || text_[eol + 1] == '%')
                break;
            ++n;
            p = eol + 1;
        }
        return n;
    }
    void processLine();
    void headerLine(std::size_t i);
    void programHeader(std::size_t start, std::size_t i);
    void messagesHeader(std::size_t start, std::size_t i);
    void messageLine(std::size_t i);
    void frameLine(std::size_t i);
    void reportBadCharacter(std::size_t i, Frame& f);
    std::vector<Comment> fc_; // the comments of the frame being read
    IsoFrame iso_;            // the data of the ISO frame being read
    void crLineEndHint();

    // Words of a frame. Each returns false after reporting an error.
    // Inlined (as span() is) into the loop over a frame's words: as calls
    // they cost a tenth of parsing a store (callgrind of bench_program).
    [[gnu::always_inline]] bool intWord(std::size_t& i, std::size_t start, std::string_view name, Word& w, int manual = 0);
    [[gnu::always_inline]] bool value(std::size_t& i, std::size_t start, std::string_view name, Value& v, int manual);
    // What the fast paths of intWord and value leave (i at the number): the
    // general lexeme and its errors.
    [[gnu::noinline]] bool intWordRest(std::size_t& i, std::size_t start, std::string_view name, Word& w,
                                       int manual);
    [[gnu::noinline]] bool valueRest(std::size_t& i, std::size_t start, std::string_view name, Value& v,
                                     int manual);
    bool operand(std::size_t& i, Operand& o, std::vector<Comment>& comments);
    void isoFrame(std::size_t& i, Frame& f, IsoFrame& iso, std::size_t& contentEnd);
    void computeFrame(std::size_t& i, Frame& f, ComputeFrame& cf, std::size_t& contentEnd);
    void ifFrame(std::size_t& i, Frame& f, IfGotoFrame& jf, std::size_t& contentEnd);
    void gotoFrame(std::size_t& i, Frame& f, GotoFrame& gf, std::size_t& contentEnd);
    bool jumpTarget(std::size_t& i, Word& target, std::vector<Comment>& comments);
    // The next GOTO at or after i, or where a comment or the line begins/ends.
    std::size_t findGoto(std::size_t i) const;
    void expectEnd(std::size_t& i, Frame& f, std::string_view trailingId); // trailing.compute, .if, .goto

    // --- sections ---------------------------------------------------------------------
    void beginSection(); // before a header: closes the current section
    void closeSection(std::vector<TriviaLine> trailing);
    void frameOutsideProgram();
};

// ----------------------------------------------------------------------------------------

void Parser::skipTriviaAndComments(std::size_t& i, std::vector<Comment>& comments) {
    while (i < line_.size()) {
        const char c = line_[i];
        if (isSpace(c)) {
            ++i;
        } else if (c == ';') {
            std::string_view t = line_.substr(i + 1);
            while (!t.empty() && isSpace(t.back()))
                t.remove_suffix(1);
            comments.push_back({Comment::Style::Semicolon, std::string(t)});
            i = line_.size();
        } else if (c == '(') {
            const std::size_t close = line_.find(')', i + 1);
            if (close == std::string_view::npos) {
                report(Rule::UnclosedComment, 0, i, line_.size(), "unclosed-comment");
                comments.push_back({Comment::Style::Parens, std::string(line_.substr(i + 1))});
                i = line_.size();
            } else {
                comments.push_back({Comment::Style::Parens, std::string(line_.substr(i + 1, close - i - 1))});
                i = close + 1;
            }
        } else {
            break;
        }
    }
}

void Parser::run() {
    currentDiagProgram_ = options_.programNumber;
    current_.number = options_.programNumber;
    std::size_t pos = 0;
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") // a UTF-8 byte order mark
        pos = 3;
    while (pos < text_.size()) {
        std::size_t eol = text_.find('\n', pos);
        if (eol == std::string_view::npos)
            eol = text_.size();
        line_ = text_.substr(pos, eol - pos);
        if (!line_.empty() && line_.back() == '\r')
            line_.remove_suffix(1);
        ++lineNo_;
        pos_ = eol + 1;
        processLine();
        crLineEndHint();
        pos = eol + 1;
    }
    // End of text: close what is open.
    closeSection(std::move(pending_));
    out_.store.headerless = !sawProgramHeader_;
}

// A CR alone is a blank (LF and CRLF end lines, program-language.md), so a
// text with CR-only line ends (old Mac editors) reads as one long line with
// errors that say nothing of line ends. Said once, on the first line with a
// bare CR that has errors; a text that reads without errors is not touched.
void Parser::crLineEndHint() {
    if (crHintGiven_ || lineErrors_ == 0)
        return;
    const std::size_t cr = line_.find('\r');
    if (cr == std::string_view::npos)
        return;
    crHintGiven_ = true;
    lineErrors_ = 0; // the hint is shown even after kMaxErrorsPerLine errors
    report(Rule::Syntax, 0, cr, cr + 1, "cr-line-end");
}

void Parser::processLine() {
    lineErrors_ = 0;
    asciiPrefix_ = text::asciiPrefix(line_);
    lineAscii_ = asciiPrefix_ == line_.size();
    colPos_ = 0;
    colCol_ = 1;
    invalidUtf8At_ = std::string_view::npos;
    if (!lineAscii_ && !utf8::isValid(line_.substr(asciiPrefix_))) { // (the ASCII start is valid)
        const std::size_t bad = text::firstInvalidUtf8(line_);
        invalidUtf8At_ = bad;
        report(Rule::InvalidUtf8, 0, bad, bad + 1, "invalid-utf8",
               {text::printable(line_.substr(bad, 1))}); // "\xFF"
    }
    std::size_t i = 0;
    skipSpaces(i);
    if (i == line_.size()) {
        // Blank lines: runs count as one, and none at the start of the text
        // (the formatter writes them so; the model stays canonical).
        if (pending_.empty() ? anythingRead_ : !pending_.back().blank())
            pending_.emplace_back();
        return;
    }
    anythingRead_ = true;
    if (line_[i] == '%') {
        headerLine(i);
        return;
    }
    if (section_ == Section::Messages && line_[i] == '#') {
        messageLine(i);
        return;
    }
    frameLine(i);
}

// --- sections ----------------------------------------------------------------------------

void Parser::frameOutsideProgram() {
    // A %L header after frames that had none: those frames belong to no program.
    const bool implicitOpen = section_ == Section::Implicit && !current_.frames.empty();
    if (sawProgramHeader_ || (!implicitOpen && !implicitStored_))
        return;
    for (auto& d : out_.diagnostics)
        if (d.program == options_.programNumber)
            d.program = 0;
    Diagnostic d;
    d.rule = Rule::FrameOutsideProgram;
    d.line = implicitFirst_.line;
    d.column = implicitFirst_.column;
    d.endColumn = implicitFirst_.endColumn;
    d.textId = "frame-outside-program";
    out_.diagnostics.push_back(std::move(d));
    if (implicitOpen) {
        current_.frames.clear();
        section_ = Section::Scratch;
    }
    if (implicitStored_) {
        out_.store.remove(options_.programNumber);
        implicitStored_ = false;
    }
}

void Parser::closeSection(std::vector<TriviaLine> trailing) {
    while (!trailing.empty() && trailing.back().blank())
        trailing.pop_back();
    switch (section_) {
    case Section::Implicit:
        if (current_.frames.empty()) {
            for (auto& t : trailing)
                out_.store.preamble.push_back(std::move(t));
        } else if (!sawProgramHeader_) {
            // End of a text without headers: this is its one program.
            current_.trailing = std::move(trailing);
            out_.store.insert(std::move(current_));
            implicitStored_ = true;
        }
        break;
    case Section::Program:
        current_.trailing = std::move(trailing);
        out_.store.insert(std::move(current_));
        break;
    case Section::Scratch:
        break;
    case Section::Messages:
        for (auto& t : trailing)
            out_.store.messages.trailing.push_back(std::move(t));
        break;
    }
    current_ = Program();
}

void Parser::beginSection() {
    // Comment lines right above a header (no blank line between) belong to
    // what the header starts; the rest closes the section before it.
    std::size_t split = pending_.size();
    while (split > 0 && !pending_[split - 1].blank())
        --split;
    std::vector<TriviaLine> above(std::make_move_iterator(pending_.begin() + static_cast<std::ptrdiff_t>(split)),
                                  std::make_move_iterator(pending_.end()));
    pending_.resize(split);
    closeSection(std::move(pending_));
    pending_ = std::move(above);
}

void Parser::headerLine(std::size_t start) {
    std::size_t i = start + 1;
    std::size_t w = i;
    while (w < line_.size() && upper(line_[w]) >= 'A' && upper(line_[w]) <= 'Z')
        ++w;
    // "%L12": the word is "L" followed by digits; "%MESSAGES".
    if (w > i && upper(line_[i]) == 'L' && (w == i + 1)) {
        programHeader(start, i + 1);
        return;
    }
    if (w - i == 8 && keyword(i, "MESSAGES")) {
        messagesHeader(start, w);
        return;
    }
    // An unknown header: the lines below still need a home; read them as
    // a program that is not stored.
    beginSection();
    section_ = Section::Scratch;
    currentDiagProgram_ = 0;
    const std::size_t end = w > i ? w : charEnd(i);
    report(Rule::BadHeader, 0, start, end, "header.unknown", {quoted(line_.substr(start, end - start))});
}

void Parser::programHeader(std::size_t start, std::size_t i) {
    frameOutsideProgram();
    beginSection();
    skipSpaces(i);
    const std::size_t numBegin = i;
    const std::size_t numEnd = numberEnd(i);
    const std::string_view lex = line_.substr(numBegin, numEnd - numBegin);
    const auto value = text::parseUnsigned(lex);
    int number = 0;
    bool ok = true;
    currentDiagProgram_ = 0;
    if (!value) {
        ok = false;
        if (lex.empty())
            report(Rule::BadHeader, 0, start, numEnd > numBegin ? numEnd : numBegin + 1, "header.no-number");
        else
            report(Rule::BadHeader, 0, start, numEnd, "header.bad-number", {quoted(lex)});
    } else if (*value < 1 || *value > kMaxPrograms) {
        ok = false;
        number = *value <= 999999999 ? static_cast<int>(*value) : 0;
        report(Rule::ProgramNumberRange, 0, start, numEnd, "program-number-range", {std::string(lex)});
    } else {
        number = static_cast<int>(*value);
        if (programLine_[static_cast<std::size_t>(number)] != 0) {
            ok = false;
            report(Rule::DuplicateProgram, 0, start, numEnd, "duplicate-program",
                   {std::to_string(number), std::to_string(programLine_[static_cast<std::size_t>(number)])});
        }
    }
    sawProgramHeader_ = true;
    current_ = Program();
    current_.number = number;
    current_.headerLine = lineNo_;
    current_.leading = std::move(pending_);
    pending_.clear();
    currentDiagProgram_ = number;
    if (ok) {
        programLine_[static_cast<std::size_t>(number)] = lineNo_;
        section_ = Section::Program;
    } else {
        section_ = Section::Scratch;
    }
    // Title and comments.
    i = numEnd;
    std::vector<Comment> comments;
    skipTrivia(i, comments);
    if (i < line_.size()) {
        report(Rule::BadHeader, 0, i, line_.size(), "header.trailing", {quoted(line_.substr(i))});
    }
    std::size_t first = 0;
    if (!comments.empty() && comments.front().style == Comment::Style::Parens) {
        current_.title = std::move(comments.front().text);
        first = 1;
    }
    for (std::size_t k = first; k < comments.size(); ++k)
        current_.headerComments.push_back(std::move(comments[k]));
}

void Parser::messagesHeader(std::size_t /*start*/, std::size_t i) {
    beginSection();
    currentDiagProgram_ = 0;
    MessageTable& t = out_.store.messages;
    if (!t.present) {
        t.present = true;
        t.headerLine = lineNo_;
        t.leading = std::move(pending_);
        pending_.clear();
    }
    // A second %MESSAGES section continues the table; comments above it
    // stay with the next entry.
    section_ = Section::Messages;
    std::vector<Comment> comments;
    skipTrivia(i, comments);
    if (i < line_.size())
        report(Rule::BadHeader, 0, i, line_.size(), "header.messages-trailing", {quoted(line_.substr(i))});
    for (auto& c : comments)
        t.headerComments.push_back(std::move(c));
}

void Parser::messageLine(std::size_t start) {
    std::size_t i = start + 1;
    skipSpaces(i);
    const std::size_t numBegin = i;
    while (i < line_.size() && isDigit(line_[i]))
        ++i;
    const std::string_view lex = line_.substr(numBegin, i - numBegin);
    skipSpaces(i);
    if (lex.empty() || at(i) != '=') {
        report(Rule::MessageSyntax, 0, start, line_.size(), "message-syntax.line");
        return;
    }
    const auto value = text::parseUnsigned(lex);
    std::string_view textPart = line_.substr(i + 1);
    while (!textPart.empty() && isSpace(textPart.back()))
        textPart.remove_suffix(1);
    if (!value || *value < 1 || *value > kMaxMessages) {
        report(Rule::MessageNumberRange, 0, start, numBegin + lex.size(), "message-number-range",
               {std::string(lex)});
        return;
    }
    const int k = static_cast<int>(*value);
    if (messageLine_[static_cast<std::size_t>(k)] != 0) {
        report(Rule::DuplicateMessage, 0, start, numBegin + lex.size(), "duplicate-message",
               {std::to_string(k), std::to_string(messageLine_[static_cast<std::size_t>(k)])});
        return;
    }
    messageLine_[static_cast<std::size_t>(k)] = lineNo_;
    Message m;
    m.number = k;
    m.text = std::string(textPart);
    m.span.line = lineNo_;
    const ColSpan s = span(start, i + 1 + textPart.size());
    m.span.column = s.column;
    m.span.endColumn = s.endColumn;
    m.textColumn = col(i + 1);
    m.leading = std::move(pending_);
    pending_.clear();
    out_.store.messages.entries.push_back(std::move(m));
}

// --- frames -------------------------------------------------------------------------------

void Parser::frameLine(std::size_t i) {
    // fc_ is empty here: the comments go straight where the frame's are read.
    skipTrivia(i, fc_);
    if (i >= line_.size()) {
        // Comments only: not a frame.
        TriviaLine t;
        t.comments.assign(std::make_move_iterator(fc_.begin()), std::make_move_iterator(fc_.end()));
        fc_.clear();
        pending_.push_back(std::move(t));
        return;
    }
    if (section_ == Section::Messages) {
        fc_.clear();
        report(Rule::MessageSyntax, 0, i, line_.size(), "message-syntax.section");
        return;
    }
    if (current_.frames.empty())
        current_.frames.reserve(estimateFrames());
    Frame& f = current_.frames.emplace_back();
    f.span.line = lineNo_;
    const std::size_t errorsBefore = out_.diagnostics.size();
    const std::size_t contentBegin = i;
    std::size_t contentEnd = i;
    if (line_[i] == '/') {
        f.skip = true;
        ++i;
        contentEnd = i;
        skipTrivia(i, fc_);
    }
    if (upper(at(i)) == 'N') {
        const std::size_t s = i;
        Word w;
        ++i;
        if (intWord(i, s, "N", w))
            f.n = w;
        else
            f.malformed = true;
        contentEnd = i;
        skipTrivia(i, fc_);
    }
    const char c = upper(at(i));
    if (c == 'R') {
        ComputeFrame body;
        computeFrame(i, f, body, contentEnd);
        f.body = body;
    } else if (c == 'I' && upper(at(i + 1)) == 'F') {
        IfGotoFrame body;
        ifFrame(i, f, body, contentEnd);
        f.body = body;
    } else if (keyword(i, "GOTO")) {
        GotoFrame body;
        gotoFrame(i, f, body, contentEnd);
        f.body = body;
    } else {
        // One IsoFrame for every frame, emptied (not built) each time.
        IsoFrame& body = iso_;
        clearIsoFrame(body);
        isoFrame(i, f, body, contentEnd);
        f.body = body;
    }
    // Most frames have no comments and no lines above: a new frame's are
    // empty already, so nothing is moved in then. Comments are moved into a
    // vector of their size, and fc_ keeps its room for the next line's (no
    // growing it again comment by comment).
    if (!fc_.empty()) {
        std::vector<Comment>& comments = f.comments.edit();
        comments.reserve(fc_.size());
        comments.insert(comments.end(), std::make_move_iterator(fc_.begin()), std::make_move_iterator(fc_.end()));
    }
    fc_.clear();
    if (out_.diagnostics.size() != errorsBefore)
        f.malformed = true;
    const ColSpan s = span(contentBegin, contentEnd);
    f.span.column = s.column;
    f.span.endColumn = s.endColumn;
    if (!pending_.empty())
        f.leading = std::move(pending_);
    pending_.clear();
    if (section_ == Section::Implicit && current_.frames.size() == 1)
        implicitFirst_ = f.span;
}

inline bool Parser::intWord(std::size_t& i, std::size_t start, std::string_view name, Word& w, int manual) {
    skipSpaces(i);
    if (at(i) == '=') {
        ++i;
        skipSpaces(i);
    }
    // Plain digits, fewer than 10 significant (what nearly every word is).
    const NumberScan n = scanNumber(i);
    if (n.whole()) {
        i = n.end;
        w.number = static_cast<int>(n.digits);
        w.span = wordSpan(start, n.end);
        return true;
    }
    return intWordRest(i, start, name, w, manual);
}

bool Parser::intWordRest(std::size_t& i, std::size_t start, std::string_view name, Word& w, int manual) {
    const std::size_t b = i;
    const std::size_t e = numberEnd(i);
    i = e;
    const std::string_view lex = line_.substr(b, e - b);
    if (lex.empty()) {
        report(Rule::Syntax, manual, start, b, "address.no-number", {std::string(name)});
        return false;
    }
    const auto v = text::parseUnsigned(lex);
    if (!v) {
        if (text::isAllDigits(lex))
            report(Rule::BadNumber, manual, start, e, "address.too-large", {std::string(name), std::string(lex)});
        else
            report(Rule::BadNumber, manual, start, e, "address.not-whole", {std::string(name), quoted(lex)});
        return false;
    }
    w.number = static_cast<int>(*v);
    w.span = span(start, e);
    return true;
}

inline bool Parser::value(std::size_t& i, std::size_t start, std::string_view name, Value& v, int manual) {
    skipSpaces(i);
    if (at(i) == '=') {
        ++i;
        skipSpaces(i);
    }
    if (upper(at(i)) == 'R') {
        const std::size_t rStart = i;
        ++i;
        Word r;
        if (!intWord(i, rStart, "R", r, manual))
            return false;
        v = Value::rParam(r.number);
        v.span = span(start, i);
        return true;
    }
    // [sign] up to 18 digits with at most one point (what nearly every value is).
    const NumberScan n = scanNumber(i);
    if (n.count > 0 && n.count <= Decimal::kMaxDigits && n.ends) {
        i = n.end;
        const auto m = static_cast<std::int64_t>(n.digits); // at most 18 digits
        v = Value::lit(Decimal::fromScaled(n.negative ? -m : m, n.fraction > 0 ? n.fraction : 0));
        v.span = wordSpan(start, n.end);
        return true;
    }
    return valueRest(i, start, name, v, manual);
}

bool Parser::valueRest(std::size_t& i, std::size_t start, std::string_view name, Value& v, int manual) {
    const std::size_t b = i;
    const std::size_t e = numberEnd(i);
    i = e;
    const std::string_view lex = line_.substr(b, e - b);
    if (lex.empty()) {
        report(Rule::Syntax, manual, start, b, "address.no-value", {std::string(name)});
        return false;
    }
    if ((lex == "-" || lex == "+") && upper(at(e)) == 'R') {
        report(Rule::Syntax, manual, start, e + 1, "address.sign-before-r", {std::string(name)});
        return false;
    }
    const auto d = Decimal::parse(lex);
    if (!d) {
        // A plain decimal fails for one of two reasons, said as such:
        // leading zeros are not significant digits.
        const bool plain = text::isPlainDecimal(lex);
        const bool tooLong = plain && text::significantDigits(lex) > Decimal::kMaxDigits;
        const bool tooFine = plain && !tooLong && text::fractionPlaces(lex) > Decimal::kMaxDigits;
        report(Rule::BadNumber, manual, start, e,
               tooLong ? "value.too-many-digits" : tooFine ? "value.too-fine" : "value.not-number", {quoted(lex)},
               {{manual ? "value-of.coordinate" : "value-of.address", {std::string(name)}, {}}});
        return false;
    }
    v = Value::lit(*d);
    v.span = span(start, e);
    return true;
}

void Parser::reportBadCharacter(std::size_t i, Frame& f) {
    f.malformed = true;
    if (text::validSequenceLength(line_, i) == 0) {
        // A byte that is not UTF-8: the line's first one is already reported
        // (invalid-utf8); a later one is shown as \xHH.
        if (i != invalidUtf8At_)
            report(Rule::Syntax, 0, i, i + 1, "unexpected-character", {quoted(line_.substr(i, 1))});
        return;
    }
    const std::size_t len = text::sequenceLength(line_, i);
    const char32_t cp = text::decodeAt(line_, i);
    if (cp >= 0x400 && cp <= 0x4FF) {
        const char latin = text::latinLookalike(cp);
        if (latin)
            report(Rule::CyrillicLetter, 0, i, i + len, "cyrillic-letter.latin",
                   {quoted(line_.substr(i, len)), std::string(1, latin)});
        else
            report(Rule::CyrillicLetter, 0, i, i + len, "cyrillic-letter", {quoted(line_.substr(i, len))});
        return;
    }
    const char c = line_[i];
    if (upper(c) >= 'A' && upper(c) <= 'Z') {
        report(Rule::UnknownAddress, 0, i, i + 1, "unknown-address", {std::string(1, upper(c))});
        return;
    }
    // (quote shows a control character as \xHH)
    report(Rule::Syntax, 0, i, i + len, "unexpected-character", {quoted(line_.substr(i, len))});
}

void Parser::isoFrame(std::size_t& at_, Frame& f, IsoFrame& iso, std::size_t& contentEnd_) {
    // The positions in locals: a store through a reference to a size_t may
    // change line_'s size for all the compiler knows, so each one would
    // reload the line at every step of the words' loops.
    std::size_t i = at_;
    std::size_t contentEnd = contentEnd_;
    Axis lastAxis = Axis::None; // the word just before was X or Z
    auto duplicate = [&](std::size_t s, std::size_t e, std::string_view sv) {
        report(Rule::DuplicateWord, 0, s, e, "duplicate-word", {std::string(sv)});
    };
    while (true) {
        skipTrivia(i, fc_);
        if (i >= line_.size())
            break;
        const std::size_t s = i;
        const char c = upper(line_[i]);
        Axis thisAxis = Axis::None;
        bool ok = true;
        switch (c) {
        case 'G': {
            if (keyword(i, "GOTO")) {
                report(Rule::Syntax, 0, s, s + 4, "goto-in-frame");
                i += 4;
                ok = false;
                break;
            }
            ++i;
            Word w;
            ok = intWord(i, s, "G", w);
            if (ok) {
                if (iso.g.full()) {
                    report(Rule::TooManyG, 0, s, i, "too-many-g", {gName(w.number)});
                    ok = false;
                } else {
                    iso.g.push_back(w);
                }
            }
            break;
        }
        case 'M': {
            ++i;
            Word w;
            ok = intWord(i, s, "M", w);
            if (ok) {
                if (iso.m.full()) {
                    report(Rule::TooManyM, 0, s, i, "too-many-m", {std::to_string(w.number)});
                    ok = false;
                } else {
                    iso.m.push_back(w);
                }
            }
            break;
        }
        case '#':
        case 'L': {
            ++i;
            Word w;
            const std::string_view name = c == '#' ? "#" : "L";
            ok = intWord(i, s, name, w);
            if (ok) {
                auto& slot = c == '#' ? iso.message : iso.call;
                if (slot) {
                    duplicate(s, i, name);
                    ok = false;
                } else {
                    slot = w;
                }
            }
            break;
        }
        case 'N': {
            ++i;
            Word w;
            intWord(i, s, "N", w);
            report(Rule::Syntax, 0, s, i, "n-not-first");
            ok = false;
            break;
        }
        case 'X':
        case 'Z': {
            ++i;
            const bool isX = c == 'X';
            Value v;
            ok = value(i, s, isX ? "X" : "Z", v, isX ? 33 : 49);
            if (ok) {
                auto& slot = isX ? iso.x : iso.z;
                if (slot) {
                    duplicate(s, i, isX ? "X" : "Z");
                    ok = false;
                } else {
                    slot = v;
                    thisAxis = isX ? Axis::X : Axis::Z;
                }
            }
            break;
        }
        case 'F': {
            ++i;
            const char next = upper(at(i));
            Axis axis = Axis::None;
            if (next == 'X' || next == 'Z') {
                axis = next == 'X' ? Axis::X : Axis::Z;
                ++i;
            } else if (lastAxis != Axis::None) {
                axis = lastAxis;
            }
            Value v;
            const std::string_view name = axis == Axis::X ? "FX" : axis == Axis::Z ? "FZ" : "F";
            ok = value(i, s, name, v, 0);
            if (!ok)
                break;
            if (axis == Axis::None) {
                report(Rule::FeedWithoutAxis, 0, s, i, "feed-without-axis");
                ok = false;
                break;
            }
            auto& slot = axis == Axis::X ? iso.fx : iso.fz;
            if (slot) {
                duplicate(s, i, name);
                ok = false;
            } else {
                slot = v;
            }
            break;
        }
        case 'R':
            report(Rule::Syntax, 0, s, s + 1, "r-outside-compute");
            ok = false;
            i = resync(i);
            break;
        case 'I':
            if (upper(at(i + 1)) == 'F') {
                report(Rule::Syntax, 0, s, s + 2, "if-in-frame");
                ok = false;
                i = line_.size();
                break;
            }
            reportBadCharacter(i, f);
            ok = false;
            i = resync(i);
            break;
        case '/':
            report(Rule::Syntax, 0, s, s + 1, "skip-not-first");
            ok = false;
            ++i;
            break;
        default:
            reportBadCharacter(i, f);
            ok = false;
            i = resync(i);
            break;
        }
        if (!ok)
            f.malformed = true;
        lastAxis = ok ? thisAxis : Axis::None;
        contentEnd = i;
    }
    at_ = i;
    contentEnd_ = contentEnd;
}

bool Parser::operand(std::size_t& i, Operand& o, std::vector<Comment>& comments) {
    skipTrivia(i, comments);
    const std::size_t s = i;
    if (upper(at(i)) == 'R') {
        ++i;
        Word r;
        if (!intWord(i, s, "R", r))
            return false;
        o = Operand::rParam(r.number);
        o.span = span(s, i);
        return true;
    }
    if (const NumberScan n = scanNumber(i); n.count > 0 && n.count <= Decimal::kMaxDigits && n.ends && n.fraction < 0) {
        // [sign] digits (nearly every literal): the value as scanned.
        i = n.end;
        const auto m = static_cast<std::int64_t>(n.digits);
        if (m > (n.negative ? -static_cast<std::int64_t>(INT32_MIN) : static_cast<std::int64_t>(INT32_MAX))) {
            report(Rule::LiteralRange, 0, s, n.end, "literal-range", {std::string(line_.substr(s, n.end - s))});
            return false;
        }
        o = Operand::lit(static_cast<std::int32_t>(n.negative ? -m : m));
        o.span = wordSpan(s, n.end);
        return true;
    }
    const std::size_t e = numberEnd(i);
    const std::string_view lex = line_.substr(s, e - s);
    if (lex.empty()) {
        report(Rule::Syntax, 0, s, s + 1, "operand.missing");
        return false;
    }
    if ((lex == "-" || lex == "+") && upper(at(e)) == 'R') {
        report(Rule::Syntax, 0, s, e + 1, "operand.sign-before-r");
        i = e;
        return false;
    }
    i = e;
    if (lex.find('.') != std::string_view::npos) {
        report(Rule::DecimalInCompute, 0, s, e, "decimal-in-compute", {quoted(lex)});
        return false;
    }
    const auto v = text::parseSigned(lex);
    if (!v) {
        if (text::countDigits(lex) == 0) {
            report(Rule::Syntax, 0, s, e, "operand.not-number", {quoted(lex)});
            return false;
        }
        report(Rule::LiteralRange, 0, s, e, "literal-range", {std::string(lex)});
        return false;
    }
    if (*v < INT32_MIN || *v > INT32_MAX) {
        report(Rule::LiteralRange, 0, s, e, "literal-range", {std::string(lex)});
        return false;
    }
    o = Operand::lit(static_cast<std::int32_t>(*v));
    o.span = span(s, e);
    return true;
}

void Parser::expectEnd(std::size_t& i, Frame& f, std::string_view trailingId) {
    skipTrivia(i, fc_);
    if (i < line_.size()) {
        report(Rule::Syntax, 0, i, line_.size(), trailingId, {quoted(line_.substr(i))});
        f.malformed = true;
        i = line_.size();
    }
}

void Parser::computeFrame(std::size_t& i, Frame& f, ComputeFrame& cf, std::size_t& contentEnd) {
    const std::size_t s = i;
    ++i;
    if (!intWord(i, s, "R", cf.target)) {
        f.malformed = true;
        return;
    }
    contentEnd = i;
    skipTrivia(i, fc_);
    if (at(i) != '=') {
        report(Rule::Syntax, 0, i, i + 1, "compute.equals", {std::to_string(cf.target.number)});
        f.malformed = true;
        return;
    }
    ++i;
    if (!operand(i, cf.a, fc_)) {
        f.malformed = true;
        return;
    }
    contentEnd = i;
    skipTrivia(i, fc_);
    if (i < line_.size()) {
        const char op = line_[i];
        ArithOp a = ArithOp::None;
        switch (op) {
        case '+':
            a = ArithOp::Add;
            break;
        case '-':
            a = ArithOp::Sub;
            break;
        case '*':
            a = ArithOp::Mul;
            break;
        case '/':
            a = ArithOp::Div;
            break;
        default:
            report(Rule::Syntax, 0, i, i + text::sequenceLength(line_, i), "compute.operation",
                   {quoted(line_.substr(i, text::sequenceLength(line_, i)))});
            f.malformed = true;
            return;
        }
        ++i;
        cf.op = a;
        if (!operand(i, cf.b, fc_)) {
            f.malformed = true;
            cf.op = ArithOp::None;
            return;
        }
        contentEnd = i;
    }
    expectEnd(i, f, "trailing.compute");
}

bool Parser::jumpTarget(std::size_t& i, Word& target, std::vector<Comment>& comments) {
    skipTrivia(i, comments);
    const std::size_t s = i;
    if (upper(at(i)) == 'N') {
        // "GOTO N5": one error that says how to write it (the target stays unread).
        std::size_t j = i + 1;
        skipSpaces(j);
        if (at(j) == '=') {
            ++j;
            skipSpaces(j);
        }
        const std::size_t e = numberEnd(j);
        const auto v = text::parseUnsigned(line_.substr(j, e - j));
        i = e > j ? e : i + 1;
        if (v)
            report(Rule::Syntax, 0, s, i, "jump.with-n", {std::to_string(*v)});
        else
            report(Rule::Syntax, 0, s, i, "jump.with-n-only");
        return false;
    }
    if (const NumberScan n = scanNumber(i); n.whole()) {
        i = n.end;
        target.number = static_cast<int>(n.digits);
        target.span = wordSpan(s, n.end);
        return true;
    }
    const std::size_t e = numberEnd(i);
    const std::string_view lex = line_.substr(s, e - s);
    i = e;
    if (lex.empty()) {
        report(Rule::Syntax, 0, s, s + 1, "jump.no-number");
        return false;
    }
    const auto v = text::parseUnsigned(lex);
    if (!v) {
        report(Rule::BadNumber, 53, s, e, "jump.bad-number", {quoted(lex)});
        return false;
    }
    target.number = static_cast<int>(*v);
    target.span = span(s, e);
    return true;
}

std::size_t Parser::findGoto(std::size_t i) const {
    while (i < line_.size() && line_[i] != '(' && line_[i] != ';' && !keyword(i, "GOTO"))
        i += text::sequenceLength(line_, i);
    return i;
}

void Parser::ifFrame(std::size_t& i, Frame& f, IfGotoFrame& jf, std::size_t& contentEnd) {
    i += 2;
    contentEnd = i;
    skipTrivia(i, fc_);
    // After an error in the R-parameter or the condition, reading goes on at
    // GOTO so that an error in the target is reported too.
    bool bad = false;
    const std::size_t rs = i;
    if (upper(at(i)) != 'R') {
        report(Rule::Syntax, 0, rs, charEnd(rs), "if.no-r");
        bad = true;
        i = findGoto(i);
    } else {
        ++i;
        const bool rOk = intWord(i, rs, "R", jf.r);
        bad = !rOk;
        contentEnd = i;
        skipTrivia(i, fc_);
        const std::size_t cs = i;
        while (i < line_.size() && (line_[i] == '>' || line_[i] == '<' || line_[i] == '=' || line_[i] == '!'))
            ++i;
        const std::string_view rel = line_.substr(cs, i - cs);
        skipSpaces(i);
        const std::size_t ve = numberEnd(i);
        const std::string_view val = line_.substr(i, ve - i);
        const bool zero =
            !val.empty() && text::isAllDigits(val) && val.find_first_not_of('0') == std::string_view::npos;
        if (rel != ">" || !zero) {
            const std::string r = rOk ? "R" + std::to_string(jf.r.number) : std::string("R<i>");
            report(Rule::BadCondition, 0, cs, ve > cs ? ve : charEnd(cs), "bad-condition", {r});
            bad = true;
            i = findGoto(ve > cs ? ve : cs);
        } else {
            i = ve;
            contentEnd = i;
        }
    }
    if (bad) {
        f.malformed = true;
        contentEnd = std::max(contentEnd, i);
    }
    skipTrivia(i, fc_);
    if (!keyword(i, "GOTO")) {
        if (!bad) // after an error, what stands here cannot be told from a broken condition
            report(Rule::Syntax, 0, i, charEnd(i), "if.no-goto");
        f.malformed = true;
        return;
    }
    i += 4;
    contentEnd = i;
    if (!jumpTarget(i, jf.target, fc_)) {
        f.malformed = true;
        contentEnd = i;
        return;
    }
    contentEnd = i;
    expectEnd(i, f, "trailing.if");
}

void Parser::gotoFrame(std::size_t& i, Frame& f, GotoFrame& gf, std::size_t& contentEnd) {
    i += 4;
    if (!jumpTarget(i, gf.target, fc_)) {
        f.malformed = true;
        return;
    }
    contentEnd = i;
    expectEnd(i, f, "trailing.goto");
}

} // namespace

ParseResult parse(std::string_view text, const ParseOptions& options) {
    ParseResult result;
    Parser p(text, options, result);
    p.run();
    return result;
}

} // namespace k528::program
