#include <QtTest>

#include "program/diagnostic_texts.h"
#include "program/formatter.h"
#include "program/parser.h"

using namespace k528::program;

namespace {

QString fmt(const char* text, int number = 1) {
    ParseOptions o;
    o.programNumber = number;
    const ParseResult r = parse(text, o);
    if (r.hasErrors())
        return "ERROR: " + QString::fromStdString(k528::program::diagnosticText(r.diagnostics.front(), false));
    return QString::fromStdString(format(r.store));
}

} // namespace

class TestFormatter : public QObject {
    Q_OBJECT
private slots:
    void canonicalFrames_data() {
        QTest::addColumn<QString>("in");
        QTest::addColumn<QString>("out");
        QTest::newRow("spec example") << "n12 g01 x5.3420 f=50.00 z-1234.678 f=1000.00"
                                      << "N12 G1 X5.342 FX50 Z-1234.678 FZ1000";
        QTest::newRow("word order") << "FZ=100 Z=-30.5 G281" << "G281 Z-30.5 FZ100";
        QTest::newRow("full order") << "X1 FX2 Z3 FZ4 L5 #6 M7 M8 G90 G1 N9"
                                    << "ERROR: the frame number N must come first in the frame";
        QTest::newRow("all words") << "N9 X1 FX2 Z3 FZ4 L5 #6 M7 M08 G90 G01"
                                   << "N9 G90 G1 M7 M8 #6 L5 X1 FX2 Z3 FZ4";
        QTest::newRow("R values") << "xr12 fx = R3 Z=R0" << "X=R12 FX=R3 Z=R0";
        QTest::newRow("dwell") << "G04 X20.500" << "G4 X20.5";
        QTest::newRow("skip") << "/ n5 g1" << "/N5 G1";
        QTest::newRow("skip without N") << "/G1 X0.0" << "/G1 X0";
        QTest::newRow("computational") << "N12 R75 = 2 * R99" << "N12 R75=2*R99";
        QTest::newRow("negative operands") << "R1 = -5 - -3" << "R1=-5--3";
        QTest::newRow("plus sign") << "R1=+5" << "R1=5";
        QTest::newRow("conditional") << "n202 if r1 > 0 goto 0301" << "N202 IF R1>0 GOTO 301";
        QTest::newRow("skip conditional") << "/IF R1>0 GOTO 1" << "/IF R1>0 GOTO 1";
        QTest::newRow("goto") << "N207 goto 33" << "N207 GOTO 33";
        QTest::newRow("N only") << "N040" << "N40";
        QTest::newRow("comments") << "(a) N1 G1 (b) X5 ;c" << "N1 G1 X5 (a) (b) ;c";
    }
    void canonicalFrames() {
        QFETCH(QString, in);
        QFETCH(QString, out);
        const QString got = fmt(in.toUtf8().constData());
        QCOMPARE(got.trimmed(), out);
    }
    void wholeFileLayout() {
        const char* in = "\n\n; K528 Studio sample\n"
                         "\n\n\n"
                         "; main\n"
                         "%l12   (ring 205)  ;  rough\n"
                         "\n"
                         "N1 G90 G01 X100.000 F=500 (approach)\n"
                         "\n\n"
                         "; the loop\n"
                         "N2 R1=R1-1\n"
                         "N3 IF R1>0 GOTO 2\n"
                         "M30\n"
                         "; after the end\n"
                         "\n\n"
                         "%L3\n"
                         "M17\n"
                         "%messages  ; table\n"
                         "#9=  DRESSING\n"
                         "; first\n"
                         "#1=ПРАВКА   \n"
                         "\n";
        // Programs in the order written, not by number.
        const char* out = "; K528 Studio sample\n"
                          "\n"
                          "; main\n"
                          "%L12 (ring 205) ;  rough\n"
                          "\n"
                          "N1 G90 G1 X100 FX500 (approach)\n"
                          "\n"
                          "; the loop\n"
                          "N2 R1=R1-1\n"
                          "N3 IF R1>0 GOTO 2\n"
                          "M30\n"
                          "; after the end\n"
                          "\n"
                          "%L3\n"
                          "M17\n"
                          "\n"
                          "%MESSAGES ; table\n"
                          "; first\n"
                          "#1=ПРАВКА\n"
                          "#9=  DRESSING\n";
        QCOMPARE(fmt(in), QString::fromUtf8(out));
        QCOMPARE(fmt(out), QString::fromUtf8(out)); // fixed point
    }
    // `run` starts a file's first program; `format` once sorted the
    // programs, so %L2 then %L1 ran L1 after formatting. Written order stays.
    void programsKeepTheOrderWritten() {
        const char* in = "%L2\nG1 X5\nM30\n%L1\nG1 X7\nM30\n%L9\nM17\n";
        const ParseResult r = parse(in, {});
        QVERIFY(!r.hasErrors());
        QCOMPARE(r.store.firstWritten(), 2);
        const std::string once = format(r.store);
        QCOMPARE(QString::fromStdString(once),
                 QString("%L2\nG1 X5\nM30\n\n%L1\nG1 X7\nM30\n\n%L9\nM17\n"));
        const ParseResult again = parse(once, {});
        QCOMPARE(again.store.firstWritten(), 2);
        QCOMPARE(QString::fromStdString(format(again.store)), QString::fromStdString(once));
        // A program without a header line (added in an editor) comes after
        // the written ones; among those, by number.
        ProgramStore s = r.store;
        Program added;
        added.number = 1;
        s.insert(added);
        Program more;
        more.number = 5;
        s.insert(more);
        std::vector<int> order;
        for (const Program* p : s.inWrittenOrder())
            order.push_back(p->number);
        QCOMPARE(order, (std::vector<int>{2, 9, 1, 5}));
    }
    void headerlessStaysHeaderless() {
        const char* in = "; shaft\nN1 G1 X5\nM30\n";
        QCOMPARE(fmt(in, 7), QString(in));
        const ParseResult r = parse(in);
        ProgramStore s = r.store;
        // A programmatic store with two programs gets headers.
        Program p2;
        p2.number = 2;
        Frame f;
        f.body = GotoFrame{Word{5, {}}};
        p2.frames.push_back(f);
        s.insert(p2);
        QCOMPARE(QString::fromStdString(format(s)), QString("%L1\n; shaft\nN1 G1 X5\nM30\n\n%L2\nGOTO 5\n"));
    }
    void emptyAndCommentOnly() {
        QCOMPARE(fmt(""), QString(""));
        QCOMPARE(fmt("\n\n\n"), QString(""));
        QCOMPARE(fmt("; only\n\n; comments\n\n"), QString("; only\n\n; comments\n"));
        QCOMPARE(fmt("%MESSAGES\n"), QString("%MESSAGES\n"));
    }
    void formatFrameOfEachKind() {
        Frame iso;
        IsoFrame i;
        i.g.push_back({1, {}});
        i.x = Value::lit(*Decimal::parse("5.342"));
        i.fx = Value::rParam(7);
        iso.body = i;
        iso.n = Word{12, {}};
        QCOMPARE(QString::fromStdString(formatFrame(iso)), QString("N12 G1 X5.342 FX=R7"));
        Frame c;
        ComputeFrame cf;
        cf.target.number = 75;
        cf.a = Operand::lit(2);
        cf.op = ArithOp::Mul;
        cf.b = Operand::rParam(99);
        c.body = cf;
        c.skip = true;
        QCOMPARE(QString::fromStdString(formatFrame(c)), QString("/R75=2*R99"));
        Frame j;
        j.body = IfGotoFrame{Word{1, {}}, Word{301, {}}};
        QCOMPARE(QString::fromStdString(formatFrame(j)), QString("IF R1>0 GOTO 301"));
        // Comments are not part of the frame's text.
        iso.comments.push_back({Comment::Style::Semicolon, "x"});
        QCOMPARE(QString::fromStdString(formatFrame(iso)), QString("N12 G1 X5.342 FX=R7"));
    }
    void formattedTextParsesToTheSameModel() {
        const char* in = "%L5 (t)\n/N1 G0 G90 M3 #2 X=R5 F1 Z-3.25 F=R6 ; c\nN2 R7=R7/-2 (half)\n"
                         "N3 IF R7>0 GOTO 2\nN4 GOTO 1\n%MESSAGES\n#2=ШЛИФОВАНИЕ\n";
        const ParseResult a = parse(in);
        QVERIFY(!a.hasErrors());
        const ParseResult b = parse(format(a.store));
        QVERIFY(!b.hasErrors());
        QVERIFY(sameContent(*a.store.find(5), *b.store.find(5)));
        QCOMPARE(QString::fromStdString(format(b.store)), QString::fromStdString(format(a.store)));
    }
};

QTEST_APPLESS_MAIN(TestFormatter)
#include "test_formatter.moc"
