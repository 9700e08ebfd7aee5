#include "util/utf8.h"

namespace k528::utf8 {

namespace {

// Decodes one code point at s[i]; returns its byte length, or 0 if malformed.
std::size_t decodeOne(std::string_view s, std::size_t i, char32_t& cp) {
    const auto b0 = static_cast<unsigned char>(s[i]);
    if (b0 < 0x80) {
        cp = b0;
        return 1;
    }
    std::size_t len = 0;
    char32_t min = 0;
    if ((b0 & 0xE0) == 0xC0) {
        len = 2;
        cp = b0 & 0x1F;
        min = 0x80;
    } else if ((b0 & 0xF0) == 0xE0) {
        len = 3;
        cp = b0 & 0x0F;
        min = 0x800;
    } else if ((b0 & 0xF8) == 0xF0) {
        len = 4;
        cp = b0 & 0x07;
        min = 0x10000;
    } else {
        return 0;
    }
    if (i + len > s.size())
        return 0;
    for (std::size_t k = 1; k < len; ++k) {
        const auto b = static_cast<unsigned char>(s[i + k]);
        if ((b & 0xC0) != 0x80)
            return 0;
        cp = (cp << 6) | (b & 0x3F);
    }
    if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
        return 0;
    return len;
}

} // namespace

std::size_t validLength(std::string_view s, std::size_t i) {
    char32_t cp;
    return decodeOne(s, i, cp);
}

bool isValid(std::string_view s) {
    const auto* const p = reinterpret_cast<const unsigned char*>(s.data());
    for (std::size_t i = 0; i < s.size();) {
        // ASCII and two-byte sequences (U+0080..U+07FF: the Cyrillic of
        // comments and texts) without decoding: no overlong form, no
        // surrogate among them. Anything else is decoded and checked whole.
        if (p[i] < 0x80) {
            ++i;
            continue;
        }
        if (p[i] >= 0xC2 && p[i] <= 0xDF && i + 1 < s.size() && (p[i + 1] & 0xC0) == 0x80) {
            i += 2;
            continue;
        }
        char32_t cp;
        const std::size_t n = decodeOne(s, i, cp);
        if (n == 0)
            return false;
        i += n;
    }
    return true;
}

std::vector<char32_t> decode(std::string_view s) {
    std::vector<char32_t> out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size();) {
        char32_t cp;
        const std::size_t n = decodeOne(s, i, cp);
        if (n == 0) {
            out.push_back(0xFFFD);
            ++i;
        } else {
            out.push_back(cp);
            i += n;
        }
    }
    return out;
}

void append(std::string& out, char32_t cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

std::string encode(const std::vector<char32_t>& cps) {
    std::string out;
    out.reserve(cps.size() * 2);
    for (const char32_t cp : cps)
        append(out, cp);
    return out;
}

std::size_t length(std::string_view s) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < s.size();) {
        char32_t cp;
        const std::size_t k = decodeOne(s, i, cp);
        i += k == 0 ? 1 : k;
        ++n;
    }
    return n;
}

std::string fitWidth(std::string_view s, std::size_t n) {
    auto cps = decode(s);
    cps.resize(n, U' ');
    return encode(cps);
}

std::string toUpper(std::string_view s) {
    auto cps = decode(s);
    for (auto& cp : cps) {
        if (cp >= U'a' && cp <= U'z')
            cp -= 0x20;
        else if (cp >= 0x430 && cp <= 0x44F) // а..я
            cp -= 0x20;
        else if (cp == 0x451) // ё
            cp = 0x401;
    }
    return encode(cps);
}

} // namespace k528::utf8
