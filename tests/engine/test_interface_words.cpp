// The interface map against appendix И, written out from the manual.
#include <QtTest>

#include "engine/interface_words.h"

#include <vector>

using namespace k528::engine;
using k528::axis::AxisId;

namespace {
bool same(ZBit a, int word, int bit) { return a.word == word && a.bit == bit; }
} // namespace

class TestInterfaceWords : public QObject {
    Q_OBJECT
private slots:
    void generalControlBits() {
        QVERIFY(same(z::EmergencyStopOk, 1000, 0));
        QVERIFY(same(z::FeedEnable, 1000, 1));
        QVERIFY(same(z::StartEnable, 1000, 2));
        QVERIFY(same(z::Start, 1000, 3));
        QVERIFY(same(z::Stop, 1000, 4));
        QVERIFY(same(z::Reset, 1000, 5));
        QVERIFY(same(z::DataHold, 1000, 6));
        QVERIFY(same(z::AckFaults, 1000, 7));
        QVERIFY(same(z::startCycle(1), 1001, 0));
        QVERIFY(same(z::startCycle(8), 1001, 7));
        QVERIFY(same(z::R150Bit, 1001, 8));
        QVERIFY(same(z::OverrideFromPlc, 1001, 11));
    }
    void axisControlBits() {
        QVERIFY(same(z::loopOff(AxisId::X), 1005, 0));
        QVERIFY(same(z::regulatorEnable(AxisId::Z), 1008, 1));
        QVERIFY(same(z::decelCam(AxisId::Z), 1008, 3));
        QVERIFY(same(z::jogMinus(AxisId::X), 1005, 8));
        QVERIFY(same(z::handwheelOn(AxisId::X, 2), 1005, 11));
        QVERIFY(same(z::handwheelMult(AxisId::Z, 1), 1008, 12));
        QVERIFY(same(z::handwheelDrf(AxisId::Z, 2), 1008, 15));
        QVERIFY(same(z::adjustMinus(AxisId::Z), 1009, 2));
        QVERIFY(same(z::outOfCycleNoZeroOffset(AxisId::X), 1006, 7));
        QVERIFY(same(z::eraseSignal(AxisId::X, 1), 1006, 12)); // G136
        QVERIFY(same(z::eraseSignal(AxisId::Z, 4), 1009, 15)); // G239
        QVERIFY(same(z::finishDressComp(AxisId::Z), 1010, 1));
    }
    void stateBits() {
        QVERIFY(same(z::ProgramRunning, 2000, 8));
        QVERIFY(same(z::M0Stop, 2000, 12));
        QVERIFY(same(z::OverrideZero, 2000, 14));
        QVERIFY(same(z::WheelChange, 2000, 15));
        QVERIFY(same(z::MStrobe, 2001, 7));
        QVERIFY(same(z::cycleRunning(1), 2001, 8));
        QVERIFY(same(z::cycleRunning(8), 2001, 15));
        QVERIFY(same(z::positionNotReached(AxisId::X), 2005, 3));
        QVERIFY(same(z::referenced(AxisId::Z), 2007, 4));
        QVERIFY(same(z::handwheelFrameActive(AxisId::Z), 2007, 9));
        QVERIFY(same(z::fastInputState(AxisId::X, 8), 2006, 7));
        QVERIFY(same(z::fastInputState(AxisId::Z, 1), 2008, 0));
    }
    // The engine's by-index door to an axis' words is the same word as its address.
    void axisWordsByIndex() {
        InterfaceWords w;
        std::uint16_t v = 1;
        for (AxisId a : {AxisId::X, AxisId::Z}) {
            const int i = static_cast<int>(a);
            for (int k = 0; k < 3; ++k, ++v) {
                w.setWord(z::axisControlWord(a, k), v);
                QCOMPARE(w.axisControl(i, k), v);
            }
            for (int k = 0; k < 2; ++k, ++v) {
                w.setAxisState(i, k, v);
                QCOMPARE(w.word(z::axisStateWord(a, k)), v);
            }
        }
        // Nothing else was written.
        QCOMPARE(w.word(1004), std::uint16_t(0));
        QCOMPARE(w.word(1011), std::uint16_t(0));
        QCOMPARE(w.word(2004), std::uint16_t(0));
        QCOMPARE(w.word(1300), std::uint16_t(0));
    }
    // The block compares and the copy take exactly the inputs (Z1000..Z1013,
    // Z1300..Z1307, Z1900..Z1907) or exactly the outputs (Z2000..Z2008).
    void blocksOfInputsAndOutputs() {
        std::vector<int> addresses;
        for (int a = 1000; a <= 2008; ++a)
            if (InterfaceWords::holds(a))
                addresses.push_back(a);
        QCOMPARE(addresses.size(), std::size_t(39));
        for (int a : addresses) {
            InterfaceWords x, y;
            y.setWord(a, 0x8001);
            const bool output = a >= 2000;
            QCOMPARE(x.sameInputs(y), output);
            QCOMPARE(x.sameOutputs(y), !output);
            x.copyOutputs(y);
            QCOMPARE(x.word(a), std::uint16_t(output ? 0x8001 : 0));
        }
    }
    void panelKeysSkipBits6And7() {
        QCOMPARE(int(z::keyBit(1)), 0);
        QCOMPARE(int(z::keyBit(6)), 5);
        QCOMPARE(int(z::keyBit(7)), 8);
        QCOMPARE(int(z::keyBit(12)), 13);
    }
    void wordsAndFields() {
        InterfaceWords w;
        w.setField(z::ModeCodeWord, z::ModeCodeFirst, z::ModeCodeWidth, 3);
        QCOMPARE(w.word(1000), std::uint16_t(0x0300));
        w.setBit(z::EmergencyStopOk, true);
        w.setBit(z::Start, true);
        QCOMPARE(w.word(1000), std::uint16_t(0x0309));
        QCOMPARE(w.field(1000, 8, 3), 3u);
        w.setBit(z::Start, false);
        QVERIFY(!w.bit(z::Start));
        w.setField(z::MCodeWord, z::MCodeFirst, z::MCodeWidth, 99);
        w.setBit(z::MStrobe, true);
        QCOMPARE(w.word(2001), std::uint16_t(99 | 0x80));
        QVERIFY(InterfaceWords::holds(1907));
        QVERIFY(InterfaceWords::holds(2002)); // held, though the manual documents no bit of it
        QVERIFY(!InterfaceWords::holds(1500));
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, w.word(1500));
    }
};

QTEST_APPLESS_MAIN(TestInterfaceWords)
#include "test_interface_words.moc"
