// The debugger's gate (engine/debug_gate.h): a breakpoint stops the program
// before its frame with the frame pointer on it, «Пуск» runs that frame;
// single frame executes one frame per «Пуск»; run to a line stops once; the
// call stack names program, frame and the R158 level; skipped frames are
// never stops; R-parameters can be set while the gate holds the program.
#include "engine/debug_gate.h"
#include "rig/engine_rig.h"

#include <QtTest>

using namespace k528;
using namespace k528::testrig;
namespace z = k528::engine::z;
using k528::engine::DebugGate;

namespace {

// «Пуск» with a fresh edge (the previous press is over).
void pressStart(EngineRig& r) {
    r.until([&] { return !r.bit(z::Start); }, 1000);
    r.m->pressStart();
}

bool untilHeld(EngineRig& r, std::int64_t maxMs = 10000) {
    return r.until(
        [&] {
            const ProgramState s = r.ctl->state();
            return s == ProgramState::Interrupted || s == ProgramState::Ended ||
                   s == ProgramState::Alarm;
        },
        maxMs);
}

} // namespace

class TestDebugGate : public QObject {
    Q_OBJECT
private slots:
    void breakpointStopsBeforeItsFrame() {
        EngineRig r("training-lathe", noHoming);
        DebugGate gate;
        r.ctl->setDebugGate(&gate);
        // Lines: 1 %L1, 2 N1, 3 N2, 4 N3, 5 N4.
        r.load("%L1\nN1 R1=5\nN2 R2=6\nN3 R3=7\nN4 M30\n");
        gate.addBreakpoint(1, 3);
        r.start(1);
        QVERIFY(untilHeld(r));
        QCOMPARE(r.ctl->state(), ProgramState::Interrupted);
        QVERIFY(gate.holding());
        QCOMPARE(r.ctl->r(1), 5);
        QCOMPARE(r.ctl->r(2), 0); // N2 has not executed
        const auto v = r.ctl->programView();
        QCOMPARE(v.program, 1);
        QCOMPARE(v.frameIndex, 1);
        QCOMPARE(v.frameNumber, 2);
        QCOMPARE(v.line, 3);
        QCOMPARE(r.ctl->r(254), 2); // R254: the frame held
        QCOMPARE(v.framesExecuted, std::int64_t{1});
        QVERIFY(gate.lastStop().has_value());
        QCOMPARE(gate.lastStop()->reason, DebugGate::Reason::Breakpoint);
        QCOMPARE(gate.lastStop()->line, 3);
        // Held: the engine lets the operator set an R-parameter.
        QVERIFY(r.ctl->setR(10, 42).ok());
        r.advance(200);
        QCOMPARE(r.ctl->state(), ProgramState::Interrupted); // waits for «Пуск»
        pressStart(r);
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->state(), ProgramState::Ended);
        QCOMPARE(r.ctl->r(2), 6);
        QCOMPARE(r.ctl->r(3), 7);
        QCOMPARE(r.ctl->r(10), 42);
        QCOMPARE(gate.stops(), std::int64_t{1});
    }

    void setRRefusedWhileExecuting() {
        EngineRig r("training-lathe", noHoming);
        DebugGate gate;
        r.ctl->setDebugGate(&gate);
        r.load("%L1\nN1 G1 Z-20 FZ500\nN2 M30\n");
        r.start(1);
        QCOMPARE(r.ctl->state(), ProgramState::Running);
        QVERIFY(!r.ctl->setR(10, 1).ok());
    }

    void breakpointInASubprogramAndTheCallStack() {
        EngineRig r("training-lathe", noHoming);
        DebugGate gate;
        r.ctl->setDebugGate(&gate);
        // Lines: 1 %L1, 2 N1, 3 N2 L5, 4 N3, 5 N4, 6 %L5, 7 N1, 8 N2.
        r.load("%L1\nN1 R1=1\nN2 L5\nN3 R3=1\nN4 M30\n%L5\nN1 R2=2\nN2 M17\n");
        gate.addBreakpoint(5, 7);
        r.start(1);
        QVERIFY(untilHeld(r));
        QCOMPARE(r.ctl->state(), ProgramState::Interrupted);
        const auto v = r.ctl->programView();
        QCOMPARE(v.program, 5);
        QCOMPARE(v.mainProgram, 1);
        QCOMPARE(v.frameNumber, 1);
        QCOMPARE(v.line, 7);
        QCOMPARE(v.nesting, 1);
        QCOMPARE(r.ctl->r(158), 1);
        QCOMPARE(r.ctl->r(2), 0);
        const auto stack = k528::engine::callStack(*r.ctl);
        QCOMPARE(int(stack.size()), 2);
        QCOMPARE(stack[0].level, 0);
        QCOMPARE(stack[0].program, 1);
        QCOMPARE(stack[0].frameNumber, 2); // N2 L5 called
        QCOMPARE(stack[0].line, 3);
        QCOMPARE(stack[1].level, 1);
        QCOMPARE(stack[1].program, 5);
        QCOMPARE(stack[1].frameNumber, 1);
        QCOMPARE(stack[1].line, 7);
        pressStart(r);
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->state(), ProgramState::Ended);
        QCOMPARE(r.ctl->r(2), 2);
        QCOMPARE(r.ctl->r(3), 1);
        QVERIFY(k528::engine::callStack(*r.ctl).empty());
    }

    void singleFrameStepsOneFramePerStart() {
        EngineRig r("training-lathe", noHoming);
        DebugGate gate;
        gate.setSingleFrame(true);
        r.ctl->setDebugGate(&gate);
        r.load("%L1\nN1 G1 Z-5 FZ2000\nN2 R1=1\n/N3 R1=9\nN4 Z-10\nN5 M30\n");
        r.start(1);
        // «Пуск» of the start ran N1 (its motion is over), held before N2.
        QVERIFY(untilHeld(r));
        QCOMPARE(r.ctl->state(), ProgramState::Interrupted);
        QCOMPARE(r.ctl->framesExecuted(), std::int64_t{1});
        QCOMPARE(r.ctl->programView().frameNumber, 2);
        QVERIFY(std::llabs(r.current(Z) + 5000) <= kRestTol);
        pressStart(r);
        QVERIFY(r.until([&] { return r.ctl->framesExecuted() == 2; }, 2000));
        QVERIFY(untilHeld(r));
        QCOMPARE(r.ctl->state(), ProgramState::Interrupted);
        QCOMPARE(r.ctl->r(1), 1);
        QCOMPARE(r.ctl->programView().frameNumber, 4); // the skipped N3 is no stop
        QCOMPARE(r.ctl->framesExecuted(), std::int64_t{2});
        pressStart(r);
        QVERIFY(r.until([&] { return r.ctl->framesExecuted() == 3; }, 2000));
        QVERIFY(untilHeld(r));
        QCOMPARE(r.ctl->state(), ProgramState::Interrupted);
        QCOMPARE(r.ctl->programView().frameNumber, 5);
        QVERIFY(std::llabs(r.current(Z) + 10000) <= kRestTol);
        pressStart(r);
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->state(), ProgramState::Ended);
        QCOMPARE(r.ctl->framesExecuted(), std::int64_t{4});
        QCOMPARE(gate.stops(), std::int64_t{3});
        QCOMPARE(gate.lastStop()->reason, DebugGate::Reason::SingleFrame);
    }

    void runToStopsOnceABreakpointEveryTime() {
        // Lines: 1 %L1, 2 N1, 3 N2, 4 N3 (the loop's test), 5 N4.
        const std::string loop = "%L1\nN1 R1=3\nN2 R1=R1-1\nN3 IF R1>0 GOTO 2\nN4 M30\n";
        {
            EngineRig r("training-lathe", noHoming);
            DebugGate gate;
            r.ctl->setDebugGate(&gate);
            r.load(loop);
            gate.runTo(1, 4);
            r.start(1);
            QVERIFY(untilHeld(r));
            QCOMPARE(r.ctl->state(), ProgramState::Interrupted);
            QCOMPARE(gate.lastStop()->reason, DebugGate::Reason::RunTo);
            QCOMPARE(r.ctl->r(1), 2);
            QVERIFY(!gate.runToTarget().has_value());
            pressStart(r);
            QVERIFY(r.runToEnd());
            QCOMPARE(r.ctl->state(), ProgramState::Ended);
            QCOMPARE(gate.stops(), std::int64_t{1});
        }
        {
            EngineRig r("training-lathe", noHoming);
            DebugGate gate;
            r.ctl->setDebugGate(&gate);
            r.load(loop);
            gate.addBreakpoint(1, 4);
            r.start(1);
            std::vector<int> seen;
            for (;;) {
                QVERIFY(untilHeld(r));
                if (r.ctl->state() != ProgramState::Interrupted)
                    break;
                seen.push_back(r.ctl->r(1));
                const std::int64_t before = gate.stops();
                pressStart(r);
                // Frames without motion: the next stop may come in the same tick.
                QVERIFY(r.until(
                    [&] { return gate.stops() > before || r.ctl->state() != ProgramState::Interrupted; },
                    2000));
            }
            QCOMPARE(r.ctl->state(), ProgramState::Ended);
            QCOMPARE(seen, (std::vector<int>{2, 1, 0}));
        }
    }

    void resetWhileHeldThenStartStopsAgain() {
        EngineRig r("training-lathe", noHoming);
        DebugGate gate;
        r.ctl->setDebugGate(&gate);
        r.load("%L1\nN1 R1=R1+1\nN2 R2=6\nN3 M30\n");
        gate.addBreakpoint(1, 3);
        r.start(1);
        QVERIFY(untilHeld(r));
        QCOMPARE(r.ctl->state(), ProgramState::Interrupted);
        r.m->pressReset();
        QVERIFY(r.untilState(ProgramState::Idle, 1000));
        QVERIFY(k528::engine::callStack(*r.ctl).empty());
        r.start(1);
        QVERIFY(untilHeld(r));
        QCOMPARE(r.ctl->state(), ProgramState::Interrupted);
        QCOMPARE(r.ctl->r(1), 2);
        QCOMPARE(r.ctl->programView().frameNumber, 2);
        QCOMPARE(gate.stops(), std::int64_t{2});
    }

    void detachedGateChangesNothing() {
        const std::string text = "%L1\nN1 R1=1\nN2 G1 Z-5 FZ2000\nN3 R2=R1+1\nN4 M30\n";
        std::int64_t frames[2] = {0, 0}, ms[2] = {0, 0};
        for (int withGate = 0; withGate < 2; ++withGate) {
            EngineRig r("training-lathe", noHoming);
            DebugGate gate; // no breakpoint, no single frame
            if (withGate)
                r.ctl->setDebugGate(&gate);
            r.load(text);
            r.start(1);
            QVERIFY(r.runToEnd());
            frames[withGate] = r.ctl->framesExecuted();
            ms[withGate] = r.ctl->programEndMs() - r.ctl->programStartMs();
            QCOMPARE(gate.stops(), std::int64_t{0});
        }
        QCOMPARE(frames[0], frames[1]);
        QCOMPARE(ms[0], ms[1]);
    }
};

QTEST_APPLESS_MAIN(TestDebugGate)
#include "test_debug_gate.moc"
