#include "program/builders.h"

#include "program/formatter.h"
#include "program/parser.h"
#include "program/validator.h"

namespace k528::program {
namespace {

bool needsContext(Rule r) {
    switch (r) {
    case Rule::JumpTarget:
    case Rule::CallMissing:
    case Rule::MessageUndefined:
    case Rule::EmptyProgram:
    case Rule::Unreachable:
    case Rule::AxisAtSubprogramEnd:
    case Rule::NestingCycle:
    case Rule::NestingDepth:
        return true;
    default:
        return false;
    }
}

Word word(int n) {
    Word w;
    w.number = n;
    return w;
}

BuiltFrame finish(Frame f) {
    BuiltFrame b;
    b.text = formatFrame(f);
    b.frame = std::move(f);
    b.problems = frameProblems(b.text);
    return b;
}

Frame head(FrameHead h) {
    Frame f;
    f.skip = h.skip;
    if (h.n != 0)
        f.n = word(h.n);
    return f;
}

int axisG(Axis a, int base) { return (a == Axis::Z ? 200 : 100) + base; }

void checkTarget(BuiltFrame& b, int target) {
    if (target >= 1 && target <= kMaxFrameNumber)
        return;
    Diagnostic d;
    d.rule = Rule::JumpTarget;
    d.manualNumber = 53;
    d.line = 1;
    d.textId = "build.jump-target";
    d.args = {std::to_string(target)};
    b.problems.insert(b.problems.begin(), d);
}

} // namespace

std::vector<Diagnostic> frameProblems(const std::string& frameText) {
    const std::string text = "%L1\n" + frameText + "\n";
    CheckResult c = check(text);
    std::vector<Diagnostic> out;
    for (Diagnostic& d : c.diagnostics) {
        if (needsContext(d.rule))
            continue;
        if (d.line == 2)
            d.line = 1; // the frame's own line
        out.push_back(std::move(d));
    }
    return out;
}

BuiltFrame buildIso(const IsoFields& in) {
    Frame f = head(in.head);
    IsoFrame iso;
    for (int g : in.g)
        iso.g.push_back(word(g));
    for (int m : in.m)
        iso.m.push_back(word(m));
    if (in.message != 0)
        iso.message = word(in.message);
    if (in.call != 0)
        iso.call = word(in.call);
    iso.x = in.x;
    iso.fx = in.fx;
    iso.z = in.z;
    iso.fz = in.fz;
    f.body = iso;
    BuiltFrame b = finish(std::move(f));
    if (static_cast<int>(in.g.size()) > kMaxGPerFrame || static_cast<int>(in.m.size()) > kMaxMPerFrame) {
        Diagnostic d;
        d.rule = in.g.size() > 3 ? Rule::TooManyG : Rule::TooManyM;
        d.line = 1;
        d.textId = "build.too-many-functions";
        b.problems.insert(b.problems.begin(), d);
    }
    return b;
}

BuiltFrame buildDwell(FrameHead h, Decimal seconds) {
    IsoFields f;
    f.head = h;
    f.g = {4};
    f.x = Value::lit(seconds);
    return buildIso(f);
}

BuiltFrame buildCall(FrameHead h, int program, std::vector<int> m) {
    IsoFields f;
    f.head = h;
    f.m = std::move(m);
    f.call = program;
    return buildIso(f);
}

BuiltFrame buildOscillation(FrameHead h, Axis axis, bool start, std::optional<Decimal> strokeMm,
                            std::optional<Decimal> feedMmPerMin) {
    IsoFields f;
    f.head = h;
    f.g = {axisG(axis, start ? 81 : 80)};
    std::optional<Value> stroke, feed;
    if (strokeMm)
        stroke = Value::lit(*strokeMm);
    if (feedMmPerMin)
        feed = Value::lit(*feedMmPerMin);
    if (axis == Axis::Z) {
        f.z = stroke;
        f.fz = feed;
    } else {
        f.x = stroke;
        f.fx = feed;
    }
    return buildIso(f);
}

BuiltFrame buildMoveUntilSignal(FrameHead h, Axis axis, int signal, Decimal targetMm, Decimal feedMmPerMin) {
    IsoFields f;
    f.head = h;
    f.g = {axisG(axis, 35 + signal)};
    if (axis == Axis::Z) {
        f.z = Value::lit(targetMm);
        f.fz = Value::lit(feedMmPerMin);
    } else {
        f.x = Value::lit(targetMm);
        f.fx = Value::lit(feedMmPerMin);
    }
    BuiltFrame b = buildIso(f);
    if (signal < 1 || signal > 4) {
        Diagnostic d;
        d.rule = Rule::UnknownG;
        d.line = 1;
        d.textId = "build.signal";
        b.problems.insert(b.problems.begin(), d);
    }
    return b;
}

BuiltFrame buildCompute(FrameHead h, int target, Operand a, ArithOp op, Operand b) {
    Frame f = head(h);
    ComputeFrame c;
    c.target = word(target);
    c.a = a;
    c.op = op;
    c.b = b;
    f.body = c;
    return finish(std::move(f));
}

BuiltFrame buildIfGoto(FrameHead h, int r, int target) {
    Frame f = head(h);
    IfGotoFrame j;
    j.r = word(r);
    j.target = word(target);
    f.body = j;
    BuiltFrame b = finish(std::move(f));
    checkTarget(b, target);
    return b;
}

BuiltFrame buildGoto(FrameHead h, int target) {
    Frame f = head(h);
    GotoFrame g;
    g.target = word(target);
    f.body = g;
    BuiltFrame b = finish(std::move(f));
    checkTarget(b, target);
    return b;
}

BuiltMessage buildMessage(int number, const std::string& text) {
    BuiltMessage b;
    b.text = "#" + std::to_string(number) + "=" + text;
    const std::string file = "%MESSAGES\n" + b.text + "\n";
    CheckResult c = check(file);
    for (Diagnostic& d : c.diagnostics) {
        if (d.rule == Rule::NoProgram)
            continue;
        d.line = 1;
        b.problems.push_back(std::move(d));
    }
    return b;
}

} // namespace k528::program
