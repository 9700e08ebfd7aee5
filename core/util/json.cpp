#include "util/json.h"

#include "util/utf8.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <limits>
#include <cmath>
#include <cstring>

namespace k528::json {

namespace {

[[noreturn]] void typeError(const char* expected) {
    throw std::runtime_error(std::string("JSON value is not ") + expected);
}

// Builds a Value from nlohmann-json's SAX events: the syntax is nlohmann's
// (RFC 8259, strict), the tree is ours (insertion order, exact int64).
class Builder {
public:
    explicit Builder(std::string_view text) : text_(text) {}

    bool null() { return add(Value()); }
    bool boolean(bool b) { return add(Value(b)); }
    bool number_integer(std::int64_t i) { return add(Value(static_cast<long long>(i))); }
    bool number_unsigned(std::uint64_t u) {
        if (u <= static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
            return add(Value(static_cast<long long>(u)));
        return add(Value(static_cast<double>(u)));
    }
    bool number_float(double d, const std::string&) { return add(Value(d)); }
    bool string(std::string& s) { return add(Value(std::move(s))); }
    bool binary(std::vector<std::uint8_t>&) { return false; } // not in JSON text
    bool start_object(std::size_t) { return open(Value(Object{})); }
    bool key(std::string& k) {
        key_ = std::move(k);
        return true;
    }
    bool end_object() { return close(); }
    bool start_array(std::size_t) { return open(Value(Array{})); }
    bool end_array() { return close(); }
    bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) {
        // A \u escape that is a lone surrogate is reported at its last hex
        // digit; the column points past the escape, where the string goes wrong.
        const std::string message = what(e);
        fail(message.find("surrogate") != std::string::npos ? position + 1 : position, message);
    }

    Value result() { return std::move(root_); }

private:
    static constexpr std::size_t maxDepth = 256;
    std::string_view text_;
    Value root_;
    std::vector<Value*> stack_;
    std::string key_;

    // nlohmann's message without its "[json.exception.parse_error.101] parse
    // error at line 1, column 6: syntax error while parsing value - " prefix.
    static std::string what(const nlohmann::detail::exception& e) {
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

    // `position` counts the bytes read, the offending one included.
    [[noreturn]] void fail(std::size_t position, const std::string& message) const {
        int line = 1, col = 1;
        const std::size_t end = position == 0 ? 0 : std::min(position - 1, text_.size());
        for (std::size_t i = 0; i < end; ++i) {
            if (text_[i] == '\n') {
                ++line;
                col = 1;
            } else {
                ++col;
            }
        }
        throw ParseError("JSON line " + std::to_string(line) + ", column " + std::to_string(col) +
                             ": " + message,
                         line, col);
    }

    Value* place(Value v) {
        if (stack_.empty()) {
            root_ = std::move(v);
            return &root_;
        }
        Value& parent = *stack_.back();
        if (parent.isArray()) {
            parent.asArray().push_back(std::move(v));
            return &parent.asArray().back();
        }
        parent.asObject().emplace_back(std::move(key_), std::move(v));
        return &parent.asObject().back().second;
    }
    bool add(Value v) {
        place(std::move(v));
        return true;
    }
    bool open(Value v) {
        if (stack_.size() >= maxDepth)
            throw ParseError("JSON nesting deeper than " + std::to_string(maxDepth), 1, 1);
        stack_.push_back(place(std::move(v)));
        return true;
    }
    bool close() {
        stack_.pop_back();
        return true;
    }
};

} // namespace

namespace {

void newline(std::string& out, int indent, int depth) {
    if (indent < 0)
        return;
    out += '\n';
    out.append(static_cast<std::size_t>(indent * depth), ' ');
}

} // namespace

bool Value::asBool() const {
    if (!isBool())
        typeError("a boolean");
    return std::get<bool>(v_);
}

std::int64_t Value::asInt() const {
    if (isInt())
        return std::get<std::int64_t>(v_);
    if (type() == Type::Double) {
        const double d = std::get<double>(v_);
        if (std::nearbyint(d) == d && std::fabs(d) < 9.2e18)
            return static_cast<std::int64_t>(d);
    }
    typeError("an integer");
}

double Value::asDouble() const {
    if (isInt())
        return static_cast<double>(std::get<std::int64_t>(v_));
    if (type() == Type::Double)
        return std::get<double>(v_);
    typeError("a number");
}

const std::string& Value::asString() const {
    if (!isString())
        typeError("a string");
    return std::get<std::string>(v_);
}

const Array& Value::asArray() const {
    if (!isArray())
        typeError("an array");
    return std::get<Array>(v_);
}

Array& Value::asArray() {
    if (!isArray())
        typeError("an array");
    return std::get<Array>(v_);
}

const Object& Value::asObject() const {
    if (!isObject())
        typeError("an object");
    return std::get<Object>(v_);
}

Object& Value::asObject() {
    if (!isObject())
        typeError("an object");
    return std::get<Object>(v_);
}

const Value* Value::find(std::string_view key) const {
    if (!isObject())
        return nullptr;
    for (const auto& [k, v] : std::get<Object>(v_))
        if (k == key)
            return &v;
    return nullptr;
}

Value& Value::set(std::string_view key, Value v) {
    if (isNull())
        v_ = Object{};
    auto& o = asObject();
    for (auto& [k, existing] : o) {
        if (k == key) {
            existing = std::move(v);
            return existing;
        }
    }
    o.emplace_back(std::string(key), std::move(v));
    return o.back().second;
}

Value& Value::push(Value v) {
    if (isNull())
        v_ = Array{};
    auto& a = asArray();
    a.push_back(std::move(v));
    return a.back();
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
    out += nlohmann::json(std::move(text)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
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

void Value::write(std::string& out, int indent, int depth) const {
    switch (type()) {
    case Type::Null:
        out += "null";
        break;
    case Type::Bool:
        out += std::get<bool>(v_) ? "true" : "false";
        break;
    case Type::Int:
        out += std::to_string(std::get<std::int64_t>(v_));
        break;
    case Type::Double:
        out += formatDouble(std::get<double>(v_));
        break;
    case Type::String:
        writeString(out, std::get<std::string>(v_));
        break;
    case Type::Array: {
        const auto& a = std::get<Array>(v_);
        out += '[';
        for (std::size_t i = 0; i < a.size(); ++i) {
            if (i)
                out += ',';
            newline(out, indent, depth + 1);
            a[i].write(out, indent, depth + 1);
        }
        if (!a.empty())
            newline(out, indent, depth);
        out += ']';
        break;
    }
    case Type::Object: {
        const auto& o = std::get<Object>(v_);
        out += '{';
        for (std::size_t i = 0; i < o.size(); ++i) {
            if (i)
                out += ',';
            newline(out, indent, depth + 1);
            writeString(out, o[i].first);
            out += indent < 0 ? ":" : ": ";
            o[i].second.write(out, indent, depth + 1);
        }
        if (!o.empty())
            newline(out, indent, depth);
        out += '}';
        break;
    }
    }
}

std::string Value::dump(int indent) const {
    std::string out;
    write(out, indent, 0);
    return out;
}

Value parse(std::string_view text) {
    Builder b(text);
    nlohmann::json::sax_parse(text.begin(), text.end(), &b, nlohmann::json::input_format_t::json, true,
                              false);
    return b.result();
}

} // namespace k528::json
