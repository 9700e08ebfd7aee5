// Random valid programs -> text -> parse -> the same model; random bytes
// and random mutations of valid programs never crash or hang the parser,
// and whatever it accepts formats to a fixed point. Seeded: the same cases
// every run.
#include <QtTest>

#include "program/diagnostic_texts.h"
#include "program/formatter.h"
#include "program/parser.h"
#include "program/validator.h"
#include "random_program.h"

using namespace k528::program;
using k528::program::testing::GeneratorOptions;
using k528::program::testing::ProgramGenerator;
using k528::program::testing::Rng;

namespace {

std::string sameStores(const ProgramStore& a, const ProgramStore& b) {
    if (a.numbers() != b.numbers())
        return "program numbers differ";
    for (const Program& p : a.programs()) {
        const Program& q = *b.find(p.number);
        if (p.frames.size() != q.frames.size())
            return "frame count of L" + std::to_string(p.number);
        for (std::size_t i = 0; i < p.frames.size(); ++i)
            if (!sameContent(p.frames[i], q.frames[i]))
                return "L" + std::to_string(p.number) + " frame " + std::to_string(i) + ": '" +
                       formatFrame(p.frames[i]) + "' vs '" + formatFrame(q.frames[i]) + "'";
        if (!sameContent(p, q))
            return "L" + std::to_string(p.number) + ": header, comments or blank lines differ";
    }
    if (a.preamble != b.preamble)
        return "preamble";
    if (a.messages.present != b.messages.present || a.messages.entries.size() != b.messages.entries.size())
        return "message table";
    for (std::size_t i = 0; i < a.messages.entries.size(); ++i) {
        const Message& m = a.messages.entries[i];
        const Message& n = b.messages.entries[i];
        if (m.number != n.number || m.text != n.text || m.leading != n.leading)
            return "message #" + std::to_string(m.number);
    }
    return {};
}

// Parses, validates and (when it parsed cleanly) formats twice: the
// properties every input must have.
void exercise(const std::string& text, int number) {
    ParseOptions o;
    o.programNumber = number;
    const ParseResult r = parse(text, o);
    for (const Diagnostic& d : r.diagnostics) {
        QVERIFY(d.line >= 1);
        QVERIFY(d.column >= 1);
        QVERIFY(d.endColumn > d.column);
        QVERIFY2(k528::program::diagnosticTexts().find(d.textId), d.textId.c_str()); // a text of the catalog
    }
    ValidateOptions vo;
    vo.nestingLimit = 1 + number % 8;
    MachineLimits m;
    m.x.softLimits = true;
    m.x.maxMm = Decimal::fromInt(100);
    m.x.decimals = 3;
    m.z.present = number % 2 == 0;
    vo.machine = m;
    const auto v = validate(r.store, vo);
    for (const Diagnostic& d : v)
        QVERIFY(d.line >= 1 && d.column >= 1 && d.endColumn > d.column);
    if (r.hasErrors())
        return;
    const std::string once = format(r.store);
    const ParseResult again = parse(once, o);
    QVERIFY2(!again.hasErrors(), (text + "\n---\n" + once).c_str());
    const std::string twice = format(again.store);
    QVERIFY2(twice == once, (once + "\n---\n" + twice).c_str());
    QCOMPARE(again.store.numbers(), r.store.numbers());
}

} // namespace

class TestRoundTrip : public QObject {
    Q_OBJECT
private slots:
    void generatedStoresReadBackExactly() {
        for (std::uint64_t seed = 1; seed <= 300; ++seed) {
            ProgramGenerator gen(seed);
            const ProgramStore store = gen.store(1 + static_cast<int>(seed % 4), static_cast<int>(seed % 60));
            const std::string text = format(store);
            const ParseResult r = parse(text);
            QVERIFY2(r.diagnostics.empty(), (std::to_string(seed) + ": " +
                                             (r.diagnostics.empty() ? "" : k528::program::diagnosticText(r.diagnostics.front(), false)) +
                                             "\n" + text).c_str());
            const std::string diff = sameStores(store, r.store);
            QVERIFY2(diff.empty(), ("seed " + std::to_string(seed) + ": " + diff + "\n" + text).c_str());
            QCOMPARE(format(r.store), text);
        }
    }
    void generatedHeaderlessProgramsReadBackExactly() {
        for (std::uint64_t seed = 1; seed <= 100; ++seed) {
            ProgramGenerator gen(seed * 7919);
            ProgramStore store;
            store.headerless = true;
            const int number = 1 + static_cast<int>(seed % 99);
            store.insert(gen.program(number, 1 + static_cast<int>(seed % 40), false));
            const std::string text = format(store);
            QVERIFY(text.find('%') == std::string::npos);
            ParseOptions o;
            o.programNumber = number;
            const ParseResult r = parse(text, o);
            QVERIFY2(r.diagnostics.empty(), text.c_str());
            const std::string diff = sameStores(store, r.store);
            QVERIFY2(diff.empty(), (diff + "\n" + text).c_str());
        }
    }
    void validGeneratedStoresHaveNoErrors() {
        GeneratorOptions go;
        go.validOnly = true;
        for (std::uint64_t seed = 1; seed <= 50; ++seed) {
            ProgramGenerator gen(seed, go);
            const ProgramStore store = gen.store(3, 80);
            const CheckResult r = check(format(store));
            for (const auto& d : r.diagnostics)
                QVERIFY2(!d.isError(), k528::program::diagnosticText(d, false).c_str());
        }
    }
    void randomBytesNeverBreakTheParser() {
        Rng rng(528);
        static const char alphabet[] = "NGMXZFRLIOT#%/=+-*.;()>0123456789 \n\n\t\rnxzfrl%MESSAGES";
        for (int i = 0; i < 3000; ++i) {
            std::string s;
            const int len = rng.below(400);
            const bool bytes = rng.chance(30);
            for (int k = 0; k < len; ++k)
                s += bytes ? static_cast<char>(rng.below(256))
                           : alphabet[rng.below(static_cast<int>(sizeof(alphabet) - 1))];
            exercise(s, 1 + rng.below(99));
        }
    }
    void mutationsOfValidProgramsNeverBreakTheParser() {
        Rng rng(2024);
        static const char pieces[][24] = {"N", "G", "M", "X", "Z", "F", "FX", "R", "L", "#", "IF", "GOTO", "%L",
                                          "%MESSAGES", "/", "=", "-", ".", ";", "(", ")", "\n", " ", "9",
                                          "0", "\xD0\xA5", "\xFF", "\r", "\t", "99999999999999999999"};
        for (int i = 0; i < 600; ++i) {
            ProgramGenerator gen(static_cast<std::uint64_t>(i) + 1000);
            std::string text = format(gen.store(1 + rng.below(3), 1 + rng.below(30)));
            const int edits = 1 + rng.below(6);
            for (int e = 0; e < edits && !text.empty(); ++e) {
                const std::size_t at = static_cast<std::size_t>(rng.below(static_cast<int>(text.size())));
                switch (rng.below(4)) {
                case 0:
                    text.erase(at, 1 + static_cast<std::size_t>(rng.below(5)));
                    break;
                case 1:
                    text.insert(at, pieces[rng.below(static_cast<int>(std::size(pieces)))]);
                    break;
                case 2:
                    text[at] = pieces[rng.below(static_cast<int>(std::size(pieces)))][0];
                    break;
                default: { // duplicate a line elsewhere
                    const std::size_t b = text.rfind('\n', at);
                    const std::size_t start = b == std::string::npos ? 0 : b + 1;
                    const std::size_t end = text.find('\n', at);
                    const std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start + 1);
                    text.insert(static_cast<std::size_t>(rng.below(static_cast<int>(text.size()))), line);
                }
                }
            }
            exercise(text, 1 + rng.below(99));
        }
    }
    void pathologicalInputsAreLinear() {
        // One enormous line, many tiny lines, deep nesting of parentheses:
        // all finish (the test's time limit guards against a hang).
        exercise(std::string(200000, 'G'), 1);
        exercise(std::string(200000, '('), 1);
        exercise(std::string(200000, '\n'), 1);
        std::string cyr;
        for (int i = 0; i < 50000; ++i)
            cyr += "\xD0\xA5" "1 ";
        exercise("(ж)" + cyr, 1);
        std::string many;
        for (int i = 0; i < 5000; ++i)
            many += "%L" + std::to_string(i % 120) + "\nL" + std::to_string(i % 99 + 1) + "\n";
        exercise(many, 1);
    }

    // The compact frame body (model.h FrameBody) gives back every field
    // exactly, spans included, at the edges of each type, in place and on
    // the heap, through copies and moves.
    void frameBodyKeepsEveryFieldExactly() {
        auto word = [](int n, int c, int e) { return Word{n, {c, e}}; };
        IsoFrame full;
        for (int k = 0; k < 3; ++k) {
            full.g.push_back(word(INT32_MAX - k, 1 + k, 2000000000 + k));
            full.m.push_back(word(INT32_MIN + k, 0, 0));
        }
        full.message = word(99, 7, 3); // an end before the column: a span not from a text
        full.call = word(-1, INT32_MAX - 5, INT32_MAX);
        Value x = Value::lit(Decimal::fromScaled(INT64_MIN + 1, 18));
        x.span = {12, 40};
        Value fx = Value::rParam(INT32_MAX);
        fx.span = {-3, -1};
        full.x = x;
        full.fx = fx;
        full.z = Value::lit(Decimal::fromScaled(INT64_MAX, 3));
        full.fz = Value::rParam(0);
        Frame f;
        f.body = full;
        QVERIFY(f.body.encodedSize() > 44); // long: on the heap
        auto check = [&](const Frame& g) {
            const auto iso = g.iso();
            QVERIFY(iso);
            QCOMPARE(iso->g.size(), 3);
            QCOMPARE(iso->m.size(), 3);
            for (int k = 0; k < 3; ++k) {
                QCOMPARE(iso->g[k].number, INT32_MAX - k);
                QCOMPARE(iso->g[k].span.column, 1 + k);
                QCOMPARE(iso->g[k].span.endColumn, 2000000000 + k);
                QCOMPARE(iso->m[k].number, INT32_MIN + k);
            }
            QCOMPARE(iso->message->span.column, 7);
            QCOMPARE(iso->message->span.endColumn, 3);
            QCOMPARE(iso->call->number, -1);
            QCOMPARE(iso->call->span.endColumn, INT32_MAX);
            QVERIFY(iso->x->literal == x.literal && !iso->x->isR());
            QCOMPARE(iso->x->span.column, 12);
            QVERIFY(iso->fx->isR());
            QCOMPARE(iso->fx->rIndex, INT32_MAX);
            QCOMPARE(iso->fx->span.column, -3);
            QVERIFY(iso->z->literal == Decimal::fromScaled(INT64_MAX, 3));
            QVERIFY(iso->fz->isR() && iso->fz->rIndex == 0);
            QVERIFY(g.body.hasM(INT32_MIN + 2) && !g.body.hasM(0));
            QCOMPARE(g.body.callTarget().value_or(7), -1);
            QVERIFY(!g.compute() && !g.ifGoto() && !g.gotoFrame());
        };
        check(f);
        Frame copy = f;
        check(copy);
        Frame moved = std::move(copy);
        check(moved);
        copy = moved; // assigning into a moved-from frame
        check(copy);

        ComputeFrame c;
        c.target = word(231, 2, 6);
        c.a = Operand::lit(INT32_MIN);
        c.op = ArithOp::Div;
        c.b = Operand::rParam(299);
        c.b.span = {10, 14};
        f.body = c; // from the heap back in place
        QVERIFY(f.body.encodedSize() <= 44);
        const auto cd = f.compute();
        QVERIFY(cd && !f.iso());
        QCOMPARE(cd->target.number, 231);
        QCOMPARE(cd->a.literal, INT32_MIN);
        QCOMPARE(cd->op, ArithOp::Div);
        QVERIFY(cd->b.isR() && cd->b.rIndex == 299 && cd->b.span.endColumn == 14);

        f.body = IfGotoFrame{word(7, 4, 6), word(301, 14, 17)};
        QCOMPARE(f.jumpTarget(), 301);
        QCOMPARE(f.ifGoto().value().r.number, 7);
        f.body = GotoFrame{word(999, 6, 9)};
        QCOMPARE(f.jumpTarget(), 999);
        QCOMPARE(f.gotoFrame().value().target.span.column, 6);
        Frame empty;
        QVERIFY(empty.iso() && empty.iso().value().empty());
    }

    // The frame model stays small (parse memory <= 5x the text).
    void frameIsCompact() { QVERIFY(sizeof(Frame) <= 96); }
};

QTEST_APPLESS_MAIN(TestRoundTrip)
#include "test_roundtrip.moc"
