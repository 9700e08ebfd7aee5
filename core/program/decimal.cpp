#include "program/decimal.h"

#include <cmath>
#include <limits>

namespace k528::program {

namespace {

__extension__ typedef __int128 Wide;

constexpr std::int64_t kPow10[19] = {1,
                                     10,
                                     100,
                                     1000,
                                     10000,
                                     100000,
                                     1000000,
                                     10000000,
                                     100000000,
                                     1000000000,
                                     10000000000,
                                     100000000000,
                                     1000000000000,
                                     10000000000000,
                                     100000000000000,
                                     1000000000000000,
                                     10000000000000000,
                                     100000000000000000,
                                     1000000000000000000};

Wide widePow10(int n) {
    if (n >= 0 && n <= 18)
        return kPow10[n];
    Wide v = 1;
    for (int i = 0; i < n; ++i)
        v *= 10;
    return v;
}

std::int64_t saturate(Wide v) {
    constexpr auto lo = std::numeric_limits<std::int64_t>::min();
    constexpr auto hi = std::numeric_limits<std::int64_t>::max();
    if (v < lo)
        return lo;
    if (v > hi)
        return hi;
    return static_cast<std::int64_t>(v);
}

} // namespace

std::optional<Decimal> Decimal::parse(std::string_view s) {
    std::size_t i = 0;
    bool negative = false;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) {
        negative = s[i] == '-';
        ++i;
    }
    {
        // At most 18 digits (nearly every value): no limit can be reached,
        // so the digits are the mantissa and the trailing zeros come off.
        std::uint64_t m = 0; // below 10^19: no overflow
        int digits = 0;
        int fraction = -1; // digits after the point; -1 before it
        std::size_t k = i;
        for (; k < s.size() && digits <= kMaxDigits; ++k) {
            const char c = s[k];
            if (c == '.') {
                if (fraction >= 0)
                    return std::nullopt;
                fraction = 0;
            } else if (c >= '0' && c <= '9') {
                m = m * 10 + (c - '0');
                ++digits;
                if (fraction >= 0)
                    ++fraction;
            } else {
                return std::nullopt;
            }
        }
        if (k == s.size() && digits <= kMaxDigits) {
            if (digits == 0)
                return std::nullopt;
            int sc = fraction > 0 ? fraction : 0;
            while (sc > 0 && m % 10 == 0) {
                m /= 10;
                --sc;
            }
            const auto value = static_cast<std::int64_t>(m);
            Decimal d;
            d.mantissa = negative ? -value : value;
            d.scale = m == 0 ? 0 : sc;
            return d;
        }
    }
    // Collect the digits, skipping leading zeros of the integer part.
    std::int64_t mantissa = 0;
    int significant = 0;
    int scale = 0;
    int pendingZeros = 0; // fraction zeros not yet multiplied in (trailing zeros are dropped)
    bool anyDigit = false;
    bool seenPoint = false;
    for (; i < s.size(); ++i) {
        const char c = s[i];
        if (c == '.') {
            if (seenPoint)
                return std::nullopt;
            seenPoint = true;
            continue;
        }
        if (c < '0' || c > '9')
            return std::nullopt;
        anyDigit = true;
        const int digit = c - '0';
        if (!seenPoint) {
            if (mantissa == 0 && digit == 0)
                continue;
            if (++significant > kMaxDigits)
                return std::nullopt;
            mantissa = mantissa * 10 + digit;
        } else if (digit == 0) {
            ++pendingZeros;
        } else {
            // Flush the zeros met since the last non-zero fraction digit.
            const int needed = (mantissa == 0 ? 0 : pendingZeros) + 1;
            if (mantissa != 0 && significant + needed > kMaxDigits)
                return std::nullopt;
            if (scale + pendingZeros + 1 > kMaxDigits)
                return std::nullopt;
            for (int k = 0; k < pendingZeros; ++k)
                mantissa *= 10;
            if (mantissa != 0)
                significant += pendingZeros;
            scale += pendingZeros + 1;
            pendingZeros = 0;
            mantissa = mantissa * 10 + digit;
            ++significant;
        }
    }
    if (!anyDigit)
        return std::nullopt;
    Decimal d;
    d.mantissa = negative ? -mantissa : mantissa;
    d.scale = mantissa == 0 ? 0 : scale;
    return d;
}

void Decimal::appendTo(std::string& out) const {
    if (mantissa == 0) {
        out += '0';
        return;
    }
    // |mantissa| as unsigned (covers INT64_MIN, which parse never produces).
    std::uint64_t m = mantissa < 0 ? 0 - static_cast<std::uint64_t>(mantissa)
                                   : static_cast<std::uint64_t>(mantissa);
    char digits[24];
    int n = 0;
    while (m != 0) {
        digits[n++] = static_cast<char>('0' + m % 10);
        m /= 10;
    }
    if (mantissa < 0)
        out += '-';
    const int intDigits = n - scale;
    if (intDigits <= 0) {
        out += '0';
        out += '.';
        for (int k = 0; k < -intDigits; ++k)
            out += '0';
        for (int k = n - 1; k >= 0; --k)
            out += digits[k];
        return;
    }
    for (int k = n - 1; k >= 0; --k) {
        out += digits[k];
        if (k == scale && scale > 0)
            out += '.';
    }
}

std::string Decimal::toString() const {
    std::string s;
    appendTo(s);
    return s;
}

std::int64_t Decimal::toUnits(int decimals) const {
    if (decimals < 0)
        decimals = 0;
    if (decimals > kMaxDigits)
        decimals = kMaxDigits;
    if (scale <= decimals)
        return saturate(static_cast<Wide>(mantissa) * widePow10(decimals - scale));
    const std::int64_t div = kPow10[scale - decimals];
    const std::int64_t q = mantissa / div;
    const std::int64_t r = mantissa % div;
    // Half away from zero: compare 2|r| with the divisor.
    const std::uint64_t twice = 2 * static_cast<std::uint64_t>(r < 0 ? -r : r);
    if (twice >= static_cast<std::uint64_t>(div))
        return mantissa < 0 ? q - 1 : q + 1;
    return q;
}

Decimal Decimal::rounded(int decimals) const {
    if (decimals < 0)
        decimals = 0;
    if (scale <= decimals)
        return *this;
    return fromScaled(toUnits(decimals), decimals);
}

double Decimal::toDouble() const {
    // Both operands are exact doubles for |mantissa| < 2^53, so the quotient
    // is the correctly rounded value.
    return static_cast<double>(mantissa) / static_cast<double>(kPow10[scale]);
}

Decimal operator+(const Decimal& a, const Decimal& b) {
    int s = a.scale > b.scale ? a.scale : b.scale;
    Wide sum = static_cast<Wide>(a.mantissa) * widePow10(s - a.scale) +
               static_cast<Wide>(b.mantissa) * widePow10(s - b.scale);
    // Give up fraction digits rather than overflow (never for real programs).
    constexpr Wide hi = static_cast<Wide>(std::numeric_limits<std::int64_t>::max());
    while ((sum > hi || sum < -hi) && s > 0) {
        sum /= 10;
        --s;
    }
    return Decimal::fromScaled(saturate(sum), s);
}

std::strong_ordering Decimal::compareScaled(const Decimal& a, const Decimal& b) {
    const int s = a.scale > b.scale ? a.scale : b.scale;
    std::int64_t sa = 0, sb = 0; // both on the larger scale, when that fits in 64 bits
    if (s <= Decimal::kMaxDigits && !__builtin_mul_overflow(a.mantissa, kPow10[s - a.scale], &sa) &&
        !__builtin_mul_overflow(b.mantissa, kPow10[s - b.scale], &sb))
        return sa <=> sb;
    const Wide x = static_cast<Wide>(a.mantissa) * widePow10(s - a.scale);
    const Wide y = static_cast<Wide>(b.mantissa) * widePow10(s - b.scale);
    if (x < y)
        return std::strong_ordering::less;
    if (x > y)
        return std::strong_ordering::greater;
    return std::strong_ordering::equal;
}

} // namespace k528::program
