#include "program/model.h"

#include <algorithm>
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

int Frame::jumpTarget() const {
    if (const auto* f = ifGoto())
        return f->target.number;
    if (const auto* f = gotoFrame())
        return f->target.number;
    return 0;
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

void MessageTable::set(int number, std::string text) {
    present = true;
    for (Message& m : entries)
        if (m.number == number) {
            m.text = std::move(text);
            return;
        }
    Message m;
    m.number = number;
    m.text = std::move(text);
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
        return a.ifGoto()->r.number == b.ifGoto()->r.number &&
               a.ifGoto()->target.number == b.ifGoto()->target.number;
    case FrameKind::Goto:
        return a.gotoFrame()->target.number == b.gotoFrame()->target.number;
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
