// A small JSON value read with nlohmann-json and written deterministically.
//
// Core may use only the standard library, Eigen and sqlite3, so the CLI's
// --json output and the machine descriptions of resources/machines are read
// and written with this. Objects keep their insertion order (output is stable
// and diff-friendly); integers are kept exactly as 64-bit values.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace k528::json {

class Value;
using Array = std::vector<Value>;
using Object = std::vector<std::pair<std::string, Value>>; // insertion order

struct ParseError : std::runtime_error {
    ParseError(const std::string& what, int line, int column)
        : std::runtime_error(what), line(line), column(column) {}
    int line;   // 1-based
    int column; // 1-based, in bytes
};

class Value {
public:
    enum class Type { Null, Bool, Int, Double, String, Array, Object };

    Value() = default;
    Value(std::nullptr_t) {}
    Value(bool b) : v_(b) {}
    Value(int i) : v_(static_cast<std::int64_t>(i)) {}
    Value(long i) : v_(static_cast<std::int64_t>(i)) {}
    Value(long long i) : v_(static_cast<std::int64_t>(i)) {}
    Value(unsigned i) : v_(static_cast<std::int64_t>(i)) {}
    Value(unsigned long i) : v_(static_cast<std::int64_t>(i)) {}
    Value(double d) : v_(d) {}
    Value(const char* s) : v_(std::string(s)) {}
    Value(std::string s) : v_(std::move(s)) {}
    Value(std::string_view s) : v_(std::string(s)) {}
    Value(Array a) : v_(std::move(a)) {}
    Value(Object o) : v_(std::move(o)) {}

    Type type() const { return static_cast<Type>(v_.index()); }
    bool isNull() const { return type() == Type::Null; }
    bool isBool() const { return type() == Type::Bool; }
    bool isInt() const { return type() == Type::Int; }
    bool isNumber() const { return type() == Type::Int || type() == Type::Double; }
    bool isString() const { return type() == Type::String; }
    bool isArray() const { return type() == Type::Array; }
    bool isObject() const { return type() == Type::Object; }

    // Accessors throw std::runtime_error naming the expected type on mismatch.
    bool asBool() const;
    std::int64_t asInt() const;  // an Int, or a Double with an integral value
    double asDouble() const;     // Int or Double
    const std::string& asString() const;
    const Array& asArray() const;
    Array& asArray();
    const Object& asObject() const;
    Object& asObject();

    // Object access. find() returns nullptr when absent (or not an object).
    const Value* find(std::string_view key) const;
    // Inserts or replaces `key` (turns a Null into an Object first).
    Value& set(std::string_view key, Value v);
    // Appends to an Array (turns a Null into an Array first).
    Value& push(Value v);

    // Compact (indent < 0) or pretty-printed with `indent` spaces.
    std::string dump(int indent = -1) const;

    friend bool operator==(const Value& a, const Value& b) { return a.v_ == b.v_; }

private:
    std::variant<std::nullptr_t, bool, std::int64_t, double, std::string, Array, Object> v_{nullptr};
    void write(std::string& out, int indent, int depth) const;
};

// Parses one JSON document (RFC 8259; no comments, no trailing commas).
// Throws ParseError with the position of the first problem.
Value parse(std::string_view text);

// Appends `s` to `out` as a JSON string literal (UTF-8 kept as is; a byte
// that is not part of well-formed UTF-8 becomes U+FFFD, so the output is
// always valid JSON text).
void writeString(std::string& out, std::string_view s);

// Shortest decimal text that reads back as exactly `d` ("6.214", "100", "1e-07").
std::string formatDouble(double d);

} // namespace k528::json
