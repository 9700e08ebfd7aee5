#include "util/json.h"

#include "util/utf8.h"

#include <charconv>
#include <cmath>
#include <cstring>

namespace k528::json {

namespace {

[[noreturn]] void typeError(const char* expected) {
    throw std::runtime_error(std::string("JSON value is not ") + expected);
}

class Parser {
public:
    explicit Parser(std::string_view t) : t_(t) {}

    Value document() {
        skipWs();
        Value v = value(0);
        skipWs();
        if (p_ != t_.size())
            fail("unexpected text after the JSON value");
        return v;
    }

private:
    static constexpr int maxDepth = 256;
    std::string_view t_;
    std::size_t p_ = 0;

    [[noreturn]] void fail(const std::string& what) const {
        int line = 1, col = 1;
        for (std::size_t i = 0; i < p_ && i < t_.size(); ++i) {
            if (t_[i] == '\n') {
                ++line;
                col = 1;
            } else {
                ++col;
            }
        }
        throw ParseError("JSON line " + std::to_string(line) + ", column " + std::to_string(col) +
                             ": " + what,
                         line, col);
    }

    bool atEnd() const { return p_ >= t_.size(); }
    char peek() const { return atEnd() ? '\0' : t_[p_]; }

    void skipWs() {
        while (!atEnd() && (t_[p_] == ' ' || t_[p_] == '\t' || t_[p_] == '\n' || t_[p_] == '\r'))
            ++p_;
    }

    void expect(char c) {
        if (peek() != c)
            fail(std::string("expected '") + c + "'");
        ++p_;
    }

    void literal(std::string_view word) {
        if (t_.substr(p_, word.size()) != word)
            fail("invalid literal");
        p_ += word.size();
    }

    Value value(int depth) {
        if (depth > maxDepth)
            fail("nesting too deep");
        switch (peek()) {
        case '{':
            return object(depth);
        case '[':
            return array(depth);
        case '"':
            return Value(string());
        case 't':
            literal("true");
            return Value(true);
        case 'f':
            literal("false");
            return Value(false);
        case 'n':
            literal("null");
            return Value(nullptr);
        default:
            if (peek() == '-' || (peek() >= '0' && peek() <= '9'))
                return number();
            if (atEnd())
                fail("unexpected end of text");
            fail("unexpected character");
        }
    }

    Value object(int depth) {
        expect('{');
        Object o;
        skipWs();
        if (peek() == '}') {
            ++p_;
            return Value(std::move(o));
        }
        for (;;) {
            skipWs();
            if (peek() != '"')
                fail("expected a string key");
            std::string key = string();
            skipWs();
            expect(':');
            skipWs();
            o.emplace_back(std::move(key), value(depth + 1));
            skipWs();
            if (peek() == ',') {
                ++p_;
                continue;
            }
            expect('}');
            return Value(std::move(o));
        }
    }

    Value array(int depth) {
        expect('[');
        Array a;
        skipWs();
        if (peek() == ']') {
            ++p_;
            return Value(std::move(a));
        }
        for (;;) {
            skipWs();
            a.push_back(value(depth + 1));
            skipWs();
            if (peek() == ',') {
                ++p_;
                continue;
            }
            expect(']');
            return Value(std::move(a));
        }
    }

    unsigned hex4() {
        if (p_ + 4 > t_.size())
            fail("truncated \\u escape");
        unsigned v = 0;
        for (int i = 0; i < 4; ++i) {
            const char c = t_[p_++];
            v <<= 4;
            if (c >= '0' && c <= '9')
                v |= static_cast<unsigned>(c - '0');
            else if (c >= 'a' && c <= 'f')
                v |= static_cast<unsigned>(c - 'a' + 10);
            else if (c >= 'A' && c <= 'F')
                v |= static_cast<unsigned>(c - 'A' + 10);
            else
                fail("invalid \\u escape");
        }
        return v;
    }

    std::string string() {
        expect('"');
        std::string out;
        for (;;) {
            if (atEnd())
                fail("unterminated string");
            const char c = t_[p_++];
            if (c == '"')
                return out;
            if (static_cast<unsigned char>(c) < 0x20)
                fail("control character in string");
            if (c != '\\') {
                out += c;
                continue;
            }
            if (atEnd())
                fail("unterminated escape");
            const char e = t_[p_++];
            switch (e) {
            case '"':
            case '\\':
            case '/':
                out += e;
                break;
            case 'b':
                out += '\b';
                break;
            case 'f':
                out += '\f';
                break;
            case 'n':
                out += '\n';
                break;
            case 'r':
                out += '\r';
                break;
            case 't':
                out += '\t';
                break;
            case 'u': {
                unsigned cp = hex4();
                if (cp >= 0xD800 && cp <= 0xDBFF) {
                    if (t_.substr(p_, 2) != "\\u")
                        fail("unpaired surrogate");
                    p_ += 2;
                    const unsigned lo = hex4();
                    if (lo < 0xDC00 || lo > 0xDFFF)
                        fail("unpaired surrogate");
                    cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
                } else if (cp >= 0xDC00 && cp <= 0xDFFF) {
                    fail("unpaired surrogate");
                }
                utf8::append(out, static_cast<char32_t>(cp));
                break;
            }
            default:
                fail("invalid escape");
            }
        }
    }

    Value number() {
        const std::size_t start = p_;
        if (peek() == '-')
            ++p_;
        if (peek() == '0') {
            ++p_;
        } else if (peek() >= '1' && peek() <= '9') {
            while (peek() >= '0' && peek() <= '9')
                ++p_;
        } else {
            fail("invalid number");
        }
        bool integral = true;
        if (peek() == '.') {
            integral = false;
            ++p_;
            if (!(peek() >= '0' && peek() <= '9'))
                fail("invalid number");
            while (peek() >= '0' && peek() <= '9')
                ++p_;
        }
        if (peek() == 'e' || peek() == 'E') {
            integral = false;
            ++p_;
            if (peek() == '+' || peek() == '-')
                ++p_;
            if (!(peek() >= '0' && peek() <= '9'))
                fail("invalid number");
            while (peek() >= '0' && peek() <= '9')
                ++p_;
        }
        const char* b = t_.data() + start;
        const char* e = t_.data() + p_;
        if (integral) {
            std::int64_t i = 0;
            auto [ptr, ec] = std::from_chars(b, e, i);
            if (ec == std::errc() && ptr == e)
                return Value(static_cast<long long>(i));
        }
        double d = 0;
        auto [ptr, ec] = std::from_chars(b, e, d);
        if (ec != std::errc() || ptr != e)
            fail("number out of range");
        return Value(d);
    }
};

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
    out += '"';
    for (std::size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (static_cast<unsigned char>(c) >= 0x80) {
            // JSON text is UTF-8: a byte that is not part of a well-formed
            // character becomes U+FFFD.
            const std::size_t len = utf8::validLength(s, i);
            if (len == 0) {
                out += "\xEF\xBF\xBD";
            } else {
                out.append(s.substr(i, len));
                i += len - 1;
            }
            continue;
        }
        switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\r':
            out += "\\r";
            break;
        case '\t':
            out += "\\t";
            break;
        case '\b':
            out += "\\b";
            break;
        case '\f':
            out += "\\f";
            break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                static const char hex[] = "0123456789abcdef";
                out += "\\u00";
                out += hex[(c >> 4) & 0xF];
                out += hex[c & 0xF];
            } else {
                out += c;
            }
        }
    }
    out += '"';
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

Value parse(std::string_view text) { return Parser(text).document(); }

} // namespace k528::json
