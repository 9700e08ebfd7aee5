// A line's failure as a link plugin reports it over its string channels
// (BytePort's errors, openClient's): an id of core/link/link_texts.cpp and
// its arguments, "\x1f" before the id and before each argument, mapped from
// Qt's error codes (the socket's, the serial port's) so that the command
// line and the desktop say it in their language («соединение отклонено»);
// the system's own words only where Qt has no code for the failure. Header
// only: the plugins link nothing of core.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>

namespace k528::link {

inline constexpr char kLineErrorMark = '\x1f';

inline std::string lineError(std::string_view id, std::initializer_list<std::string_view> args = {}) {
    std::string t(1, kLineErrorMark);
    t += id;
    for (std::string_view a : args) {
        t += kLineErrorMark;
        t += a;
    }
    return t;
}

// For the frame log (no catalog there): "line.refused", "line.socket-other: …".
inline std::string lineErrorPlain(std::string_view error) {
    if (error.empty() || error.front() != kLineErrorMark)
        return std::string(error);
    std::string t;
    for (char c : error.substr(1))
        t += c == kLineErrorMark ? std::string(" ") : std::string(1, c);
    return t;
}

} // namespace k528::link
