// The program store of the K528-05 (manual 2.7): up to 99 programs numbered
// 1..99, each a sequence of up to 999 frames of four kinds, and the table of
// technological messages #1..99 (20 characters each).
//
// The model is what the interpreter executes: a frame holds its kind, skip
// flag, optional number N and the data of its kind, with values exactly as
// written (Decimal), never pre-rounded. It also keeps what the canonical
// formatter needs to give the text back: every word's column span, comments
// and blank lines.
//
// Positions: lines are 1-based; columns are 1-based and count Unicode code
// points (a tab is one column); an end column is exclusive, so a word
// "X5.3" at the start of a line spans columns 1..5. See docs/program-language.md.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "program/decimal.h"

namespace k528::program {

// --- Limits of the language (manual 2.7, program-language.md) ---------------
inline constexpr int kMaxPrograms = 99;       // program numbers 1..99
inline constexpr int kMaxFrames = 999;        // frames in one program
inline constexpr int kMaxFrameNumber = 999;   // N 1..999
inline constexpr int kMaxGPerFrame = 3;
inline constexpr int kMaxMPerFrame = 3;
inline constexpr int kMaxG = 299;
inline constexpr int kMaxM = 99;
inline constexpr int kMaxMessages = 99;       // #1..99
inline constexpr int kMessageLength = 20;     // characters (LCD line 2)
inline constexpr int kRCount = 300;           // R0..R299
inline constexpr int kFirstSystemR = 150;     // R150..R299 reserved by the system (app. Л)
inline constexpr int kFirstReadOnlyR = 232;   // R232..R262 read only (app. Л)
inline constexpr int kLastReadOnlyR = 262;
inline constexpr int kDefaultNestingLimit = 8; // subprogram nesting (message 48)
// X, Z: ±9999.999 mm; FX, FZ: 0.001..10000 mm/min.
inline constexpr Decimal kMaxCoordinate = Decimal::fromScaled(9999999, 3);
inline constexpr Decimal kMinFeed = Decimal::fromScaled(1, 3);
inline constexpr Decimal kMaxFeed = Decimal::fromInt(10000);

// --- Source positions ---------------------------------------------------------
struct ColSpan {
    int column = 0;    // 1-based, code points
    int endColumn = 0; // exclusive
};

struct SourceSpan {
    int line = 0; // 1-based; 0 = not from a text
    int column = 0;
    int endColumn = 0;
};

// --- Comments ------------------------------------------------------------------
struct Comment {
    enum class Style : std::uint8_t {
        Semicolon, // "; text" to the end of the line
        Parens,    // "(text)"
    };
    Style style = Style::Semicolon;
    std::string text; // between the delimiters, verbatim (a ';' comment right-trimmed)

    friend bool operator==(const Comment&, const Comment&) = default;
};

// A line that is not a frame: a blank line (no comments) or comments only.
struct TriviaLine {
    std::vector<Comment> comments;
    bool blank() const { return comments.empty(); }
    friend bool operator==(const TriviaLine&, const TriviaLine&) = default;
};

// --- Frames ---------------------------------------------------------------------

// An integer word: G, M, # (message), L (call), N, an R index, a jump target.
struct Word {
    int number = 0;
    ColSpan span; // the word with its address ("G281", "N12", "#5")
};

// Up to N items in place (no allocation): the G and M words of a frame.
template <class T, int N> class SmallVec {
public:
    static constexpr int kCapacity = N;
    int size() const { return count_; }
    bool empty() const { return count_ == 0; }
    bool full() const { return count_ == N; }
    void push_back(const T& v) {
        if (count_ < N)
            items_[count_++] = v;
    }
    void clear() { count_ = 0; }
    const T& operator[](int i) const { return items_[static_cast<std::size_t>(i)]; }
    T& operator[](int i) { return items_[static_cast<std::size_t>(i)]; }
    const T* begin() const { return items_.data(); }
    const T* end() const { return items_.data() + count_; }
    T* begin() { return items_.data(); }
    T* end() { return items_.data() + count_; }

private:
    std::array<T, N> items_{};
    std::uint8_t count_ = 0;
};

// The value of X, Z, FX or FZ: an exact decimal, or an R-parameter read in
// discretes of the axis (discretes per minute for FX/FZ).
struct Value {
    enum class Kind : std::uint8_t { Literal, RParam };
    Decimal literal; // Kind::Literal: millimetres, mm/min, or seconds (G04)
    int rIndex = 0;  // Kind::RParam
    ColSpan span;    // the whole word with its address ("X=-30.5", "FZR12")
    Kind kind = Kind::Literal;

    bool isR() const { return kind == Kind::RParam; }
    static Value lit(Decimal d) {
        Value v;
        v.literal = d;
        return v;
    }
    static Value rParam(int index) {
        Value v;
        v.kind = Kind::RParam;
        v.rIndex = index;
        return v;
    }
};

// 1. ISO frame: [G]0..3 [M]0..3 [#k] [L p] [X] [FX] [Z] [FZ].
struct IsoFrame {
    SmallVec<Word, kMaxGPerFrame> g; // in the order written
    SmallVec<Word, kMaxMPerFrame> m; // in the order written
    std::optional<Word> message;     // #k: technological message 1..99
    std::optional<Word> call;        // L p: call program p as a subprogram
    std::optional<Value> x, fx, z, fz;

    bool hasG(int number) const;
    bool hasM(int number) const;
    const Word* findG(int number) const;
    const Word* findM(int number) const;
    bool empty() const { return g.empty() && m.empty() && !message && !call && !x && !fx && !z && !fz; }
};

// 2. Computational frame: R<target> = a [op b]. Integers (discretes); division
// truncates toward zero; overflow and division by zero are alarm 46 at run time.
struct Operand {
    enum class Kind : std::uint8_t { Literal, RParam };
    Kind kind = Kind::Literal;
    std::int32_t literal = 0; // Kind::Literal
    int rIndex = 0;           // Kind::RParam
    ColSpan span;

    bool isR() const { return kind == Kind::RParam; }
    static Operand lit(std::int32_t v) {
        Operand o;
        o.literal = v;
        return o;
    }
    static Operand rParam(int index) {
        Operand o;
        o.kind = Kind::RParam;
        o.rIndex = index;
        return o;
    }
};

enum class ArithOp : std::uint8_t { None, Add, Sub, Mul, Div };
char arithOpChar(ArithOp op); // '+', '-', '*', '/' (0 for None)

struct ComputeFrame {
    Word target; // the R index written to
    Operand a;
    ArithOp op = ArithOp::None;
    Operand b; // when op != None
};

// 3. Conditional jump: IF R<i> > 0 GOTO <target>.
struct IfGotoFrame {
    Word r; // the R index tested
    Word target;
};

// 4. Unconditional jump: GOTO <target>.
struct GotoFrame {
    Word target;
};

enum class FrameKind : std::uint8_t { Iso, Compute, IfGoto, Goto };

struct Frame {
    std::variant<IsoFrame, ComputeFrame, IfGotoFrame, GotoFrame> body;
    bool skip = false;         // '/': the frame is not executed
    std::optional<Word> n;     // frame number N
    SourceSpan span;           // the frame's text on its line, comments excluded
    bool malformed = false;    // the parser reported an error in this frame
    std::vector<Comment> comments;   // on the frame's line, in order
    std::vector<TriviaLine> leading; // comment and blank lines just above it

    FrameKind kind() const { return static_cast<FrameKind>(body.index()); }
    int number() const { return n ? n->number : 0; } // 0 = no N
    const IsoFrame* iso() const { return std::get_if<IsoFrame>(&body); }
    const ComputeFrame* compute() const { return std::get_if<ComputeFrame>(&body); }
    const IfGotoFrame* ifGoto() const { return std::get_if<IfGotoFrame>(&body); }
    const GotoFrame* gotoFrame() const { return std::get_if<GotoFrame>(&body); }
    IsoFrame* iso() { return std::get_if<IsoFrame>(&body); }
    ComputeFrame* compute() { return std::get_if<ComputeFrame>(&body); }
    IfGotoFrame* ifGoto() { return std::get_if<IfGotoFrame>(&body); }
    GotoFrame* gotoFrame() { return std::get_if<GotoFrame>(&body); }
    // The jump target of an IF or GOTO frame (0 otherwise).
    int jumpTarget() const;
};

// --- Programs ---------------------------------------------------------------------
class Program {
public:
    int number = 0;                   // 1..99
    std::optional<std::string> title; // "%L12 (title)"
    std::vector<Comment> headerComments; // further comments on the header line
    std::vector<TriviaLine> leading;     // comment lines right above the header
    std::vector<Frame> frames;
    std::vector<TriviaLine> trailing; // comment and blank lines after the last frame
    int headerLine = 0;               // line of "%L<n>"; 0 if the text had no header

    // Index into `frames` of the first frame numbered n, or -1. Valid after
    // reindex(): the parser calls it; call it again after editing `frames`.
    int indexOfN(int n) const {
        return n >= 1 && n <= kMaxFrameNumber ? byN_[static_cast<std::size_t>(n)] : -1;
    }
    void reindex();

private:
    std::array<std::int32_t, kMaxFrameNumber + 1> byN_ = filled();
    static constexpr std::array<std::int32_t, kMaxFrameNumber + 1> filled() {
        std::array<std::int32_t, kMaxFrameNumber + 1> a{};
        for (auto& v : a)
            v = -1;
        return a;
    }
};

// --- Messages ---------------------------------------------------------------------
struct Message {
    int number = 0;      // 1..99
    std::string text;    // up to 20 characters, shown on LCD line 2
    SourceSpan span;     // the "#k=text" line
    int textColumn = 0;  // column of the text's first character
    std::vector<TriviaLine> leading; // comment and blank lines above it
};

struct MessageTable {
    bool present = false; // the text had a %MESSAGES section
    int headerLine = 0;
    std::vector<Comment> headerComments;
    std::vector<TriviaLine> leading;  // comment lines right above %MESSAGES
    std::vector<Message> entries;     // in the order read
    std::vector<TriviaLine> trailing; // comment and blank lines after the last entry

    const Message* find(int number) const;
    // Text of message k, or nullptr.
    const std::string* text(int number) const {
        const Message* m = find(number);
        return m ? &m->text : nullptr;
    }
    // Adds or replaces message k (the section becomes present).
    void set(int number, std::string text);
};

// --- The store ----------------------------------------------------------------------
class ProgramStore {
public:
    // Programs sorted by number.
    std::span<const Program> programs() const { return programs_; }
    std::span<Program> programs() { return programs_; }
    std::size_t size() const { return programs_.size(); }
    bool empty() const { return programs_.empty(); }

    const Program* find(int number) const;
    Program* find(int number);
    bool contains(int number) const { return find(number) != nullptr; }
    // Adds a program, or replaces the one with the same number. Reindexes it.
    Program& insert(Program p);
    bool remove(int number);
    std::vector<int> numbers() const;
    // The programs in the order their text was written: by headerLine, the
    // ones without a header line (added by an editor, built in code) last, by
    // number. `k528 format` writes them in this order and `k528 run` starts
    // the first of it by default, so formatting never changes what runs.
    std::vector<const Program*> inWrittenOrder() const;
    // The number of the first program in written order; 0 for an empty store.
    int firstWritten() const;

    MessageTable messages;

    // Layout of the text the store came from (used by the formatter):
    bool headerless = false;          // one program without a %L header
    std::vector<TriviaLine> preamble; // comment lines before the first program

private:
    std::vector<Program> programs_;
};

// True if two frames / programs have the same content: kind, skip flag, N,
// words and values, comments and blank lines. Source positions are ignored.
bool sameContent(const Frame& a, const Frame& b);
bool sameContent(const Program& a, const Program& b);

} // namespace k528::program
