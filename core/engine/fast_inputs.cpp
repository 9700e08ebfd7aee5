#include "engine/fast_inputs.h"
#include "engine/cparams.h"

namespace k528::engine {

bool fastActiveLevel(int axis, FastFunction f) {
    switch (f) {
    case FastFunction::Reset:
    case FastFunction::DriveReady:
    case FastFunction::Erase2:
    case FastFunction::Erase3:
    case FastFunction::Erase4:
        return true;
    case FastFunction::Erase1:
        return axis != 0; // Е.1.1: touch relay of X at 0; Е.1.2: Z at 1
    case FastFunction::None:
    case FastFunction::DisplayMode:
    case FastFunction::LimitPlus:
    case FastFunction::LimitMinus:
    case FastFunction::DecelCam:
        return false;
    }
    return true;
}

void FastInputMap::configure(std::span<const std::int64_t> c) {
    for (int a = 0; a < 2; ++a) {
        in_[static_cast<std::size_t>(a)].fill(-1);
        for (int f = 0; f < kFastFunctionCount; ++f)
            level_[static_cast<std::size_t>(a)][static_cast<std::size_t>(f)] =
                fastActiveLevel(a, static_cast<FastFunction>(f));
        for (int i = 0; i < 8; ++i) {
            const std::size_t n = c::fastInput(a, i);
            const std::int64_t v = n < c.size() ? c[n] : 0;
            const FastFunction f = v >= 1 && v < kFastFunctionCount ? static_cast<FastFunction>(v)
                                                                    : FastFunction::None;
            fn_[static_cast<std::size_t>(a)][static_cast<std::size_t>(i)] = f;
            auto& slot = in_[static_cast<std::size_t>(a)][static_cast<std::size_t>(f)];
            if (f != FastFunction::None && slot < 0) // the first input wins (the validator warns)
                slot = static_cast<std::int8_t>(i);
        }
    }
}

} // namespace k528::engine
