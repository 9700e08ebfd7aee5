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
#include <initializer_list>
#include <utility>
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

// A frame's data as read back from its compact form (FrameBody): a value
// with a pointer's face. `if (const auto iso = f.iso()) use(iso->x);` — the
// handle holds the decoded data, so keep it in a variable: `->` on a
// temporary handle does not compile (it would point into a dead object),
// while `*f.iso()` gives a copy (`const IsoFrame& i = *f.iso();` is safe).
template <class T> class Decoded {
public:
    Decoded() = default;
    explicit Decoded(const T& v) : value_(v), has_(true) {}
    // Filled in place: fill(T&).
    template <class F> Decoded(std::in_place_t, F&& fill) : has_(true) { fill(value_); }
    explicit operator bool() const { return has_; }
    bool has_value() const { return has_; }
    const T* operator->() const& { return &value_; }
    const T* operator->() const&& = delete;
    const T& operator*() const& { return value_; }
    T operator*() && { return std::move(value_); }
    // The data by value (f.iso().value().x); an empty T for an empty handle.
    T value() const { return value_; }
    // The data, or nullptr (valid while the handle lives).
    const T* get() const& { return has_ ? &value_ : nullptr; }

private:
    T value_{};
    bool has_ = false;
};

// The data of a frame of any kind in a compact byte form (variable-length
// integers; a word's position as offsets): about a tenth of the size of the
// structures above, in place for ordinary frames (no allocation) and on the
// heap for long ones. Assign a frame kind's structure to it; read it back
// with the Frame accessors (iso(), compute(), ...). Program memory stays a
// few times the size of the text (bench parse_memory).
class FrameBody {
public:
    FrameBody() = default; // an empty ISO frame
    FrameBody(const IsoFrame& v) { *this = v; }
    FrameBody(const ComputeFrame& v) { *this = v; }
    FrameBody(const IfGotoFrame& v) { *this = v; }
    FrameBody(const GotoFrame& v) { *this = v; }
    FrameBody(const FrameBody& o) { assign(o.kind_, o.data(), o.size_); }
    FrameBody(FrameBody&& o) noexcept { steal(o); }
    FrameBody& operator=(const FrameBody& o) {
        if (this != &o)
            assign(o.kind_, o.data(), o.size_);
        return *this;
    }
    FrameBody& operator=(FrameBody&& o) noexcept {
        if (this != &o) {
            release();
            steal(o);
        }
        return *this;
    }
    ~FrameBody() { release(); }

    FrameBody& operator=(const IsoFrame& v);
    FrameBody& operator=(const ComputeFrame& v);
    FrameBody& operator=(const IfGotoFrame& v);
    FrameBody& operator=(const GotoFrame& v);

    FrameKind kind() const { return kind_; }
    std::size_t index() const { return static_cast<std::size_t>(kind_); } // as std::variant's
    // The data (precondition: kind() matches).
    IsoFrame isoFrame() const {
        IsoFrame f;
        decode(f);
        return f;
    }
    void decode(IsoFrame& f) const; // f is empty
    // An ISO frame has M<number> (false for other kinds), without decoding the rest.
    bool hasM(int number) const { return hasAnyM({number}); }
    // An ISO frame has one of these M words (one pass over the start of the frame).
    bool hasAnyM(std::initializer_list<int> numbers) const;
    ComputeFrame computeFrame() const;
    IfGotoFrame ifGotoFrame() const;
    GotoFrame gotoFrame() const;
    // The jump target of an IF or GOTO frame (0 otherwise), without decoding the rest.
    int jumpTarget() const;
    // The program an ISO frame calls with L (nullopt: none, or not an ISO frame).
    std::optional<int> callTarget() const;
    std::size_t encodedSize() const { return size_; }

private:
    static constexpr std::size_t kInline = 44;
    const std::uint8_t* data() const { return heap_ ? heapPtr() : inline_; }
    std::uint8_t* heapPtr() const;
    void assign(FrameKind kind, const std::uint8_t* bytes, std::size_t n);
    void release();
    void steal(FrameBody& o) noexcept;

    alignas(8) std::uint8_t inline_[kInline] = {}; // the bytes, or (heap_) a pointer to them
    std::uint16_t size_ = 0;
    FrameKind kind_ = FrameKind::Iso;
    bool heap_ = false;
};

// A vector that is empty for most frames: one pointer (null when empty).
// Reads like the std::vector it holds; edit() gives that vector to change.
template <class T> class RareVec {
public:
    RareVec() = default;
    RareVec(std::vector<T> v) { *this = std::move(v); }
    RareVec(std::initializer_list<T> l) : RareVec(std::vector<T>(l)) {}
    RareVec(const RareVec& o) : p_(o.p_ ? new std::vector<T>(*o.p_) : nullptr) {}
    RareVec(RareVec&& o) noexcept : p_(o.p_) { o.p_ = nullptr; }
    RareVec& operator=(const RareVec& o) {
        if (this != &o)
            *this = o.vec();
        return *this;
    }
    RareVec& operator=(RareVec&& o) noexcept {
        if (this != &o) {
            delete p_;
            p_ = o.p_;
            o.p_ = nullptr;
        }
        return *this;
    }
    RareVec& operator=(std::vector<T> v) {
        if (v.empty()) {
            delete p_;
            p_ = nullptr;
        } else if (p_) {
            *p_ = std::move(v);
        } else {
            p_ = new std::vector<T>(std::move(v));
        }
        return *this;
    }
    ~RareVec() { delete p_; }

    const std::vector<T>& vec() const { return p_ ? *p_ : empty_(); }
    operator const std::vector<T>&() const { return vec(); }
    std::vector<T>& edit() {
        if (!p_)
            p_ = new std::vector<T>();
        return *p_;
    }

    std::size_t size() const { return p_ ? p_->size() : 0; }
    bool empty() const { return !p_ || p_->empty(); }
    auto begin() const { return vec().begin(); }
    auto end() const { return vec().end(); }
    auto begin() { return p_ ? p_->begin() : typename std::vector<T>::iterator(); }
    auto end() { return p_ ? p_->end() : typename std::vector<T>::iterator(); }
    const T& operator[](std::size_t i) const { return (*p_)[i]; }
    T& operator[](std::size_t i) { return (*p_)[i]; }
    const T& front() const { return p_->front(); }
    const T& back() const { return p_->back(); }
    T& front() { return p_->front(); }
    T& back() { return p_->back(); }
    void push_back(const T& v) { edit().push_back(v); }
    void push_back(T&& v) { edit().push_back(std::move(v)); }
    template <class... A> T& emplace_back(A&&... a) { return edit().emplace_back(std::forward<A>(a)...); }
    void clear() {
        delete p_;
        p_ = nullptr;
    }

    friend bool operator==(const RareVec& a, const RareVec& b) { return a.vec() == b.vec(); }
    friend bool operator==(const RareVec& a, const std::vector<T>& b) { return a.vec() == b; }

private:
    static const std::vector<T>& empty_() {
        static const std::vector<T> e;
        return e;
    }
    std::vector<T>* p_ = nullptr;
};

struct Frame {
    RareVec<Comment> comments;    // on the frame's line, in order
    RareVec<TriviaLine> leading;  // comment and blank lines just above it
    FrameBody body;               // the data of its kind (assign an IsoFrame, ComputeFrame, ...)
    std::optional<Word> n;        // frame number N
    SourceSpan span;              // the frame's text on its line, comments excluded
    bool skip = false;            // '/': the frame is not executed
    bool malformed = false;       // the parser reported an error in this frame

    FrameKind kind() const { return body.kind(); }
    int number() const { return n ? n->number : 0; } // 0 = no N
    // The data of the frame's kind, or an empty handle for another kind.
    Decoded<IsoFrame> iso() const {
        return kind() == FrameKind::Iso ? Decoded<IsoFrame>(std::in_place, [this](IsoFrame& v) { body.decode(v); })
                                        : Decoded<IsoFrame>();
    }
    Decoded<ComputeFrame> compute() const {
        return kind() == FrameKind::Compute ? Decoded<ComputeFrame>(body.computeFrame())
                                            : Decoded<ComputeFrame>();
    }
    Decoded<IfGotoFrame> ifGoto() const {
        return kind() == FrameKind::IfGoto ? Decoded<IfGotoFrame>(body.ifGotoFrame()) : Decoded<IfGotoFrame>();
    }
    Decoded<GotoFrame> gotoFrame() const {
        return kind() == FrameKind::Goto ? Decoded<GotoFrame>(body.gotoFrame()) : Decoded<GotoFrame>();
    }
    // The jump target of an IF or GOTO frame (0 otherwise).
    int jumpTarget() const { return body.jumpTarget(); }
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
    // The machine file's own message (its [messages], put into the
    // controller's memory when it is built from the file), not a program
    // file's text: a window in English may show the file's English of it.
    // A text set over it (set()) is a program's, even when it reads the same.
    bool machineFile = false;
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
    // Adds or replaces message k (the section becomes present); the text is
    // no longer the machine file's (Message::machineFile).
    void set(int number, std::string text);
    // Adds or replaces message k as the machine file's own (the machine's
    // #k, which has an English text of its own besides the Russian).
    void setMachineFile(int number, std::string text);

private:
    void put(int number, std::string text, bool machineFile);
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
