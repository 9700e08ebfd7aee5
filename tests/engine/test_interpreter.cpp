// The interpreter: built-in M functions, subprograms and nesting, jumps,
// computations (46), run-time checks, messages, the bound on frames without
// motion — what a run's end cannot show. What a program does from its start
// to its end is the golden cases' (tests/programs/: end of text, M02 in a
// subprogram, M17, a subprogram's end, the nesting limit, the skip flag,
// arithmetic and 46, M00); a test here asserts the state on the way or a
// machine the golden cases cannot set up.
#include "engine/self_test.h"
#include "profile/english.h"
#include "rig/engine_rig.h"

#include <QtTest>

using namespace k528;
using namespace k528::testrig;
namespace z = k528::engine::z;

namespace {

// Puts the programs of `text` into the store as the panel's editor does (a
// program edited on the panel: no check before), starts L1 and runs it to its end.
bool runAsEdited(EngineRig& r, const char* text) {
    const program::ParseResult p = program::parse(text);
    program::ProgramStore* store = r.ctl->editablePrograms();
    if (!store)
        return false;
    for (const auto& prog : p.store.programs())
        store->insert(prog);
    r.ctl->programsEdited();
    r.start(1);
    return r.runToEnd();
}

} // namespace

class TestInterpreter : public QObject {
    Q_OBJECT
private slots:
    // «M00: останов в кадре. Выполнение УП приостанавливается до появления сигнала «ПУСК»»:
    // the wait itself (the run on after «Пуск»: golden case m00-waits-for-start).
    void m00WaitsForStart() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G1 Z-5 FZ2000 M0\nN2 Z-10\n");
        r.start(1);
        QVERIFY(r.untilState(ProgramState::M0, 5000));
        QVERIFY(std::llabs(r.current(Z) + 5000) <=
                kRestTol); // the motion of the frame is done first
        QVERIFY(r.bit(z::M0Stop));
        QVERIFY(!r.bit(z::ProgramRunning));
        r.advance(3000);
        QCOMPARE(r.ctl->state(), ProgramState::M0);
        r.m->pressStart();
        QVERIFY(r.runToEnd());
        QVERIFY(!r.bit(z::M0Stop));
    }
    // «M02: конец программы. По сигналу от ПЛК «ПУСК» УП будет выполняться с начала.»
    void m02EndsAndRestarts() {
        for (const char* end : {"M2", "M30"}) {
            EngineRig r("training-lathe", noHoming);
            r.load(std::string("%L1\nN1 R1=R1+1\nN2 ") + end + "\nN3 R1=100\n");
            r.start(1);
            QVERIFY(r.runToEnd());
            QCOMPARE(r.ctl->state(), ProgramState::Ended);
            QVERIFY(r.bit(z::EndOrReset));
            QCOMPARE(r.ctl->r(1), 1);
            r.m->pressStart();
            r.advance(200);
            QCOMPARE(r.ctl->state(), ProgramState::Ended);
            QCOMPARE(r.ctl->r(1), 2); // from the top again; N3 never runs
        }
    }
    // M02 inside a subprogram ends the program (golden case m02-in-subprogram);
    // «Пуск» then starts the main program from its top.
    void m02InSubprogram() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 R1=R1+1\nN2 L2\nN3 R3=1\n%L2\nN1 L3\n%L3\nN1 M2\n");
        r.start(1);
        QVERIFY(r.runToEnd());
        r.m->pressStart();
        r.advance(300);
        QCOMPARE(r.ctl->state(), ProgramState::Ended);
        QCOMPARE(r.ctl->r(1), 2);
        QCOMPARE(r.ctl->r(158), 0);
    }
    // «M17: конец подпрограммы ... УП продолжается с кадра, следующего за кадром с вызовом.»
    // (the return: golden case m17-subprogram-return); R158, R250, R253, R254
    // while the subprogram stands at M00.
    void subprogramReturn() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 R1=1\nN2 L2\nN3 R3=R1+R2\n%L2\nN1 R2=5\nN2 M0\nN3 M17\nN4 R2=99\n");
        r.start(1);
        QVERIFY(r.untilState(ProgramState::M0, 5000));
        QCOMPARE(r.ctl->r(158), 1); // R158: the nesting level
        QCOMPARE(r.ctl->r(253), 2); // R253: the executing (sub)program
        QCOMPARE(r.ctl->r(250), 1); // R250: the program of АВТОМАТ
        QCOMPARE(r.ctl->r(254), 2); // R254: N of the frame
        QCOMPARE(r.ctl->programView().nesting, 1);
    }
    // Nesting deeper than the limit: message 48 (golden case nesting-limit-48,
    // the profile's 8 levels); the limit is the profile's `nesting_limit`.
    void nestingLimit() {
        EngineRig q("training-lathe", [](auto& p) {
            noHoming(p);
            p.simulation.set("nesting_limit", "2");
        });
        q.load("%L1\nN1 L2\n%L2\nN1 L3\n%L3\nN1 R5=1\n");
        q.start(1);
        QVERIFY(q.runToEnd());
        QCOMPARE(q.ctl->state(), ProgramState::Ended);
        QCOMPARE(q.ctl->r(5), 1);
        q.load("%L3\nN1 L4\n%L4\nN1 R5=2\n");
        q.start(1);
        QVERIFY(q.runToEnd());
        QVERIFY(q.hasAlarm(48));
    }
    // 45 «L отсутствует»: starting or calling a program that does not exist.
    void missingProgram() {
        EngineRig r("training-lathe", noHoming);
        r.start(42);
        QCOMPARE(r.ctl->state(), ProgramState::Alarm);
        QVERIFY(r.hasAlarm(45));
        r.m->pressReset();
        r.advance(50);
        QVERIFY(!r.hasAlarm(45)); // «Сброс» acknowledges program errors
        r.load("%L1\nN1 R1=1\nN2 L77\n");
        r.start(1);
        QVERIFY(r.runToEnd());
        const auto* a = r.alarm(45);
        QVERIFY(a);
        QCOMPARE(a->program, 1);
        QCOMPARE(a->line, 3);
    }
    void jumps() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 R1=5\nN2 R2=R2+3\nN3 R1=R1-1\nN4 IF R1>0 GOTO 2\nN5 GOTO 7\nN6 R2=0\nN7 "
               "R3=1\n");
        r.start(1);
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->r(2), 15);
        QCOMPARE(r.ctl->r(3), 1);
        r.load("%L1\nN1 GOTO 99\n");
        r.start(1);
        QVERIFY(r.runToEnd());
        QVERIFY(r.hasAlarm(53)); // «Ошибка перехода»
    }
    // Frames without motion run within a tick, at most kFramesPerTick a tick:
    // an endless loop keeps running, the engine stays responsive.
    void loopWithoutMotionIsBounded() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 R1=R1+1\nN2 GOTO 1\n");
        r.start(1);
        const std::int64_t f0 = r.ctl->framesExecuted();
        r.advance(1000);
        const std::int64_t frames = r.ctl->framesExecuted() - f0;
        QCOMPARE(frames, 1000 * k528::engine::kFramesPerTick);
        QCOMPARE(r.ctl->state(), ProgramState::Running);
        r.m->pressReset();
        r.advance(20);
        QCOMPARE(r.ctl->state(), ProgramState::Idle);
    }
    // R arithmetic: int32, truncation toward zero, 46 on overflow (golden case
    // arithmetic-46); each other way to 46: /0, below -2^31, -2^31 / -1, a
    // product past int32.
    void arithmetic() {
        for (const char* bad : {"R1=R2/0", "R1=-2147483647\nR1=R1-2",
                                "R1=-2147483647\nR1=R1-1\nR2=-1\nR3=R1/R2", "R1=65536\nR2=R1*R1"}) {
            EngineRig q("training-lathe", noHoming);
            q.load(std::string("%L1\n") + bad + "\n");
            q.start(1);
            QVERIFY(q.runToEnd());
            QVERIFY2(q.hasAlarm(46), bad);
        }
        // A read-only parameter has no message of its own: 46.
        EngineRig q("training-lathe", noHoming);
        q.load("%L1\nR240=5\n");
        q.start(1);
        QVERIFY(q.runToEnd());
        QVERIFY(q.hasAlarm(46));
    }
    // Run-time versions of the validator's rules (a program edited on the panel).
    void runTimeChecks() {
        const std::pair<const char*, int> cases[] = {
            {"%L1\nN1 G5 Z-1\n", 47},
            {"%L1\nN1 G0 G1 Z-1\n", 47},
            {"%L1\nN1 X1 L2\n%L2\nM17\n", 34},
            {"%L1\nN1 Z1 L2\n%L2\nM17\n", 50},
            {"%L1\nN1 X1 M17\n", 35},
            {"%L1\nN1 G4 Z1\n", 63},
            {"%L1\nN1 G4 X1 L2\n%L2\nM17\n", 64},
            {"%L1\nN1 M30 L2\n%L2\nM17\n", 58},
            {"%L1\nN1 M2 M17\n", 62},
            {"%L1\nN1 L2\n%L2\nN1 G1 Z-1 FZ100\n", 52},
        };
        for (const auto& [text, msg] : cases) {
            EngineRig r("training-lathe", noHoming);
            QVERIFY(runAsEdited(r, text));
            QVERIFY2(r.hasAlarm(msg),
                     qPrintable(QString(text).replace('\n', '|') + " " + alarmList(r)));
        }
    }
    // 54 «Дублирование номеров кадров» (a program edited on the panel), at its start or call.
    void duplicateFrameNumbers() {
        const std::pair<const char*, int> cases[] = {{"%L1\nN1 R1=1\nN2 R1=2\nN2 R1=3\n", 4},
                                                     {"%L1\nN1 L2\n%L2\nN5 R1=1\nN5 M17\n", 5}};
        for (const auto& [text, line] : cases) {
            EngineRig r("training-lathe", noHoming);
            QVERIFY(runAsEdited(r, text));
            QVERIFY(r.hasAlarm(54));
            QCOMPARE(r.alarm(54)->line, line);
            QCOMPARE(r.ctl->r(1), 0);
        }
    }
    // 43/44: the wheel diameter R207 outside R205..R206 blocks the program,
    // not the manual cycles (Z2005.11/.12 show it).
    void wheelDiameter() {
        EngineRig r("grinder-205", noHoming);
        QVERIFY(r.ctl->setR(207, 21000).ok()); // > R206 = 20.500
        r.load("%L1\nN1 R1=1\n%L11\nN1 R2=1\n");
        r.start(1);
        QVERIFY(r.hasAlarm(43));
        QCOMPARE(r.ctl->r(1), 0);
        QVERIFY(r.bit(z::WheelAboveMax));
        r.m->pressReset();
        r.advance(50);
        QVERIFY(r.ctl->selectMode(Mode::Manual).ok());
        r.m->startCycle(1); // C143 = L11
        r.advance(100);
        QCOMPARE(r.ctl->r(2), 1);
        QVERIFY(r.ctl->setR(207, 13000).ok()); // < R205 = 14.000
        r.tick();
        QVERIFY(r.bit(z::WheelBelowMin));
        QVERIFY(r.bit(z::WheelChange));
        r.start(1);
        QVERIFY(r.hasAlarm(44));
    }
    // «#: номер технологического сообщения ... остается на экране до кадра с новым номером».
    void technologicalMessage() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 #2 G4 X0.1\nN2 R1=2\nN3 G4 X0.1\nN4 M0\nN5 #5 "
               "M0\n%MESSAGES\n#2=ТОРЦОВКА\n#5=ОТВОД\n");
        r.start(1);
        QVERIFY(r.untilState(ProgramState::M0, 2000));
        QCOMPARE(r.ctl->programView().messageNumber, 2);
        QCOMPARE(QString::fromStdString(r.ctl->programView().messageText), QString("ТОРЦОВКА"));
        r.m->pressStart();
        r.advance(5);
        QVERIFY(r.untilState(ProgramState::M0, 2000));
        QCOMPARE(QString::fromStdString(r.ctl->programView().messageText), QString("ОТВОД"));
    }
    // The view says where the message's text comes from: the machine file's
    // message (whose English the file gives) or a program file's own text,
    // even one that reads as the machine's; a number without text has none.
    void technologicalMessageOrigin() {
        EngineRig r("training-lathe", noHoming);
        // The lathe's file: #1=ПОДВОД (APPROACH), #2=ТОРЦОВКА (FACING).
        r.load("%L1\nN1 #1 M0\nN2 #2 M0\nN3 #77 M0\n%MESSAGES\n#2=ТОРЦОВКА\n");
        r.start(1);
        using engine::MessageOrigin;
        struct Shown {
            int number;
            MessageOrigin origin;
            const char* ru;
            const char* en;
        };
        for (const Shown& want : {Shown{1, MessageOrigin::MachineFile, "ПОДВОД", "APPROACH"},
                                  Shown{2, MessageOrigin::Program, "ТОРЦОВКА", "ТОРЦОВКА"},
                                  Shown{77, MessageOrigin::None, "", ""}}) {
            QVERIFY(r.untilState(ProgramState::M0, 2000));
            const engine::ProgramView v = r.ctl->programView();
            QCOMPARE(v.messageNumber, want.number);
            QCOMPARE(v.messageOrigin, want.origin);
            QCOMPARE(engine::programMessageText(v, r.prof, false), std::string(want.ru));
            QCOMPARE(engine::programMessageText(v, r.prof, true), std::string(want.en));
            r.m->pressStart();
            r.advance(5);
        }
        // The memory kept as the machine's: an English stays with its own
        // Russian only, never with another text loaded over it.
        QVERIFY(r.runToEnd(2000));
        program::ProgramStore* store = r.ctl->editablePrograms();
        QVERIFY(store);
        store->messages.set(5, "ОТХОД");
        store->messages.set(9, "ПРОВЕРКА");
        const profile::MachineProfile kept =
            engine::memoryProfile(r.prof, r.ctl->c(), r.ctl->rValues(), r.ctl->programs());
        QCOMPARE(profile::messageText(kept, 1, true), std::string("APPROACH"));
        QCOMPARE(profile::messageText(kept, 2, true), std::string("FACING"));
        QCOMPARE(profile::messageText(kept, 5, true), std::string("ОТХОД"));
        QCOMPARE(profile::messageText(kept, 9, true), std::string("ПРОВЕРКА"));
        QVERIFY(!kept.simulation.has(profile::englishKey("#5")));
    }
    // «Сброс» aborts without continuation; modal defaults return (G01, G54, G55, G90).
    void resetRestoresDefaults() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G91 G0 G53\nN2 G256 M0\n");
        r.start(1);
        QVERIFY(r.untilState(ProgramState::M0, 2000));
        QVERIFY(r.ctl->modal().incremental);
        QVERIFY(r.ctl->modal().rapid);
        QCOMPARE(r.ctl->modal().components, 53);
        QCOMPARE(r.ctl->modal().noOverrideAxis, 1);
        r.m->pressReset();
        r.advance(30);
        QCOMPARE(r.ctl->state(), ProgramState::Idle);
        QVERIFY(r.bit(z::EndOrReset));
        QVERIFY(!r.ctl->modal().incremental);
        QVERIFY(!r.ctl->modal().rapid);
        QCOMPARE(r.ctl->modal().components, 54);
        QCOMPARE(r.ctl->modal().noOverrideAxis, -1);
        r.m->pressStart(); // no continuation: starts from the top
        QVERIFY(r.untilState(ProgramState::M0, 2000));
        QCOMPARE(r.ctl->programView().frameNumber, 2);
    }
};

QTEST_APPLESS_MAIN(TestInterpreter)
#include "test_interpreter.moc"
