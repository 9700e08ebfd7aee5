// The positioner's messages 1..64 (appendix М) and the PLC message bits the
// positioner remembers for the panel (2.3, 2.6, appendix И):
//
//   category  messages                                   acknowledged by
//   Fault     axis loop and drive (1, 4..8, 13, 16, 17,  Z1000.7 (rising edge), ESC with
//             20..24, 29, 32, 56, 57), E-stop 9, limit    C124 = 1, when the cause is gone
//             switches 10/11/26/27, soft limits 12/28,
//             homing 40/41, constants 37..39
//   Program   run-time errors of a program (33..36,      «Сброс» (Z1000.5, ESC with C123,
//             42..54, 58..64)                            fast input function 1)
//   System    2, 3, 14, 15, 18, 19, 25, 30, 31, 55       ESC with C125 = 1, when the cause is gone
//
// A message is `active` while its cause lasts (a condition) and `latched`
// until acknowledged; events (program errors, a servo fault) latch without
// staying active. The list shows latched messages in the order they came.
//
// PLC messages (Z1900..Z1903, Z1307): machine alarms (Z1900/Z1901) and system
// messages (Z1307) stay after their bit drops until acknowledged (Z1000.7
// erases every remembered alarm bit that is 0 at that moment, for as long as
// it is 1; ESC with C124/C125); work messages (Z1902/Z1903) show only while
// their bit is 1.
#pragma once

#include "engine/interface_words.h"
#include "engine/types.h"

#include <array>
#include <cstdint>
#include <vector>

namespace k528::engine {

inline constexpr int kMessageCount = 64;

enum class AlarmCategory : std::uint8_t { Fault, Program, System };
std::string_view alarmCategoryName(AlarmCategory c); // "fault", "program", "system"

// The category of positioner message n (1..64).
constexpr AlarmCategory alarmCategory(int n) {
    switch (n) {
    case 2:
    case 3:
    case 14:
    case 15:
    case 18:
    case 19:
    case 25:
    case 30:
    case 31:
    case 55:
        return AlarmCategory::System;
    default:
        break;
    }
    if ((n >= 33 && n <= 36) || (n >= 42 && n <= 54) || (n >= 58 && n <= 64))
        return AlarmCategory::Program;
    return AlarmCategory::Fault;
}
// Bit n-1 set for each message of category c.
constexpr std::uint64_t alarmCategoryMask(AlarmCategory c) {
    std::uint64_t m = 0;
    for (int n = 1; n <= 64; ++n)
        if (alarmCategory(n) == c)
            m |= std::uint64_t{1} << (n - 1);
    return m;
}
// The axis a message is about: 0 = X, 1 = Z, -1 = none.
int alarmAxis(int n);

struct AlarmEntry {
    bool active = false;  // the cause is present now
    bool latched = false; // shown until acknowledged
    int program = 0;      // program and source line, for program errors
    int line = 0;
    std::uint32_t order = 0; // when it latched (for the list order)
};

class AlarmRegistry {
public:
    // Latches message n; `activeCondition` keeps it active until clear().
    // Returns true if it was not latched before.
    bool raise(int n, bool activeCondition = false, int program = 0, int line = 0);
    // The cause of a condition message is gone (it stays latched).
    void clear(int n) {
        e_[static_cast<std::size_t>(n)].active = false;
        activeMask_ &= ~bit(n);
    }
    // Raises or clears a condition message.
    void setCondition(int n, bool on) {
        if (on)
            raise(n, true);
        else if (e_[static_cast<std::size_t>(n)].active)
            clear(n);
    }
    // Unlatches every message of `category` whose cause is gone.
    void acknowledge(AlarmCategory category);
    void acknowledgeAll();

    const AlarmEntry& entry(int n) const { return e_[static_cast<std::size_t>(n)]; }
    bool latched(int n) const { return (latchedMask_ & bit(n)) != 0; }
    bool active(int n) const { return (activeMask_ & bit(n)) != 0; }
    bool anyLatched() const { return latchedMask_ != 0; }
    bool anyLatched(AlarmCategory c) const { return (latchedMask_ & maskOf(c)) != 0; }
    bool anyActive(AlarmCategory c) const { return (activeMask_ & maskOf(c)) != 0; }
    std::uint64_t latchedMask() const { return latchedMask_; }
    std::uint64_t activeMask() const { return activeMask_; }
    // The bit of message n in the masks above.
    static constexpr std::uint64_t messageBit(int n) { return bit(n); }
    // Latched message numbers in the order they latched.
    std::vector<int> latchedList() const;

private:
    static constexpr std::uint64_t bit(int n) { return std::uint64_t{1} << (n - 1); }
    static constexpr std::uint64_t maskOf(AlarmCategory c) {
        constexpr std::uint64_t masks[3] = {alarmCategoryMask(AlarmCategory::Fault),
                                            alarmCategoryMask(AlarmCategory::Program),
                                            alarmCategoryMask(AlarmCategory::System)};
        return masks[static_cast<int>(c)];
    }
    std::array<AlarmEntry, kMessageCount + 1> e_{};
    std::uint64_t latchedMask_ = 0, activeMask_ = 0;
    std::uint32_t order_ = 0;
};

// The PLC's message bits as the positioner remembers them.
class PlcMessages {
public:
    // Reads Z1900..Z1903 and Z1307 (each tick).
    void update(const InterfaceWords& w);
    // Erases remembered machine alarms whose bit is 0 now.
    void acknowledgeAlarms() { alarmLatched_ &= alarmNow_; }
    void acknowledgeSystem() { systemLatched_ &= systemNow_; }
    void clear() { alarmLatched_ = alarmNow_ = work_ = 0, systemLatched_ = systemNow_ = 0; }

    // Bit k-1 = message k (alarm 1..32, work 1..32, system 1..16).
    std::uint32_t alarms() const { return alarmLatched_; }    // shown
    std::uint32_t alarmsPresent() const { return alarmNow_; } // bit set now
    std::uint32_t work() const { return work_; }
    std::uint16_t system() const { return systemLatched_; }
    std::uint16_t systemPresent() const { return systemNow_; }
    friend bool operator==(const PlcMessages&, const PlcMessages&) = default;

private:
    std::uint32_t alarmLatched_ = 0, alarmNow_ = 0, work_ = 0;
    std::uint16_t systemLatched_ = 0, systemNow_ = 0;
};

} // namespace k528::engine
