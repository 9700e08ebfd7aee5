#include "panel/screens/frame_editor.h"

#include "engine/rparams.h"

#include <algorithm>
#include <cstdlib>
#include <span>
#include <string_view>

namespace k528::panel {

namespace {

using program::ArithOp;
using program::Decimal;
using program::FrameKind;
using program::Operand;
using program::Value;
using F = FrameEditor::Field;
using K = Entry::Kind;

// Where a field is on the LCD: its name (what blinks while it is chosen)
// and its value (typed text goes there).
struct FieldSpec {
    F id;
    int row;
    int nameCol;
    std::string_view name;
    int valueCol;
    int width; // characters that can be typed
    K kind;
};

// The layouts of 2.6.7 (docs/panel.md). Line 1 column 1 is the skip flag;
// the number N takes columns 2–5 in every type.
constexpr FieldSpec kIso[] = {
    {F::N, 0, 2, "N", 3, 3, K::Digits},         {F::G1, 0, 6, "G", 7, 3, K::Digits},
    {F::G2, 0, 10, "G", 11, 3, K::Digits},      {F::G3, 0, 14, "G", 15, 3, K::Digits},
    {F::Message, 0, 18, "#", 19, 2, K::Digits}, {F::M1, 1, 2, "M", 3, 2, K::Digits},
    {F::M2, 1, 6, "M", 7, 2, K::Digits},        {F::M3, 1, 10, "M", 11, 2, K::Digits},
    {F::Call, 1, 18, "L", 19, 2, K::Digits},    {F::X, 2, 1, "X", 2, 10, K::Frame},
    {F::FX, 2, 12, "F=", 14, 7, K::Frame},      {F::Z, 3, 1, "Z", 2, 10, K::Frame},
    {F::FZ, 3, 12, "F=", 14, 7, K::Frame},
};
constexpr FieldSpec kCompute[] = {
    {F::N, 0, 2, "N", 3, 3, K::Digits},
    {F::Target, 0, 6, "R", 7, 3, K::Digits},
    {F::A, 1, 6, "=", 7, 12, K::Operand},
    {F::B, 2, 6, "", 6, 13, K::OpOperand}, // the operation (column 6) and the operand
};
constexpr FieldSpec kIf[] = {
    {F::N, 0, 2, "N", 3, 3, K::Digits},
    {F::RTest, 0, 9, "R", 10, 3, K::Digits}, // «IF» in columns 6–7, «>0» after the number
    {F::Jump, 1, 6, "GOTO", 11, 3, K::Digits},
};
constexpr FieldSpec kGoto[] = {
    {F::N, 0, 2, "N", 3, 3, K::Digits},
    {F::Jump, 0, 6, "GOTO", 11, 3, K::Digits},
};

std::span<const FieldSpec> layout(FrameKind k) {
    switch (k) {
    case FrameKind::Iso:
        return kIso;
    case FrameKind::Compute:
        return kCompute;
    case FrameKind::IfGoto:
        return kIf;
    case FrameKind::Goto:
        return kGoto;
    }
    return kIso;
}

program::Word word(int n) {
    program::Word w;
    w.number = n;
    return w;
}

// A literal with at least `decimals` digits after the point: 5 -> "5.000".
std::string literalText(const Decimal& d, int decimals) {
    std::string s = d.toString();
    const auto point = s.find('.');
    int have = point == std::string::npos ? 0 : static_cast<int>(s.size() - point - 1);
    if (have < decimals) {
        if (point == std::string::npos)
            s += '.';
        s.append(static_cast<std::size_t>(decimals - have), '0');
    }
    return s;
}

std::string valueText(const std::optional<Value>& v, int decimals) {
    if (!v)
        return {};
    return v->isR() ? "R" + std::to_string(v->rIndex) : literalText(v->literal, decimals);
}

// valueText padded to at most `decimals`, fewer when the field is too narrow
// for them (F=10000.00 in 7 cells shows «10000.0»: the same feed).
std::string fittedValueText(const std::optional<Value>& v, int decimals, int width) {
    std::string t = valueText(v, decimals);
    for (int d = decimals - 1; d >= 0 && static_cast<int>(t.size()) > width; --d)
        t = valueText(v, d);
    return t;
}

std::string operandText(const std::optional<Operand>& o) {
    if (!o)
        return {};
    return o->isR() ? "R" + std::to_string(o->rIndex) : std::to_string(o->literal);
}

std::string intText(const std::optional<int>& v) {
    return v ? std::to_string(*v) : std::string();
}

// "123" -> 123 within [lo, hi]; nullopt otherwise.
std::optional<int> parseInt(std::string_view t, int lo, int hi) {
    if (t.empty() || t.size() > 9)
        return std::nullopt;
    int v = 0;
    for (const char c : t) {
        if (c < '0' || c > '9')
            return std::nullopt;
        v = v * 10 + (c - '0');
    }
    if (v < lo || v > hi)
        return std::nullopt;
    return v;
}

std::optional<int> parseRIndex(std::string_view t) {
    if (t.empty() || t[0] != 'R')
        return std::nullopt;
    return parseInt(t.substr(1), 0, engine::kRCount - 1);
}

// X, Z (mm, ±9999.999) or FX, FZ (mm/min, 0.001..10000), or R<n>.
std::optional<Value> parseValue(std::string_view t, bool feed) {
    if (const auto r = parseRIndex(t))
        return Value::rParam(*r);
    const auto d = Decimal::parse(t);
    if (!d)
        return std::nullopt;
    if (feed ? (*d < program::kMinFeed || *d > program::kMaxFeed)
             : (*d > program::kMaxCoordinate || *d < -program::kMaxCoordinate))
        return std::nullopt;
    return Value::lit(*d);
}

std::optional<Operand> parseOperand(std::string_view t) {
    if (const auto r = parseRIndex(t))
        return Operand::rParam(*r);
    if (t.empty())
        return std::nullopt;
    const bool neg = t[0] == '-';
    const std::string_view digits = neg ? t.substr(1) : t;
    if (digits.empty() || digits.size() > 10)
        return std::nullopt;
    long long v = 0;
    for (const char c : digits) {
        if (c < '0' || c > '9')
            return std::nullopt;
        v = v * 10 + (c - '0');
    }
    v = neg ? -v : v;
    if (v < engine::kRMin || v > engine::kRMax)
        return std::nullopt;
    return Operand::lit(static_cast<std::int32_t>(v));
}

ArithOp opOf(char c) {
    switch (c) {
    case '+':
        return ArithOp::Add;
    case '-':
        return ArithOp::Sub;
    case '*':
        return ArithOp::Mul;
    case '/':
        return ArithOp::Div;
    default:
        return ArithOp::None;
    }
}

std::optional<int>* intField(FrameDraft& d, F f) {
    switch (f) {
    case F::N:
        return &d.n;
    case F::G1:
        return &d.g[0];
    case F::G2:
        return &d.g[1];
    case F::G3:
        return &d.g[2];
    case F::M1:
        return &d.m[0];
    case F::M2:
        return &d.m[1];
    case F::M3:
        return &d.m[2];
    case F::Message:
        return &d.message;
    case F::Call:
        return &d.call;
    case F::Target:
        return &d.target;
    case F::RTest:
        return &d.rTest;
    case F::Jump:
        return &d.jump;
    default:
        return nullptr;
    }
}

std::optional<Value>* valueField(FrameDraft& d, F f) {
    switch (f) {
    case F::X:
        return &d.x;
    case F::FX:
        return &d.fx;
    case F::Z:
        return &d.z;
    case F::FZ:
        return &d.fz;
    default:
        return nullptr;
    }
}

// Empties a field (DEL).
void clearField(FrameDraft& d, F f) {
    if (auto* i = intField(d, f))
        i->reset();
    else if (auto* v = valueField(d, f))
        v->reset();
    else if (f == F::A)
        d.a.reset();
    else if (f == F::B) {
        d.op = ArithOp::None;
        d.b.reset();
    }
}

// The range of an integer field.
std::pair<int, int> intRange(F f) {
    switch (f) {
    case F::N:
    case F::Jump:
        return {1, program::kMaxFrameNumber};
    case F::G1:
    case F::G2:
    case F::G3:
        return {0, program::kMaxG};
    case F::M1:
    case F::M2:
    case F::M3:
        return {0, program::kMaxM};
    case F::Message:
        return {1, program::kMaxMessages};
    case F::Call:
        return {1, program::kMaxPrograms};
    case F::Target:
    case F::RTest:
        return {0, engine::kRCount - 1};
    default:
        return {0, 0};
    }
}

} // namespace

// ---------------------------------------------------------------------------
// FrameDraft

FrameDraft FrameDraft::from(const program::Frame& f) {
    FrameDraft d;
    d.kind = f.kind();
    d.skip = f.skip;
    if (f.n)
        d.n = f.n->number;
    if (const auto iso = f.iso()) {
        for (int i = 0; i < iso->g.size(); ++i)
            d.g[static_cast<std::size_t>(i)] = iso->g[i].number;
        for (int i = 0; i < iso->m.size(); ++i)
            d.m[static_cast<std::size_t>(i)] = iso->m[i].number;
        if (iso->message)
            d.message = iso->message->number;
        if (iso->call)
            d.call = iso->call->number;
        d.x = iso->x;
        d.fx = iso->fx;
        d.z = iso->z;
        d.fz = iso->fz;
    } else if (const auto c = f.compute()) {
        d.target = c->target.number;
        d.a = c->a;
        d.op = c->op;
        if (c->op != ArithOp::None)
            d.b = c->b;
    } else if (const auto i = f.ifGoto()) {
        d.rTest = i->r.number;
        d.jump = i->target.number;
    } else if (const auto g = f.gotoFrame()) {
        d.jump = g->target.number;
    }
    return d;
}

std::optional<program::Frame> FrameDraft::toFrame() const {
    program::Frame f;
    f.skip = skip;
    if (n)
        f.n = word(*n);
    switch (kind) {
    case FrameKind::Iso: {
        program::IsoFrame iso;
        for (const auto& v : g)
            if (v)
                iso.g.push_back(word(*v));
        for (const auto& v : m)
            if (v)
                iso.m.push_back(word(*v));
        if (message)
            iso.message = word(*message);
        if (call)
            iso.call = word(*call);
        iso.x = x;
        iso.fx = fx;
        iso.z = z;
        iso.fz = fz;
        if (!n && iso.empty())
            return std::nullopt;
        f.body = iso;
        break;
    }
    case FrameKind::Compute: {
        if (!target || !a || (op != ArithOp::None && !b))
            return std::nullopt;
        program::ComputeFrame c;
        c.target = word(*target);
        c.a = *a;
        c.op = op;
        if (op != ArithOp::None)
            c.b = *b;
        f.body = c;
        break;
    }
    case FrameKind::IfGoto: {
        if (!rTest || !jump)
            return std::nullopt;
        program::IfGotoFrame i;
        i.r = word(*rTest);
        i.target = word(*jump);
        f.body = i;
        break;
    }
    case FrameKind::Goto: {
        if (!jump)
            return std::nullopt;
        program::GotoFrame gf;
        gf.target = word(*jump);
        f.body = gf;
        break;
    }
    }
    return f;
}

// ---------------------------------------------------------------------------
// The editor

const program::Program* FrameEditor::prog(const Context& ctx) const {
    return ctx.engine().programs().find(program_);
}

int FrameEditor::frameCount(const Context& ctx) const {
    const program::Program* p = prog(ctx);
    return p ? static_cast<int>(p->frames.size()) : 0;
}

FrameDraft FrameEditor::draft(const Context& ctx) const {
    if (pending_)
        return *pending_;
    const program::Program* p = prog(ctx);
    if (p && index_ >= 0 && index_ < static_cast<int>(p->frames.size()))
        return FrameDraft::from(p->frames[static_cast<std::size_t>(index_)]);
    return FrameDraft{};
}

FrameEditor::Field FrameEditor::field(const Context& ctx) const {
    const auto specs = layout(draft(ctx).kind);
    return specs[static_cast<std::size_t>(
                     std::clamp(field_, 0, static_cast<int>(specs.size()) - 1))]
        .id;
}

// Keeps the position valid when the store changed under the editor, and
// shows a new empty frame in an empty program.
void FrameEditor::ensureFrame(Context& ctx) {
    const int count = frameCount(ctx);
    if (pendingNew_) {
        index_ = std::clamp(index_, 0, count);
        return;
    }
    if (count == 0) {
        pendingNew_ = true;
        pending_ = FrameDraft{};
        index_ = 0;
        field_ = 0;
        return;
    }
    index_ = std::clamp(index_, 0, count - 1);
}

void FrameEditor::open(int number, Context& ctx) {
    program_ = number;
    index_ = 0;
    pendingNew_ = false;
    pending_.reset();
    field_ = 0;
    typeMenu_ = false;
    entry_.stop();
    ensureFrame(ctx);
}

bool FrameEditor::apply(const FrameDraft& d, Context& ctx) {
    const std::optional<program::Frame> frame = d.toFrame();
    if (!frame) {
        pending_ = d; // incomplete: held here until it is
        return true;
    }
    program::ProgramStore* store = ctx.engine().editablePrograms();
    if (!store) {
        ctx.inputError(); // a program is under way: no editing
        return false;
    }
    program::Program* p = store->find(program_);
    if (!p) {
        program::Program np;
        np.number = program_;
        p = &store->insert(std::move(np));
    }
    if (!pendingNew_ && index_ >= static_cast<int>(p->frames.size())) {
        pendingNew_ = true; // the store lost the frame meanwhile: it goes in again
        index_ = static_cast<int>(p->frames.size());
    }
    if (pendingNew_) {
        if (static_cast<int>(p->frames.size()) >= program::kMaxFrames) {
            ctx.inputError();
            return false;
        }
        const int at = std::clamp(index_, 0, static_cast<int>(p->frames.size()));
        p->frames.insert(p->frames.begin() + at, *frame);
        index_ = at;
        pendingNew_ = false;
    } else {
        program::Frame& old = p->frames[static_cast<std::size_t>(index_)];
        program::Frame f = *frame;
        f.comments = std::move(old.comments); // the text's comments stay with the frame
        f.leading = std::move(old.leading);
        old = std::move(f);
    }
    pending_.reset();
    ctx.engine().programsEdited();
    return true;
}

bool FrameEditor::commitField(Context& ctx) {
    if (!entry_.active())
        return true;
    const std::string text = entry_.text();
    entry_.stop();
    FrameDraft d = draft(ctx);
    const auto specs = layout(d.kind);
    const F f =
        specs[static_cast<std::size_t>(std::clamp(field_, 0, static_cast<int>(specs.size()) - 1))]
            .id;
    bool ok = true;
    if (text.empty()) {
        clearField(d, f);
    } else if (auto* i = intField(d, f)) {
        const auto [lo, hi] = intRange(f);
        const auto v = parseInt(text, lo, hi);
        ok = v.has_value();
        if (ok && f == F::Target && engine::rReadOnly(*v))
            ok = false; // R232..R262 cannot be written
        if (ok && f == F::N)
            if (const program::Program* p = prog(ctx))
                for (std::size_t k = 0; k < p->frames.size(); ++k)
                    if ((pendingNew_ || static_cast<int>(k) != index_) &&
                        p->frames[k].number() == *v)
                        ok = false; // message 54: numbers are unique
        if (ok)
            *i = *v;
    } else if (auto* v = valueField(d, f)) {
        const auto val = parseValue(text, f == F::FX || f == F::FZ);
        ok = val.has_value();
        if (ok)
            *v = *val;
    } else if (f == F::A) {
        const auto o = parseOperand(text);
        ok = o.has_value();
        if (ok)
            d.a = *o;
    } else if (f == F::B) {
        const ArithOp op = opOf(text[0]);
        const auto o = parseOperand(text.substr(1));
        ok = op != ArithOp::None && o.has_value();
        if (ok) {
            d.op = op;
            d.b = *o;
        }
    }
    if (!ok) {
        ctx.inputError();
        return false;
    }
    return apply(d, ctx);
}

void FrameEditor::dropPending(Context& ctx) {
    if (pendingNew_) {
        pendingNew_ = false;
        pending_.reset();
        // The position is that of the frame after the dropped one.
        const int count = frameCount(ctx);
        if (index_ >= count)
            index_ = count - 1;
    } else {
        pending_.reset();
    }
    ensureFrame(ctx);
}

void FrameEditor::leave(Context& ctx) {
    commitField(ctx);
    typeMenu_ = false;
    pending_.reset(); // an incomplete frame: a new one goes, an old one keeps its stored form
    pendingNew_ = false;
}

void FrameEditor::gotoFrame(int delta, Context& ctx) {
    if (!commitField(ctx))
        return;
    int target = index_ + delta;
    if (pendingNew_ && delta > 0 && index_ >= frameCount(ctx))
        return; // the new frame is the last one
    if (pendingNew_) {
        // The new frame stands before frame index_ of the store.
        target = delta < 0 ? index_ - 1 : index_;
        pendingNew_ = false;
    }
    pending_.reset();
    const int count = frameCount(ctx);
    index_ = std::clamp(target, 0, std::max(count - 1, 0));
    field_ = 0;
    ensureFrame(ctx);
}

void FrameEditor::newFrame(FrameKind kind, Context& ctx) {
    if (!commitField(ctx))
        return;
    int at = index_ + 1;
    if (pendingNew_ || pending_) {
        if (pendingNew_)
            at = index_; // the new frame left empty is replaced
        pending_.reset();
        pendingNew_ = false;
    }
    if (frameCount(ctx) >= program::kMaxFrames) {
        ctx.inputError();
        ensureFrame(ctx);
        return;
    }
    FrameDraft d;
    d.kind = kind;
    pending_ = d;
    pendingNew_ = true;
    index_ = at;
    field_ = 0;
}

void FrameEditor::deleteFrame(Context& ctx) {
    entry_.stop();
    if (pendingNew_) {
        dropPending(ctx);
        field_ = 0;
        return;
    }
    program::ProgramStore* store = ctx.engine().editablePrograms();
    program::Program* p = store ? store->find(program_) : nullptr;
    if (!p || index_ >= static_cast<int>(p->frames.size())) {
        ctx.inputError();
        return;
    }
    p->frames.erase(p->frames.begin() + index_);
    pending_.reset();
    ctx.engine().programsEdited();
    field_ = 0;
    const int count = static_cast<int>(p->frames.size());
    if (index_ >= count)
        index_ = count - 1;
    ensureFrame(ctx);
}

void FrameEditor::moveField(Key k, Context& ctx) {
    if (!commitField(ctx))
        return;
    const auto specs = layout(draft(ctx).kind);
    const int count = static_cast<int>(specs.size());
    field_ = std::clamp(field_, 0, count - 1);
    if (k == Key::Right) {
        field_ = (field_ + 1) % count;
        return;
    }
    if (k == Key::Left) {
        field_ = (field_ + count - 1) % count;
        return;
    }
    // ▲▼: the field of the nearest row above / below whose name is nearest in column.
    const FieldSpec& cur = specs[static_cast<std::size_t>(field_)];
    const int dir = k == Key::Down ? 1 : -1;
    for (int row = cur.row + dir; row >= 0 && row < kLcdRows; row += dir) {
        int best = -1;
        for (int i = 0; i < count; ++i) {
            const FieldSpec& s = specs[static_cast<std::size_t>(i)];
            if (s.row != row)
                continue;
            if (best < 0 ||
                std::abs(s.nameCol - cur.nameCol) <
                    std::abs(specs[static_cast<std::size_t>(best)].nameCol - cur.nameCol))
                best = i;
        }
        if (best >= 0) {
            field_ = best;
            return;
        }
    }
}

void FrameEditor::key(KeyPress k, Context& ctx) {
    ensureFrame(ctx);
    if (typeMenu_) {
        // «Укажите тип кадра»: 1, 2, 3.
        const int d = digitOf(k.key);
        if (d >= 1 && d <= 3) {
            typeMenu_ = false;
            newFrame(d == 1   ? FrameKind::Compute
                     : d == 2 ? FrameKind::IfGoto
                              : FrameKind::Goto,
                     ctx);
        }
        return;
    }
    const FrameDraft d = draft(ctx);
    const auto specs = layout(d.kind);
    field_ = std::clamp(field_, 0, static_cast<int>(specs.size()) - 1);
    const FieldSpec& spec = specs[static_cast<std::size_t>(field_)];
    switch (k.key) {
    case Key::Up:
    case Key::Down:
        if (k.shift)
            gotoFrame(k.key == Key::Up ? -1 : 1, ctx);
        else
            moveField(k.key, ctx);
        return;
    case Key::Left:
    case Key::Right:
        moveField(k.key, ctx);
        return;
    case Key::Enter:
        commitField(ctx);
        return;
    case Key::Ins:
        newFrame(FrameKind::Iso, ctx);
        return;
    case Key::Ack:
        if (commitField(ctx))
            typeMenu_ = true;
        return;
    case Key::Exclamation: {
        if (!commitField(ctx))
            return;
        FrameDraft t = draft(ctx);
        t.skip = !t.skip;
        apply(t, ctx);
        return;
    }
    case Key::Del:
        if (entry_.active()) {
            entry_.backspace();
        } else if (spec.id == F::N) {
            deleteFrame(ctx);
        } else {
            FrameDraft t = d;
            clearField(t, spec.id);
            apply(t, ctx);
        }
        return;
    default:
        break;
    }
    const char c = typedChar(k.key);
    if (c == 0)
        return;
    if (entry_.begin(k.key, spec.kind, spec.width))
        return;
    // Typing a computational frame as it reads: R123 = R1 + 12.
    const bool typed = entry_.active();
    const bool isOp = c == '+' || c == '-' || c == '*' || c == '/';
    if (spec.id == F::Target && c == '=' && (typed || d.target)) {
        if (commitField(ctx))
            field_ = 2; // A
    } else if (spec.id == F::A && isOp && (typed || d.a)) {
        if (commitField(ctx)) {
            field_ = 3; // B
            entry_.start(K::OpOperand, kCompute[3].width);
            entry_.type(k.key);
        }
    }
}

void FrameEditor::render(Canvas& c, const Context& ctx) const {
    if (typeMenu_) {
        // As printed (2.6.7), «кадр безусл.перех» cut to the line.
        c.put(0, 1, "Укажите тип кадра");
        c.put(1, 1, "1-вычислит.кадр");
        c.put(2, 1, "2-кадр усл.перехода");
        c.put(3, 1, "3-кадр безусл.перех");
        return;
    }
    const FrameDraft d = draft(ctx);
    const auto specs = layout(d.kind);
    const int cur = std::clamp(field_, 0, static_cast<int>(specs.size()) - 1);
    const int decX = ctx.engine().axisView(engine::AxisId::X).scale.decimals();
    const int decZ = ctx.engine().axisView(engine::AxisId::Z).scale.decimals();
    if (d.skip)
        c.put(0, 1, "/");
    if (d.kind == FrameKind::IfGoto)
        c.put(0, 6, "IF");
    for (int i = 0; i < static_cast<int>(specs.size()); ++i) {
        const FieldSpec& s = specs[static_cast<std::size_t>(i)];
        const bool typing = i == cur && entry_.active();
        std::string value;
        std::string name(s.name);
        FrameDraft t = d;
        if (const auto* iv = intField(t, s.id))
            value = intText(*iv);
        switch (s.id) {
        case F::X:
            value = valueText(d.x, decX);
            break;
        case F::Z:
            value = valueText(d.z, decZ);
            break;
        case F::FX:
            value = fittedValueText(d.fx, 2, s.width);
            break;
        case F::FZ:
            value = fittedValueText(d.fz, 2, s.width);
            break;
        case F::A:
            value = operandText(d.a);
            break;
        case F::B:
            if (d.op != ArithOp::None)
                value = std::string(1, program::arithOpChar(d.op)) + operandText(d.b);
            break;
        default:
            break;
        }
        if (typing)
            value = entry_.text();
        if (!name.empty())
            c.put(s.row, s.nameCol, name);
        c.put(s.row, s.valueCol, value);
        if (s.id == F::RTest)
            c.put(s.row, s.valueCol + textWidth(value), ">0");
        if (i == cur) {
            if (typing)
                c.blink(s.row, std::min(s.valueCol + textWidth(value), s.valueCol + s.width - 1),
                        1);
            else
                c.blink(s.row, s.nameCol, std::max(textWidth(name), 1));
        }
    }
}

} // namespace k528::panel
