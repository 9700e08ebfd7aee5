#include "plc/json_reader.h"

#include <cmath>

namespace k528::plc {

namespace {

std::string describe(const std::string& source, const std::string& path, const std::string& msg) {
    std::string s = source;
    if (!path.empty())
        s += ": " + path;
    s += ": " + msg;
    return s;
}

std::string typeName(const json::Value& v) {
    switch (v.type()) {
    case json::Value::Type::Null:
        return "null";
    case json::Value::Type::Bool:
        return "true/false";
    case json::Value::Type::Int:
    case json::Value::Type::Double:
        return "a number";
    case json::Value::Type::String:
        return "a string";
    case json::Value::Type::Array:
        return "an array";
    case json::Value::Type::Object:
        return "an object";
    }
    return "?";
}

} // namespace

DescriptionError::DescriptionError(std::string source, std::string path, std::string message)
    : std::runtime_error(describe(source, path, message)), source_(std::move(source)),
      path_(std::move(path)), message_(std::move(message)) {}

bool isCommentKey(std::string_view key) {
    return key == "comment" || (!key.empty() && key.front() == '_');
}

json::Value parseDocument(std::string_view text, const std::string& source) {
    try {
        return json::parse(text);
    } catch (const json::ParseError& e) {
        throw DescriptionError(source, "", e.what());
    }
}

void JsonNode::fail(const std::string& message) const {
    throw DescriptionError(source_, path_, message);
}

void JsonNode::failAt(std::string_view key, const std::string& message) const {
    throw DescriptionError(source_, childPath(key), message);
}

std::string JsonNode::childPath(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void JsonNode::expectObject() const {
    if (!v_->isObject())
        fail("expected an object, found " + typeName(*v_));
    const json::Object& o = v_->asObject();
    for (std::size_t i = 0; i < o.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (o[i].first == o[j].first)
                failAt(o[i].first, "appears twice");
}

void JsonNode::expectObject(std::initializer_list<std::string_view> allowed) const {
    expectObject();
    for (const auto& [k, v] : v_->asObject()) {
        if (isCommentKey(k))
            continue;
        bool ok = false;
        for (std::string_view a : allowed)
            ok = ok || a == k;
        if (!ok) {
            std::string list;
            for (std::string_view a : allowed)
                list += (list.empty() ? "" : ", ") + std::string(a);
            failAt(k, "unknown key (known here: " + list + ")");
        }
    }
}

bool JsonNode::has(std::string_view key) const {
    return v_->isObject() && v_->find(key) != nullptr;
}

JsonNode JsonNode::child(std::string_view key) const {
    const json::Value* c = v_->isObject() ? v_->find(key) : nullptr;
    if (!c)
        failAt(key, "is missing");
    return JsonNode(*c, source_, childPath(key));
}

JsonNode JsonNode::element(std::size_t i) const {
    return JsonNode(v_->asArray()[i], source_, path_ + "[" + std::to_string(i) + "]");
}

std::vector<JsonNode> JsonNode::elements() const {
    if (!v_->isArray())
        fail("expected an array, found " + typeName(*v_));
    std::vector<JsonNode> out;
    for (std::size_t i = 0; i < v_->asArray().size(); ++i)
        out.push_back(element(i));
    return out;
}

std::vector<JsonNode> JsonNode::optionalArray(std::string_view key) const {
    if (!has(key))
        return {};
    return child(key).elements();
}

std::vector<std::string> JsonNode::keys() const {
    std::vector<std::string> k;
    if (v_->isObject())
        for (const auto& [name, v] : v_->asObject())
            if (!isCommentKey(name))
                k.push_back(name);
    return k;
}

std::string JsonNode::asString() const {
    if (!v_->isString())
        fail("expected a string, found " + typeName(*v_));
    return v_->asString();
}

std::string JsonNode::string(std::string_view key) const {
    return child(key).asString();
}

std::string JsonNode::string(std::string_view key, std::string_view fallback) const {
    return has(key) ? string(key) : std::string(fallback);
}

std::int64_t JsonNode::asInteger(std::int64_t min, std::int64_t max) const {
    if (!v_->isNumber())
        fail("expected a whole number, found " + typeName(*v_));
    if (!v_->isInt()) {
        const double d = v_->asDouble();
        if (d != std::floor(d))
            fail("expected a whole number, found " + json::formatDouble(d));
    }
    const std::int64_t n = v_->asInt();
    if (n < min || n > max)
        fail(std::to_string(n) + " is outside " + std::to_string(min) + ".." + std::to_string(max));
    return n;
}

std::int64_t JsonNode::integer(std::string_view key, std::int64_t min, std::int64_t max) const {
    return child(key).asInteger(min, max);
}

std::int64_t JsonNode::integer(std::string_view key, std::int64_t min, std::int64_t max,
                               std::int64_t fallback) const {
    return has(key) ? integer(key, min, max) : fallback;
}

double JsonNode::number(std::string_view key, double min, double max) const {
    const JsonNode c = child(key);
    if (!c.value().isNumber())
        c.fail("expected a number, found " + typeName(c.value()));
    const double d = c.value().asDouble();
    if (!(d >= min && d <= max))
        c.fail(json::formatDouble(d) + " is outside " + json::formatDouble(min) + ".." +
               json::formatDouble(max));
    return d;
}

double JsonNode::number(std::string_view key, double min, double max, double fallback) const {
    return has(key) ? number(key, min, max) : fallback;
}

bool JsonNode::boolean(std::string_view key, bool fallback) const {
    if (!has(key))
        return fallback;
    const JsonNode c = child(key);
    if (!c.value().isBool())
        c.fail("expected true or false, found " + typeName(c.value()));
    return c.value().asBool();
}

std::vector<std::string> JsonNode::strings(std::string_view key) const {
    if (!has(key))
        return {};
    const JsonNode c = child(key);
    if (c.value().isString())
        return {c.value().asString()};
    std::vector<std::string> out;
    for (const JsonNode& e : c.elements())
        out.push_back(e.asString());
    return out;
}

} // namespace k528::plc
