// UTF-8 text helpers. Russian texts (panel screens, messages, diagnostics)
// are UTF-8 everywhere; the K923 LCD counts characters, not bytes.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace k528::utf8 {

// True if `s` is well-formed UTF-8 (no overlongs, no surrogates).
bool isValid(std::string_view s);

// Length of the well-formed character at s[i] (no overlongs, no
// surrogates, at most U+10FFFF), or 0 if s[i] does not start one.
std::size_t validLength(std::string_view s, std::size_t i);

// Decodes `s` into code points; malformed bytes become U+FFFD.
std::vector<char32_t> decode(std::string_view s);

// Encodes one code point / a sequence of code points.
void append(std::string& out, char32_t cp);
std::string encode(const std::vector<char32_t>& cps);

// Number of code points in `s` (malformed bytes count one each).
std::size_t length(std::string_view s);

// The first `n` code points of `s`, then padded with spaces to exactly `n`.
std::string fitWidth(std::string_view s, std::size_t n);

// Upper case for ASCII and Cyrillic (А-Я, Ё); other characters unchanged.
std::string toUpper(std::string_view s);

} // namespace k528::utf8
