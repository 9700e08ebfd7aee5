// The R-parameters of the positioner (manual 2.5, appendix Л): R0..R299,
// signed 32-bit integers. R0..R149 belong to the user, R150..R299 are
// reserved by the system; R232..R262 are read only (the engine rewrites them
// every tick). Coordinates are display discretes of their axis, feeds display
// discretes per minute.
//
// Arithmetic of computational frames (2.7.1.2): + - * / on 32-bit values,
// division truncating toward zero; a result outside the 32-bit range or a
// division by zero is message 46 «Переполнение».
#pragma once

#include "program/model.h"

#include <array>
#include <cstdint>
#include <span>

namespace k528::engine {

inline constexpr int kRCount = 300;
inline constexpr int kRReadOnlyFirst = 232;
inline constexpr int kRReadOnlyLast = 262;
inline constexpr std::int64_t kRMin = -2147483648LL;
inline constexpr std::int64_t kRMax = 2147483647LL;

// Reserved numbers the engine uses (appendix Л).
namespace r {
inline constexpr int PlcBit = 150;           // ← Z1001.8
inline constexpr int SafetyZoneXMinus = 151; // R151..R154: safety zone, machine system
inline constexpr int NestingLevel = 158;
inline constexpr int OscillationX = 184; // R184..R191 X, R192..R199 Z (screen 7)
inline constexpr int OscillationZ = 192;
inline constexpr int WheelNew = 204, WheelMin = 205, WheelMax = 206, WheelCurrent = 207;
inline constexpr int DressRoughX = 210, DressFinishX = 211; // periphery, discretes of X
inline constexpr int DressRoughZ = 214, DressFinishZ = 215; // face, discretes of Z
inline constexpr int AdjustX = 218;                         // R218/R219: подналадка
inline constexpr int InitialX = 220; // R220/R221: исходное положение (machine system)
inline constexpr int DressingSumX = 224; // R224/R225
inline constexpr int CorrectionX = 226;  // R226/R227
inline constexpr int ZeroOffsetX = 228;  // R228/R229
inline constexpr int DrfX = 230;         // R230/R231
inline constexpr int MachineX = 232;     // read only from here
inline constexpr int CurrentX = 234;
inline constexpr int SpeedX = 236;
inline constexpr int ErrorX = 238;
inline constexpr int DacX = 240;
inline constexpr int EraseErrorX = 242;
inline constexpr int RemainingX = 244;
inline constexpr int HomeDistanceX = 246;
inline constexpr int Override = 249;
inline constexpr int CurrentProgram = 250;
inline constexpr int SelectedProgram = 252;
inline constexpr int ExecutingProgram = 253;
inline constexpr int FrameNumber = 254;
inline constexpr int PanelValue = 256;
inline constexpr int PanelAddress = 257;
inline constexpr int PulsesX = 261;
} // namespace r

constexpr bool rReadOnly(int n) {
    return n >= kRReadOnlyFirst && n <= kRReadOnlyLast;
}
constexpr bool rValid(int n) {
    return n >= 0 && n < kRCount;
}
constexpr bool fitsR(std::int64_t v) {
    return v >= kRMin && v <= kRMax;
}

class RStore {
public:
    std::int32_t operator[](int n) const { return v_[static_cast<std::size_t>(n)]; }
    std::int32_t get(int n) const { return v_[static_cast<std::size_t>(n)]; }
    // Unchecked store (the engine's own writes; callers check number and range).
    void set(int n, std::int32_t v) { v_[static_cast<std::size_t>(n)] = v; }
    // Adds `delta`; false (value unchanged) if the result leaves the 32-bit range.
    bool add(int n, std::int64_t delta);
    std::span<const std::int32_t> values() const { return v_; }
    void clear() { v_.fill(0); }
    friend bool operator==(const RStore&, const RStore&) = default;

private:
    std::array<std::int32_t, kRCount> v_{};
};

// a op b with the rules of 2.7.1.2. `ok` false: overflow or division by zero.
struct ArithResult {
    std::int32_t value = 0;
    bool ok = true;
    bool divisionByZero = false;
};
ArithResult arith(std::int32_t a, program::ArithOp op, std::int32_t b);

} // namespace k528::engine
