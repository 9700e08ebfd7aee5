// Start from a frame (docs/engine.md, "Start from a frame"): for every frame
// of the sample programs, every time it is reached, the run started there
// with the state the preview rebuilt (engine::findStartPoint) on the
// simulated machine (machine::runProgram, as `k528 run --from`) ends as the
// run from the beginning does. "Equals" (docs/engine.md): the same status;
// every present axis' current and machine coordinates within ДОПУСК ПОЗ of
// each other (the axes rest inside it, not on the discrete); every writable
// R-parameter the same (R0..R231, R263..R299 but R150, R158: the machine
// writes those); the same modal state, technological message and program
// where it ended; the same M functions handed to the PLC but the program
// control's (M00, M02, M17, M30: a start hands the others again, in order).
// Frames inside an oscillation (Gx81 .. its Gx80) are no start frames and
// are counted apart.
#include "engine/preview_run.h"
#include "machine/run.h"
#include "profile/builtin.h"
#include "program/parser.h"
#include "util/input_file.h"

#include <QtTest>

#include <cstdlib>
#include <string>

using namespace k528;

namespace {

std::string readSample(const char* name) {
    std::string text, error;
    if (!util::readInputFile(std::string(K528_SOURCE_DIR "/resources/samples/") + name, text, error))
        qFatal("%s", error.c_str());
    return text;
}

std::vector<int> withoutProgramControl(const std::vector<int>& m) {
    std::vector<int> out;
    for (int c : m)
        if (engine::replayedMFunction(c))
            out.push_back(c);
    return out;
}

struct Counts {
    int starts = 0, oscillating = 0;
};

void checkEveryFrame(const char* sample, const char* machine, Counts& counts) {
    const profile::MachineProfile prof = profile::builtin(machine);
    const program::ParseResult parsed = program::parse(readSample(sample));
    if (parsed.hasErrors())
        qFatal("%s does not parse", sample);
    const int number = parsed.store.firstWritten();
    const engine::RunOptions plain;
    const engine::RunResult full = machine::runProgram(prof, parsed.store, number, plain);
    if (full.status != engine::RunStatus::Completed)
        qFatal("%s: the run from the beginning did not complete", sample);
    engine::PreviewOptions po;
    po.fromReferencePoint = true;
    for (const program::Program& p : parsed.store.programs()) {
        for (int i = 0; i < static_cast<int>(p.frames.size()); ++i) {
            for (int pass = 1; pass < 50; ++pass) {
                const engine::StartSearch s =
                    engine::findStartPoint(prof, parsed.store, number, {p.number, i, pass}, po);
                if (s.outcome == engine::StartSearch::Outcome::NotReached)
                    break;
                if (s.outcome == engine::StartSearch::Outcome::Oscillating) {
                    ++counts.oscillating;
                    continue;
                }
                ++counts.starts;
                engine::RunOptions o;
                o.from = s.point;
                const engine::RunResult r = machine::runProgram(prof, parsed.store, number, o);
                const QByteArray where = QByteArray(sample) + " L" + QByteArray::number(p.number) +
                                         " line " + QByteArray::number(p.frames[static_cast<std::size_t>(i)].span.line) +
                                         " pass " + QByteArray::number(pass);
                QVERIFY2(r.status == engine::RunStatus::Completed, where.constData());
                for (int a = 0; a < 2; ++a) {
                    const engine::RunAxis& x = r.axes[static_cast<std::size_t>(a)];
                    const engine::RunAxis& y = full.axes[static_cast<std::size_t>(a)];
                    if (!y.present)
                        continue;
                    const std::int64_t tol = prof.c[a == 0 ? 31 : 83] * (y.scale.diameter ? 2 : 1) + 2;
                    QVERIFY2(std::llabs(x.currentDisc - y.currentDisc) <= tol,
                             (where + " axis " + QByteArray::number(a) + " current " +
                              QByteArray::number(static_cast<qlonglong>(x.currentDisc)) + " vs " +
                              QByteArray::number(static_cast<qlonglong>(y.currentDisc)))
                                 .constData());
                    QVERIFY2(std::llabs(x.machineDisc - y.machineDisc) <= tol, where.constData());
                }
                for (int n = 0; n < 300; ++n) {
                    if (engine::rReadOnly(n) || n == 150 || n == 158)
                        continue;
                    QVERIFY2(r.r[static_cast<std::size_t>(n)] == full.r[static_cast<std::size_t>(n)],
                             (where + " R" + QByteArray::number(n) + " = " +
                              QByteArray::number(r.r[static_cast<std::size_t>(n)]) + " vs " +
                              QByteArray::number(full.r[static_cast<std::size_t>(n)]))
                                 .constData());
                }
                QVERIFY2(r.modal == full.modal, where.constData());
                QCOMPARE(r.messageNumber, full.messageNumber);
                QCOMPARE(r.program, full.program);
                QCOMPARE(r.line, full.line);
                QVERIFY2(withoutProgramControl(r.mFunctions) == withoutProgramControl(full.mFunctions),
                         where.constData());
            }
        }
    }
}

} // namespace

class RunFrom : public QObject {
    Q_OBJECT
private slots:
    void latheShaftEveryFrame() {
        Counts c;
        checkEveryFrame("lathe-shaft.k528", "training-lathe", c);
        qInfo("%d starts, %d frames inside an oscillation", c.starts, c.oscillating);
        if (QTest::currentTestFailed())
            return;
        // L1: 13 frames once (N10..N13 five times), L2 five passes, L3 once.
        QVERIFY2(c.starts > 50, QByteArray::number(c.starts).constData());
        QCOMPARE(c.oscillating, 0);
    }
    void latheGroovesEveryFrame() {
        Counts c;
        checkEveryFrame("lathe-grooves.k528", "training-lathe", c);
        qInfo("%d starts, %d frames inside an oscillation", c.starts, c.oscillating);
        if (QTest::currentTestFailed())
            return;
        QVERIFY2(c.starts > 30, QByteArray::number(c.starts).constData());
        QCOMPARE(c.oscillating, 0);
    }
    void grinderEveryFrame() {
        Counts c;
        checkEveryFrame("grinder-bore-205.k528", "grinder-205", c);
        qInfo("%d starts, %d frames inside an oscillation", c.starts, c.oscillating);
        if (QTest::currentTestFailed())
            return;
        QVERIFY2(c.starts > 20, QByteArray::number(c.starts).constData());
        // N5..N10 of L5 run while Z oscillates (N4 G281 .. N10 G280).
        QCOMPARE(c.oscillating, 6);
    }
    // The rebuilt state before the third roughing pass of lathe-shaft.
    void stateBeforeAFrame() {
        const profile::MachineProfile prof = profile::builtin("training-lathe");
        const program::ParseResult parsed = program::parse(readSample("lathe-shaft.k528"));
        const program::Program* l2 = parsed.store.find(2);
        QVERIFY(l2);
        engine::PreviewOptions po;
        po.fromReferencePoint = true;
        const engine::StartSearch s =
            engine::findStartPoint(prof, parsed.store, 1, {2, l2->indexOfN(2), 3}, po);
        QCOMPARE(s.outcome, engine::StartSearch::Outcome::Found);
        const engine::StartPoint& p = s.point;
        QCOMPARE(p.mainProgram, 1);
        QCOMPARE(p.program, 2);
        QCOMPARE(p.frameNumber, 2);
        QCOMPARE(p.callers.size(), std::size_t{1});
        QCOMPARE(p.callers[0].program, 1);
        QVERIFY(p.modal.rapid); // N1 G0 X=R10 before it
        QCOMPARE(p.messageNumber, 1);
        QCOMPARE(p.mFunctions, (std::vector<int>{3, 8}));
        bool r10 = false;
        for (const auto& [n, v] : p.r)
            if (n == 10) {
                r10 = true;
                QCOMPARE(v, 34000); // Ø40 - 3 × 2
            }
        QVERIFY(r10);
        QCOMPARE(p.axes[0].currentDisc, 34000);
        QCOMPARE(p.axes[1].currentDisc, 2000);
        // A frame that does not exist that often is not reached.
        QCOMPARE(engine::findStartPoint(prof, parsed.store, 1, {2, l2->indexOfN(2), 6}, po).outcome,
                 engine::StartSearch::Outcome::NotReached);
    }
};

QTEST_GUILESS_MAIN(RunFrom)
#include "test_run_from.moc"
