#include "helper_path.h"

#include <string>
#include <unistd.h>

#ifndef K528_HELPER_DIR_FROM_BIN
#error "K528_HELPER_DIR_FROM_BIN (the helper folder relative to the program folder) comes from CMake"
#endif

namespace k528::cli {

std::vector<std::filesystem::path> helperCandidates(std::string_view name) {
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec)
        return {};
    const std::filesystem::path bin = self.parent_path();
    return {bin / name, (bin / K528_HELPER_DIR_FROM_BIN / name).lexically_normal()};
}

std::filesystem::path findHelper(std::string_view name) {
    for (const auto& c : helperCandidates(name))
        if (::access(c.c_str(), X_OK) == 0)
            return c;
    return {};
}

std::string helperSearchText(std::string_view name) {
    std::string text;
    for (const auto& c : helperCandidates(name)) {
        if (!text.empty())
            text += ", ";
        text += c.string();
    }
    return text.empty() ? std::string("(k528's own folder is unknown)") : text;
}

} // namespace k528::cli
