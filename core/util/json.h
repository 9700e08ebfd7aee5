// JSON values are nlohmann-json's (Json = nlohmann::ordered_json, see
// util/json_fwd.h). What the project adds: parsing that reports a line and a
// column, and the deterministic writer of the CLI's --json output and tests.
#pragma once

#include "util/json_fwd.h"

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <string_view>

namespace k528::json {

struct ParseError : std::runtime_error {
    ParseError(const std::string& what, int line, int column)
        : std::runtime_error(what), line(line), column(column) {}
    int line;   // 1-based
    int column; // 1-based, in bytes
};

// Parses one JSON document (RFC 8259; no comments, no trailing commas; at most
// 256 arrays and objects deep). Throws ParseError with the position of the
// first problem. `callback` (nlohmann's parser callback) sees every event; it
// may throw to refuse the document. A key given twice in one object keeps its
// first place and its last value (nlohmann's rule).
Json parse(std::string_view text, const Json::parser_callback_t& callback = nullptr);

// Compact (indent < 0) or pretty-printed with `indent` spaces, like
// Json::dump, except that numbers are written by formatDouble ("100", not
// "100.0") and strings by writeString (invalid UTF-8 does not throw).
std::string dump(const Json& v, int indent = -1);

// Appends `s` to `out` as a JSON string literal (UTF-8 kept as is; a byte
// that is not part of well-formed UTF-8 becomes U+FFFD, so the output is
// always valid JSON text).
void writeString(std::string& out, std::string_view s);

// Shortest decimal text that reads back as exactly `d` ("6.214", "100", "1e-07").
std::string formatDouble(double d);

} // namespace k528::json
