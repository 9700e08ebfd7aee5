// Data files of resources/ compiled into the core library: machine profiles,
// machine descriptions and sample programs, available wherever the binaries
// run (build tree, installed package, tests) without a search path.
#pragma once

#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace k528::resources {

struct Resource {
    std::string_view path; // relative to resources/, '/' separators, e.g. "profiles/grinder-205.k528m"
    std::string_view data; // the file's bytes
};

// Every embedded file, sorted by path.
std::span<const Resource> all();

// The file at `path`, if embedded.
std::optional<std::string_view> find(std::string_view path);

// Every embedded file whose path starts with `prefix` (e.g. "samples/").
std::vector<Resource> under(std::string_view prefix);

} // namespace k528::resources
