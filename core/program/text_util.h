// Small byte- and code-point-level helpers shared by the parser and the
// validator (internal to core/program).
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>

#include "util/utf8.h"

namespace k528::program::text {

constexpr bool isDigit(char c) { return c >= '0' && c <= '9'; }
constexpr bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
constexpr char upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }

// The length of the ASCII start of s (s.size() when s is all ASCII).
inline std::size_t asciiPrefix(std::string_view s) {
    static_assert(std::endian::native == std::endian::little, "the first byte of a word is its lowest");
    // Eight bytes at a time; the first byte with its high bit set found in
    // its word (no loop over bytes, whose exit was mispredicted line by line).
    constexpr std::uint64_t kHigh = 0x8080808080808080ULL;
    const char* const d = s.data();
    const std::size_t n = s.size();
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        std::uint64_t w;
        std::memcpy(&w, d + i, sizeof w);
        if (const std::uint64_t high = w & kHigh)
            return i + static_cast<std::size_t>(std::countr_zero(high)) / 8;
    }
    if (n >= 8) {
        // The last bytes in one word with bytes before them (ASCII, read above).
        std::uint64_t w;
        std::memcpy(&w, d + n - 8, sizeof w);
        const std::uint64_t high = w & kHigh;
        return high ? n - 8 + static_cast<std::size_t>(std::countr_zero(high)) / 8 : n;
    }
    while (i < n && static_cast<unsigned char>(d[i]) < 0x80)
        ++i;
    return i;
}

inline bool isAscii(std::string_view s) { return asciiPrefix(s) == s.size(); }

// Length of a well-formed UTF-8 sequence at s[i], or 1 for a malformed byte.
inline std::size_t sequenceLength(std::string_view s, std::size_t i) {
    const auto b0 = static_cast<unsigned char>(s[i]);
    std::size_t len = 1;
    if (b0 < 0x80)
        return 1;
    if ((b0 & 0xE0) == 0xC0)
        len = 2;
    else if ((b0 & 0xF0) == 0xE0)
        len = 3;
    else if ((b0 & 0xF8) == 0xF0)
        len = 4;
    else
        return 1;
    if (i + len > s.size())
        return 1;
    for (std::size_t k = 1; k < len; ++k)
        if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80)
            return 1;
    return len;
}

// The code point at s[i] (U+FFFD for a malformed byte).
inline char32_t decodeAt(std::string_view s, std::size_t i) {
    const std::size_t len = sequenceLength(s, i);
    const auto b0 = static_cast<unsigned char>(s[i]);
    if (len == 1)
        return b0 < 0x80 ? b0 : 0xFFFD;
    char32_t cp = len == 2 ? (b0 & 0x1F) : len == 3 ? (b0 & 0x0F) : (b0 & 0x07);
    for (std::size_t k = 1; k < len; ++k)
        cp = (cp << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
    return cp;
}

// Length of the well-formed UTF-8 character at s[i], or 0 if s[i] does not
// start one (overlongs and surrogates count as malformed).
inline std::size_t validSequenceLength(std::string_view s, std::size_t i) {
    return utf8::validLength(s, i);
}

// Byte offset of the first byte that is not part of well-formed UTF-8
// (s.size() if there is none). Overlongs and surrogates count as malformed.
inline std::size_t firstInvalidUtf8(std::string_view s) {
    for (std::size_t i = 0; i < s.size();) {
        const std::size_t len = validSequenceLength(s, i);
        if (len == 0)
            return i;
        i += len;
    }
    return s.size();
}

// The Latin capital a Cyrillic letter looks like (Х -> X), or 0.
inline char latinLookalike(char32_t cp) {
    switch (cp) {
    case U'А': case U'а': return 'A';
    case U'В': case U'в': return 'B';
    case U'Е': case U'е': return 'E';
    case U'К': case U'к': return 'K';
    case U'М': case U'м': return 'M';
    case U'Н': case U'н': return 'H';
    case U'О': case U'о': return 'O';
    case U'Р': case U'р': return 'P';
    case U'С': case U'с': return 'C';
    case U'Т': case U'т': return 'T';
    case U'У': case U'у': return 'Y';
    case U'Х': case U'х': return 'X';
    default: return 0;
    }
}

inline std::string hexByte(unsigned char b) {
    static constexpr char digits[] = "0123456789ABCDEF";
    return std::string{digits[b >> 4], digits[b & 15]};
}

// `s` as a message may quote it: whole UTF-8 characters as they are, each
// byte that is not part of one and each control character (tab aside) as
// "\xHH". The result is always valid UTF-8.
inline std::string printable(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size();) {
        const std::size_t len = validSequenceLength(s, i);
        const auto b = static_cast<unsigned char>(s[i]);
        if (len == 0 || (len == 1 && ((b < 0x20 && b != '\t') || b == 0x7F))) {
            out += "\\x";
            out += hexByte(b);
            ++i;
            continue;
        }
        out.append(s.substr(i, len));
        i += len;
    }
    return out;
}

inline bool isAllDigits(std::string_view s) {
    if (s.empty())
        return false;
    for (const char c : s)
        if (!isDigit(c))
            return false;
    return true;
}

inline int countDigits(std::string_view s) {
    int n = 0;
    for (const char c : s)
        n += isDigit(c) ? 1 : 0;
    return n;
}

// Significant digits of a plain decimal text: from its first non-zero digit
// to its last one that counts (leading zeros and the fraction's trailing
// zeros are not significant): "00000.00000000000000000001" has 1, "1200" 4.
inline int significantDigits(std::string_view s) {
    const std::size_t point = s.find('.');
    const std::string_view intPart = s.substr(0, point);
    const std::string_view frac = point == std::string_view::npos ? std::string_view() : s.substr(point + 1);
    std::string digits;
    for (const char c : intPart)
        if (isDigit(c))
            digits += c;
    const std::size_t lastFrac = frac.find_last_not_of('0');
    if (lastFrac != std::string_view::npos)
        for (const char c : frac.substr(0, lastFrac + 1))
            if (isDigit(c))
                digits += c;
    const std::size_t first = digits.find_first_not_of('0');
    return first == std::string::npos ? 0 : static_cast<int>(digits.size() - first);
}

// Digits after the point up to its last non-zero one: "0.0100" has 2.
inline int fractionPlaces(std::string_view s) {
    const std::size_t point = s.find('.');
    if (point == std::string_view::npos)
        return 0;
    const std::size_t last = s.find_last_not_of('0');
    return last == std::string_view::npos || last <= point ? 0 : static_cast<int>(last - point);
}

// True for "[sign]digits[.digits]" with at least one digit.
inline bool isPlainDecimal(std::string_view s) {
    std::size_t i = 0;
    if (i < s.size() && (s[i] == '+' || s[i] == '-'))
        ++i;
    int points = 0;
    int digits = 0;
    for (; i < s.size(); ++i) {
        if (s[i] == '.')
            ++points;
        else if (isDigit(s[i]))
            ++digits;
        else
            return false;
    }
    return points <= 1 && digits > 0;
}

// Digits only, at most 9 significant digits.
inline std::optional<std::int64_t> parseUnsigned(std::string_view s) {
    if (!isAllDigits(s))
        return std::nullopt;
    std::size_t i = 0;
    while (i + 1 < s.size() && s[i] == '0')
        ++i;
    if (s.size() - i > 9)
        return std::nullopt;
    std::int64_t v = 0;
    for (; i < s.size(); ++i)
        v = v * 10 + (s[i] - '0');
    return v;
}

// "[+|-]digits", at most 18 significant digits.
inline std::optional<std::int64_t> parseSigned(std::string_view s) {
    bool negative = false;
    if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
        negative = s[0] == '-';
        s.remove_prefix(1);
    }
    if (!isAllDigits(s))
        return std::nullopt;
    std::size_t i = 0;
    while (i + 1 < s.size() && s[i] == '0')
        ++i;
    if (s.size() - i > 18)
        return std::nullopt;
    std::int64_t v = 0;
    for (; i < s.size(); ++i)
        v = v * 10 + (s[i] - '0');
    return negative ? -v : v;
}

} // namespace k528::program::text
