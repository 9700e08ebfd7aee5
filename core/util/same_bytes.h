// Whether two blocks of N bytes are equal, compared inline in a few wide
// loads (16 bytes with SSE2, else 8): for the small fixed blocks the tick
// compares every tick (interface words, status bytes), where a call of memcmp
// costs more than the compare. A block whose size is not a multiple of the
// load ends with a load that overlaps the one before (no byte-wise tail).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace k528::util {

template <std::size_t N> bool sameBytes(const void* a, const void* b) {
    static_assert(N > 0);
    const auto* p = static_cast<const unsigned char*>(a);
    const auto* q = static_cast<const unsigned char*>(b);
#if defined(__SSE2__)
    if constexpr (N >= 16) {
        __m128i diff = _mm_setzero_si128();
        const auto chunk = [&](std::size_t at) {
            const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + at));
            const __m128i y = _mm_loadu_si128(reinterpret_cast<const __m128i*>(q + at));
            diff = _mm_or_si128(diff, _mm_xor_si128(x, y));
        };
        for (std::size_t i = 0; i + 16 <= N; i += 16)
            chunk(i);
        if constexpr (N % 16 != 0)
            chunk(N - 16);
        return _mm_movemask_epi8(_mm_cmpeq_epi8(diff, _mm_setzero_si128())) == 0xFFFF;
    }
#endif
    if constexpr (N >= 8) {
        std::uint64_t diff = 0;
        const auto chunk = [&](std::size_t at) {
            std::uint64_t x, y;
            std::memcpy(&x, p + at, 8);
            std::memcpy(&y, q + at, 8);
            diff |= x ^ y;
        };
        for (std::size_t i = 0; i + 8 <= N; i += 8)
            chunk(i);
        if constexpr (N % 8 != 0)
            chunk(N - 8);
        return diff == 0;
    } else {
        return std::memcmp(p, q, N) == 0; // under 8 bytes: the compiler inlines it
    }
}

} // namespace k528::util
