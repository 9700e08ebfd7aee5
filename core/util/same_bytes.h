// Whether two blocks of N bytes are equal, compared eight bytes at a time
// inline: for the small fixed blocks the tick compares every tick (interface
// words, status bytes), where a call of memcmp costs more than the compare.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace k528::util {

template <std::size_t N> bool sameBytes(const void* a, const void* b) {
    const auto* p = static_cast<const unsigned char*>(a);
    const auto* q = static_cast<const unsigned char*>(b);
    std::uint64_t diff = 0;
    std::size_t i = 0;
    for (; i + 8 <= N; i += 8) {
        std::uint64_t x, y;
        std::memcpy(&x, p + i, 8);
        std::memcpy(&y, q + i, 8);
        diff |= x ^ y;
    }
    for (; i < N; ++i)
        diff |= static_cast<std::uint64_t>(p[i] ^ q[i]);
    return diff == 0;
}

} // namespace k528::util
