#include "catalog/messages.h"

#include <QtTest>

#include <algorithm>

#include "program/diagnostic_texts.h"
#include "program/parser.h"
#include "program/validator.h"

using namespace k528::program;

Q_DECLARE_METATYPE(k528::program::Rule)
Q_DECLARE_METATYPE(k528::program::Severity)

namespace {

// A machine for the machine-constant rules: X a diameter axis with software
// limits -10..250.0005 mm and F УСК.АВТ. 5000 mm/min at 0.001 mm; Z with
// limits -400..20 at 0.01 mm; Z absent when asked.
MachineLimits testMachine(bool zPresent = true) {
    MachineLimits m;
    m.x.diameter = true;
    m.x.softLimits = true;
    m.x.minMm = Decimal::fromInt(-10);
    m.x.maxMm = Decimal::fromScaled(2500005, 4);
    m.x.maxFeedMmPerMin = Decimal::fromInt(5000);
    m.x.decimals = 3;
    m.z.present = zPresent;
    m.z.softLimits = true;
    m.z.minMm = Decimal::fromInt(-400);
    m.z.maxMm = Decimal::fromInt(20);
    m.z.maxFeedMmPerMin = Decimal::fromInt(8000);
    m.z.decimals = 2;
    return m;
}

enum Setup { Plain = 0, Machine = 1, MachineNoZ = 2, Limit3 = 3 };

ValidateOptions options(int setup) {
    ValidateOptions o;
    if (setup == Machine)
        o.machine = testMachine();
    if (setup == MachineNoZ)
        o.machine = testMachine(false);
    if (setup == Limit3)
        o.nestingLimit = 3;
    return o;
}

std::vector<Diagnostic> diags(const std::string& text, int setup = Plain) {
    return check(text, {}, options(setup)).diagnostics;
}

std::vector<const Diagnostic*> withRule(const std::vector<Diagnostic>& d, Rule r) {
    std::vector<const Diagnostic*> out;
    for (const auto& x : d)
        if (x.rule == r)
            out.push_back(&x);
    return out;
}

std::string chain(int programs) { // L1 -> L2 -> ... -> Ln
    std::string s;
    for (int i = 1; i <= programs; ++i) {
        s += "%L" + std::to_string(i) + "\n";
        if (i < programs)
            s += "L" + std::to_string(i + 1) + "\n";
        s += i == 1 ? "M30\n" : "M17\n";
    }
    return s;
}

std::string frames(int n) {
    std::string s = "%L1\n";
    for (int i = 0; i < n - 1; ++i)
        s += "G1 X1\n";
    return s + "M30\n";
}

std::string dump(const std::vector<Diagnostic>& d) {
    std::string s;
    for (const auto& x : d)
        s += std::to_string(x.line) + ":" + std::to_string(x.column) + " " + std::string(ruleId(x.rule)) + " " +
             k528::program::diagnosticText(x, false) + "\n";
    return s;
}

} // namespace

class TestValidator : public QObject {
    Q_OBJECT
private slots:
    // Each rule: a text that triggers it (with its manual number and
    // severity) and a near miss that does not.
    void rules_data() {
        QTest::addColumn<QByteArray>("bad");
        QTest::addColumn<QByteArray>("good");
        QTest::addColumn<Rule>("rule");
        QTest::addColumn<int>("manual");
        QTest::addColumn<Severity>("severity");
        QTest::addColumn<int>("setup");
        QTest::addColumn<int>("line");
        auto row = [](const char* name, const std::string& bad, const std::string& good, Rule r, int manual,
                      Severity s = Severity::Error, int setup = Plain, int line = 0) {
            QTest::newRow(name) << QByteArray::fromStdString(bad) << QByteArray::fromStdString(good) << r << manual
                                << s << setup << line;
        };
        const auto W = Severity::Warning;
        const auto E = Severity::Error;
        row("N0", "N0 G1 X1\nM30\n", "N1 G1 X1\nM30\n", Rule::FrameNumberRange, 0, E, Plain, 1);
        row("N1000", "N1000 G1 X1\nM30\n", "N999 G1 X1\nM30\n", Rule::FrameNumberRange, 0);
        row("duplicate N", "N1 G1 X1\nN1 G0 X2\nM30\n", "N1 G1 X1\nN2 G0 X2\nM30\n", Rule::DuplicateFrameNumber, 54, E,
            Plain, 2);
        row("1000 frames", frames(1000), frames(999), Rule::TooManyFrames, 0, E, Plain, 1001);
        row("empty program", "%L1\nM30\n%L2\n", "%L1\nM30\n%L2\nM17\n", Rule::EmptyProgram, 0, W, Plain, 3);
        row("X above 9999.999", "X10000\nM30\n", "X9999.999\nM30\n", Rule::CoordinateRange, 33);
        row("X just above", "X-9999.9991\nM30\n", "X-9999.9990\nM30\n", Rule::CoordinateRange, 33);
        row("Z below", "Z-10000\nM30\n", "Z-9999.999\nM30\n", Rule::CoordinateRange, 49);
        row("feed 0", "X5 FX0\nM30\n", "X5 FX0.001\nM30\n", Rule::FeedRange, 0);
        row("feed negative", "Z5 FZ-5\nM30\n", "Z5 FZ5\nM30\n", Rule::FeedRange, 0);
        row("feed above 10000", "Z5 FZ10000.001\nM30\n", "Z5 FZ10000\nM30\n", Rule::FeedRange, 0);
        row("G2", "G2 X5\nM30\n", "G1 X5\nM30\n", Rule::UnknownG, 47);
        row("G300", "G300 X5\nM30\n", "G292 X5\nM30\n", Rule::UnknownG, 47);
        row("G310", "G310\nM30\n", "G210\nM30\n", Rule::UnknownG, 47);
        row("G336", "G336 Z5\nM30\n", "G236 Z5\nM30\n", Rule::UnknownG, 47);
        row("G0 G1", "G0 G1 X5\nM30\n", "G0 G90 X5\nM30\n", Rule::GSameGroup, 47);
        row("G136 G237", "G136 G237 X5 Z5\nM30\n", "G136 G256 X5 Z5\nM30\n", Rule::GSameGroup, 47);
        row("G55 G156", "G55 G156\nM30\n", "G54 G156\nM30\n", Rule::GSameGroup, 47);
        row("G90 G91", "G90 G91 X1\nM30\n", "G90 G1 X1\nM30\n", Rule::GSameGroup, 47);
        row("G180 G281", "G180 G281 Z-3 FZ5\nM30\n", "G180\nG281 Z-3 FZ5\nM30\n", Rule::GSameGroup, 47);
        row("G1 G1", "G1 G1 X1\nM30\n", "G1 X1\nM30\n", Rule::GSameGroup, 47);
        row("M100", "M100\nM30\n", "M99\nM30\n", Rule::MRange, 0);
        row("M3 M3", "M3 M8 M3\nM30\n", "M3 M8 M4\nM30\n", Rule::MRepeated, 0, W);
        row("#0", "#0 X1\nM30\n", "#1 X1\nM30\n", Rule::MessageRange, 0);
        row("#100", "#100 X1\nM30\n", "#99 X1\nM30\n", Rule::MessageRange, 0);
        row("message undefined", "#5 X1\nM30\n%MESSAGES\n#4=A\n", "#5 X1\nM30\n%MESSAGES\n#5=A\n",
            Rule::MessageUndefined, 0, W);
        row("message with no table", "#5 X1\nM30\n%MESSAGES\n", "#5 X1\nM30\n", Rule::MessageUndefined, 0, W);
        row("L0", "%L1\nL0\nM30\n", "%L1\nL2\nM30\n%L2\nM17\n", Rule::CallRange, 0);
        row("L100", "%L1\nL100\nM30\n", "%L1\nL99\nM30\n%L99\nM17\n", Rule::CallRange, 0);
        row("missing subprogram", "%L1\nN5 L3\nM30\n%L2\nM17\n", "%L1\nN5 L2\nM30\n%L2\nM17\n", Rule::CallMissing, 45,
            E, Plain, 2);
        row("R300 target", "R300=1\nM30\n", "R299=1\nM30\n", Rule::RIndexRange, 0);
        row("R300 operand", "R1=R300+1\nM30\n", "R1=R299+1\nM30\n", Rule::RIndexRange, 0);
        row("R300 in X", "X=R300\nM30\n", "X=R299\nM30\n", Rule::RIndexRange, 0);
        row("R300 in IF", "N1 IF R300>0 GOTO 1\nM30\n", "N1 IF R299>0 GOTO 1\nM30\n", Rule::RIndexRange, 0);
        row("write R232", "R232=1\nM30\n", "R231=1\nM30\n", Rule::ReadOnlyR, 0);
        row("write R262", "R262=R1\nM30\n", "R263=R1\nM30\n", Rule::ReadOnlyR, 0);
        row("read R240", "R240=R1\nM30\n", "R1=R240\nM30\n", Rule::ReadOnlyR, 0);
        row("divide by 0", "R1=R2/0\nM30\n", "R1=R2*0\nM30\n", Rule::DivisionByZero, 46);
        row("constant overflow +", "R1=2147483647+1\nM30\n", "R1=2147483646+1\nM30\n", Rule::ConstantOverflow, 46);
        row("constant overflow *", "R1=65536*32768\nM30\n", "R1=65536*32767\nM30\n", Rule::ConstantOverflow, 46);
        row("constant overflow /", "R1=-2147483648/-1\nM30\n", "R1=-2147483648/1\nM30\n", Rule::ConstantOverflow, 46);
        row("constant overflow -", "R1=-2147483648-1\nM30\n", "R1=-2147483647-1\nM30\n", Rule::ConstantOverflow, 46);
        row("jump nowhere", "N1 GOTO 5\nN2 M30\n", "N1 GOTO 2\nN2 M30\n", Rule::JumpTarget, 53, E, Plain, 1);
        row("IF nowhere", "N1 IF R1>0 GOTO 7\nM30\n", "N1 IF R1>0 GOTO 1\nM30\n", Rule::JumpTarget, 53);
        row("jump to 1000", "GOTO 1000\nM30\n", "GOTO 999\nN999 M30\n", Rule::JumpTarget, 53);
        row("jump to N of other program", "%L1\nGOTO 5\nM30\n%L2\nN5 M17\n", "%L1\nGOTO 5\nN5 M30\n%L2\nM17\n",
            Rule::JumpTarget, 53);
        row("X with L", "%L1\nL2 X5\nM30\n%L2\nM17\n", "%L1\nL2 FX5\nM30\n%L2\nM17\n", Rule::AxisWithCall, 34);
        row("Z with L", "%L1\nL2 Z=R5\nM30\n%L2\nM17\n", "%L1\nL2\nZ=R5\nM30\n%L2\nM17\n", Rule::AxisWithCall, 50);
        row("X with M17", "X5 M17\n", "X5\nM17\n", Rule::AxisWithM17, 35);
        row("Z with M17", "G1 Z5 M17\n", "G1 Z5\nM17\n", Rule::AxisWithM17, 51);
        row("X at end of L", "%L1\nL2\nM30\n%L2\nG1 X5\n", "%L1\nL2\nM30\n%L2\nG1 X5\nM17\n", Rule::AxisAtSubprogramEnd,
            36, E, Plain, 5);
        row("Z at end of L", "%L1\nL2\nM30\n%L2\nG1 Z5\n", "%L1\nM30\n%L2\nG1 Z5\n", Rule::AxisAtSubprogramEnd, 52);
        row("M30/L", "%L1\nM30 L2\n%L2\nM17\n", "%L1\nM3 L2\nM30\n%L2\nM17\n", Rule::EndCombination, 58);
        row("M2/L", "%L1\nM02 L2\n%L2\nM17\n", "%L1\nL2\nM02\n%L2\nM17\n", Rule::EndCombination, 59);
        row("M17/L", "%L1\nL2\nM30\n%L2\nM17 L3\n%L3\nM17\n", "%L1\nL2\nM30\n%L2\nL3\nM17\n%L3\nM17\n",
            Rule::EndCombination, 60);
        row("M30/M17", "M30 M17\n", "M30\nM17\n", Rule::EndCombination, 61);
        row("M2/M17", "M2 M17\n", "M2\n", Rule::EndCombination, 62);
        row("G04 with Z", "G04 X2 Z5\nM30\n", "G04 X2\nZ5\nM30\n", Rule::DwellWithZ, 63);
        row("G04 with L", "%L1\nG04 X2 L2\nM30\n%L2\nM17\n", "%L1\nG04 X2\nL2\nM30\n%L2\nM17\n", Rule::DwellWithCall, 64);
        row("G04 negative", "G04 X-1\nM30\n", "G04 X0\nM30\n", Rule::DwellNegative, 33);
        row("G04 too long", "G04 X10000\nM30\n", "G04 X9999.999\nM30\n", Rule::CoordinateRange, 33);
        row("G04 without X", "G04\nM30\n", "G04 X20.5\nM30\n", Rule::DwellWithoutTime, 0, W);
        row("G192 without X", "G192\nM30\n", "G192 X12.324\nM30\n", Rule::AxisFunctionWithoutValue, 0, W);
        row("G281 without Z", "G281 X5 FZ100\nM30\n", "G281 Z=-30.5 Fz=100\nM30\n", Rule::AxisFunctionWithoutValue, 0, W);
        row("G136 without X", "G136 Z5\nM30\n", "G136 X5\nM30\n", Rule::AxisFunctionWithoutValue, 0, W);
        row("after GOTO", "GOTO 2\nG1 X5\nN2 M30\n", "IF R1>0 GOTO 2\nG1 X5\nN2 M30\n", Rule::Unreachable, 0, W, Plain, 2);
        row("after M30", "M30\nG1 X5\n", "M00\nG1 X5\nM30\n", Rule::Unreachable, 0, W);
        row("after skipped GOTO", "GOTO 2\nG1 X5\nN2 M30\n", "/GOTO 2\nG1 X5\nN2 M30\n", Rule::Unreachable, 0, W);
        row("jumped over, not a target", "GOTO 2\nN3 G1 X5\nN2 M30\n", "GOTO 3\nN3 G1 X5\nN2 M30\n", Rule::Unreachable,
            0, W);
        row("self call", "%L1\nL1\nM30\n", "%L1\nL2\nM30\n%L2\nM17\n", Rule::NestingCycle, 48, W);
        row("call cycle", "%L1\nL2\nM30\n%L2\nL3\nM17\n%L3\nL2\nM17\n", chain(3), Rule::NestingCycle, 48, W);
        row("nesting 9 of 8", chain(10), chain(9), Rule::NestingDepth, 48, W, Plain, 2);
        row("nesting 4 of 3", chain(5), chain(4), Rule::NestingDepth, 48, W, Limit3);
        // Against a machine's constants.
        row("Z on a machine without Z", "G1 Z5\nM30\n", "G1 X5\nM30\n", Rule::AxisAbsent, 0, W, MachineNoZ);
        row("FZ without Z", "X5 FZ5\nM30\n", "X5 FX5\nM30\n", Rule::AxisAbsent, 0, W, MachineNoZ);
        row("G236 without Z", "G236 X5\nM30\n", "G136 X5\nM30\n", Rule::AxisAbsent, 0, W, MachineNoZ);
        row("X beyond + limit", "G1 X250.001\nM30\n", "G1 X250\nM30\n", Rule::SoftLimit, 12, W, Machine);
        row("X beyond - limit", "G1 X-10.001\nM30\n", "G1 X-10\nM30\n", Rule::SoftLimit, 12, W, Machine);
        row("Z beyond + limit", "G1 Z21\nM30\n", "G1 Z20\nM30\n", Rule::SoftLimit, 28, W, Machine);
        row("incremental is not checked", "G90 X300\nM30\n", "G91 X300\nM30\n", Rule::SoftLimit, 12, W, Machine);
        row("after G90 again", "G91 X300\nG90 X300\nM30\n", "G90 X1\nG91 X300\nM30\n", Rule::SoftLimit, 12, W, Machine);
        row("set position is not motion", "X300\nM30\n", "G192 X300\nM30\n", Rule::SoftLimit, 12, W, Machine);
        row("oscillation stroke", "Z-500\nM30\n", "G281 Z-500 FZ100\nM30\n", Rule::SoftLimit, 28, W, Machine);
        row("dwell seconds", "X300\nM30\n", "G04 X300\nM30\n", Rule::SoftLimit, 12, W, Machine);
        row("feed above F УСК.АВТ.", "X5 FX5000.001\nM30\n", "X5 FX5000\nM30\n", Rule::FeedAboveMax, 0, W, Machine);
        row("FZ above", "Z5 FZ8001\nM30\n", "Z5 FZ8000\nM30\n", Rule::FeedAboveMax, 0, W, Machine);
        row("X finer than the discrete", "X5.3425\nM30\n", "X5.342\nM30\n", Rule::DiscreteRounding, 0, W, Machine);
        row("Z finer than the discrete", "Z1.005\nM30\n", "Z1.01\nM30\n", Rule::DiscreteRounding, 0, W, Machine);
        row("FX finer than the discrete", "X1 FX10.0001\nM30\n", "X1 FX10.001\nM30\n", Rule::DiscreteRounding, 0, W,
            Machine);
        // The message table.
        row("message of 21", "%MESSAGES\n#1=123456789012345678901\n", "%MESSAGES\n#1=12345678901234567890\n",
            Rule::MessageTooLong, 0);
        row("message of 21 cyrillic", "%MESSAGES\n#1=ЧЕРНОВАЯ ПОДАЧА КРУГА\n", "%MESSAGES\n#1=ЧЕРНОВАЯ ПОДАЧА КРУГ\n",
            Rule::MessageTooLong, 0);
        row("tab in message", "%MESSAGES\n#1=A\tB\n", "%MESSAGES\n#1=A B\n", Rule::MessageCharacter, 0);
        row("symbol in message", "%MESSAGES\n#1=Ø40\n", "%MESSAGES\n#1=ДИАМЕТР 40 №2\n", Rule::MessageCharset, 0, W);
    }
    void rules() {
        QFETCH(QByteArray, bad);
        QFETCH(QByteArray, good);
        QFETCH(Rule, rule);
        QFETCH(int, manual);
        QFETCH(Severity, severity);
        QFETCH(int, setup);
        QFETCH(int, line);
        const auto b = diags(bad.toStdString(), setup);
        const auto hits = withRule(b, rule);
        QVERIFY2(!hits.empty(), (std::string("not reported; got:\n") + dump(b)).c_str());
        for (const Diagnostic* d : hits) {
            QCOMPARE(d->manualNumber, manual);
            QCOMPARE(d->severity, severity);
            // One text per message: `check` opens with the text `run` shows
            // (the catalog's, table М.1).
            if (manual > 0)
                QVERIFY2(k528::program::diagnosticText(*d, true).rfind(std::string(k528::catalog::positionerMessage(manual).textRu), 0) == 0,
                         k528::program::diagnosticText(*d, true).c_str());
            QVERIFY(d->column >= 1 && d->endColumn > d->column);
            QVERIFY2(k528::program::diagnosticTexts().find(d->textId), d->textId.c_str()); // a text of the catalog
        }
        if (line)
            QCOMPARE(hits.front()->line, line);
        const auto g = diags(good.toStdString(), setup);
        QVERIFY2(withRule(g, rule).empty(), dump(g).c_str());
        // The near misses are clean programs altogether (a few expected warnings aside).
        for (const auto& d : g)
            QVERIFY2(d.severity == Severity::Warning || rule == Rule::CallRange, dump(g).c_str());
    }

    // --- Details of single rules ------------------------------------------------------
    void messagesUseTheManualsWording() {
        const auto d = diags("%L1\nN5 L2 X5\nN6 GOTO 9\nN6 G0 G1 G300\nM30\n");
        auto text = [&](Rule r) { return QString::fromStdString(k528::program::diagnosticText(*withRule(d, r).front(), true)); };
        QVERIFY(text(Rule::CallMissing).startsWith("L отсутствует"));
        QVERIFY(text(Rule::CallMissing).contains("L2"));
        QVERIFY(text(Rule::AxisWithCall).startsWith("X/L"));
        QVERIFY(text(Rule::JumpTarget).startsWith("Ошибка перехода"));
        QVERIFY(text(Rule::JumpTarget).contains("N9"));
        QVERIFY(text(Rule::DuplicateFrameNumber).startsWith("Дублирование номеров кадров"));
        QVERIFY(text(Rule::DuplicateFrameNumber).contains("строке 3"));
        QVERIFY(text(Rule::UnknownG).startsWith("G?"));
        QVERIFY(text(Rule::UnknownG).contains("G300"));
        QVERIFY(text(Rule::GSameGroup).contains("G00") && text(Rule::GSameGroup).contains("G01"));
        const auto n = diags(chain(10));
        QVERIFY(QString::fromStdString(k528::program::diagnosticText(*withRule(n, Rule::NestingDepth).front(), true)).startsWith("Глубина вложения L"));
    }
    void positionsPointAtTheWord() {
        const auto d = diags("%L1\nN1 G1 G300 X5\nN2 L7\nM30\n");
        const Diagnostic* g = withRule(d, Rule::UnknownG).front();
        QCOMPARE(g->line, 2);
        QCOMPARE(g->column, 7);
        QCOMPARE(g->endColumn, 11);
        QCOMPARE(g->program, 1);
        const Diagnostic* l = withRule(d, Rule::CallMissing).front();
        QCOMPARE(l->line, 3);
        QCOMPARE(l->column, 4);
        QCOMPARE(l->endColumn, 6);
    }
    void nestingReportsOnlyWhereTheChainIsTooDeep() {
        const auto d = diags(chain(10)); // L1 -> ... -> L10: 9 levels from L1, 8 from L2
        const auto hits = withRule(d, Rule::NestingDepth);
        QCOMPARE(hits.size(), std::size_t(1));
        QCOMPARE(hits.front()->program, 1);
        QVERIFY(QString::fromStdString(k528::program::diagnosticText(*hits.front(), false)).contains("L1->L2->L3->L4->L5->L6->L7->L8->L9->L10"));
        QVERIFY(QString::fromStdString(k528::program::diagnosticText(*hits.front(), false)).contains("9 levels"));
        // A cycle is reported at every call on it, with the path.
        const auto c = diags("%L1\nL2\nM30\n%L2\nL3\nM17\n%L3\nL2\nM17\n");
        const auto cyc = withRule(c, Rule::NestingCycle);
        QCOMPARE(cyc.size(), std::size_t(2));
        QVERIFY(QString::fromStdString(k528::program::diagnosticText(*cyc[0], false)).contains("L2->L3->L2"));
        QVERIFY(QString::fromStdString(k528::program::diagnosticText(*cyc[1], false)).contains("L3->L2->L3"));
        QVERIFY(withRule(c, Rule::NestingDepth).empty()); // L1 calls into the cycle: no extra noise
    }
    void nestingFollowsCallsOutOfACycle() {
        // L1 -> L2, L2 <-> L3, L3 -> L4 -> ... -> L14: below the call L1 -> L2
        // the chain L2 -> L3 -> L4 -> ... -> L14 nests 12 more levels.
        std::string text = "%L1\nL2\nM30\n%L2\nL3\nM17\n%L3\nL2\nL4\nM17\n";
        for (int i = 4; i <= 14; ++i) {
            text += "%L" + std::to_string(i) + "\n";
            if (i < 14)
                text += "L" + std::to_string(i + 1) + "\n";
            text += "M17\n";
        }
        const auto d = diags(text);
        std::vector<const Diagnostic*> fromL1;
        for (const Diagnostic* x : withRule(d, Rule::NestingDepth))
            if (x->program == 1)
                fromL1.push_back(x);
        QVERIFY2(fromL1.size() == 1, dump(d).c_str());
        const QString en = QString::fromStdString(k528::program::diagnosticText(*fromL1.front(), false));
        QVERIFY2(en.contains("L1->L2->L3->L4->L5->L6->L7->L8->L9->L10->L11->L12->L13->L14 nests 13 levels"),
                 qPrintable(en));
        QCOMPARE(fromL1.front()->line, 2);
        // The entry into the cycle from the other side goes round it first.
        const auto e = diags("%L1\nL3\nM30\n" + text.substr(std::string("%L1\nL2\nM30\n").size()));
        bool found = false;
        for (const Diagnostic* x : withRule(e, Rule::NestingDepth))
            if (x->program == 1)
                found = QString::fromStdString(k528::program::diagnosticText(*x, false)).contains("L1->L3->L4->") &&
                        QString::fromStdString(k528::program::diagnosticText(*x, false)).contains(" 12 levels");
        QVERIFY2(found, dump(e).c_str());
        // A member that calls out only through another member still gets the chain.
        const auto f = diags("%L1\nL2\nM30\n%L2\nL3\nM17\n%L3\nL2\nL4\nM17\n%L4\nL5\nM17\n%L5\nM17\n",
                             Limit3);
        const auto deep = withRule(f, Rule::NestingDepth);
        QVERIFY2(deep.size() == 1, dump(f).c_str());
        QCOMPARE(deep.front()->program, 1);
        QVERIFY(QString::fromStdString(k528::program::diagnosticText(*deep.front(), false)).contains("L1->L2->L3->L4->L5 nests 4 levels"));
    }
    // A jump frame whose condition or target is malformed: only the syntax
    // errors, no jump error for a target that was never read, no frames
    // reported unreachable for want of it.
    void malformedJumps_data() {
        QTest::addColumn<QByteArray>("frame");
        QTest::addColumn<QString>("expected");
        QTest::addColumn<bool>("targetRead");
        auto row = [](const char* frame, const char* expected, bool read) {
            QTest::newRow(frame) << QByteArray(frame) << QString(expected) << read;
        };
        row("IF R1>5 GOTO 9", "2:6 bad-condition", true);
        row("GOTO N5", "2:6 syntax", false);
        row("IF R>0 GOTO 1", "2:4 syntax", true);
        row("GOTO 5.5", "2:6 bad-number", false);
        row("GOTO", "2:5 syntax", false);
        row("IF 5>0 GOTO 9", "2:4 syntax", true);
        row("IF R1>5 GOTO", "2:6 bad-condition|2:13 syntax", false);
        // The target after a bad condition is still read and checked.
        row("IF R1>5 GOTO 7", "2:6 bad-condition|2:14 jump-target", true);
        row("IF R1>5 GOTO N9", "2:6 bad-condition|2:14 syntax", false);
        row("IF R1>=0 GOTO 0", "2:6 bad-condition|2:15 jump-target", true);
        // A target that was read is checked even in a malformed frame.
        row("IF R1>0 GOTO 7 X", "2:14 jump-target|2:16 syntax", true);
    }
    void malformedJumps() {
        QFETCH(QByteArray, frame);
        QFETCH(QString, expected);
        QFETCH(bool, targetRead);
        const auto d = diags("N1 G1 X1\n" + frame.toStdString() + "\nN9 G1 X2\nM30\n");
        QStringList got;
        for (const auto& x : d)
            got << QString("%1:%2 %3").arg(x.line).arg(x.column).arg(QString::fromStdString(std::string(ruleId(x.rule))));
        QCOMPARE(got.join('|'), expected);
        // Below GOTO 9 the next two frames are unreachable, unless the malformed
        // jump among them lost its target: it may lead anywhere.
        const auto u = withRule(diags("N1 GOTO 9\nG1 X1\n" + frame.toStdString() + "\nN9 M30\n"), Rule::Unreachable);
        QCOMPARE(u.size(), std::size_t(targetRead ? 1 : 0));
    }
    void unreachableGroupsARun() {
        const auto d = diags("N1 GOTO 9\nG1 X1\nG1 X2\nG1 X3\nN9 M30\nG1 X4\n");
        const auto u = withRule(d, Rule::Unreachable);
        QCOMPARE(u.size(), std::size_t(2));
        QCOMPARE(u[0]->line, 2);
        QVERIFY(QString::fromStdString(k528::program::diagnosticText(*u[0], false)).contains("lines 2-4"));
        QCOMPARE(u[1]->line, 6);
    }
    void subprogramEndRules() {
        // Only a called program is a subprogram; a skipped last frame is not its end.
        QVERIFY(withRule(diags("%L2\nG1 X5\n"), Rule::AxisAtSubprogramEnd).empty());
        QVERIFY(withRule(diags("%L1\nL2\nM30\n%L2\n/G1 X5\n"), Rule::AxisAtSubprogramEnd).empty());
        // With M17 in the last frame, X is 35, not 36.
        const auto d = diags("%L1\nL2\nM30\n%L2\nG1 X5 M17\n");
        QVERIFY(withRule(d, Rule::AxisAtSubprogramEnd).empty());
        QCOMPARE(withRule(d, Rule::AxisWithM17).size(), std::size_t(1));
    }
    void dwellTimeIsNotACoordinate() {
        // X of G04 is seconds (table 5): with M17 the frame dwells, then returns (not 35).
        const auto m17 = diags("%L1\nL2\nM30\n%L2\nG04 X2 M17\n");
        QVERIFY(!hasErrors(m17));
        // A dwell as the last frame of a subprogram without M17 is not 36.
        QVERIFY(withRule(diags("%L1\nL2\nM30\n%L2\nG04 X2\n"), Rule::AxisAtSubprogramEnd).empty());
        // A dwell with a call is 64 only, not 34; its Z stays a coordinate (63, 50).
        const auto call = diags("%L1\nG04 X2 L2\nM30\n%L2\nM17\n");
        QVERIFY(withRule(call, Rule::AxisWithCall).empty());
        QCOMPARE(withRule(call, Rule::DwellWithCall).size(), std::size_t(1));
        const auto z = diags("%L1\nG04 Z2 L2\nM30\n%L2\nM17\n");
        QCOMPARE(withRule(z, Rule::DwellWithZ).size(), std::size_t(1));
        QCOMPARE(withRule(z, Rule::AxisWithCall).size(), std::size_t(1));
    }
    void machineLimitsFollowG90G91() {
        // After G91 nothing is checked until G90.
        const auto d = diags("G90 X1\nG91 X300\nX300\nG90\nX300\nM30\n", Machine);
        const auto s = withRule(d, Rule::SoftLimit);
        QCOMPARE(s.size(), std::size_t(1));
        QCOMPARE(s.front()->line, 5);
        QVERIFY(QString::fromStdString(k528::program::diagnosticText(*s.front(), true)).contains("на диаметр"));
        // Without a machine nothing of this kind is said.
        QVERIFY(withRule(diags("X300 FX9000 Z5.005\nM30\n"), Rule::SoftLimit).empty());
        QVERIFY(withRule(diags("X300 FX9000 Z5.005\nM30\n"), Rule::FeedAboveMax).empty());
        QVERIFY(withRule(diags("X300 FX9000 Z5.005\nM30\n"), Rule::DiscreteRounding).empty());
        const auto r = diags("X5.3425\nM30\n", Machine);
        QVERIFY(QString::fromStdString(k528::program::diagnosticText(*withRule(r, Rule::DiscreteRounding).front(), false)).contains("5.343"));
    }
    void skippedFramesAreStillChecked() {
        QCOMPARE(withRule(diags("/G2 X1\nM30\n"), Rule::UnknownG).size(), std::size_t(1));
        QCOMPARE(withRule(diags("/GOTO 7\nM30\n"), Rule::JumpTarget).size(), std::size_t(1));
    }
    void malformedFrameNumbersStillCount() {
        // N5 has a syntax error but is a jump target: no 53 on top of it.
        const auto d = diags("GOTO 5\nN5 G1 X5..3\nM30\n");
        QVERIFY(withRule(d, Rule::JumpTarget).empty());
        QCOMPARE(withRule(d, Rule::BadNumber).size(), std::size_t(1));
    }
    void oneProgramAtATimeGivesTheSameAsTheStore() {
        const std::string text = "%L1\nN1 L2\nN2 GOTO 7\nM30\n%L2\nL3 X5\nM17\n%L3\nL2\n"
                                 "G1 Z1\n%L4\nG04 Z1\n%MESSAGES\n#1=" + std::string(25, 'A') + "\n";
        const ParseResult parsed = parse(text);
        const auto all = validate(parsed.store);
        const CallGraph graph(parsed.store);
        std::size_t sum = 0;
        for (int n : parsed.store.numbers()) {
            const auto one = validateProgram(parsed.store, n, graph);
            for (const auto& d : one)
                QCOMPARE(d.program, n);
            sum += one.size();
        }
        QCOMPARE(sum + validateMessages(parsed.store.messages).size(), all.size());
        QVERIFY(sum > 5);
    }
    void callGraphFollowsEdits() {
        ParseResult parsed = parse("%L1\nL2\nM30\n%L2\nM17\n");
        ProgramStore& store = parsed.store;
        CallGraph graph(store);
        QVERIFY(graph.isCalled(2));
        QVERIFY(!graph.isCalled(1));
        QCOMPARE(graph.callsFrom(1).size(), std::size_t(1));
        QCOMPARE(graph.callsFrom(1)[0].callee, 2);
        QCOMPARE(graph.callsFrom(1)[0].frameIndex, 0);
        // Program 2 now calls program 1: a cycle.
        ParseOptions o;
        o.programNumber = 2;
        ParseResult edited = parse("L1\nM17\n", o);
        graph.update(edited.store.programs()[0]);
        store.insert(edited.store.programs()[0]);
        QCOMPARE(graph.callerCount(1), 1);
        QCOMPARE(withRule(validateProgram(store, 2, graph), Rule::NestingCycle).size(), std::size_t(1));
        graph.remove(2);
        QVERIFY(!graph.isCalled(1));
        QVERIFY(graph.callsFrom(2).empty());
        QVERIFY(validateProgram(store, 77, graph).empty());
    }
    void checkMergesAndSorts() {
        const CheckResult r = check("N1 G2\nX5..3\nIF R1>0 GOTO 9\nM30\n");
        QVERIFY(r.syntaxErrors);
        QVERIFY(r.hasErrors());
        QVERIFY(std::is_sorted(r.diagnostics.begin(), r.diagnostics.end(),
                               [](const Diagnostic& a, const Diagnostic& b) { return a.line < b.line; }));
        QCOMPARE(r.diagnostics.size(), std::size_t(3));
        const CheckResult clean = check("N1 G1 X5 FX100\nN2 M30\n");
        QVERIFY(!clean.syntaxErrors);
        QVERIFY(clean.diagnostics.empty());
        QCOMPARE(clean.store.numbers(), std::vector<int>{1});
    }
    void ruleIdsAreUnique() {
        std::vector<std::string> ids;
        for (int r = 0; r <= static_cast<int>(Rule::DiscreteRounding); ++r)
            ids.emplace_back(ruleId(static_cast<Rule>(r)));
        std::sort(ids.begin(), ids.end());
        QVERIFY(std::adjacent_find(ids.begin(), ids.end()) == ids.end());
        QVERIFY(std::find(ids.begin(), ids.end(), "unknown") == ids.end());
    }
};

QTEST_APPLESS_MAIN(TestValidator)
#include "test_validator.moc"
