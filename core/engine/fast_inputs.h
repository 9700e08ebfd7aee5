// The fast inputs Вх1..Вх8 of the two CP34.23 modules (manual 1.3.12.2) and
// their functions (C107..C114 for module 1 / axis X, C115..C122 for module 2
// / axis Z; tables Е.1.1 and Е.1.2). The column «Сигнал» of those tables is
// read as the level at which the function is active: a reset is a 1, a limit
// switch or the deceleration cam a 0 (normally closed contacts, as GOST
// 26642 asks of «конец хода»), a gauge signal a 1 (the touch relay of X a 0).
// Table Е.1.2 lists functions 1..9 for Z; the profile allows no more.
#pragma once

#include <array>
#include <cstdint>
#include <span>

namespace k528::engine {

enum class FastFunction : std::uint8_t {
    None = 0,
    Reset = 1,       // «Сброс системы в исходное состояние»
    DisplayMode = 2, // «Ось в режиме индикации» (loop open, follow-up)
    DriveReady = 3,  // «Готовность привода оси»
    LimitPlus = 4,   // «Ограничение перемещения в "+"»
    LimitMinus = 5,  // «Ограничение перемещения в "-"»
    DecelCam = 6,    // «Торможение перед опорной точкой»
    Erase1 = 7, // «Стирание остатка пути – сигнал 1..4» (Gx36..Gx39)
    Erase2 = 8,
    Erase3 = 9,
    Erase4 = 10,
};
inline constexpr int kFastFunctionCount = 11; // 0..10

// The level at which function f is active on the module of axis `axis`.
bool fastActiveLevel(int axis, FastFunction f);

// The functions of one module, and their states decoded each tick.
class FastInputMap {
public:
    // From C-parameters indexed by number (c[107..122]).
    void configure(std::span<const std::int64_t> c);
    FastFunction function(int axis, int input) const { return fn_[axis][input]; } // input 0..7
    // The input (0..7) carrying function f on the module of `axis`, or -1.
    int inputOf(int axis, FastFunction f) const { return in_[axis][static_cast<int>(f)]; }
    bool wired(int axis, FastFunction f) const { return inputOf(axis, f) >= 0; }
    // Whether function f is active given the module's input byte. A function
    // on no input is never active.
    bool active(int axis, FastFunction f, std::uint8_t inputs) const {
        const int i = in_[axis][static_cast<int>(f)];
        return i >= 0 && (((inputs >> i) & 1u) != 0) == level_[axis][static_cast<int>(f)];
    }

private:
    std::array<std::array<FastFunction, 8>, 2> fn_{};
    std::array<std::array<std::int8_t, kFastFunctionCount>, 2> in_{};
    std::array<std::array<bool, kFastFunctionCount>, 2> level_{};
};

} // namespace k528::engine
