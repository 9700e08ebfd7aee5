// What the editor's refactorings, masters and colouring rely on in core:
// renumber/move/copy keep every jump and call (property test over the
// samples and random stores), the frame builders give canonical frames that
// re-parse to the same frame, and the tokens follow the parser's spans.
#include <QtTest>

#include <map>

#include "program/builders.h"
#include "program/formatter.h"
#include "program/parser.h"
#include "program/refactor.h"
#include "program/tokens.h"
#include "program/validator.h"
#include "random_program.h"
#include "resources/embedded.h"

using namespace k528;
using namespace k528::program;

namespace {

// For every jump frame (by index): the index of the frame it goes to, or -1.
std::map<int, int> jumpGraph(const Program& p) {
    std::map<int, int> g;
    for (std::size_t i = 0; i < p.frames.size(); ++i)
        if (const int t = p.frames[i].jumpTarget(); t != 0)
            g[static_cast<int>(i)] = p.indexOfN(t);
    return g;
}

std::vector<ProgramStore> corpus() {
    std::vector<ProgramStore> out;
    for (const auto& r : resources::under("samples/"))
        if (r.path.size() > 5 && r.path.substr(r.path.size() - 5) == ".k528")
            out.push_back(parse(r.data).store);
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        testing::GeneratorOptions o;
        o.maxFrameNumber = 400;
        testing::ProgramGenerator gen(seed, o);
        out.push_back(gen.store(3, 60));
    }
    return out;
}

} // namespace

class TestEditing : public QObject {
    Q_OBJECT
private slots:
    void renumberKeepsEveryJump() {
        int jumps = 0;
        for (const ProgramStore& original : corpus()) {
            for (const auto& [start, step] : {std::pair{1, 1}, std::pair{10, 10}, std::pair{5, 3}}) {
                ProgramStore s = original;
                for (Program& p : s.programs()) {
                    if (start + (static_cast<int>(p.frames.size()) - 1) * step > 999)
                        continue;
                    Program before = p;
                    before.reindex();
                    QVERIFY(renumber(p, start, step).ok);
                    for (std::size_t i = 0; i < p.frames.size(); ++i)
                        QCOMPARE(p.frames[i].number(), start + static_cast<int>(i) * step);
                    // Through the text: the same frames go to the same frames.
                    const ProgramStore back = parse(format(s)).store;
                    const Program* q = back.find(p.number);
                    QVERIFY(q);
                    const auto g0 = jumpGraph(before);
                    const auto g1 = jumpGraph(*q);
                    QCOMPARE(g1.size(), g0.size());
                    for (const auto& [from, to] : g0) {
                        if (to >= 0) {
                            QCOMPARE(g1.at(from), to);
                            ++jumps;
                        }
                    }
                }
            }
        }
        QVERIFY(jumps > 100);
    }
    void renumberRefusesPast999() {
        Program p = parse("%L1\nG1 X1\nG1 X2\nGOTO 1\n").store.programs()[0];
        const Program before = p;
        const RefactorResult r = renumber(p, 990, 10);
        QVERIFY(!r.ok);
        QCOMPARE(r.textId, std::string("refactor.past-999"));
        QCOMPARE(r.text(false), std::string("the last frame number would exceed 999 (3 frames)"));
        QVERIFY(sameContent(p, before));
    }
    void renumberExample() {
        ProgramStore s = parse("%L1\nN5 G1 X1\nIF R1>0 GOTO 7\nN7 GOTO 5\nM30\n").store;
        QVERIFY(renumber(s.programs()[0], 10, 10).ok);
        QCOMPARE(format(s), std::string("%L1\nN10 G1 X1\nN20 IF R1>0 GOTO 30\nN30 GOTO 10\nN40 M30\n"));
    }
    void moveKeepsEveryCall() {
        int calls = 0;
        for (const ProgramStore& original : corpus()) {
            for (const Program& victim : original.programs()) {
                int to = 1;
                while (to <= 99 && original.contains(to))
                    ++to;
                ProgramStore s = original;
                QVERIFY(moveProgram(s, victim.number, to).ok);
                QVERIFY(!s.contains(victim.number));
                QVERIFY(s.contains(to));
                const ProgramStore back = parse(format(s)).store;
                // Every call: same caller frame, callee renamed when it was the moved one.
                for (const Program& p : original.programs()) {
                    const int now = p.number == victim.number ? to : p.number;
                    const Program* q = back.find(now);
                    QVERIFY(q);
                    QCOMPARE(q->frames.size(), p.frames.size());
                    for (std::size_t i = 0; i < p.frames.size(); ++i) {
                        const auto a = p.frames[i].iso();
                        const auto b = q->frames[i].iso();
                        if (!a || !a->call)
                            continue;
                        QVERIFY(b && b->call);
                        QCOMPARE(b->call->number, a->call->number == victim.number ? to : a->call->number);
                        ++calls;
                    }
                }
            }
        }
        QVERIFY(calls > 20);
    }
    void moveAndCopyRefuseBadNumbers() {
        ProgramStore s = parse("%L1\nL2\nM30\n%L2\nM17\n").store;
        QVERIFY(!moveProgram(s, 3, 4).ok);
        QVERIFY(!moveProgram(s, 1, 2).ok);
        QVERIFY(!moveProgram(s, 1, 100).ok);
        QVERIFY(copyProgram(s, 2, 7).ok);
        QCOMPARE(format(s), std::string("%L1\nL2\nM30\n\n%L2\nM17\n\n%L7\nM17\n"));
        QVERIFY(moveProgram(s, 2, 9).ok);
        QCOMPARE(format(s), std::string("%L1\nL9\nM30\n\n%L7\nM17\n\n%L9\nM17\n"));
    }
    void buildersGiveCanonicalFramesThatReparse() {
        std::vector<BuiltFrame> built;
        IsoFields iso;
        iso.head.n = 12;
        iso.g = {1};
        iso.x = Value::lit(*Decimal::parse("5.342"));
        iso.fx = Value::lit(Decimal::fromInt(50));
        iso.z = Value::lit(*Decimal::parse("-1234.678"));
        iso.fz = Value::lit(Decimal::fromInt(1000));
        built.push_back(buildIso(iso));
        QCOMPARE(built.back().text, std::string("N12 G1 X5.342 FX50 Z-1234.678 FZ1000"));
        built.push_back(buildDwell({false, 3}, *Decimal::parse("20.5")));
        QCOMPARE(built.back().text, std::string("N3 G4 X20.5"));
        built.push_back(buildCall({true, 0}, 11));
        QCOMPARE(built.back().text, std::string("/L11"));
        built.push_back(buildCompute({false, 14}, 101, Operand::rParam(32), ArithOp::Div, Operand::lit(3)));
        QCOMPARE(built.back().text, std::string("N14 R101=R32/3"));
        built.push_back(buildIfGoto({false, 202}, 1, 301));
        QCOMPARE(built.back().text, std::string("N202 IF R1>0 GOTO 301"));
        built.push_back(buildGoto({}, 5));
        QCOMPARE(built.back().text, std::string("GOTO 5"));
        built.push_back(buildOscillation({}, Axis::Z, true, Decimal::fromInt(-3), Decimal::fromInt(200)));
        QCOMPARE(built.back().text, std::string("G281 Z-3 FZ200"));
        built.push_back(buildMoveUntilSignal({}, Axis::X, 2, *Decimal::parse("-1.5"), Decimal::fromInt(20)));
        QCOMPARE(built.back().text, std::string("G137 X-1.5 FX20"));
        for (const BuiltFrame& b : built) {
            QVERIFY2(b.ok(), b.text.c_str());
            const ParseResult r = parse("%L1\n" + b.text + "\n");
            QVERIFY(!r.hasErrors());
            QCOMPARE(r.store.programs()[0].frames.size(), std::size_t(1));
            const Frame& again = r.store.programs()[0].frames[0];
            QVERIFY2(sameContent(again, b.frame), b.text.c_str());
            QCOMPARE(formatFrame(again), b.text);
        }
    }
    void buildersReportTheRules() {
        BuiltFrame b = buildDwell({}, Decimal::fromInt(-1));
        QVERIFY(!b.ok());
        IsoFields iso;
        iso.g = {4};
        iso.x = Value::lit(Decimal::fromInt(1));
        iso.z = Value::lit(Decimal::fromInt(1));
        b = buildIso(iso);
        QVERIFY(!b.ok());
        QCOMPARE(b.problems.front().rule, Rule::DwellWithZ);
        QVERIFY(!buildCompute({}, 240, Operand::lit(1)).ok()); // read-only R
        QVERIFY(!buildGoto({}, 1000).ok());
        QVERIFY(buildGoto({}, 999).ok()); // the target is the file's business
        QVERIFY(buildMessage(3, "ПРАВКА").ok());
        QVERIFY(!buildMessage(3, "123456789012345678901").ok());
    }
    void tokensFollowTheParser() {
        const std::string text = "%L3 (title) ; c\n/N12 g1 X=5.3 F50 Z-1 M3 L4 #2 (x)\nN13 R75=2*R99\n"
                                 "IF R1>0 GOTO 12\n%MESSAGES\n#2=ПРАВКА\n";
        const TokenizeResult t = tokenize(text);
        auto kindAt = [&](int line, int col) {
            for (const Token& k : t.tokens)
                if (k.line == line && k.column <= col && col < k.endColumn)
                    return k.kind;
            return TokenKind::Default;
        };
        QCOMPARE(kindAt(1, 1), TokenKind::Header);
        QCOMPARE(kindAt(1, 6), TokenKind::Title);
        QCOMPARE(kindAt(1, 14), TokenKind::Comment);
        QCOMPARE(kindAt(2, 1), TokenKind::Skip);
        QCOMPARE(kindAt(2, 2), TokenKind::FrameNumber);
        QCOMPARE(kindAt(2, 6), TokenKind::GWord);
        QCOMPARE(kindAt(2, 9), TokenKind::AxisValue);
        QCOMPARE(kindAt(2, 15), TokenKind::Feed);
        QCOMPARE(kindAt(2, 19), TokenKind::AxisValue);
        QCOMPARE(kindAt(2, 23), TokenKind::MWord);
        QCOMPARE(kindAt(2, 26), TokenKind::Call);
        QCOMPARE(kindAt(2, 29), TokenKind::MessageRef);
        QCOMPARE(kindAt(2, 32), TokenKind::Comment);
        QCOMPARE(kindAt(3, 5), TokenKind::RParam);
        QCOMPARE(kindAt(3, 8), TokenKind::Operator);
        QCOMPARE(kindAt(3, 9), TokenKind::Literal);
        QCOMPARE(kindAt(3, 11), TokenKind::RParam);
        QCOMPARE(kindAt(4, 1), TokenKind::Keyword);
        QCOMPARE(kindAt(4, 4), TokenKind::RParam);
        QCOMPARE(kindAt(4, 9), TokenKind::Keyword);
        QCOMPARE(kindAt(4, 14), TokenKind::JumpTarget);
        QCOMPARE(kindAt(5, 1), TokenKind::Header);
        QCOMPARE(kindAt(6, 1), TokenKind::MessageNumber);
        QCOMPARE(kindAt(6, 5), TokenKind::MessageText);
        // Byte offsets: the Cyrillic text spans 12 bytes for 6 columns.
        for (const Token& k : t.tokens) {
            if (k.kind == TokenKind::MessageText) {
                QCOMPARE(k.endColumn - k.column, 6);
                QCOMPARE(text.substr(k.begin, k.end - k.begin), std::string("ПРАВКА"));
            }
            QVERIFY(k.begin < k.end && k.end <= text.size());
        }
        for (std::size_t i = 1; i < t.tokens.size(); ++i)
            QVERIFY(t.tokens[i - 1].end <= t.tokens[i].begin);
    }
};

QTEST_APPLESS_MAIN(TestEditing)
#include "test_editing.moc"
