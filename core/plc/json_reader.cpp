#include "plc/json_reader.h"

#include "plc/description_texts.h"

#include "util/json.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace k528::plc {

namespace {

using profile::problem;

std::string describe(const std::string& source, const std::string& path, const std::string& msg) {
    std::string s = source;
    if (!path.empty())
        s += ": " + path;
    s += ": " + msg;
    return s;
}

// The id of the name of v's type ("type.string": "a string").
std::string_view typeId(const Json& v) {
    switch (v.type()) {
    case Json::value_t::null:
        return "type.null";
    case Json::value_t::boolean:
        return "type.boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
        return "type.number";
    case Json::value_t::string:
        return "type.string";
    case Json::value_t::array:
        return "type.array";
    case Json::value_t::object:
        return "type.object";
    default:
        return "type.other";
    }
}

} // namespace

DescriptionError::DescriptionError(std::string source, std::string path, profile::Problem p)
    : std::runtime_error(describe(source, path, descriptionText(p, false))), source_(std::move(source)),
      path_(std::move(path)), problem_(std::move(p)) {}

std::string DescriptionError::message() const { return descriptionText(problem_, false); }

std::string DescriptionError::text(bool russian) const {
    return describe(source_, path_, descriptionText(problem_, russian));
}

bool isCommentKey(std::string_view key) {
    return key == "comment" || (!key.empty() && key.front() == '_');
}

Json parseDocument(std::string_view text, const std::string& source) {
    // nlohmann keeps one entry for a key given twice; a description must not
    // have one (one of the two would be silently lost), so the parse stops at
    // the second with the key's path ("logic", "inputs[0].name").
    struct Level {
        bool array = false;
        std::size_t index = 0;         // of the element being read (arrays)
        std::vector<std::string> keys; // so far (objects); back() is being read
    };
    std::vector<Level> levels;
    const auto keyCheck = [&](int, Json::parse_event_t event, Json& parsed) {
        switch (event) {
        case Json::parse_event_t::object_start:
        case Json::parse_event_t::array_start:
            levels.push_back({event == Json::parse_event_t::array_start, 0, {}});
            break;
        case Json::parse_event_t::key: {
            const std::string& key = parsed.get_ref<const std::string&>();
            std::vector<std::string>& keys = levels.back().keys;
            if (std::find(keys.begin(), keys.end(), key) != keys.end()) {
                std::string path;
                for (std::size_t i = 0; i + 1 < levels.size(); ++i)
                    path += levels[i].array ? "[" + std::to_string(levels[i].index) + "]"
                                            : (path.empty() ? "" : ".") + levels[i].keys.back();
                throw DescriptionError(source, path.empty() ? key : path + "." + key,
                                       problem("json.twice"));
            }
            keys.push_back(key);
            break;
        }
        case Json::parse_event_t::object_end:
        case Json::parse_event_t::array_end:
            levels.pop_back();
            [[fallthrough]];
        case Json::parse_event_t::value:
            if (!levels.empty() && levels.back().array)
                ++levels.back().index;
            break;
        }
        return true;
    };
    try {
        return json::parse(text, keyCheck);
    } catch (const json::ParseError& e) {
        throw DescriptionError(source, "",
                               problem("json.syntax", {e.what(), std::to_string(e.line), std::to_string(e.column)}));
    }
}

void JsonNode::fail(profile::Problem p) const {
    throw DescriptionError(source_, path_, std::move(p));
}

void JsonNode::failAt(std::string_view key, profile::Problem p) const {
    throw DescriptionError(source_, childPath(key), std::move(p));
}

std::string JsonNode::childPath(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

bool JsonNode::isObject() const {
    return v_->is_object();
}

bool JsonNode::isArray() const {
    return v_->is_array();
}

bool JsonNode::isString() const {
    return v_->is_string();
}

void JsonNode::expectObject() const {
    // (a key given twice is refused by parseDocument)
    if (!v_->is_object())
        fail(withText("json.expected-object", {}, typeId(*v_)));
}

void JsonNode::expectObject(std::initializer_list<std::string_view> allowed) const {
    expectObject();
    for (const auto& [k, v] : v_->get_ref<const Json::object_t&>()) {
        if (isCommentKey(k))
            continue;
        bool ok = false;
        for (std::string_view a : allowed)
            ok = ok || a == k;
        if (!ok) {
            std::string list;
            for (std::string_view a : allowed)
                list += (list.empty() ? "" : ", ") + std::string(a);
            failAt(k, problem("json.unknown-key", {list}));
        }
    }
}

bool JsonNode::has(std::string_view key) const {
    return v_->is_object() && v_->contains(key);
}

JsonNode JsonNode::child(std::string_view key) const {
    if (v_->is_object())
        if (const auto it = v_->find(key); it != v_->end())
            return JsonNode(*it, source_, childPath(key));
    failAt(key, problem("json.missing"));
}

JsonNode JsonNode::element(std::size_t i) const {
    return JsonNode(v_->at(i), source_, path_ + "[" + std::to_string(i) + "]");
}

std::vector<JsonNode> JsonNode::elements() const {
    if (!v_->is_array())
        fail(withText("json.expected-array", {}, typeId(*v_)));
    std::vector<JsonNode> out;
    for (std::size_t i = 0; i < v_->size(); ++i)
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
    if (v_->is_object())
        for (const auto& [name, v] : v_->get_ref<const Json::object_t&>())
            if (!isCommentKey(name))
                k.push_back(name);
    return k;
}

std::string JsonNode::asString() const {
    if (!v_->is_string())
        fail(withText("json.expected-string", {}, typeId(*v_)));
    return v_->get<std::string>();
}

std::string JsonNode::string(std::string_view key) const {
    return child(key).asString();
}

std::string JsonNode::string(std::string_view key, std::string_view fallback) const {
    return has(key) ? string(key) : std::string(fallback);
}

std::int64_t JsonNode::asInteger(std::int64_t min, std::int64_t max) const {
    if (!v_->is_number())
        fail(withText("json.expected-integer", {}, typeId(*v_)));
    const auto outside = [&](const std::string& n) {
        fail(problem("json.outside", {n, std::to_string(min), std::to_string(max)}));
    };
    std::int64_t n = 0;
    if (v_->is_number_float()) { // 2.0 is the whole number 2
        const double d = v_->get<double>();
        if (d != std::floor(d))
            fail(problem("json.expected-integer", {json::formatDouble(d)}));
        if (!(std::fabs(d) < 9.2e18))
            outside(json::formatDouble(d));
        n = static_cast<std::int64_t>(d);
    } else if (v_->is_number_unsigned()) {
        const std::uint64_t u = v_->get<std::uint64_t>();
        if (u > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
            outside(std::to_string(u));
        n = static_cast<std::int64_t>(u);
    } else {
        n = v_->get<std::int64_t>();
    }
    if (n < min || n > max)
        outside(std::to_string(n));
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
    if (!c.value().is_number())
        c.fail(withText("json.expected-number", {}, typeId(c.value())));
    const double d = c.value().get<double>();
    if (!(d >= min && d <= max))
        c.fail(problem("json.outside", {json::formatDouble(d), json::formatDouble(min), json::formatDouble(max)}));
    return d;
}

double JsonNode::number(std::string_view key, double min, double max, double fallback) const {
    return has(key) ? number(key, min, max) : fallback;
}

bool JsonNode::boolean(std::string_view key, bool fallback) const {
    if (!has(key))
        return fallback;
    const JsonNode c = child(key);
    if (!c.value().is_boolean())
        c.fail(withText("json.expected-bool", {}, typeId(c.value())));
    return c.value().get<bool>();
}

std::vector<std::string> JsonNode::strings(std::string_view key) const {
    if (!has(key))
        return {};
    const JsonNode c = child(key);
    if (c.value().is_string())
        return {c.value().get<std::string>()};
    std::vector<std::string> out;
    for (const JsonNode& e : c.elements())
        out.push_back(e.asString());
    return out;
}

} // namespace k528::plc
