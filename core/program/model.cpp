#include "program/model.h"

#include <algorithm>
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
// A sequence of items. Integers are variable-length (7 bits a byte, the
// signed ones zigzag-coded); a span is written as the distance of its
// column from the end of the item before (0 for the first) and its width.
//   ISO:     items in the order L, #, m..., g..., X, FX, Z, FZ, each a tag
//            byte (slot, | 0x10 for an R-parameter) then the number (a
//            literal value: mantissa and a scale byte) and the span.
//   Compute: target word, operand a, op byte, operand b (operand: kind byte,
//            literal or R index, span).
//   IfGoto:  r word, target word.   Goto: target word.
namespace {

// In this order in the bytes: L first and the M words early, so that
// callTarget() and hasM() read only the start of a frame.
enum IsoSlot : std::uint8_t { SlotCall, SlotMessage, SlotM, SlotG, SlotX, SlotFX, SlotZ, SlotFZ };
constexpr std::uint8_t kRFlag = 0x10;

std::uint64_t zig(std::int64_t v) {
    return (static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63);
}
std::int64_t unzig(std::uint64_t u) { return static_cast<std::int64_t>(u >> 1) ^ -static_cast<std::int64_t>(u & 1); }

class Writer {
public:
    void byte(std::uint8_t b) { buf_[n_++] = b; }
    void uvar(std::uint64_t v) {
        while (v >= 0x80) {
            buf_[n_++] = static_cast<std::uint8_t>(v | 0x80);
            v >>= 7;
        }
        buf_[n_++] = static_cast<std::uint8_t>(v);
    }
    void svar(std::int64_t v) { uvar(zig(v)); }
    void span(const ColSpan& s) {
        svar(static_cast<std::int64_t>(s.column) - prevEnd_);
        svar(static_cast<std::int64_t>(s.endColumn) - s.column);
        prevEnd_ = s.endColumn;
    }
    void word(const Word& w) {
        svar(w.number);
        span(w.span);
    }
    void operand(const Operand& o) {
        byte(static_cast<std::uint8_t>(o.kind));
        svar(o.isR() ? o.rIndex : o.literal);
        span(o.span);
    }
    const std::uint8_t* data() const { return buf_; }
    std::size_t size() const { return n_; }

private:
    // The longest item is 1 + 10 + 1 + 2 * 5 bytes; a frame has at most 12.
    std::uint8_t buf_[512];
    std::size_t n_ = 0;
    std::int64_t prevEnd_ = 0;
};

class Reader {
public:
    Reader(const std::uint8_t* p, std::size_t n) : p_(p), end_(p + n) {}
    bool done() const { return p_ >= end_; }
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
        s.column = static_cast<int>(prevEnd_ + svar());
        s.endColumn = static_cast<int>(s.column + svar());
        prevEnd_ = s.endColumn;
        return s;
    }
    Word word() {
        Word w;
        w.number = ivar();
        w.span = span();
        return w;
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
    const std::uint8_t* end_;
    std::int64_t prevEnd_ = 0;
};

// Inlined: four calls a frame, each mostly testing an empty slot.
[[gnu::always_inline]] inline void writeValue(Writer& w, IsoSlot slot, const std::optional<Value>& v) {
    if (!v)
        return;
    if (v->isR()) {
        w.byte(static_cast<std::uint8_t>(slot | kRFlag));
        w.svar(v->rIndex);
    } else {
        w.byte(slot);
        w.svar(v->literal.mantissa);
        w.byte(static_cast<std::uint8_t>(v->literal.scale));
    }
    w.span(v->span);
}

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
    Writer w;
    if (v.call) {
        w.byte(SlotCall);
        w.word(*v.call);
    }
    if (v.message) {
        w.byte(SlotMessage);
        w.word(*v.message);
    }
    for (const Word& m : v.m) {
        w.byte(SlotM);
        w.word(m);
    }
    for (const Word& g : v.g) {
        w.byte(SlotG);
        w.word(g);
    }
    writeValue(w, SlotX, v.x);
    writeValue(w, SlotFX, v.fx);
    writeValue(w, SlotZ, v.z);
    writeValue(w, SlotFZ, v.fz);
    assign(FrameKind::Iso, w.data(), w.size());
    return *this;
}

FrameBody& FrameBody::operator=(const ComputeFrame& v) {
    Writer w;
    w.word(v.target);
    w.operand(v.a);
    w.byte(static_cast<std::uint8_t>(v.op));
    w.operand(v.b);
    assign(FrameKind::Compute, w.data(), w.size());
    return *this;
}

FrameBody& FrameBody::operator=(const IfGotoFrame& v) {
    Writer w;
    w.word(v.r);
    w.word(v.target);
    assign(FrameKind::IfGoto, w.data(), w.size());
    return *this;
}

FrameBody& FrameBody::operator=(const GotoFrame& v) {
    Writer w;
    w.word(v.target);
    assign(FrameKind::Goto, w.data(), w.size());
    return *this;
}

bool FrameBody::hasAnyM(std::initializer_list<int> numbers) const {
    if (kind_ != FrameKind::Iso)
        return false;
    Reader r(data(), size_);
    while (!r.done()) {
        const auto slot = static_cast<IsoSlot>(r.byte() & 0x0F);
        if (slot > SlotM)
            break;
        const int n = r.ivar();
        if (slot == SlotM && std::find(numbers.begin(), numbers.end(), n) != numbers.end())
            return true;
        r.uvar(); // span
        r.uvar();
    }
    return false;
}

void FrameBody::decode(IsoFrame& f) const {
    Reader r(data(), size_);
    while (!r.done()) {
        const std::uint8_t tag = r.byte();
        const auto slot = static_cast<IsoSlot>(tag & 0x0F);
        switch (slot) {
        case SlotG:
            f.g.push_back(r.word());
            break;
        case SlotM:
            f.m.push_back(r.word());
            break;
        case SlotMessage:
            f.message = r.word();
            break;
        case SlotCall:
            f.call = r.word();
            break;
        case SlotX:
        case SlotFX:
        case SlotZ:
        case SlotFZ: {
            Value& v = (slot == SlotX ? f.x : slot == SlotFX ? f.fx : slot == SlotZ ? f.z : f.fz).emplace();
            if (tag & kRFlag) {
                v.kind = Value::Kind::RParam;
                v.rIndex = r.ivar();
            } else {
                v.literal.mantissa = r.svar();
                v.literal.scale = r.byte();
            }
            v.span = r.span();
            break;
        }
        }
    }
}

ComputeFrame FrameBody::computeFrame() const {
    ComputeFrame c;
    Reader r(data(), size_);
    c.target = r.word();
    c.a = r.operand();
    c.op = static_cast<ArithOp>(r.byte());
    c.b = r.operand();
    return c;
}

IfGotoFrame FrameBody::ifGotoFrame() const {
    IfGotoFrame j;
    Reader r(data(), size_);
    j.r = r.word();
    j.target = r.word();
    return j;
}

GotoFrame FrameBody::gotoFrame() const {
    GotoFrame j;
    Reader r(data(), size_);
    j.target = r.word();
    return j;
}

int FrameBody::jumpTarget() const {
    if (kind_ == FrameKind::Goto) {
        Reader r(data(), size_);
        return r.ivar();
    }
    if (kind_ == FrameKind::IfGoto) {
        Reader r(data(), size_);
        r.ivar();
        r.uvar();
        r.uvar();
        return r.ivar();
    }
    return 0;
}

std::optional<int> FrameBody::callTarget() const {
    if (kind_ != FrameKind::Iso || size_ == 0)
        return std::nullopt;
    Reader r(data(), size_);
    if (static_cast<IsoSlot>(r.byte() & 0x0F) != SlotCall) // L comes first
        return std::nullopt;
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
