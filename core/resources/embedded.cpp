#include "resources/embedded.h"

#include <algorithm>

namespace k528::resources {

std::optional<std::string_view> find(std::string_view path) {
    const auto files = all();
    const auto it = std::lower_bound(files.begin(), files.end(), path,
                                     [](const Resource& r, std::string_view p) { return r.path < p; });
    if (it != files.end() && it->path == path)
        return it->data;
    return std::nullopt;
}

std::vector<Resource> under(std::string_view prefix) {
    std::vector<Resource> out;
    for (const auto& r : all())
        if (r.path.substr(0, prefix.size()) == prefix)
            out.push_back(r);
    return out;
}

} // namespace k528::resources
