// The C-parameters (machine constants) of the positioner the engine reads by
// number (manual appendix Е, table Ж), named as the R-parameters are in
// rparams.h: `c_.c[c::EscResets]`, never a bare `c_.c[123]`. C1..C52 describe
// axis X and C53..C104 axis Z in the same layout; axis::Constants
// (axis/constants.h) reads those blocks into named fields. Values are kept as
// the table holds them (std::int64_t, indexed by number; c[0] unused).
#pragma once

#include <cstddef>

namespace k528::engine {

inline constexpr int kCCount = 152; // C1..C152

namespace c {
// The axis blocks: C(XBlock + k) of X, C(ZBlock + k) of Z, k = 0..51.
inline constexpr std::size_t XBlock = 1;
inline constexpr std::size_t ZBlock = 53;
inline constexpr std::size_t HomeNegativeX = 9;    // ПБТ В "-" (C61 for Z)
inline constexpr std::size_t EncoderChannelX = 17; // N ДОС (C69 for Z)
inline constexpr std::size_t DacChannelX = 18;     // N ЦАП (C70 for Z)
inline constexpr std::size_t Handwheel1Channel = 105; // N М1
inline constexpr std::size_t Handwheel2Channel = 106; // N М2
inline constexpr std::size_t FastInputsX = 107; // C107..C114: functions of Вх1..Вх8, module 1 (X)
inline constexpr std::size_t FastInputsZ = 115; // C115..C122: module 2 (Z)
inline constexpr std::size_t EscResets = 123;             // ESC =сброс в исх.сост
inline constexpr std::size_t EscAcknowledgesFaults = 124; // ESC =квитир.авар.БЦС
inline constexpr std::size_t EscAcknowledgesSystem = 125; // ESC = квитир.сист.БЦС
inline constexpr std::size_t OverrideKeyL1 = 139; // C139..C142: «Корректор по L1..L4»
inline constexpr std::size_t ManualCycle1 = 143;  // C143..C150: «N ручного цикла 1..8»

// Axis a (0 = X, 1 = Z): the C-parameter of its block that X has at `xNumber`.
constexpr std::size_t ofAxis(std::size_t xNumber, int a) { return xNumber + (a == 0 ? 0 : ZBlock - XBlock); }
// Handwheel k (0, 1): its pulse channel code.
constexpr std::size_t handwheelChannel(int k) { return Handwheel1Channel + static_cast<std::size_t>(k); }
// Fast input Вх(i+1) (i = 0..7) of module a (0 = X, 1 = Z): its function.
constexpr std::size_t fastInput(int a, int i) {
    return (a == 0 ? FastInputsX : FastInputsZ) + static_cast<std::size_t>(i);
}
// Key L (1..4): its override code.
constexpr std::size_t overrideKey(int l) { return OverrideKeyL1 + static_cast<std::size_t>(l - 1); }
// Manual cycle n (1..8): its program number (0: not defined).
constexpr std::size_t manualCycle(int n) { return ManualCycle1 + static_cast<std::size_t>(n - 1); }
} // namespace c

} // namespace k528::engine
