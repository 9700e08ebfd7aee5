// Coordinates as 2.4: current = absolute − zero offset − dressing sum −
// correction − handwheel offset (R224..R231); G50..G53 leave one out in a
// program, the PLC's out-of-cycle bits outside one; Gx92 and «установка
// фактического значения» recompute the zero offset.
#include "rig/engine_rig.h"

#include <QtTest>

using namespace k528;
using namespace k528::testrig;
namespace z = k528::engine::z;

namespace {
// Components of Z: dressing 100, correction 200, zero offset 1000, DRF 50 (discretes).
void presetZ(EngineRig& r) {
    QVERIFY(r.ctl->setR(225, 100).ok());
    QVERIFY(r.ctl->setR(227, 200).ok());
    QVERIFY(r.ctl->setR(229, 1000).ok());
    QVERIFY(r.ctl->setR(231, 50).ok());
}
} // namespace

class TestCoordinates : public QObject {
    Q_OBJECT
private slots:
    void components() {
        EngineRig r("training-lathe", noHoming);
        presetZ(r);
        r.tick();
        QCOMPARE(r.current(Z), r.machine(Z) - 1350);
        QCOMPARE(r.ctl->r(235), std::int32_t(r.current(Z)));
        QCOMPARE(r.ctl->r(233), std::int32_t(r.machine(Z)));
        r.load("%L1\nN1 G1 Z-10 FZ2000\n");
        r.start(1);
        QVERIFY(r.runToEnd());
        QVERIFY(std::llabs(r.current(Z) + 10000) <= kRestTol);
        QVERIFY(std::llabs(r.machine(Z) - (-10000 + 1350)) <= kRestTol);
    }
    // Each of G50..G53 leaves its component out; G54 takes all back.
    void programExclusions() {
        const std::pair<int, std::int64_t> cases[] = {
            {50, 1300}, {51, 1150}, {52, 1250}, {53, 350}, {54, 1350}};
        for (const auto& [g, offset] : cases) {
            EngineRig r("training-lathe", noHoming);
            presetZ(r);
            r.load("%L1\nN1 G" + std::to_string(g) + " G1 Z-10 FZ2000\nN2 M0\n");
            r.start(1);
            QVERIFY(r.untilState(ProgramState::M0, 5000));
            QVERIFY2(std::llabs(r.machine(Z) - (-10000 + offset)) <= kRestTol,
                     qPrintable(QString::number(g)));
            QVERIFY(std::llabs(r.current(Z) + 10000) <= kRestTol); // shown in the same system
        }
    }
    // Outside a program the PLC's «Вне цикла отмена ...» bits do the same.
    void plcOutOfCycleBits() {
        EngineRig r("training-lathe", noHoming);
        presetZ(r);
        r.tick();
        const std::int64_t m = r.machine(Z);
        QCOMPARE(r.current(Z), m - 1350);
        r.w().setBit(z::outOfCycleNoZeroOffset(Z), true);
        r.tick();
        QCOMPARE(r.current(Z), m - 350);
        r.w().setBit(z::outOfCycleNoDrf(Z), true);
        r.tick();
        QCOMPARE(r.current(Z), m - 300);
        r.w().setBit(z::outOfCycleNoDressing(Z), true);
        r.w().setBit(z::outOfCycleNoCorrection(Z), true);
        r.tick();
        QCOMPARE(r.current(Z), m);
        // In a program the bits do not count: G54 (all active) rules.
        r.load("%L1\nN1 M0\n");
        r.start(1);
        QVERIFY(r.untilState(ProgramState::M0, 2000));
        QCOMPARE(r.current(Z), m - 1350);
    }
    // Gx92: the current coordinate becomes the value; the zero offset absorbs it.
    void setPosition() {
        EngineRig r("training-lathe", noHoming);
        presetZ(r);
        r.load("%L1\nN1 G1 Z-10 FZ2000\nN2 G292 Z5\nN3 G1 Z0\n");
        r.start(1);
        QVERIFY(r.until([&] { return r.ctl->programView().frameNumber == 3; }, 5000));
        const std::int64_t m = r.machine(Z);
        // Z-10 commanded becomes Z5: the zero offset moves by exactly 15 mm,
        // whatever rest error the servo had (the commanded point counts).
        QCOMPARE(r.ctl->r(229), 1000 - 15000);
        QVERIFY(std::llabs(r.current(Z) - 5000) <= kRestTol);
        QVERIFY(r.runToEnd());
        QVERIFY(std::llabs(r.current(Z)) <= kRestTol);
        QVERIFY(std::llabs(r.machine(Z) - (m - 5000)) <= kRestTol);
    }
    // The manual's «G192 X12.324» on the lathe's diameter axis: the zero
    // offset R228 moves by exactly the commanded difference (diameter
    // discretes), and X then counts from the new zero.
    void setPositionOnDiameter() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G0 X50\nN2 G192 X12.324\nN3 G0 X0\n");
        r.start(1);
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->state(), ProgramState::Ended);
        QCOMPARE(r.ctl->r(228), 50000 - 12324);
        QVERIFY(std::llabs(r.current(X)) <= kRestTol);
        QVERIFY(std::llabs(r.machine(X) - (50000 - 12324)) <= kRestTol);
    }
    // ПРЕДУСТАНОВКИ: «При установке текущего значения ... производится перерасчет «Смещения нуля»».
    void setCurrentValue() {
        EngineRig r("training-lathe");
        QVERIFY(r.home());
        QVERIFY(!r.ctl->setCurrentValue(X, 50000).ok()); // not in ПБТ
        QVERIFY(r.ctl->selectMode(Mode::SetActual).ok());
        const std::int64_t m = r.machine(X);
        const auto res = r.ctl->setCurrentValue(X, 50000);
        QVERIFY(res.ok());
        QCOMPARE(std::int64_t(r.ctl->r(228)), m - 50000);
        QCOMPARE(r.current(X), 50000);
        QCOMPARE(r.ctl->r(234), 50000);
        QCOMPARE(r.machine(X), m); // the axis did not move
        QCOMPARE(r.ctl->setCurrentValue(X, 1).refusal, k528::engine::Refusal::None);
    }
    // Presets from the K923 (R224..R231 are writable, R232..R262 are not).
    void panelWrites() {
        EngineRig r("training-lathe", noHoming);
        QVERIFY(r.ctl->setR(228, -5000).ok());
        QCOMPARE(r.ctl->r(256), -5000); // R256/R257: the panel's write
        QCOMPARE(r.ctl->r(257), (1 << 16) | 228);
        const auto ro = r.ctl->setR(232, 1);
        QCOMPARE(ro.refusal, k528::engine::Refusal::ReadOnly);
        QCOMPARE(ro.text(), std::string("R232 is read only (R232..R262)"));
        QCOMPARE(ro.text(true), std::string("R232 только для чтения (R232..R262)"));
        QCOMPARE(r.ctl->setR(300, 1).refusal, k528::engine::Refusal::NoSuchParameter);
        QCOMPARE(r.ctl->setR(1, 3000000000LL).refusal, k528::engine::Refusal::ValueOutOfRange);
        r.load("%L1\nN1 G4 X2\n");
        r.start(1);
        QCOMPARE(r.ctl->setR(1, 5).refusal, k528::engine::Refusal::ProgramActive);
    }
    // A refusal without an id of its own says its kind, from the same catalog.
    void aRefusalOfItsKindOnly() {
        k528::engine::OpResult off;
        off.refusal = k528::engine::Refusal::NotPowered;
        QCOMPARE(off.text(), std::string("the controller is off"));
        QCOMPARE(off.text(true), std::string("устройство выключено"));
        off.args = {"X"};
        QCOMPARE(off.text(), std::string("the controller is off X"));
        QVERIFY(k528::engine::OpResult::accepted().text(true).empty());
    }
};

QTEST_APPLESS_MAIN(TestCoordinates)
#include "test_coordinates.moc"
