#include "profile/builtin.h"

#include "profile/text_format.h"
#include "resources/embedded.h"

#include <filesystem>
#include <system_error>

namespace k528::profile {

namespace {

constexpr std::string_view kDir = "profiles/";
constexpr std::string_view kExt = ".k528m";

std::string builtinList() {
    std::string s;
    for (const auto& n : builtinNames())
        s += (s.empty() ? "" : ", ") + n;
    return s;
}

} // namespace

std::vector<std::string> builtinNames() {
    std::vector<std::string> names;
    for (const auto& r : resources::under(kDir)) {
        std::string_view p = r.path.substr(kDir.size());
        if (p.size() > kExt.size() && p.substr(p.size() - kExt.size()) == kExt &&
            p.find('/') == std::string_view::npos)
            names.emplace_back(p.substr(0, p.size() - kExt.size()));
    }
    return names; // resources are sorted by path
}

bool isBuiltin(std::string_view name) {
    return resources::find(std::string(kDir) + std::string(name) + std::string(kExt)).has_value();
}

std::string_view builtinText(std::string_view name) {
    const auto data = resources::find(std::string(kDir) + std::string(name) + std::string(kExt));
    if (!data)
        throw FileError(std::string(name), 0, problem("builtin.unknown", {builtinList()}));
    return *data;
}

MachineProfile builtin(std::string_view name) {
    return readMachineText(builtinText(name), std::string(name));
}

MachineProfile load(std::string_view nameOrPath) {
    if (nameOrPath.empty())
        throw FileError("", 0, problem("builtin.none-given", {builtinList()}));
    if (isBuiltin(nameOrPath))
        return builtin(nameOrPath);
    const std::filesystem::path path{std::string(nameOrPath)};
    std::error_code ec;
    // Something that exists but is no regular file (/dev/zero, a FIFO) is
    // refused by readMachineFile with its reason.
    if (!std::filesystem::exists(path, ec))
        throw FileError(std::string(nameOrPath), 0, problem("builtin.neither", {builtinList()}));
    return readMachineFile(path);
}

} // namespace k528::profile
