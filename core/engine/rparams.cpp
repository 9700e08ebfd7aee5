#include "engine/rparams.h"

namespace k528::engine {

bool RStore::add(int n, std::int64_t delta) {
    const std::int64_t v = static_cast<std::int64_t>(get(n)) + delta;
    if (!fitsR(v))
        return false;
    set(n, static_cast<std::int32_t>(v));
    return true;
}

ArithResult arith(std::int32_t a, program::ArithOp op, std::int32_t b) {
    ArithResult r;
    const std::int64_t x = a, y = b;
    std::int64_t v = x;
    switch (op) {
    case program::ArithOp::None:
        v = x;
        break;
    case program::ArithOp::Add:
        v = x + y;
        break;
    case program::ArithOp::Sub:
        v = x - y;
        break;
    case program::ArithOp::Mul:
        v = x * y; // |x·y| <= 2^62: exact in 64 bits
        break;
    case program::ArithOp::Div:
        if (y == 0) {
            r.ok = false;
            r.divisionByZero = true;
            return r;
        }
        v = x / y; // C++ truncates toward zero; -2^31 / -1 = 2^31 overflows below
        break;
    }
    if (!fitsR(v)) {
        r.ok = false;
        return r;
    }
    r.value = static_cast<std::int32_t>(v);
    return r;
}

} // namespace k528::engine
