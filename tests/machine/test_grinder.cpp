// grinder-205 (appendix Ж) as an operator runs it: drives on, home, the
// gauge cycle of L1 ending on the gauge's «size» signal, the dressing cycle
// with compensation, the wheel diameter bookkeeping, the manual cycles the
// PLC starts from the K923 keys.
#include "engine/interface_words.h"
#include "engine/rparams.h"
#include "rig/machine_rig.h"

using namespace k528;
using namespace k528::testrig;
namespace z = engine::z;

class TestGrinder : public QObject {
    Q_OBJECT
private slots:
    // The grinding cycle: touch, rough, finish, size — each move of X ends on
    // its signal from the gauge, the last one on «size».
    void gaugeCycleEndsOnSize() {
        MachineRig r("grinder-205");
        QVERIFY(r.drivesOn());
        QVERIFY(r.home());
        const machine::MachineView v0 = r.sim->view();
        QVERIFY(v0.hasGrinding && v0.ringPresent);
        QCOMPARE(v0.boreMm, 24.7);

        QVERIFY(r.start(1));
        // M3: the frame waits until the wheel and the work spindle are at speed.
        QVERIFY(r.until([&] { return r.c().state() == ProgramState::WaitingM; }, 1000));
        QVERIFY(r.until([&] { return r.work(2); }, 1000)); // «Разгон шпинделя круга»
        QCOMPARE(r.c().state(), ProgramState::WaitingM);
        QVERIFY(r.until([&] { return r.c().programView().frameNumber == 4; }, 30000));
        QVERIFY(r.rpm("wheel") > 23000);
        QVERIFY(r.sim->view().gaugeIn);

        // Follow the frames and note where X stood when each one ended.
        std::map<int, double> endX;
        std::map<int, double> boreAtEnd;
        int frame = 4;
        bool sawTouch = false, sawRough = false, sawFinish = false, sawSize = false;
        const bool done = r.until(
            [&] {
                const machine::MachineView v = r.sim->view();
                sawTouch = sawTouch || v.touch;
                sawRough = sawRough || v.rough;
                sawFinish = sawFinish || v.finish;
                sawSize = sawSize || v.size;
                const int n = r.c().programView().frameNumber;
                if (n != frame) {
                    endX[frame] = r.mm(X);
                    boreAtEnd[frame] = v.boreMm;
                    frame = n;
                }
                return n >= 8 || r.c().state() == ProgramState::Alarm;
            },
            120000);
        QVERIFY2(done, r.alarmList().c_str());
        QVERIFY2(r.alarms().empty(), r.alarmList().c_str());
        QVERIFY(sawTouch && sawRough && sawFinish && sawSize);
        // Each move ended well before its programmed target: on its signal.
        QVERIFY(endX[4] < 24.9 - 0.05); // G136 to X24.9: touch at the blank's 24.700
        QVERIFY(std::fabs(endX[4] - 24.7) < 0.01);
        QVERIFY(endX[5] < 25.1 - 0.05); // G137: rough allowance removed at 24.990
        QVERIFY(boreAtEnd[5] >= 24.990 && boreAtEnd[5] < 24.995);
        QVERIFY(endX[6] < 25.2 - 0.1); // G138: finish allowance removed at 24.998
        QVERIFY(boreAtEnd[6] >= 24.998 && boreAtEnd[6] < 25.0);
        QVERIFY(endX[7] < 25.2 - 0.1); // G139 ends on «size»
        QVERIFY(boreAtEnd[7] >= 25.0);
        QVERIFY(boreAtEnd[7] < 25.0008); // the spark-out does not overshoot the size
        // The positioner took the following error at the moment of the signal.
        QVERIFY(r.c().r(242) != 0);

        QVERIFY(r.runToEnd());
        QCOMPARE(r.c().state(), ProgramState::Ended);
        const machine::MachineView v = r.sim->view();
        QVERIFY(!v.gaugeIn);
        QVERIFY(v.boreMm >= 25.0 && v.boreMm < 25.0008);
        QVERIFY(v.wheelMm < 18.5); // the wheel wore while grinding
        const auto codes = r.sim->mCodes();
        QCOMPARE(codes, (std::vector<int>{3, 13, 8, 20, 21, 5, 9, 30}));
    }

    // Without the gauge (retracted) the moves run to their programmed
    // targets: the signals really come from the gauge.
    void withoutGaugeTheMovesRunToTheirTargets() {
        MachineRig r("grinder-205");
        QVERIFY(r.drivesOn());
        QVERIFY(r.home());
        r.load("%L7\nN1 G90 G0 M3 Z126\nN2 X24.4\nN3 G138 X24.5 FX3\nN4 M5 M30\n");
        QVERIFY(r.start(7));
        QVERIFY(r.runToEnd(60000));
        QCOMPARE(r.c().state(), ProgramState::Ended);
        QVERIFY(std::fabs(r.mm(X) - 24.5) < 0.006);
    }

    // Dressing (manual cycle 4, key K3): the wheel is trimmed by the diamond,
    // R207 follows, the PLC compensates the dressing (Z1007.0) so that R224
    // grows by R210 and X keeps naming the wheel's edge.
    void dressingCycleWithCompensation() {
        MachineRig r("grinder-205");
        QVERIFY(r.drivesOn());
        QVERIFY(r.home());
        r.c().selectMode(Mode::Manual);
        r.advance(50);
        const double wheel0 = r.sim->view().wheelMm;
        const std::int32_t r207 = r.c().r(engine::r::WheelCurrent);
        const std::int32_t r224 = r.c().r(engine::r::DressingSumX);
        const std::int32_t cut = r.c().r(engine::r::DressRoughX);
        QCOMPARE(cut, 20);
        // K3 on the K923: Z1300 bit of K3.
        r.c().words().setBit(engine::ZBit{1300, z::keyBit(3)}, true);
        r.advance(30);
        QVERIFY(!r.c().words().bit(engine::ZBit{1300, z::keyBit(3)})); // the PLC took the key
        QVERIFY(r.bit(z::cycleRunning(4)));
        QVERIFY(r.work(4));                      // «Идёт правка круга»
        QCOMPARE(r.c().r(engine::r::PlcBit), 0); // rough dressing
        QVERIFY(r.until([&] { return !r.bit(z::cycleRunning(4)); }, 120000));
        QVERIFY2(r.alarms().empty(), r.alarmList().c_str());
        const double wheel1 = r.sim->view().wheelMm;
        // The diamond takes what X really pushed past it: R210 within ДОПУСК ПОЗ.
        QVERIFY2(std::fabs((wheel0 - wheel1) - 0.020) < 0.006,
                 qPrintable(QString::number(wheel0 - wheel1, 'f', 6)));
        QCOMPARE(r.c().r(engine::r::WheelCurrent), r207 - cut);
        QCOMPARE(r.c().r(engine::r::DressingSumX), r224 + cut);
        QCOMPARE(r.sim->mCodes().back(), 2);
        const auto codes = r.sim->mCodes();
        QVERIFY(std::find(codes.begin(), codes.end(), 60) != codes.end());

        // K4: finish dressing, R150 = 1 through Z1001.8, R211 and M61.
        r.c().words().setBit(engine::ZBit{1300, z::keyBit(4)}, true);
        r.advance(30);
        QVERIFY(r.bit(z::cycleRunning(4)));
        QCOMPARE(r.c().r(engine::r::PlcBit), 1);
        QVERIFY(r.work(15));
        QVERIFY(r.until([&] { return !r.bit(z::cycleRunning(4)); }, 120000));
        QVERIFY(std::fabs((wheel1 - r.sim->view().wheelMm) - 0.005) < 0.006);
        QCOMPARE(r.c().r(engine::r::DressingSumX), r224 + cut + 5);
        const auto codes2 = r.sim->mCodes();
        QVERIFY(std::find(codes2.begin(), codes2.end(), 61) != codes2.end());
    }

    // After dressing, the next ring still comes out at size: the
    // compensation keeps the program's X on the wheel's edge.
    void sizeHoldsAfterDressingAndANewRing() {
        MachineRig r("grinder-205");
        QVERIFY(r.drivesOn());
        QVERIFY(r.home());
        QVERIFY(r.start(1));
        QVERIFY(r.runToEnd(120000));
        QCOMPARE(r.c().state(), ProgramState::Ended);
        // Dress (rough).
        r.c().selectMode(Mode::Manual);
        r.advance(50);
        r.c().words().setBit(engine::ZBit{1300, z::keyBit(3)}, true);
        r.advance(30);
        QVERIFY(r.until([&] { return !r.bit(z::cycleRunning(4)); }, 120000));
        // A new ring: once the work spindle stands, open the chuck (the ground
        // ring comes out), clamp a blank.
        QVERIFY(r.until([&] { return std::fabs(r.rpm("work")) < 1; }, 5000));
        r.push(Button::ChuckPedal);
        QVERIFY(r.until([&] { return r.sim->view().chuckOpen; }, 3000));
        QVERIFY(!r.sim->view().ringPresent);
        QVERIFY(r.work(1)); // «Загрузите кольцо»
        r.push(Button::ChuckPedal);
        QVERIFY(r.until([&] { return r.sim->view().chuckClamped; }, 3000));
        QVERIFY(r.sim->view().ringPresent);
        QCOMPARE(r.sim->view().boreMm, 24.7);
        r.advance(50);
        QVERIFY(r.start(1));
        QVERIFY(r.runToEnd(120000));
        QVERIFY2(r.c().state() == ProgramState::Ended, r.alarmList().c_str());
        QVERIFY(r.sim->view().boreMm >= 25.0 && r.sim->view().boreMm < 25.0008);
        QCOMPARE(r.sim->view().ringsGround, 2);
    }

    // The wheel below R205: «Необходима смена круга» Z2000.15, the work
    // message, the red LED; «Пуск» reaches the positioner, which blocks the
    // program with message 44 «D круга < Dmin» (appendix М); after a wheel
    // change and the acknowledgement, R207 = R204 and programs run again.
    void wheelChange() {
        MachineRig r("grinder-205", [](profile::MachineProfile& p) { p.r[207] = 13990; });
        QVERIFY(r.drivesOn());
        QVERIFY(r.home());
        r.advance(20);
        QVERIFY(r.bit(z::WheelChange));
        QVERIFY(r.bit(z::WheelBelowMin));
        QVERIFY(r.work(5));
        QVERIFY((r.c().words().word(z::RedLedsWord) >> z::keyBit(3)) & 1u);
        // The PLC lets «Пуск» through; the positioner refuses the program (44).
        QVERIFY(r.bit(z::StartEnable));
        QVERIFY(!r.start(1)); // false: it ended in an alarm
        QCOMPARE(r.c().state(), ProgramState::Alarm);
        QVERIFY2(r.hasAlarm(44), r.alarmList().c_str());
        QCOMPARE(r.c().framesExecuted(), std::int64_t(0));
        QVERIFY(std::fabs(r.sim->view().wheelMm - 13.99) < 1e-9);
        QVERIFY(r.sim->changeWheel());
        r.push(Button::Reset); // acknowledges 44
        QVERIFY2(!r.hasAlarm(44), r.alarmList().c_str());
        QCOMPARE(r.c().r(engine::r::WheelCurrent), 20000);
        QVERIFY(!r.bit(z::WheelChange));
        QVERIFY(r.bit(z::StartEnable));
        QVERIFY(!r.work(5));
        QVERIFY(r.start(1));
        QVERIFY(r.runToEnd(120000));
        QVERIFY2(r.c().state() == ProgramState::Ended, r.alarmList().c_str());
        QVERIFY2(r.sim->view().boreMm >= 25.0 && r.sim->view().boreMm < 25.0008,
                 qPrintable(QString::number(r.sim->view().boreMm, 'f', 6)));
    }

    // Manual cycle 1 from K1 (C143 = 11) returns to R220/R221.
    void cycleOneFromTheKey() {
        MachineRig r("grinder-205");
        QVERIFY(r.drivesOn());
        QVERIFY(r.home());
        r.c().selectMode(Mode::Manual);
        r.sim->selectHandwheel(machine::HandwheelAxis::Z);
        r.sim->selectHandwheelMultiplier(2);
        r.advance(30);
        r.sim->turnHandwheel(-100); // Z away from home
        r.advance(3000);
        QVERIFY(r.mm(Z) < 185.0);
        r.c().words().setBit(engine::ZBit{1300, z::keyBit(1)}, true);
        r.advance(30);
        QVERIFY(r.bit(z::cycleRunning(1)));
        QVERIFY(r.until([&] { return !r.bit(z::cycleRunning(1)); }, 60000));
        QVERIFY(std::fabs(r.mm(Z) - 190.0) < 0.005);
        QVERIFY(std::fabs(r.mm(X) - 0.0) < 0.005);
    }
};

QTEST_APPLESS_MAIN(TestGrinder)
#include "test_grinder.moc"
