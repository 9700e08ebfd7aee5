// An exact decimal number as written in a program: X5.342, FZ1000, G04 X20.5.
//
// The value is mantissa / 10^scale. Values are kept exactly (never as a
// binary double): the engine rounds them to the axis discrete at run time,
// the formatter prints the shortest exact text. A Decimal is always
// normalised (no trailing zeros after the point, scale 0 for integers, no
// negative zero), so two equal values are equal member for member.
#pragma once

#include <compare>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace k528::program {

struct Decimal {
    // Up to 18 significant digits; scale 0..18.
    static constexpr int kMaxDigits = 18;

    std::int64_t mantissa = 0;
    std::int32_t scale = 0;

    constexpr Decimal() = default;
    // mantissa / 10^scale, normalised (scale is clamped to 0..18).
    static constexpr Decimal fromScaled(std::int64_t mantissa, int scale) {
        if (scale < 0)
            scale = 0;
        if (scale > kMaxDigits)
            scale = kMaxDigits;
        while (scale > 0 && mantissa % 10 == 0) {
            mantissa /= 10;
            --scale;
        }
        Decimal d;
        d.mantissa = mantissa;
        d.scale = mantissa == 0 ? 0 : scale;
        return d;
    }
    static constexpr Decimal fromInt(std::int64_t v) {
        Decimal d;
        d.mantissa = v;
        return d;
    }

    // Reads "[+|-]digits[.digits]" or "[+|-].digits"; nullopt when malformed
    // or when more than kMaxDigits significant digits are needed.
    static std::optional<Decimal> parse(std::string_view text);

    // Shortest exact text: "5", "5.342", "-0.5", "0".
    std::string toString() const;
    void appendTo(std::string& out) const;

    bool isNegative() const { return mantissa < 0; }
    bool isZero() const { return mantissa == 0; }
    bool isInteger() const { return scale == 0; }
    // Digits after the point (0 for integers).
    int fractionDigits() const { return scale; }

    // The value in units of 10^-decimals, rounded half away from zero
    // (decimals 0..18): Decimal 5.3425 with decimals 3 gives 5343. Saturates
    // at the int64 range instead of overflowing.
    std::int64_t toUnits(int decimals) const;
    // The value rounded half away from zero to `decimals` digits, as a Decimal.
    Decimal rounded(int decimals) const;

    // Nearest double (for display and statistics only; never for limits).
    double toDouble() const;

    // Exact sum and negation (saturating far beyond any program value).
    friend Decimal operator+(const Decimal& a, const Decimal& b);
    friend Decimal operator-(const Decimal& a) { return fromScaled(-a.mantissa, a.scale); }

    friend bool operator==(const Decimal&, const Decimal&) = default;
    friend std::strong_ordering operator<=>(const Decimal& a, const Decimal& b) {
        return a.scale == b.scale ? a.mantissa <=> b.mantissa : compareScaled(a, b);
    }
    // operator<=> for two different scales.
    static std::strong_ordering compareScaled(const Decimal& a, const Decimal& b);
};

} // namespace k528::program
