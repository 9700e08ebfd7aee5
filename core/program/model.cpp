#include "program/model.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <utility>

namespace k528::program {

bool IsoFrame::hasG(int number) const { return findG(number) != nullptr; }
bool IsoFrame::hasM(int number) const { return findM(number) != nullptr; }

const Word* IsoFrame::findG(int number) const {
    for (const Word& w : g)
        if (w.number == number)
            return &w;
    return nullptr;
}

const Word* IsoFrame::findM(int number) const {
    for (const Word& w : m)
        if (w.number == number)
            return &w;
    return nullptr;
}

char arithOpChar(ArithOp op) {
    switch (op) {
    case ArithOp::Add:
        return '+';
    case ArithOp::Sub:
        return '-';
    case ArithOp::Mul:
        return '*';
    case ArithOp::Div:
        return '/';
    case ArithOp::None:
        break;
    }
    return 0;
}

// --- FrameBody: the compact form -----------------------------------------------------------
//
// Integers are variable-length (7 bits a byte, the signed ones
// zigzag-coded). A span is the distance of its column from the end of the
// item before (0 for the first) and its width: one byte when the distance
// is 0..7 and the width 1..16 (words one blank apart, as a text is
// written), else a 0x80 byte and the two as integers.
//   ISO:     two bytes (low byte first) saying which items follow: the
//            counts of G and M words (2 bits each), then a bit for each of
//            #, L, X, FX, Z, FZ, then one for each value that is an
//            R-parameter; then the items in the order of the canonical
//            text: g..., m..., #, L, X, FX, Z, FZ. A word is its number and
//            span, a value its R index or its mantissa and a scale byte,
//            and its span. An empty ISO frame has no bytes.
//   Compute: target word, operand a, op byte, operand b (operand: kind byte,
//            literal or R index, span).
//   IfGoto:  r word, target word.   Goto: target word.
// The two bytes first let a reader go straight to what it wants (no tag to
// test a word), and the order of the text keeps spans in their one byte.
namespace {

// The bits of the two bytes first.
constexpr unsigned kMShift = 2;          // G count in bits 0-1, M count in 2-3
constexpr unsigned kHasMessage = 1u << 4;
constexpr unsigned kHasCall = 1u << 5;
constexpr unsigned kHasValue = 1u << 6;  // X, FX, Z, FZ: bits 6-9
constexpr unsigned kValueIsR = 1u << 10; // X, FX, Z, FZ: bits 10-13

std::uint64_t zig(std::int64_t v) {
    return (static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63);
}
std::int64_t unzig(std::uint64_t u) { return static_cast<std::int64_t>(u >> 1) ^ -static_cast<std::int64_t>(u & 1); }

// Writing goes through a local pointer, not a member: a byte stored
// through a member pointer may change any member for all the compiler
// knows, so each byte would reload and store the position again.
struct Out {
    std::uint8_t* p;
    std::int64_t prevEnd = 0;
};
[[gnu::always_inline]] inline void putByte(Out& o, std::uint8_t b) { *o.p++ = b; }
[[gnu::always_inline]] inline void putU(Out& o, std::uint64_t v) {
    std::uint8_t* p = o.p;
    while (v >= 0x80) {
        *p++ = static_cast<std::uint8_t>(v | 0x80);
        v >>= 7;
    }
    *p++ = static_cast<std::uint8_t>(v);
    o.p = p;
}
[[gnu::always_inline]] inline void putS(Out& o, std::int64_t v) { putU(o, zig(v)); }
[[gnu::always_inline]] inline void putSpan(Out& o, const ColSpan& s) {
    const std::int64_t delta = static_cast<std::int64_t>(s.column) - o.prevEnd;
    const std::int64_t width = static_cast<std::int64_t>(s.endColumn) - s.column;
    if (delta >= 0 && delta <= 7 && width >= 1 && width <= 16) {
        putByte(o, static_cast<std::uint8_t>(delta << 4 | (width - 1)));
    } else {
        putByte(o, 0x80);
        putS(o, delta);
        putS(o, width);
    }
    o.prevEnd = s.endColumn;
}
[[gnu::always_inline]] inline void putWord(Out& o, const Word& w) {
    putS(o, w.number);
    putSpan(o, w.span);
}
[[gnu::always_inline]] inline void putValue(Out& o, const Value& v) {
    if (v.isR()) {
        putS(o, v.rIndex);
    } else {
        putS(o, v.literal.mantissa);
        putByte(o, static_cast<std::uint8_t>(v.literal.scale));
    }
    putSpan(o, v.span);
}
inline void putOperand(Out& o, const Operand& x) {
    putByte(o, static_cast<std::uint8_t>(x.kind));
    putS(o, x.isR() ? x.rIndex : x.literal);
    putSpan(o, x.span);
}
// The longest item is 10 + 1 + 1 + 2 * 10 bytes; a frame has at most 12,
// after two bytes.
constexpr std::size_t kMaxEncoded = 512;

class Reader {
public:
    explicit Reader(const std::uint8_t* p) : p_(p) {}
    std::uint8_t byte() { return *p_++; }
    std::uint64_t uvar() {
        if (!(*p_ & 0x80)) // one byte: most spans and small numbers
            return *p_++;
        std::uint64_t v = 0;
        int shift = 0;
        while (true) {
            const std::uint8_t b = *p_++;
            v |= static_cast<std::uint64_t>(b & 0x7F) << shift;
            if (!(b & 0x80))
                return v;
            shift += 7;
        }
    }
    std::int64_t svar() { return unzig(uvar()); }
    int ivar() { return static_cast<int>(svar()); }
    ColSpan span() {
        ColSpan s;
        const std::uint8_t b = *p_++;
        if (!(b & 0x80)) {
            s.column = static_cast<int>(prevEnd_ + (b >> 4));
            s.endColumn = static_cast<int>(s.column + (b & 0x0F) + 1);
        } else {
            s.column = static_cast<int>(prevEnd_ + svar());
            s.endColumn = static_cast<int>(s.column + svar());
        }
        prevEnd_ = s.endColumn;
        return s;
    }
    void skipSpan() {
        if (*p_++ & 0x80) {
            uvar();
            uvar();
        }
    }
    void skipWord() {
        uvar();
        skipSpan();
    }
    Word word() {
        Word w;
        w.number = ivar();
        w.span = span();
        return w;
    }
    void value(Value& v, bool isR) {
        if (isR) {
            v.kind = Value::Kind::RParam;
            v.rIndex = ivar();
        } else {
            v.literal.mantissa = svar();
            v.literal.scale = byte();
        }
        v.span = span();
    }
    Operand operand() {
        Operand o;
        o.kind = static_cast<Operand::Kind>(byte());
        const int v = ivar();
        if (o.isR())
            o.rIndex = v;
        else
            o.literal = v;
        o.span = span();
        return o;
    }

private:
    const std::uint8_t* p_;
    std::int64_t prevEnd_ = 0;
};

} // namespace

std::uint8_t* FrameBody::heapPtr() const {
    std::uint8_t* p = nullptr;
    std::memcpy(&p, inline_, sizeof p);
    return p;
}

void FrameBody::release() {
    if (heap_)
        delete[] heapPtr();
    heap_ = false;
    size_ = 0;
}

void FrameBody::steal(FrameBody& o) noexcept {
    std::memcpy(inline_, o.inline_, kInline);
    size_ = o.size_;
    kind_ = o.kind_;
    heap_ = o.heap_;
    o.heap_ = false;
    o.size_ = 0;
    o.kind_ = FrameKind::Iso;
}

void FrameBody::assign(FrameKind kind, const std::uint8_t* bytes, std::size_t n) {
    // `bytes` never points into this body (self-assignment is excluded).
    release();
    if (n > kInline) {
        auto* p = new std::uint8_t[n];
        std::memcpy(p, bytes, n);
        std::memcpy(inline_, &p, sizeof p);
        heap_ = true;
    } else if (n) {
        std::memcpy(inline_, bytes, n);
    }
    size_ = static_cast<std::uint16_t>(n);
    kind_ = kind;
}

FrameBody& FrameBody::operator=(const IsoFrame& v) {
    std::uint8_t buf[kMaxEncoded];
    Out o{buf};
    const std::optional<Word>* const words[] = {&v.message, &v.call};
    const std::optional<Value>* const values[] = {&v.x, &v.fx, &v.z, &v.fz};
    unsigned head = static_cast<unsigned>(v.g.size()) | static_cast<unsigned>(v.m.size()) << kMShift;
#pragma GCC unroll 2
    for (int k = 0; k < 2; ++k)
        head |= *words[k] ? kHasMessage << k : 0;
#pragma GCC unroll 4
    for (int k = 0; k < 4; ++k)
        head |= *values[k] ? (kHasValue << k) | ((*values[k])->isR() ? kValueIsR << k : 0) : 0;
    if (head != 0) {
        putByte(o, static_cast<std::uint8_t>(head));
        putByte(o, static_cast<std::uint8_t>(head >> 8));
        for (const Word& g : v.g)
            putWord(o, g);
        for (const Word& m : v.m)
            putWord(o, m);
        for (const auto* w : words)
            if (*w)
                putWord(o, **w);
        for (unsigned present = (head / kHasValue) & 15; present != 0; present &= present - 1)
            putValue(o, **values[std::countr_zero(present)]);
    }
    const auto n = static_cast<std::size_t>(o.p - buf);
    if (n <= kInline && !heap_) {
        // Nearly every frame: a copy of fixed size (the buffer is longer),
        // without the general assign().
        std::memcpy(inline_, buf, kInline);
        size_ = static_cast<std::uint16_t>(n);
        kind_ = FrameKind::Iso;
    } else {
        assign(FrameKind::Iso, buf, n);
    }
    return *this;
}

FrameBody& FrameBody::operator=(const ComputeFrame& v) {
    std::uint8_t buf[kMaxEncoded];
    Out o{buf};
    putWord(o, v.target);
    putOperand(o, v.a);
    putByte(o, static_cast<std::uint8_t>(v.op));
    putOperand(o, v.b);
    assign(FrameKind::Compute, buf, static_cast<std::size_t>(o.p - buf));
    return *this;
}

FrameBody& FrameBody::operator=(const IfGotoFrame& v) {
    std::uint8_t buf[kMaxEncoded];
    Out o{buf};
    putWord(o, v.r);
    putWord(o, v.target);
    assign(FrameKind::IfGoto, buf, static_cast<std::size_t>(o.p - buf));
    return *this;
}

FrameBody& FrameBody::operator=(const GotoFrame& v) {
    std::uint8_t buf[kMaxEncoded];
    Out o{buf};
    putWord(o, v.target);
    assign(FrameKind::Goto, buf, static_cast<std::size_t>(o.p - buf));
    return *this;
}

namespace {
unsigned isoHead(const std::uint8_t* p) { return p[0] | static_cast<unsigned>(p[1]) << 8; }
int gCount(unsigned head) { return static_cast<int>(head & 3); }
int mCount(unsigned head) { return static_cast<int>((head >> kMShift) & 3); }
} // namespace

bool FrameBody::hasAnyM(std::initializer_list<int> numbers) const {
    if (kind_ != FrameKind::Iso || size_ == 0)
        return false;
    const unsigned head = isoHead(data());
    Reader r(data() + 2);
    for (int k = gCount(head); k > 0; --k)
        r.skipWord();
    for (int k = mCount(head); k > 0; --k) {
        const int n = r.ivar();
        if (std::find(numbers.begin(), numbers.end(), n) != numbers.end())
            return true;
        r.skipSpan();
    }
    return false;
}

void FrameBody::decode(IsoFrame& f) const {
    if (size_ == 0)
        return;
    const unsigned head = isoHead(data());
    Reader r(data() + 2);
    for (int k = gCount(head); k > 0; --k)
        f.g.push_back(r.word());
    for (int k = mCount(head); k > 0; --k)
        f.m.push_back(r.word());
    if (head & kHasMessage)
        f.message = r.word();
    if (head & kHasCall)
        f.call = r.word();
    std::optional<Value>* const values[] = {&f.x, &f.fx, &f.z, &f.fz};
    for (unsigned present = (head / kHasValue) & 15; present != 0; present &= present - 1) {
        const int k = std::countr_zero(present);
        r.value(values[k]->emplace(), (head & (kValueIsR << k)) != 0);
    }
}

ComputeFrame FrameBody::computeFrame() const {
    ComputeFrame c;
    Reader r(data());
    c.target = r.word();
    c.a = r.operand();
    c.op = static_cast<ArithOp>(r.byte());
    c.b = r.operand();
    return c;
}

IfGotoFrame FrameBody::ifGotoFrame() const {
    IfGotoFrame j;
    Reader r(data());
    j.r = r.word();
    j.target = r.word();
    return j;
}

GotoFrame FrameBody::gotoFrame() const {
    GotoFrame j;
    Reader r(data());
    j.target = r.word();
    return j;
}

int FrameBody::jumpTarget() const {
    if (kind_ == FrameKind::Goto) {
        Reader r(data());
        return r.ivar();
    }
    if (kind_ == FrameKind::IfGoto) {
        Reader r(data());
        r.skipWord();
        return r.ivar();
    }
    return 0;
}

std::optional<int> FrameBody::callTarget() const {
    if (kind_ != FrameKind::Iso || size_ == 0)
        return std::nullopt;
    const unsigned head = isoHead(data());
    if (!(head & kHasCall))
        return std::nullopt;
    Reader r(data() + 2);
    for (int k = gCount(head) + mCount(head) + ((head & kHasMessage) ? 1 : 0); k > 0; --k)
        r.skipWord();
    return r.ivar();
}

void Program::reindex() {
    byN_ = filled();
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const int n = frames[i].number();
        if (n >= 1 && n <= kMaxFrameNumber && byN_[static_cast<std::size_t>(n)] < 0)
            byN_[static_cast<std::size_t>(n)] = static_cast<std::int32_t>(i);
    }
}

const Message* MessageTable::find(int number) const {
    for (const Message& m : entries)
        if (m.number == number)
            return &m;
    return nullptr;
}

void MessageTable::set(int number, std::string text) { put(number, std::move(text), false); }

void MessageTable::setMachineFile(int number, std::string text) { put(number, std::move(text), true); }

void MessageTable::put(int number, std::string text, bool machineFile) {
    present = true;
    for (Message& m : entries)
        if (m.number == number) {
            m.text = std::move(text);
            m.machineFile = machineFile;
            return;
        }
    Message m;
    m.number = number;
    m.text = std::move(text);
    m.machineFile = machineFile;
    entries.push_back(std::move(m));
}

namespace {
auto lowerByNumber(const std::vector<Program>& v, int number) {
    return std::lower_bound(v.begin(), v.end(), number,
                            [](const Program& p, int n) { return p.number < n; });
}
} // namespace

const Program* ProgramStore::find(int number) const {
    const auto it = lowerByNumber(programs_, number);
    return it != programs_.end() && it->number == number ? &*it : nullptr;
}

Program* ProgramStore::find(int number) {
    return const_cast<Program*>(std::as_const(*this).find(number));
}

Program& ProgramStore::insert(Program p) {
    p.reindex();
    auto it = std::lower_bound(programs_.begin(), programs_.end(), p.number,
                               [](const Program& q, int n) { return q.number < n; });
    if (it != programs_.end() && it->number == p.number) {
        *it = std::move(p);
        return *it;
    }
    return *programs_.insert(it, std::move(p));
}

bool ProgramStore::remove(int number) {
    auto it = std::lower_bound(programs_.begin(), programs_.end(), number,
                               [](const Program& q, int n) { return q.number < n; });
    if (it == programs_.end() || it->number != number)
        return false;
    programs_.erase(it);
    return true;
}

std::vector<const Program*> ProgramStore::inWrittenOrder() const {
    std::vector<const Program*> v;
    v.reserve(programs_.size());
    for (const Program& p : programs_)
        v.push_back(&p);
    const auto key = [](const Program* p) {
        return std::pair(p->headerLine > 0 ? p->headerLine : std::numeric_limits<int>::max(), p->number);
    };
    std::sort(v.begin(), v.end(), [&](const Program* a, const Program* b) { return key(a) < key(b); });
    return v;
}

int ProgramStore::firstWritten() const {
    const auto v = inWrittenOrder();
    return v.empty() ? 0 : v.front()->number;
}

std::vector<int> ProgramStore::numbers() const {
    std::vector<int> v;
    v.reserve(programs_.size());
    for (const Program& p : programs_)
        v.push_back(p.number);
    return v;
}

namespace {

bool sameWord(const Word& a, const Word& b) { return a.number == b.number; }

template <class T> bool sameOpt(const std::optional<T>& a, const std::optional<T>& b, bool (*eq)(const T&, const T&)) {
    if (a.has_value() != b.has_value())
        return false;
    return !a || eq(*a, *b);
}

bool sameValue(const Value& a, const Value& b) {
    if (a.kind != b.kind)
        return false;
    return a.isR() ? a.rIndex == b.rIndex : a.literal == b.literal;
}

bool sameOperand(const Operand& a, const Operand& b) {
    if (a.kind != b.kind)
        return false;
    return a.isR() ? a.rIndex == b.rIndex : a.literal == b.literal;
}

template <int N> bool sameWords(const SmallVec<Word, N>& a, const SmallVec<Word, N>& b) {
    if (a.size() != b.size())
        return false;
    for (int i = 0; i < a.size(); ++i)
        if (a[i].number != b[i].number)
            return false;
    return true;
}

} // namespace

bool sameContent(const Frame& a, const Frame& b) {
    if (a.kind() != b.kind() || a.skip != b.skip || a.number() != b.number() ||
        a.n.has_value() != b.n.has_value())
        return false;
    if (a.comments != b.comments || a.leading != b.leading)
        return false;
    switch (a.kind()) {
    case FrameKind::Iso: {
        const IsoFrame& x = *a.iso();
        const IsoFrame& y = *b.iso();
        return sameWords(x.g, y.g) && sameWords(x.m, y.m) && sameOpt(x.message, y.message, sameWord) &&
               sameOpt(x.call, y.call, sameWord) && sameOpt(x.x, y.x, sameValue) &&
               sameOpt(x.fx, y.fx, sameValue) && sameOpt(x.z, y.z, sameValue) &&
               sameOpt(x.fz, y.fz, sameValue);
    }
    case FrameKind::Compute: {
        const ComputeFrame& x = *a.compute();
        const ComputeFrame& y = *b.compute();
        return x.target.number == y.target.number && sameOperand(x.a, y.a) && x.op == y.op &&
               (x.op == ArithOp::None || sameOperand(x.b, y.b));
    }
    case FrameKind::IfGoto:
        return a.body.ifGotoFrame().r.number == b.body.ifGotoFrame().r.number &&
               a.jumpTarget() == b.jumpTarget();
    case FrameKind::Goto:
        return a.jumpTarget() == b.jumpTarget();
    }
    return false;
}

bool sameContent(const Program& a, const Program& b) {
    if (a.number != b.number || a.title != b.title || a.headerComments != b.headerComments ||
        a.leading != b.leading || a.trailing != b.trailing || a.frames.size() != b.frames.size())
        return false;
    for (std::size_t i = 0; i < a.frames.size(); ++i)
        if (!sameContent(a.frames[i], b.frames[i]))
            return false;
    return true;
}

} // namespace k528::program
