// `k528 serve`, `k528 link` and `k528 shop` (after reading the database) run k528-link (link_main.cpp), the Qt half of
// the command line that loads the RS485 plugin, with the same arguments:
// k528 itself stays plain C++ (docs/link.md). k528-link is looked for next
// to k528 (build tree, /usr/bin) and in ../libexec/k528.
#include "cli.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace k528::cli {

namespace {

int forward(const char* command, std::span<const std::string> args) {
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    std::vector<std::filesystem::path> candidates;
    if (!ec) {
        candidates.push_back(self.parent_path() / "k528-link");
        candidates.push_back(self.parent_path().parent_path() / "libexec" / "k528" / "k528-link");
    }
    for (const auto& c : candidates) {
        if (::access(c.c_str(), X_OK) != 0)
            continue;
        std::vector<std::string> all = {c.string(), command};
        all.insert(all.end(), args.begin(), args.end());
        std::vector<char*> argv;
        for (std::string& s : all)
            argv.push_back(s.data());
        argv.push_back(nullptr);
        ::execv(c.c_str(), argv.data());
        std::fprintf(stderr, "k528: cannot run %s: %s\n", c.c_str(), std::strerror(errno));
        return ExitUsage;
    }
    std::fprintf(stderr,
                 "k528: %s needs k528-link (the Qt SerialBus half of the command line), which is not "
                 "installed next to k528\n",
                 command);
    return ExitUsage;
}

} // namespace

int forwardToLink(const char* command, std::span<const std::string> args) { return forward(command, args); }
int runServe(std::span<const std::string> args) { return forward("serve", args); }
int runLink(std::span<const std::string> args) { return forward("link", args); }

} // namespace k528::cli
