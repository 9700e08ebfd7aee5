#include "util/json.h"

#include "util/utf8.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>

namespace k528::json {

namespace {

constexpr int maxDepth = 256;

// nlohmann's message without its "[json.exception.parse_error.101] parse
// error at line 1, column 6: syntax error while parsing value - " prefix.
std::string message(const Json::parse_error& e) {
    std::string m = e.what();
    for (const char* marker : {" - ", ": "}) {
        const auto p = m.rfind(marker);
        if (p != std::string::npos) {
            m = m.substr(p + std::strlen(marker));
            break;
        }
    }
    return m;
}

// The error at nlohmann's byte count (the offending byte included), with
// our line and column.
ParseError positioned(std::string_view text, const Json::parse_error& e) {
    const std::string what = message(e);
    // A \u escape that is a lone surrogate is reported at its last hex
    // digit; the column points past the escape, where the string goes wrong.
    const std::size_t position = what.find("surrogate") != std::string::npos ? e.byte + 1 : e.byte;
    int line = 1, col = 1;
    const std::size_t end = position == 0 ? 0 : std::min(position - 1, text.size());
    for (std::size_t i = 0; i < end; ++i) {
        if (text[i] == '\n') {
            ++line;
            col = 1;
        } else {
            ++col;
        }
    }
    return ParseError("JSON line " + std::to_string(line) + ", column " + std::to_string(col) +
                          ": " + what,
                      line, col);
}

void newline(std::string& out, int indent, int depth) {
    if (indent < 0)
        return;
    out += '\n';
    out.append(static_cast<std::size_t>(indent * depth), ' ');
}

void write(std::string& out, const Json& v, int indent, int depth) {
    switch (v.type()) {
    case Json::value_t::boolean:
        out += v.get<bool>() ? "true" : "false";
        break;
    case Json::value_t::number_integer:
        out += std::to_string(v.get<std::int64_t>());
        break;
    case Json::value_t::number_unsigned:
        out += std::to_string(v.get<std::uint64_t>());
        break;
    case Json::value_t::number_float:
        out += formatDouble(v.get<double>());
        break;
    case Json::value_t::string:
        writeString(out, v.get_ref<const std::string&>());
        break;
    case Json::value_t::array: {
        out += '[';
        bool first = true;
        for (const Json& e : v) {
            if (!first)
                out += ',';
            first = false;
            newline(out, indent, depth + 1);
            write(out, e, indent, depth + 1);
        }
        if (!v.empty())
            newline(out, indent, depth);
        out += ']';
        break;
    }
    case Json::value_t::object: {
        out += '{';
        bool first = true;
        for (const auto& [key, e] : v.get_ref<const Json::object_t&>()) {
            if (!first)
                out += ',';
            first = false;
            newline(out, indent, depth + 1);
            writeString(out, key);
            out += indent < 0 ? ":" : ": ";
            write(out, e, indent, depth + 1);
        }
        if (!v.empty())
            newline(out, indent, depth);
        out += '}';
        break;
    }
    default: // null; binary and discarded do not come from JSON text
        out += "null";
        break;
    }
}

} // namespace

Json parse(std::string_view text, const Json::parser_callback_t& callback) {
    const Json::parser_callback_t check = [&](int depth, Json::parse_event_t event, Json& parsed) {
        if ((event == Json::parse_event_t::object_start ||
             event == Json::parse_event_t::array_start) &&
            depth >= maxDepth)
            throw ParseError("JSON nesting deeper than " + std::to_string(maxDepth), 1, 1);
        return !callback || callback(depth, event, parsed);
    };
    try {
        return Json::parse(text.begin(), text.end(), check, true, false);
    } catch (const Json::parse_error& e) {
        throw positioned(text, e);
    }
}

std::string dump(const Json& v, int indent) {
    std::string out;
    write(out, v, indent, 0);
    return out;
}

void writeString(std::string& out, std::string_view s) {
    // JSON text is UTF-8: each byte that is not part of a well-formed
    // character becomes U+FFFD (one per byte, as utf8::validLength sees it;
    // nlohmann's error_handler_t::replace would merge a truncated sequence
    // into one), then nlohmann-json escapes the text.
    std::string text;
    if (!utf8::isValid(s)) {
        text.reserve(s.size() + 8);
        for (std::size_t i = 0; i < s.size();) {
            const std::size_t len = static_cast<unsigned char>(s[i]) < 0x80 ? 1 : utf8::validLength(s, i);
            if (len == 0) {
                text += "\xEF\xBF\xBD";
                ++i;
            } else {
                text.append(s.substr(i, len));
                i += len;
            }
        }
    } else {
        text.assign(s);
    }
    out += Json(std::move(text)).dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string formatDouble(double d) {
    if (!std::isfinite(d))
        return "null"; // JSON has no NaN/Inf
    if (d == 0)
        return "0";
    char buf[64];
    auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, d);
    (void)ec;
    return std::string(buf, ptr);
}

} // namespace k528::json
