// The positioner's side of the wiring to the machine (manual 1.3.12, app. Е):
// the four pulse channels of the two CP34.23 modules (encoders and
// handwheels, C17/C69, C105/C106), their 2×8 fast inputs (functions by
// C107..C122), the four DAC channels of the CM32.03 (C18/C70), the regulator
// enable command of each drive, and the health of the modules the power-on
// test checks. The machine writes the inputs before a tick, the engine
// writes the outputs during it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace k528::engine {

// One pulse channel of a CP34.23: a quadrature counter (counts ×4 lines).
struct PulseChannel {
    std::int64_t count = 0; // raw counts as wired
    bool line1Ok = true;    // line monitoring of the two tracks
    bool line2Ok = true;
    bool zeroMark = false;          // a zero mark passed since the last tick
    std::int64_t zeroMarkCount = 0; // ... at this count
    friend bool operator==(const PulseChannel&, const PulseChannel&) = default;
};

inline constexpr int kPulseChannels = 4; // module 1 ch 1, ch 2, module 2 ch 1, ch 2
inline constexpr int kDacChannels = 4;
inline constexpr int kFastInputs = 8; // per CP34.23 module

struct MachineIo {
    // --- inputs: machine -> positioner ---
    std::array<PulseChannel, kPulseChannels> pulse{};
    // Fast inputs Вх1..Вх8 of module 1 (functions C107..C114, axis X block)
    // and module 2 (C115..C122, axis Z block): bit n-1 = Вх n, 1 = +24 V.
    std::array<std::uint8_t, 2> fastInputs{};
    // Module health (power-on test and system messages 2, 3, 14, 18, 19, 25, 30).
    bool pulseModule1Ok = true; // CP34.23 at place 0 (message 2)
    bool pulseModule2Ok = true; // CP34.23 at place 1 (message 18)
    bool dacModuleOk = true;    // CM32.03 (message 3)
    bool commModuleOk = true;   // CP52.05 (message 14)
    bool plcLinkOk = true;      // message 19
    bool panelLinkOk = true;    // message 25
    bool memoryOk = true;       // RAM/ROM test (message 30)

    // --- outputs: positioner -> machine ---
    std::array<int, kDacChannels> dac{};   // codes, ±2047 = ±10 V
    std::array<bool, 2> regulatorEnable{}; // drive regulator enable, X and Z
    friend bool operator==(const MachineIo&, const MachineIo&) = default;
};

// The module health flags follow each other, pulseModule1Ok first, right
// after the fast inputs: the engine reads them as one block of bytes
// (Positioner::systemChecks, Positioner::routineInputs).
inline constexpr std::size_t kMachineHealthFlags = 7;
inline constexpr std::size_t kMachineStatusBytes = 2 + kMachineHealthFlags; // from fastInputs
static_assert(offsetof(MachineIo, memoryOk) - offsetof(MachineIo, pulseModule1Ok) ==
                  kMachineHealthFlags - 1,
              "the health flags of MachineIo must stay together, in this order");
static_assert(offsetof(MachineIo, pulseModule1Ok) == offsetof(MachineIo, fastInputs) + 2,
              "the health flags of MachineIo must follow the fast inputs");
// Those bytes of `io` (fast inputs, then health): the object's own bytes.
inline const unsigned char* machineStatusBytes(const MachineIo& io) {
    return reinterpret_cast<const unsigned char*>(&io) + offsetof(MachineIo, fastInputs);
}
inline const unsigned char* machineHealthBytes(const MachineIo& io) {
    return reinterpret_cast<const unsigned char*>(&io) + offsetof(MachineIo, pulseModule1Ok);
}

} // namespace k528::engine
