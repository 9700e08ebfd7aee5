// The PLC <-> positioner interface of appendix И (and table 2/4 of 2.2/2.3):
// sixteen-bit words, bit for bit. This is the engine's only door to the
// machine: the simulated PLC writes Z1000..Z1013 (and the panel words), the
// positioner writes Z2000..Z2008.
//
// Bits the manual leaves undocumented are free; where the engine needs a bit
// the manual does not name, it uses a free one and says so here (extensions
// are marked EXT and listed in docs/plc-interface.md).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "axis/constants.h"
#include "util/same_bytes.h"

namespace k528::engine {

// One bit of one word: Z<word>.<bit>.
struct ZBit {
    std::uint16_t word;
    std::uint8_t bit;
};

// The words of the interface, addressed by their PLC address.
class InterfaceWords {
public:
    // Addresses held: 1000..1013, 1300..1307, 1900..1907, 2000..2008.
    static bool holds(int address);
    // The index of a held address in that order (0..38), -1 for another.
    static constexpr int kWordCount = 14 + 8 + 8 + 9;
    static constexpr int slotOf(int a) {
        if (a >= 1000 && a <= 1013)
            return a - 1000;
        if (a >= 1300 && a <= 1307)
            return 14 + (a - 1300);
        if (a >= 1900 && a <= 1907)
            return 22 + (a - 1900);
        if (a >= 2000 && a <= 2008)
            return 30 + (a - 2000);
        return -1;
    }

    std::uint16_t word(int address) const { return w_[slot(address)]; }
    void setWord(int address, std::uint16_t value) { w_[slot(address)] = value; }
    bool bit(ZBit b) const { return (word(b.word) >> b.bit) & 1u; }
    // An axis' words by its index (0 = X, 1 = Z), without looking the
    // address up (the engine reads them every tick): control word k = 0..2
    // (Z1005..Z1007 of X, Z1008..Z1010 of Z) and state word k = 0..1
    // (Z2005/Z2006 of X, Z2007/Z2008 of Z).
    std::uint16_t axisControl(int axis, int k) const {
        return w_[static_cast<std::size_t>(kAxisControlSlot + 3 * axis + k)];
    }
    void setAxisState(int axis, int k, std::uint16_t value) {
        w_[static_cast<std::size_t>(kAxisStateSlot + 2 * axis + k)] = value;
    }
    void setBit(ZBit b, bool on) {
        std::uint16_t& w = w_[slot(b.word)];
        w = static_cast<std::uint16_t>(on ? (w | (1u << b.bit)) : (w & ~(1u << b.bit)));
    }
    // A field of `width` bits starting at `first` (e.g. the mode code Z1000.8-10).
    unsigned field(int address, int first, int width) const {
        return (word(address) >> first) & ((1u << width) - 1u);
    }
    void setField(int address, int first, int width, unsigned value) {
        const std::uint16_t mask = static_cast<std::uint16_t>(((1u << width) - 1u) << first);
        std::uint16_t& w = w_[slot(address)];
        w = static_cast<std::uint16_t>((w & ~mask) | ((value << first) & mask));
    }

    friend bool operator==(const InterfaceWords&, const InterfaceWords&) = default;
    // The words the positioner reads, Z1000..Z1013, Z1300..Z1307, Z1900..Z1907, in slot order.
    static constexpr int kInputWords = 30;
    const std::uint16_t* inputs() const { return w_.data(); }
    // The positioner's own words, Z2000..Z2008, in slot order.
    static constexpr int kOutputWords = kWordCount - kInputWords;
    const std::uint16_t* outputs() const { return w_.data() + kInputWords; }
    // Whether the words the positioner reads (Z1000..Z1013, Z1300..Z1307,
    // Z1900..Z1907) are those of `o`; its own Z2000..Z2008 are not compared.
    bool sameInputs(const InterfaceWords& o) const {
        return util::sameBytes<kInputSlots * sizeof(std::uint16_t)>(w_.data(), o.w_.data());
    }
    // The same for the positioner's own words Z2000..Z2008 (the PLC reads
    // them every tick), and their copy.
    bool sameOutputs(const InterfaceWords& o) const {
        return util::sameBytes<kOutputSlots * sizeof(std::uint16_t)>(w_.data() + kInputSlots,
                                                                      o.w_.data() + kInputSlots);
    }
    void copyOutputs(const InterfaceWords& from) {
        std::copy_n(from.w_.begin() + kInputSlots, kOutputSlots, w_.begin() + kInputSlots);
    }

private:
    // Index of a held address; throws std::out_of_range for an address not
    // held. Inline: with a constant address it folds to a constant.
    static int slot(int a) {
        const int s = slotOf(a);
        if (s < 0)
            notHeld(a);
        return s;
    }
    [[noreturn]] static void notHeld(int address);
    static constexpr int kAxisControlSlot = 5; // slot(1005)
    static constexpr int kAxisStateSlot = 35;  // slot(2005)
    static constexpr int kInputSlots = kInputWords; // slots 0..29: Z1000..Z1907
    static constexpr int kOutputSlots = 9;     // slots 30..38: Z2000..Z2008
    std::array<std::uint16_t, kWordCount> w_{};
};

namespace z {

// ---- Z1000: general control (PLC -> positioner) ---------------------------
inline constexpr ZBit EmergencyStopOk{1000, 0}; // 1 = working, 0 = emergency stop
inline constexpr ZBit FeedEnable{1000, 1};      // «Общая деблокировка подачи»
inline constexpr ZBit StartEnable{1000, 2};     // «Деблокировка пуска программы»
inline constexpr ZBit Start{1000, 3};           // «Пуск программы обработки»
inline constexpr ZBit Stop{1000, 4};            // «Стоп программы обработки»
inline constexpr ZBit Reset{1000, 5};           // «Сброс в исходное состояние» (0->1)
inline constexpr ZBit DataHold{1000, 6};        // «Блокировка ввода данных»
inline constexpr ZBit AckFaults{1000, 7};       // «Квитирование сообщений о неисправностях»
inline constexpr int ModeCodeWord = 1000, ModeCodeFirst = 8, ModeCodeWidth = 3; // Z1000.8-10
inline constexpr ZBit MAcknowledge{1000, 11};   // EXT: M function done (GOST 26642 «FIN»)

// Mode codes of Z1000.8-10.
enum class ModeCode : unsigned {
    Panel = 0,         // the mode is chosen on the K923
    Auto = 1,          // АВТОМАТ
    Manual = 2,        // РУЧНОЙ
    Reference = 3,     // ПРИВЯЗКА К БАЗОВОЙ ТОЧКЕ
    SetActual = 4,     // установка фактического значения (ПРЕДУСТАНОВКИ)
    MachineData = 5,   // ввод данных станка (С-ПАРАМЕТРЫ)
    ProgramInput = 6,  // ввод программы обработки (РЕДАКТИРОВАНИЕ УП)
    DataControl = 7,   // управление данными
};

// ---- Z1001 -------------------------------------------------------------
// Z1001.0..7: start manual cycle 1..8 (programs of C143..C150).
inline constexpr ZBit startCycle(int n) { return ZBit{1001, static_cast<std::uint8_t>(n - 1)}; }
inline constexpr ZBit R150Bit{1001, 8};             // copied into R150
inline constexpr ZBit OverrideFromPlc{1001, 11};    // use the code of Z1001.12-15
inline constexpr int OverrideCodeWord = 1001, OverrideCodeFirst = 12, OverrideCodeWidth = 4;

// ---- axis control words: X = Z1005..Z1007, Z = Z1008..Z1010 ---------------
inline constexpr std::uint16_t axisControlWord(axis::AxisId a, int k) {
    return static_cast<std::uint16_t>((a == axis::AxisId::X ? 1005 : 1008) + k);
}
inline constexpr ZBit axisBit(axis::AxisId a, int k, int bit) {
    return ZBit{axisControlWord(a, k), static_cast<std::uint8_t>(bit)};
}
// First word (Z1005 / Z1008)
inline constexpr ZBit loopOff(axis::AxisId a) { return axisBit(a, 0, 0); }
inline constexpr ZBit regulatorEnable(axis::AxisId a) { return axisBit(a, 0, 1); }
inline constexpr ZBit axisFeedEnable(axis::AxisId a) { return axisBit(a, 0, 2); }
inline constexpr ZBit decelCam(axis::AxisId a) { return axisBit(a, 0, 3); }
inline constexpr ZBit accel2(axis::AxisId a) { return axisBit(a, 0, 4); }
inline constexpr ZBit limitPlus(axis::AxisId a) { return axisBit(a, 0, 5); }
inline constexpr ZBit limitMinus(axis::AxisId a) { return axisBit(a, 0, 6); }
inline constexpr ZBit jogPlus(axis::AxisId a) { return axisBit(a, 0, 7); }
inline constexpr ZBit jogMinus(axis::AxisId a) { return axisBit(a, 0, 8); }
inline constexpr ZBit rapid(axis::AxisId a) { return axisBit(a, 0, 9); }
inline constexpr ZBit handwheelOn(axis::AxisId a, int wheel) { return axisBit(a, 0, wheel == 1 ? 10 : 11); }
inline constexpr ZBit handwheelMult(axis::AxisId a, int wheel) { return axisBit(a, 0, wheel == 1 ? 12 : 13); }
inline constexpr ZBit handwheelDrf(axis::AxisId a, int wheel) { return axisBit(a, 0, wheel == 1 ? 14 : 15); }
// Second word (Z1006 / Z1009)
inline constexpr ZBit adjustPlus(axis::AxisId a) { return axisBit(a, 1, 1); }
inline constexpr ZBit adjustMinus(axis::AxisId a) { return axisBit(a, 1, 2); }
inline constexpr ZBit encoderOn(axis::AxisId a) { return axisBit(a, 1, 3); }
inline constexpr ZBit outOfCycleNoDrf(axis::AxisId a) { return axisBit(a, 1, 4); }        // as G50
inline constexpr ZBit outOfCycleNoCorrection(axis::AxisId a) { return axisBit(a, 1, 5); } // as G51
inline constexpr ZBit outOfCycleNoDressing(axis::AxisId a) { return axisBit(a, 1, 6); }   // as G52
inline constexpr ZBit outOfCycleNoZeroOffset(axis::AxisId a) { return axisBit(a, 1, 7); } // as G53
// Z1006.12..15: erase the rest of the path, signal 1..4 (Gx36..Gx39)
inline constexpr ZBit eraseSignal(axis::AxisId a, int n) { return axisBit(a, 1, 11 + n); }
// Third word (Z1007 / Z1010)
inline constexpr ZBit roughDressComp(axis::AxisId a) { return axisBit(a, 2, 0); }
inline constexpr ZBit finishDressComp(axis::AxisId a) { return axisBit(a, 2, 1); }

// ---- Z2000: general state (positioner -> PLC) ----------------------------
inline constexpr ZBit Ready{2000, 0};
inline constexpr ZBit ModeAuto{2000, 1};
inline constexpr ZBit ModeManual{2000, 2};
inline constexpr ZBit ModeReference{2000, 3};
inline constexpr ZBit ModeSetActual{2000, 4};
inline constexpr ZBit ModeMachineData{2000, 5};
inline constexpr ZBit ModeProgramInput{2000, 6};
inline constexpr ZBit ModeDataControl{2000, 7};
inline constexpr ZBit ProgramRunning{2000, 8};
inline constexpr ZBit ProgramInterrupted{2000, 9};
inline constexpr ZBit EndOrReset{2000, 10};
inline constexpr ZBit DwellRunning{2000, 11};
inline constexpr ZBit M0Stop{2000, 12};
inline constexpr ZBit OverrideZero{2000, 14};
inline constexpr ZBit WheelChange{2000, 15};

// ---- Z2001: M function and manual cycles ---------------------------------
inline constexpr int MCodeWord = 2001, MCodeFirst = 0, MCodeWidth = 7; // Z2001.0-6
inline constexpr ZBit MStrobe{2001, 7};
inline constexpr ZBit cycleRunning(int n) { return ZBit{2001, static_cast<std::uint8_t>(7 + n)}; }

// ---- axis state words: X = Z2005/Z2006, Z = Z2007/Z2008 -------------------
inline constexpr std::uint16_t axisStateWord(axis::AxisId a, int k) {
    return static_cast<std::uint16_t>((a == axis::AxisId::X ? 2005 : 2007) + k);
}
inline constexpr ZBit stateBit(axis::AxisId a, int bit) { return ZBit{axisStateWord(a, 0), static_cast<std::uint8_t>(bit)}; }
inline constexpr ZBit loopError(axis::AxisId a) { return stateBit(a, 0); }
inline constexpr ZBit commandPlus(axis::AxisId a) { return stateBit(a, 1); }
inline constexpr ZBit commandMinus(axis::AxisId a) { return stateBit(a, 2); }
inline constexpr ZBit positionNotReached(axis::AxisId a) { return stateBit(a, 3); }
inline constexpr ZBit referenced(axis::AxisId a) { return stateBit(a, 4); }
inline constexpr ZBit rapidMotion(axis::AxisId a) { return stateBit(a, 5); }
inline constexpr ZBit loopClosed(axis::AxisId a) { return stateBit(a, 6); }
inline constexpr ZBit regulatorEnabled(axis::AxisId a) { return stateBit(a, 7); }
inline constexpr ZBit atInitialPosition(axis::AxisId a) { return stateBit(a, 8); }
inline constexpr ZBit handwheelFrameActive(axis::AxisId a) { return stateBit(a, 9); } // Gx10
inline constexpr ZBit safetyZone(axis::AxisId a) { return stateBit(a, 10); }
inline constexpr ZBit WheelBelowMin{2005, 11};
inline constexpr ZBit WheelAboveMax{2005, 12};
// Z2006 / Z2008: states of fast inputs 1..8 of the CP34.23 of the axis.
inline constexpr ZBit fastInputState(axis::AxisId a, int n) {
    return ZBit{axisStateWord(a, 1), static_cast<std::uint8_t>(n - 1)};
}

// ---- panel and message words (2.3, table 4) -----------------------------
inline constexpr int KeysWord = 1300;                // K1..K12 pressed (PLC clears)
inline constexpr int SystemMessagesWord = 1307;      // module failures, bit n = place n
inline constexpr int AlarmMessagesFirst = 1900;      // Z1900, Z1901: 32 machine alarms
inline constexpr int WorkMessagesFirst = 1902;       // Z1902, Z1903: 32 work messages
inline constexpr int GreenLedsWord = 1906;
inline constexpr int RedLedsWord = 1907;
// K1..K6 are bits 0..5, K7..K12 bits 8..13 of Z1300/Z1906/Z1907.
inline constexpr std::uint8_t keyBit(int k) { return static_cast<std::uint8_t>(k <= 6 ? k - 1 : k + 1); }

} // namespace z
} // namespace k528::engine
