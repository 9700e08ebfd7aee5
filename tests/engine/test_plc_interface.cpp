// The PLC <-> positioner words of appendix И as the engine writes and reads
// them: the M hand-over on Z2001 with the acknowledgement Z1000.11, the
// state bits of Z2000/Z2001/Z2005..Z2008, the PLC's messages (latching and
// acknowledgement), R150, override from the PLC.
#include "rig/engine_rig.h"

#include <QtTest>

using namespace k528;
using namespace k528::testrig;
namespace z = k528::engine::z;

class TestPlcInterface : public QObject {
    Q_OBJECT
private slots:
    // Every M goes to the PLC with the change strobe; the frame waits for the
    // acknowledgement, then moves.
    void mHandshake() {
        EngineRig r("training-lathe", noHoming);
        r.m->setAutoAcknowledgeM(false);
        r.load("%L1\nN1 M3 M8 G1 Z-5 FZ2000\nN2 M30\n");
        r.start(1);
        // Code first, the strobe >= 20 ms later (GOST T2).
        QCOMPARE(r.w().field(z::MCodeWord, z::MCodeFirst, z::MCodeWidth), 3u);
        QVERIFY(!r.bit(z::MStrobe));
        QVERIFY(r.until([&] { return r.bit(z::MStrobe); }, 100));
        QVERIFY(r.ctl->timeMs() - r.ctl->programStartMs() >= 20);
        QCOMPARE(r.ctl->state(), ProgramState::WaitingM);
        QCOMPARE(r.ctl->programView().mCode, 3);
        // No acknowledgement: the frame waits, no motion.
        r.advance(2000);
        QVERIFY(r.bit(z::MStrobe));
        QVERIFY(std::llabs(r.current(Z)) <= kRestTol);
        r.m->acknowledgeM();
        QVERIFY(r.until([&] { return !r.bit(z::MStrobe); }, 10));
        QVERIFY(r.until([&] { return r.bit(z::MStrobe); }, 200));
        QCOMPARE(r.w().field(z::MCodeWord, z::MCodeFirst, z::MCodeWidth), 8u);
        QVERIFY(std::llabs(r.current(Z)) <= kRestTol);
        r.m->acknowledgeM();
        QVERIFY(r.until([&] { return r.z().moving; }, 200));
        QVERIFY(r.until([&] { return r.bit(z::MStrobe); }, 5000)); // M30 of N2
        QCOMPARE(r.w().field(z::MCodeWord, z::MCodeFirst, z::MCodeWidth), 30u);
        QVERIFY(std::llabs(r.current(Z) + 5000) <= kRestTol);
        r.m->acknowledgeM();
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->state(), ProgramState::Ended);
        QCOMPARE(r.m->mLog(), (std::vector<int>{3, 8, 30}));
        QCOMPARE(r.w().field(z::MCodeWord, z::MCodeFirst, z::MCodeWidth),
                 30u); // stays until the next M
    }
    // The mode bits Z2000.1..7, «Готовность» Z2000.0, and the program state bits.
    void stateBits() {
        EngineRig r("training-lathe", noHoming);
        QVERIFY(r.bit(z::Ready));
        QVERIFY(r.bit(z::ModeManual));
        const ZBit modes[] = {z::ModeAuto,       z::ModeManual,      z::ModeReference,
                              z::ModeSetActual,  z::ModeMachineData, z::ModeProgramInput,
                              z::ModeDataControl};
        for (int f = 1; f <= 7; ++f) {
            QVERIFY(r.ctl->selectMode(static_cast<Mode>(f)).ok());
            r.tick();
            for (int k = 1; k <= 7; ++k)
                QCOMPARE(r.bit(modes[k - 1]), k == f);
        }
        r.load("%L1\nN1 G1 Z-10 FZ1000\nN2 G4 X1\n");
        r.start(1);
        QVERIFY(r.bit(z::ModeAuto));
        QVERIFY(r.bit(z::ProgramRunning));
        QVERIFY(r.bit(z::positionNotReached(Z)));
        QVERIFY(!r.bit(z::positionNotReached(X)));
        QVERIFY(r.bit(z::loopClosed(Z)) && r.bit(z::regulatorEnabled(Z)));
        QVERIFY(r.bit(z::referenced(Z))); // АВТ.БЕЗ ПБТ: «заблокирована параметром станка»
        QVERIFY(!r.bit(z::rapidMotion(Z)));
        QVERIFY(r.until([&] { return r.bit(z::DwellRunning); }, 5000));
        QVERIFY(!r.bit(z::positionNotReached(Z)));
        QVERIFY(r.runToEnd());
        QVERIFY(!r.bit(z::ProgramRunning));
        QVERIFY(r.bit(z::EndOrReset));
        r.load("%L2\nN1 G0 Z-30\n");
        r.start(2);
        r.advance(100);
        QVERIFY(r.bit(z::rapidMotion(Z)));
    }
    // Z2006/Z2008 mirror the fast inputs; Z2005.1/.2 show manual commands.
    void axisWords() {
        EngineRig r("training-lathe", noHoming);
        // Training lathe: X1 drive ready (level 1), X2/X3 limits (0 = pressed), X4 cam.
        const std::uint16_t fx = r.w().word(2006);
        QCOMPARE(fx & 1u, 1u);     // drive ready
        QCOMPARE(fx & 0x6u, 0x6u); // limit switches closed (not pressed)
        QCOMPARE(fx & 0xF0u, 0u);  // inputs 5..8 unused
        QCOMPARE(r.w().word(2008) & 1u, 1u);
        r.m->setJog(X, -1);
        r.advance(50);
        QVERIFY(r.bit(z::commandMinus(X)));
        QVERIFY(!r.bit(z::commandPlus(X)));
        r.m->setJog(X, 0);
        r.advance(50);
        QVERIFY(!r.bit(z::commandMinus(X)));
        r.m->setDriveReady(Z, false);
        r.advance(5);
        QCOMPARE(r.w().word(2008) & 1u, 0u);
        QVERIFY(r.hasAlarm(32)); // «Нет готовности привода оси Z»
        QVERIFY(r.bit(z::loopError(Z)));
    }
    // Machine alarms (Z1900/Z1901) stay until acknowledged; Z1000.7 erases
    // the bits that are 0 at that moment; work messages show while present;
    // system messages (Z1307) stay until ESC with C125.
    void plcMessages() {
        EngineRig r("training-lathe", noHoming);
        r.m->setPlcAlarm(3, true);
        r.m->setPlcAlarm(18, true);
        r.m->setPlcWork(2, true);
        r.m->setPlcSystem(1, true);
        r.tick();
        QCOMPARE(r.ctl->plcMessages().alarms, (1u << 2) | (1u << 17));
        QCOMPARE(r.ctl->plcMessages().work, 1u << 1);
        QCOMPARE(r.ctl->plcMessages().system, std::uint16_t(1));
        QVERIFY(r.hasAlarm(55)); // the positioner's «Отказ модулей ввода/вывода в ПЛК»
        r.m->setPlcAlarm(3, false);
        r.m->setPlcWork(2, false);
        r.m->setPlcSystem(1, false);
        r.tick();
        QCOMPARE(r.ctl->plcMessages().alarms, (1u << 2) | (1u << 17)); // remembered
        QCOMPARE(r.ctl->plcMessages().work, 0u);                       // gone with its bit
        QCOMPARE(r.ctl->plcMessages().system, std::uint16_t(1));
        r.m->pressAcknowledge();
        r.tick();
        QCOMPARE(r.ctl->plcMessages().alarms, 1u << 17);         // bit 3 erased, bit 18 still 1
        QCOMPARE(r.ctl->plcMessages().system, std::uint16_t(1)); // not by Z1000.7
        r.ctl->escape();                                         // C125 = 1 on the training lathe
        QCOMPARE(r.ctl->plcMessages().system, std::uint16_t(0));
        // Z1000.7 held at 1: an alarm vanishes as soon as its bit drops.
        r.w().setBit(z::AckFaults, true);
        r.m->setPlcAlarm(18, false);
        r.tick();
        QCOMPARE(r.ctl->plcMessages().alarms, 0u);
    }
    void escWithoutC124DoesNotAcknowledge() {
        EngineRig r("training-lathe", [](auto& p) {
            noHoming(p);
            p.setC(124, 0);
        });
        r.m->setPlcAlarm(1, true);
        r.tick();
        r.m->setPlcAlarm(1, false);
        r.tick();
        r.ctl->escape();
        QCOMPARE(r.ctl->plcMessages().alarms, 1u);
    }
    void r150AndPlcOverride() {
        EngineRig r("training-lathe", noHoming);
        r.m->setR150Bit(true);
        r.tick();
        QCOMPARE(r.ctl->r(150), 1);
        r.m->setR150Bit(false);
        r.tick();
        QCOMPARE(r.ctl->r(150), 0);
        QCOMPARE(r.ctl->r(249), 100);
        QVERIFY(r.ctl->pressOverrideKey(3).ok()); // C141 = 7: 50 %
        r.tick();
        QCOMPARE(r.ctl->r(249), 50);
        r.m->setOverrideCode(4); // PLC: 10 %, has priority
        r.tick();
        QCOMPARE(r.ctl->r(249), 10);
        QVERIFY(r.ctl->programView().overrideFromPlc);
        r.m->setOverrideCode(std::nullopt);
        r.tick();
        QCOMPARE(r.ctl->r(249), 50);
        QVERIFY(!r.ctl->pressOverrideKey(5).ok());
    }
    // Z2005.8 «Исходное положение» (R220/R221) and Z2005.10 «Зона безопасности» (R151..R154).
    void initialPositionAndSafetyZone() {
        EngineRig r("training-lathe");
        QVERIFY(r.home());
        QVERIFY(r.ctl->setR(220, 270000).ok()); // the X reference point
        QVERIFY(r.ctl->setR(151, 260000).ok());
        QVERIFY(r.ctl->setR(152, 280000).ok());
        r.advance(5);
        QVERIFY(r.bit(z::atInitialPosition(X)));
        QVERIFY(r.bit(z::safetyZone(X)));
        QVERIFY(!r.bit(z::safetyZone(Z)));
        r.load("%L1\nN1 G1 X250 FX2000\n");
        r.start(1);
        QVERIFY(r.runToEnd());
        QVERIFY(!r.bit(z::atInitialPosition(X)));
        QVERIFY(!r.bit(z::safetyZone(X)));
    }
};

QTEST_APPLESS_MAIN(TestPlcInterface)
#include "test_plc_interface.moc"
