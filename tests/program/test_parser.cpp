#include <QtTest>

#include <algorithm>

#include "program/diagnostic_texts.h"
#include "program/formatter.h"
#include "program/parser.h"
#include "util/utf8.h"

using namespace k528::program;
namespace utf8 = k528::utf8;

namespace {

ParseResult p(const char* text, int number = 1) {
    ParseOptions o;
    o.programNumber = number;
    return parse(text, o);
}

// The only frame of a headerless one-frame text that must parse cleanly.
Frame one(const char* text) {
    const ParseResult r = p(text);
    if (!r.diagnostics.empty())
        qWarning("%s: %s", text, k528::program::diagnosticText(r.diagnostics.front(), false).c_str());
    if (r.diagnostics.size() != 0 || r.store.size() != 1 || r.store.programs()[0].frames.size() != 1)
        return Frame{};
    return r.store.programs()[0].frames[0];
}

int count(const ParseResult& r, Rule rule) {
    return static_cast<int>(std::count_if(r.diagnostics.begin(), r.diagnostics.end(),
                                          [&](const Diagnostic& d) { return d.rule == rule; }));
}

const Diagnostic* find(const ParseResult& r, Rule rule) {
    for (const auto& d : r.diagnostics)
        if (d.rule == rule)
            return &d;
    return nullptr;
}

QString canon(const Frame& f) { return QString::fromStdString(formatFrame(f)); }

} // namespace

class TestParser : public QObject {
    Q_OBJECT
private slots:
    // --- The manual's own frames (2.6.7, 2.7.1, table 5) ----------------------------
    void manualComputationalFrames() {
        Frame f = one("N12 R75=2*R99");
        QCOMPARE(f.kind(), FrameKind::Compute);
        QCOMPARE(f.number(), 12);
        const ComputeFrame& c = *f.compute();
        QCOMPARE(c.target.number, 75);
        QVERIFY(!c.a.isR());
        QCOMPARE(c.a.literal, 2);
        QCOMPARE(c.op, ArithOp::Mul);
        QVERIFY(c.b.isR());
        QCOMPARE(c.b.rIndex, 99);
        QCOMPARE(canon(one("N13 R32=R75+R45")), QString("N13 R32=R75+R45"));
        QCOMPARE(canon(one("N14 R101=R32/3")), QString("N14 R101=R32/3"));
        QCOMPARE(canon(one("N15 R3=R101-R4")), QString("N15 R3=R101-R4"));
        QCOMPARE(canon(one("N12 R123=R1+12")), QString("N12 R123=R1+12"));
        QCOMPARE(canon(one("R5=-12")), QString("R5=-12"));
        QCOMPARE(canon(one("R5=R1--12")), QString("R5=R1--12"));
        QCOMPARE(one("R5=-2147483648").compute().value().a.literal, INT32_MIN);
    }
    void manualJumps() {
        Frame f = one("N202 IF R1>0 GOTO 301");
        QCOMPARE(f.kind(), FrameKind::IfGoto);
        QCOMPARE(f.number(), 202);
        QCOMPARE(f.ifGoto().value().r.number, 1);
        QCOMPARE(f.ifGoto().value().target.number, 301);
        QCOMPARE(f.jumpTarget(), 301);
        Frame g = one("N207 GOTO 33");
        QCOMPARE(g.kind(), FrameKind::Goto);
        QCOMPARE(g.gotoFrame().value().target.number, 33);
        QCOMPARE(canon(one("n202 if r1 > 0 goto 301")), QString("N202 IF R1>0 GOTO 301"));
        QCOMPARE(canon(one("N202IFR1>0GOTO301")), QString("N202 IF R1>0 GOTO 301"));
    }
    void manualIsoFrames() {
        Frame dwell = one("G04 X20.500");
        QCOMPARE(dwell.iso().value().g.size(), 1);
        QCOMPARE(dwell.iso().value().g[0].number, 4);
        QCOMPARE(QString::fromStdString(dwell.iso().value().x->literal.toString()), QString("20.5"));
        Frame osc = one("G281 Z=-30.5 Fz=100");
        QCOMPARE(osc.iso().value().g[0].number, 281);
        QCOMPARE(QString::fromStdString(osc.iso().value().z->literal.toString()), QString("-30.5"));
        QCOMPARE(QString::fromStdString(osc.iso().value().fz->literal.toString()), QString("100"));
        Frame set = one("G192 X12.324");
        QCOMPARE(set.iso().value().g[0].number, 192);
        QCOMPARE(set.iso().value().x->literal, *Decimal::parse("12.324"));
        // The panel's example frame (2.6.7): F= after each axis.
        QCOMPARE(canon(one("N12 X5.342 F=50.00 Z-1234.678 F=1000.00")),
                 QString("N12 X5.342 FX50 Z-1234.678 FZ1000"));
    }
    void isoWordsKeepOrderAndValues() {
        Frame f = one("N7 G90 G1 G54 M3 M8 M98 #5 L12 X=R12 FXR3 Z0.5 FZ=R299");
        const IsoFrame& i = *f.iso();
        QCOMPARE(i.g.size(), 3);
        QCOMPARE(i.g[0].number, 90);
        QCOMPARE(i.g[1].number, 1);
        QCOMPARE(i.g[2].number, 54);
        QCOMPARE(i.m.size(), 3);
        QCOMPARE(i.m[2].number, 98);
        QCOMPARE(i.message->number, 5);
        QCOMPARE(i.call->number, 12);
        QVERIFY(i.x->isR());
        QCOMPARE(i.x->rIndex, 12);
        QVERIFY(i.fx->isR());
        QCOMPARE(i.fx->rIndex, 3);
        QCOMPARE(i.z->literal, *Decimal::parse("0.5"));
        QCOMPARE(i.fz->rIndex, 299);
    }
    void caseAndSpacesDoNotMatter() {
        QCOMPARE(canon(one("n1g1x5")), QString("N1 G1 X5"));
        QCOMPARE(canon(one("N1 G01 X5")), QString("N1 G1 X5"));
        QCOMPARE(canon(one("N001   g0001\tx 5.000")), QString("N1 G1 X5"));
        QCOMPARE(canon(one("X = -30.5 fx = 12")), QString("X-30.5 FX12"));
        QCOMPARE(canon(one("X5 Z3 F100")), QString("X5 Z3 FZ100"));
        QCOMPARE(canon(one("X5 F50 Z3 F100")), QString("X5 FX50 Z3 FZ100"));
        QCOMPARE(canon(one("FZ7 X1")), QString("X1 FZ7"));
        QCOMPARE(canon(one("X.5 Z-.25")), QString("X0.5 Z-0.25"));
    }
    void skipFlag() {
        Frame f = one("/N5 G1 X5");
        QVERIFY(f.skip);
        QCOMPARE(f.number(), 5);
        QVERIFY(one("/ R1=R1+1").skip);
        QVERIFY(one("/IF R1>0 GOTO 5").skip);
        QVERIFY(one("/").skip);
        QVERIFY(!one("N5 G1").skip);
    }
    void emptyFrameWithNumberOnly() {
        Frame f = one("N40");
        QCOMPARE(f.kind(), FrameKind::Iso);
        QVERIFY(f.iso().value().empty());
        QCOMPARE(f.number(), 40);
    }

    // --- Comments, blank lines, headers, messages ---------------------------------
    void commentsAreKeptAndAreNotFrames() {
        const ParseResult r = p("; whole line\n"
                                "(also a whole line) (two)\n"
                                "\n"
                                "N1 G1 (rapid? no) X5 ; trailing\n"
                                "N2 M30\n");
        QVERIFY(r.diagnostics.empty());
        const Program& prog = r.store.programs()[0];
        QCOMPARE(prog.frames.size(), std::size_t(2));
        const Frame& f = prog.frames[0];
        QCOMPARE(f.comments.size(), std::size_t(2));
        QCOMPARE(f.comments[0].style, Comment::Style::Parens);
        QCOMPARE(QString::fromStdString(f.comments[0].text), QString("rapid? no"));
        QCOMPARE(f.comments[1].style, Comment::Style::Semicolon);
        QCOMPARE(QString::fromStdString(f.comments[1].text), QString(" trailing"));
        QCOMPARE(f.leading.size(), std::size_t(3)); // comment, comments, blank
        QVERIFY(f.leading[2].blank());
        QCOMPARE(f.leading[1].comments.size(), std::size_t(2));
        QVERIFY(f.iso().value().x.has_value());
    }
    void semicolonInsideParensAndParensInsideSemicolon() {
        Frame f = one("G1 (a;b) X5 ; c (d)");
        QCOMPARE(QString::fromStdString(f.comments[0].text), QString("a;b"));
        QCOMPARE(QString::fromStdString(f.comments[1].text), QString(" c (d)"));
    }
    void headersTitlesAndPrograms() {
        const ParseResult r = p("; shop file\n"
                                "\n"
                                "; the main program\n"
                                "%L12 (ring 205, rough) ; v2\n"
                                "N1 L3\n"
                                "N2 M30\n"
                                "%l3\n"
                                "G1 X5\n"
                                "M17\n");
        QVERIFY(r.diagnostics.empty());
        QCOMPARE(r.store.numbers(), (std::vector<int>{3, 12}));
        QVERIFY(!r.store.headerless);
        const Program& p12 = *r.store.find(12);
        QCOMPARE(QString::fromStdString(*p12.title), QString("ring 205, rough"));
        QCOMPARE(p12.headerComments.size(), std::size_t(1));
        QCOMPARE(p12.headerLine, 4);
        QCOMPARE(p12.leading.size(), std::size_t(1)); // the comment right above the header
        QCOMPARE(r.store.preamble.size(), std::size_t(1));
        QCOMPARE(r.store.find(3)->frames.size(), std::size_t(2));
        QVERIFY(!r.store.find(3)->title.has_value());
    }
    void headerlessTakesTheGivenNumber() {
        const ParseResult r = p("G1 X5\nM30\n", 42);
        QVERIFY(r.diagnostics.empty());
        QVERIFY(r.store.headerless);
        QCOMPARE(r.store.numbers(), std::vector<int>{42});
        // Comments only: no program at all.
        const ParseResult c = p("; nothing yet\n\n");
        QVERIFY(c.store.empty());
        QCOMPARE(c.store.preamble.size(), std::size_t(1));
    }
    void messageTable() {
        const ParseResult r = p("%L1\nN1 #2 G1 X5\nM30\n"
                                "%MESSAGES\n"
                                "; line 2 of the LCD\n"
                                "#2=ЧЕРНОВАЯ ПОДАЧА\n"
                                "#1=  with (parens); and semicolon   \n");
        QVERIFY(r.diagnostics.empty());
        const MessageTable& t = r.store.messages;
        QVERIFY(t.present);
        QCOMPARE(t.entries.size(), std::size_t(2));
        QCOMPARE(QString::fromStdString(*t.text(2)), QString("ЧЕРНОВАЯ ПОДАЧА"));
        // The text is everything after '=', right-trimmed: no comments in it.
        QCOMPARE(QString::fromStdString(*t.text(1)), QString("  with (parens); and semicolon"));
        QCOMPARE(t.find(2)->leading.size(), std::size_t(1));
        QCOMPARE(t.find(1)->textColumn, 4);
        QVERIFY(t.text(3) == nullptr);
    }
    void headerlessWithMessages() {
        const ParseResult r = p("N1 #1 G1 X5\n%MESSAGES\n#1=A\n", 7);
        QVERIFY(r.diagnostics.empty());
        QVERIFY(r.store.headerless);
        QCOMPARE(r.store.numbers(), std::vector<int>{7});
    }
    void crlfAndByteOrderMark() {
        const ParseResult r = p("\xEF\xBB\xBF%L1\r\nN1 G1 X5 ; c\r\nM30\r\n");
        QVERIFY(r.diagnostics.empty());
        const Frame& f = r.store.find(1)->frames[0];
        QCOMPARE(QString::fromStdString(f.comments[0].text), QString(" c"));
        QCOMPARE(f.span.line, 2);
    }
    // CR alone is no line end (LF or CRLF); a text with CR-only
    // line ends gets an error that says so, once.
    void crOnlyLineEndsAreNamed() {
        const ParseResult r = p("%L1\rN1 G1 X5\rM30\r");
        QVERIFY(r.hasErrors());
        int hints = 0;
        for (const Diagnostic& d : r.diagnostics)
            if (k528::program::diagnosticText(d, false).find("CR without LF does not end a line") != std::string::npos) {
                ++hints;
                QCOMPARE(d.line, 1);
                QCOMPARE(d.column, 4);
            }
        QCOMPARE(hints, 1);
        // A stray CR in a text that reads well stays a blank, without a hint.
        QVERIFY(p("G1\rX5\nM30\n").diagnostics.empty());
    }
    // Leading zeros are not significant digits; a value finer than
    // 18 places is refused for that reason.
    void leadingZerosAreNotSignificant() {
        QVERIFY(p("G1 X000000000000000000000000005.5\n").diagnostics.empty());
        QVERIFY(p("G1 X00000.000000000000000001\n").diagnostics.empty()); // 18 places
        const ParseResult fine = p("G1 X00000.00000000000000000001\n");
        QCOMPARE(fine.diagnostics.size(), std::size_t(1));
        QVERIFY2(k528::program::diagnosticText(fine.diagnostics[0], false).find("more than 18 digits after the decimal point") !=
                     std::string::npos,
                 k528::program::diagnosticText(fine.diagnostics[0], false).c_str());
        const ParseResult many = p("G1 X1234567890.123456789\n");
        QCOMPARE(many.diagnostics.size(), std::size_t(1));
        QVERIFY(k528::program::diagnosticText(many.diagnostics[0], false).find("more than 18 significant digits") != std::string::npos);
        QVERIFY(p("G1 X0001234567890.12345678000\n").diagnostics.empty()); // 18 significant
    }
    void lastLineWithoutNewline() {
        const ParseResult r = p("G1 X5\nM30");
        QCOMPARE(r.store.programs()[0].frames.size(), std::size_t(2));
    }

    // --- Positions ---------------------------------------------------------------------
    void spansAreCodePointsEndExclusive() {
        const ParseResult r = p("%L1\n(подвод) N5 G1 X-5.3 FZ=R7\n");
        const Frame& f = r.store.find(1)->frames[0];
        QCOMPARE(f.span.line, 2);
        // "(подвод) " is 9 code points (16 bytes): N5 starts at column 10.
        QCOMPARE(f.n->span.column, 10);
        QCOMPARE(f.n->span.endColumn, 12);
        QCOMPARE(f.iso().value().g[0].span.column, 13);
        QCOMPARE(f.iso().value().x->span.column, 16);
        QCOMPARE(f.iso().value().x->span.endColumn, 21);
        QCOMPARE(f.iso().value().fz->span.column, 22);
        QCOMPARE(f.iso().value().fz->span.endColumn, 27);
        QCOMPARE(f.span.column, 10);
        QCOMPARE(f.span.endColumn, 27);
        const ParseResult e = p("(ø) Q5\n");
        const Diagnostic* d = find(e, Rule::UnknownAddress);
        QVERIFY(d);
        QCOMPARE(d->column, 5);
        QCOMPARE(d->endColumn, 6);
        QCOMPARE(d->line, 1);
    }

    // A column is a code point wherever the line's first non-ASCII character
    // stands: in its first eight bytes, further on, in its last bytes, on
    // lines shorter and longer than eight bytes.
    void columnsAfterTheFirstNonAsciiCharacter() {
        for (int k = 0; k <= 20; ++k) {
            const std::string a(static_cast<std::size_t>(k), 'a');
            // "(" a..a "ж) " is k + 4 code points: Q5 starts at column k + 5.
            const ParseResult before = parse("(" + a + "\xD0\xB6) Q5\n");
            const Diagnostic* d = find(before, Rule::UnknownAddress);
            QVERIFY2(d, qPrintable(QString::number(k)));
            QCOMPARE(d->column, k + 5);
            QCOMPARE(d->endColumn, k + 6);
            // The comment runs to the line's end, its last character the
            // non-ASCII one: k + 5 code points in all.
            const ParseResult last = parse("Q5 (" + a + "\xD0\xB6\n");
            d = find(last, Rule::UnclosedComment);
            QVERIFY2(d, qPrintable(QString::number(k)));
            QCOMPARE(d->column, 4);
            QCOMPARE(d->endColumn, k + 6);
        }
    }

    // --- Errors: each rule triggers, its near miss does not, and parsing goes on ------
    void syntaxRules_data() {
        QTest::addColumn<QByteArray>("bad");
        QTest::addColumn<QByteArray>("good");
        QTest::addColumn<int>("rule");
        QTest::addColumn<int>("manual");
        auto row = [](const char* name, const char* bad, const char* good, Rule r, int manual = 0) {
            QTest::newRow(name) << QByteArray(bad) << QByteArray(good) << static_cast<int>(r) << manual;
        };
        row("invalid utf-8", "G1 X5 ; \xFF\xFE\n", "G1 X5 ; ПРОХОД\n", Rule::InvalidUtf8);
        row("unclosed comment", "G1 (abc X5\n", "G1 (abc) X5\n", Rule::UnclosedComment);
        row("N not first", "G1 N5 X5\n", "N5 G1 X5\n", Rule::Syntax);
        row("slash not first", "N5 / G1\n", "/N5 G1\n", Rule::Syntax);
        row("sign before R", "X-R5\n", "X=R5\n", Rule::Syntax, 33);
        row("negated R operand", "R1=-R2\n", "R1=0-R2\n", Rule::Syntax);
        row("GOTO N", "GOTO N5\nN5 M30\n", "GOTO 5\nN5 M30\n", Rule::Syntax);
        row("GOTO in ISO frame", "G1 GOTO 5\nN5 M30\n", "G1\nGOTO 5\nN5 M30\n", Rule::Syntax);
        row("IF in ISO frame", "G1 IF R1>0 GOTO 5\nN5 M30\n", "IF R1>0 GOTO 5\nN5 M30\n", Rule::Syntax);
        row("R in ISO frame", "G1 R1=5\n", "G1\nR1=5\n", Rule::Syntax);
        row("address without number", "G X5\n", "G0 X5\n", Rule::Syntax);
        row("axis without value", "G1 X\n", "G1 X0\n", Rule::Syntax, 33);
        row("compute without =", "R1 5\n", "R1=5\n", Rule::Syntax);
        row("compute bad operation", "R1=R2%3\n", "R1=R2/3\n", Rule::Syntax);
        row("compute trailing text", "R1=R2+3 X5\n", "R1=R2+3 ; X5\n", Rule::Syntax);
        row("IF without R", "IF 5>0 GOTO 5\nN5 M30\n", "IF R5>0 GOTO 5\nN5 M30\n", Rule::Syntax);
        row("IF without GOTO", "IF R1>0 5\nN5 M30\n", "IF R1>0 GOTO 5\nN5 M30\n", Rule::Syntax);
        row("GOTO without number", "GOTO\n", "GOTO 1\n", Rule::Syntax);
        row("unexpected character", "G1 X5 ?\n", "G1 X5\n", Rule::Syntax);
        row("control character", "G1\x01 X5\n", "G1 X5\n", Rule::Syntax);
        row("cyrillic X", "G1 \xD0\xA5" "5\n", "G1 X5\n", Rule::CyrillicLetter);
        row("cyrillic M", "\xD0\x9C" "30\n", "M30\n", Rule::CyrillicLetter);
        row("unknown address", "G1 Q5\n", "G1 M5\n", Rule::UnknownAddress);
        row("unknown address Y", "G1 Y5\n", "G1 Z5\n", Rule::UnknownAddress);
        row("two X", "X1 X2\n", "X1 Z2\n", Rule::DuplicateWord);
        row("two FX", "X1 F2 FX3\n", "X1 F2 Z3 FZ3\n", Rule::DuplicateWord);
        row("two L", "L1 L2\n", "L1\nL2\n", Rule::DuplicateWord);
        row("two #", "#1 #2\n", "#1\n#2\n", Rule::DuplicateWord);
        row("four G", "G0 G90 G54 G55\n", "G0 G90 G54\n", Rule::TooManyG);
        row("four M", "M3 M8 M10 M11\n", "M3 M8 M10\n", Rule::TooManyM);
        row("F without axis", "G1 F50\n", "G1 X5 F50\n", Rule::FeedWithoutAxis);
        row("F after FX", "X5 FX50 F60\n", "X5 FX50\n", Rule::FeedWithoutAxis);
        row("F after G", "X5 G1 F60\n", "G1 X5 F60\n", Rule::FeedWithoutAxis);
        row("two points X", "X5..3\n", "X5.3\n", Rule::BadNumber, 33);
        row("two points Z", "Z1.2.3\n", "Z1.23\n", Rule::BadNumber, 49);
        row("too many digits", "X1234567890.123456789\n", "X123456789.123456789\n", Rule::BadNumber, 33);
        row("fraction in G", "G1.5\n", "G1\n", Rule::BadNumber);
        row("sign in N", "N-5 G1\n", "N5 G1\n", Rule::BadNumber);
        row("huge G", "G99999999999\n", "G999999999\n", Rule::BadNumber);
        row("bad jump target", "GOTO 5.5\n", "GOTO 5\nN5 M30\n", Rule::BadNumber, 53);
        row("decimal in compute", "R1=2.5\n", "R1=25\n", Rule::DecimalInCompute);
        row("decimal in operand b", "R1=R2*0.5\n", "R1=R2/2\n", Rule::DecimalInCompute);
        row("literal above int32", "R1=2147483648\n", "R1=2147483647\n", Rule::LiteralRange);
        row("literal below int32", "R1=-2147483649\n", "R1=-2147483648\n", Rule::LiteralRange);
        row("literal far out", "R1=R2+99999999999999999999\n", "R1=R2+999999999\n", Rule::LiteralRange);
        row("condition >=", "IF R1>=0 GOTO 5\nN5 M30\n", "IF R1>0 GOTO 5\nN5 M30\n", Rule::BadCondition);
        row("condition >5", "IF R1>5 GOTO 5\nN5 M30\n", "IF R1 > 00 GOTO 5\nN5 M30\n", Rule::BadCondition);
        row("condition <", "IF R1<0 GOTO 5\nN5 M30\n", "IF R1>0 GOTO 5\nN5 M30\n", Rule::BadCondition);
        row("header without number", "%L\nM30\n", "%L1\nM30\n", Rule::BadHeader);
        row("header letters", "%LX\nM30\n", "%L1\nM30\n", Rule::BadHeader);
        row("unknown header", "%PROGRAM 1\nM30\n", "%L1\nM30\n", Rule::BadHeader);
        row("text after header", "%L5 G1\nM30\n", "%L5 (G1) ; x\nM30\n", Rule::BadHeader);
        row("text after messages", "%MESSAGES 5\n#1=A\n", "%MESSAGES ; five\n#1=A\n", Rule::BadHeader);
        row("program 0", "%L0\nM30\n", "%L1\nM30\n", Rule::ProgramNumberRange);
        row("program 100", "%L100\nM30\n", "%L99\nM30\n", Rule::ProgramNumberRange);
        row("program twice", "%L5\nM30\n%L5\nM30\n", "%L5\nM30\n%L6\nM30\n", Rule::DuplicateProgram);
        row("frames before header", "G1 X5\n%L1\nM30\n", "; note\n%L1\nG1 X5\nM30\n", Rule::FrameOutsideProgram);
        row("frames, messages, header", "G1 X5\n%MESSAGES\n#1=A\n%L1\nM30\n", "G1 X5\n%MESSAGES\n#1=A\n",
            Rule::FrameOutsideProgram);
        row("message without =", "%MESSAGES\n#5 TEXT\n", "%MESSAGES\n#5=TEXT\n", Rule::MessageSyntax);
        row("message without number", "%MESSAGES\n#=TEXT\n", "%MESSAGES\n#1=TEXT\n", Rule::MessageSyntax);
        row("frame in messages", "%MESSAGES\n#1=A\nG1 X5\n", "%MESSAGES\n#1=A\n; G1 X5\n", Rule::MessageSyntax);
        row("message 0", "%MESSAGES\n#0=A\n", "%MESSAGES\n#1=A\n", Rule::MessageNumberRange);
        row("message 100", "%MESSAGES\n#100=A\n", "%MESSAGES\n#99=A\n", Rule::MessageNumberRange);
        row("message twice", "%MESSAGES\n#5=A\n#5=B\n", "%MESSAGES\n#5=A\n#6=B\n", Rule::DuplicateMessage);
    }
    void syntaxRules() {
        QFETCH(QByteArray, bad);
        QFETCH(QByteArray, good);
        QFETCH(int, rule);
        QFETCH(int, manual);
        const ParseResult b = parse(bad.toStdString());
        const Diagnostic* d = find(b, static_cast<Rule>(rule));
        QVERIFY2(d, qPrintable(QString("rule %1 not reported").arg(QString::fromLatin1(ruleId(static_cast<Rule>(rule))))));
        QCOMPARE(d->severity, Severity::Error);
        QCOMPARE(d->manualNumber, manual);
        QVERIFY(d->line >= 1 && d->column >= 1 && d->endColumn > d->column);
        QVERIFY2(k528::program::diagnosticTexts().find(d->textId), d->textId.c_str()); // a text of the catalog
        QVERIFY(b.hasErrors());
        const ParseResult g = parse(good.toStdString());
        QVERIFY2(g.diagnostics.empty(),
                 g.diagnostics.empty() ? "" : qPrintable(QString::fromStdString(k528::program::diagnosticText(g.diagnostics.front(), false))));
    }

    // One pass reports every error; a bad line does not hide the next.
    void recoveryReportsEverythingInOnePass() {
        const ParseResult r = p("%L1\n"
                                "N1 G1 X5..3 Q7 Z1.2.3\n"   // three errors in one frame
                                "N2 G1 X5\n"                 // fine
                                "N3 R1=2.5\n"                // compute error
                                "%LX\n"                      // bad header
                                "N4 IF R1>=0 GOTO 2\n"       // bad condition (in the unstored program)
                                "%L2\n"
                                "N1 X1 X2\n"                 // duplicate word
                                "%MESSAGES\n"
                                "#0=A\n"                     // bad message number
                                "#1=B\n");
        QCOMPARE(count(r, Rule::BadNumber), 2);
        QCOMPARE(count(r, Rule::UnknownAddress), 1);
        QCOMPARE(count(r, Rule::DecimalInCompute), 1);
        QCOMPARE(count(r, Rule::BadHeader), 1);
        QCOMPARE(count(r, Rule::BadCondition), 1);
        QCOMPARE(count(r, Rule::DuplicateWord), 1);
        QCOMPARE(count(r, Rule::MessageNumberRange), 1);
        QCOMPARE(r.diagnostics.size(), std::size_t(8));
        // What could be read is there.
        QCOMPARE(r.store.numbers(), (std::vector<int>{1, 2}));
        const Program& p1 = *r.store.find(1);
        QCOMPARE(p1.frames.size(), std::size_t(3));
        QVERIFY(p1.frames[0].malformed);
        QVERIFY(!p1.frames[1].malformed);
        QCOMPARE(p1.frames[1].iso().value().x->literal, Decimal::fromInt(5));
        QVERIFY(p1.frames[2].malformed);
        // The malformed frame keeps its number and the words that were fine.
        QCOMPARE(p1.frames[0].number(), 1);
        QCOMPARE(p1.frames[0].iso().value().g[0].number, 1);
        QCOMPARE(QString::fromStdString(*r.store.messages.text(1)), QString("B"));
        // Diagnostics name their program.
        QCOMPARE(find(r, Rule::DuplicateWord)->program, 2);
        QCOMPARE(find(r, Rule::MessageNumberRange)->program, 0);
        QCOMPARE(find(r, Rule::DecimalInCompute)->program, 1);
        QCOMPARE(find(r, Rule::DecimalInCompute)->line, 4);
    }
    // Messages quote input text as whole UTF-8 characters and show bytes that
    // are not UTF-8 as \xHH: a message is valid UTF-8 whatever the input.
    void strayByteIsReportedOnceAndEscaped() {
        const ParseResult r = parse("G1 X5\xFF\nM30\n");
        QCOMPARE(r.diagnostics.size(), std::size_t(1));
        const Diagnostic& d = r.diagnostics.front();
        QCOMPARE(d.rule, Rule::InvalidUtf8);
        QCOMPARE(d.line, 1);
        QCOMPARE(d.column, 6);
        QVERIFY(QString::fromStdString(k528::program::diagnosticText(d, false)).contains("\\xFF"));
        QVERIFY(utf8::isValid(k528::program::diagnosticText(d, true)) && utf8::isValid(k528::program::diagnosticText(d, false)));
        // A second bad byte on the line (the first one is invalid-utf8) and an
        // overlong sequence are unexpected characters, shown escaped.
        const ParseResult two = parse("G1 \xFE X5 \xC0\x80 Z1 \x80\n");
        QCOMPARE(two.diagnostics.size(), std::size_t(3));
        QCOMPARE(two.diagnostics[0].rule, Rule::InvalidUtf8);
        QCOMPARE(two.diagnostics[0].column, 4);
        QCOMPARE(two.diagnostics[1].rule, Rule::Syntax);
        QCOMPARE(two.diagnostics[1].column, 9);
        QCOMPARE(QString::fromStdString(k528::program::diagnosticText(two.diagnostics[1], true)), QString("Неожиданный символ «\\xC0»"));
        QCOMPARE(two.diagnostics[2].column, 15);
        QCOMPARE(QString::fromStdString(k528::program::diagnosticText(two.diagnostics[2], false)), QString("unexpected character '\\x80'"));
        for (const auto& x : two.diagnostics)
            QVERIFY(utf8::isValid(k528::program::diagnosticText(x, true)) && utf8::isValid(k528::program::diagnosticText(x, false)));
    }
    void quotedTextKeepsWholeCharacters() {
        const ParseResult h = parse("%\xD0\x96\nM30\n"); // %Ж
        const Diagnostic* d = find(h, Rule::BadHeader);
        QVERIFY(d);
        QCOMPARE(QString::fromStdString(k528::program::diagnosticText(*d, true)), QString("Неизвестный заголовок «%Ж»: ожидается %L<номер программы> или %MESSAGES"));
        QCOMPARE(QString::fromStdString(k528::program::diagnosticText(*d, false)), QString("unknown header '%Ж': expected %L<program number> or %MESSAGES"));
        QCOMPARE(d->column, 1);
        QCOMPARE(d->endColumn, 3);
        // Text after a header, after %MESSAGES and after a jump frame.
        const struct {
            const char* text;
            Rule rule;
            const char* quoted;
        } cases[] = {
            {"%L1 \xD0\x96\xFF\x01\nM30\n", Rule::BadHeader, "«Ж\\xFF\\x01»"},
            {"%MESSAGES \xD0\x96\xFF\n", Rule::BadHeader, "«Ж\\xFF»"},
            {"N1 GOTO 1 \xD0\x96\xFF\n", Rule::Syntax, "«Ж\\xFF»"},
            {"R1=R2 \xD0\x96\n", Rule::Syntax, "«Ж»"},
        };
        for (const auto& c : cases) {
            const ParseResult r = parse(c.text);
            const Diagnostic* e = find(r, c.rule);
            QVERIFY2(e, c.text);
            QVERIFY2(QString::fromStdString(k528::program::diagnosticText(*e, true)).contains(QString::fromUtf8(c.quoted)),
                     k528::program::diagnosticText(*e, true).c_str());
            for (const auto& x : r.diagnostics)
                QVERIFY(utf8::isValid(k528::program::diagnosticText(x, true)) && utf8::isValid(k528::program::diagnosticText(x, false)));
        }
    }
    // A bad condition or target is one error; the rest of the frame is still read.
    void jumpFramesRecover_data() {
        QTest::addColumn<QByteArray>("frame");
        QTest::addColumn<QString>("expected");
        QTest::newRow("bad condition") << QByteArray("IF R1>5 GOTO 9") << "1:6 bad-condition";
        QTest::newRow("bad condition, GOTO N")
            << QByteArray("IF R1>5 GOTO N9") << "1:6 bad-condition the only jump condition is R1>0|"
                                                "1:14 syntax the jump target is written without N: GOTO 9";
        QTest::newRow("bad condition, bad target")
            << QByteArray("IF R1<0 GOTO 5.5") << "1:6 bad-condition|1:14 bad-number";
        QTest::newRow("bad condition, trailing text")
            << QByteArray("IF R1>=R2 GOTO 9 X") << "1:6 bad-condition|1:18 syntax";
        QTest::newRow("bad condition, no GOTO") << QByteArray("IF R1>5") << "1:6 bad-condition";
        QTest::newRow("R without number")
            << QByteArray("IF R>0 GOTO N9") << "1:4 syntax address R|1:13 syntax the jump target is written";
        QTest::newRow("no R") << QByteArray("IF 5>0 (c) GOTO 5.5") << "1:4 syntax IF must|1:17 bad-number";
        QTest::newRow("GOTO N5") << QByteArray("GOTO N5") << "1:6 syntax the jump target is written without N: GOTO 5";
        QTest::newRow("GOTO N5.5")
            << QByteArray("GOTO N5.5") << "1:6 syntax the jump target is written without N: GOTO <frame number";
    }
    void jumpFramesRecover() {
        QFETCH(QByteArray, frame);
        QFETCH(QString, expected);
        const ParseResult r = parse(frame.toStdString());
        QStringList got;
        for (const auto& d : r.diagnostics)
            got << QString("%1:%2 %3 %4").arg(d.line).arg(d.column).arg(QString::fromStdString(std::string(ruleId(d.rule)))).arg(QString::fromStdString(k528::program::diagnosticText(d, false)));
        const QStringList want = expected.split('|');
        QVERIFY2(got.size() == want.size(), qPrintable(got.join('\n')));
        for (int k = 0; k < want.size(); ++k)
            QVERIFY2(got[k].startsWith(want[k]), qPrintable(got.join('\n')));
        QVERIFY(r.store.programs()[0].frames[0].malformed);
    }
    void errorsPerLineAreCapped() {
        std::string line = "G1";
        for (int i = 0; i < 200; ++i)
            line += " Q1";
        const ParseResult r = parse(line + "\nQ2\n");
        QCOMPARE(count(r, Rule::UnknownAddress), 8 + 1);
    }
    void frameOutsideProgramMovesToProgramZero() {
        const ParseResult r = p("G1 X5..3\n%L1\nM30\n", 5);
        QCOMPARE(r.store.numbers(), std::vector<int>{1});
        QCOMPARE(find(r, Rule::BadNumber)->program, 0);
        QCOMPARE(find(r, Rule::FrameOutsideProgram)->line, 1);
    }
    void cyrillicHintNamesTheLatinLetter() {
        const ParseResult r = parse("G1 \xD1\x85" "5\n"); // lower-case х
        const Diagnostic* d = find(r, Rule::CyrillicLetter);
        QVERIFY(d);
        QVERIFY(QString::fromStdString(k528::program::diagnosticText(*d, true)).contains("(X)"));
        QCOMPARE(d->column, 4);
        QCOMPARE(d->endColumn, 5);
        // The X5 that follows is not reported again as garbage.
        QCOMPARE(r.diagnostics.size(), std::size_t(1));
    }
};

QTEST_APPLESS_MAIN(TestParser)
#include "test_parser.moc"
