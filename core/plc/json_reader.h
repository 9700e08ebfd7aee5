// Strict reading of a JSON document with errors that name the file and the
// path inside the document ("logic[4].when"), for the machine descriptions
// of resources/machines (docs/machine-description.md). Every object's keys are
// checked: an unknown key is an error (a typo must not be silently ignored);
// keys "comment" and those starting with '_' are comments and skipped.
#pragma once

#include "profile/problem.h"
#include "util/json_fwd.h"

#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace k528::plc {

// A machine description that cannot be used: what is wrong as an id and its
// arguments (description_texts.h); what() is "file: path: message" in English.
class DescriptionError : public std::runtime_error {
public:
    DescriptionError(std::string source, std::string path, profile::Problem problem);
    const std::string& source() const { return source_; }
    const std::string& path() const { return path_; } // "" for the whole document
    const profile::Problem& problem() const { return problem_; }
    // What is wrong, in English (without file and path).
    std::string message() const;
    // "file: path: message" in a language (the command line's words).
    std::string text(bool russian) const;

private:
    std::string source_, path_;
    profile::Problem problem_;
};

// One node of the document being read, with its path.
class JsonNode {
public:
    JsonNode(const Json& v, std::string source, std::string path)
        : v_(&v), source_(std::move(source)), path_(std::move(path)) {}

    const Json& value() const { return *v_; }
    const std::string& path() const { return path_; }
    const std::string& source() const { return source_; }
    [[noreturn]] void fail(profile::Problem problem) const;
    [[noreturn]] void failAt(std::string_view key, profile::Problem problem) const;

    bool isObject() const;
    bool isArray() const;
    bool isString() const;

    // This node must be an object whose keys are among `allowed` (comments aside).
    void expectObject(std::initializer_list<std::string_view> allowed) const;
    void expectObject() const; // any keys
    bool has(std::string_view key) const;
    JsonNode child(std::string_view key) const;                      // must exist
    JsonNode element(std::size_t i) const;                           // of an array
    std::vector<JsonNode> elements() const;                          // this node must be an array
    std::vector<JsonNode> optionalArray(std::string_view key) const; // absent -> empty
    std::vector<std::string> keys() const; // object keys in order (comments aside)

    std::string string(std::string_view key) const; // required
    std::string string(std::string_view key, std::string_view fallback) const;
    std::string asString() const;
    std::int64_t integer(std::string_view key, std::int64_t min, std::int64_t max) const;
    std::int64_t integer(std::string_view key, std::int64_t min, std::int64_t max,
                         std::int64_t fallback) const;
    std::int64_t asInteger(std::int64_t min, std::int64_t max) const;
    double number(std::string_view key, double min, double max, double fallback) const;
    double number(std::string_view key, double min, double max) const;
    bool boolean(std::string_view key, bool fallback) const;
    // A string or an array of strings (absent -> empty).
    std::vector<std::string> strings(std::string_view key) const;

private:
    std::string childPath(std::string_view key) const;
    const Json* v_;
    std::string source_, path_;
};

// Parses `text` as JSON; a syntax error becomes a DescriptionError with its
// line and column, a key given twice in one object one with the key's path.
Json parseDocument(std::string_view text, const std::string& source);

bool isCommentKey(std::string_view key);

} // namespace k528::plc
