// `k528 serve`, `k528 link` and `k528 shop` (after reading the database) run k528-link (link_main.cpp), the Qt half of
// the command line that loads the RS485 plugin, with the same arguments:
// k528 itself stays plain C++ (docs/link.md). k528-link is a helper, not a
// command: next to k528 in the build tree, in /usr/lib/k528studio when
// installed (helper_path.h).
#include "cli.h"
#include "cli_texts.h"
#include "helper_path.h"
#include "util/system_texts.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace k528::cli {

namespace {

int forward(const char* command, std::span<const std::string> args) {
    const std::filesystem::path helper = findHelper("k528-link");
    if (!helper.empty()) {
        std::vector<std::string> all = {helper.string(), command};
        all.insert(all.end(), args.begin(), args.end());
        std::vector<char*> argv;
        for (std::string& s : all)
            argv.push_back(s.data());
        argv.push_back(nullptr);
        ::execv(helper.c_str(), argv.data());
        std::fprintf(stderr, "k528: %s\n",
                     cliText("helper.cannot-run", {helper.string(), util::systemText(util::systemError(errno), russianCommandLine())})
                         .c_str());
        return ExitUsage;
    }
    std::fprintf(stderr, "k528: %s\n", cliText("helper.no-link", {command, helperSearchText("k528-link")}).c_str());
    return ExitUsage;
}

} // namespace

int forwardToLink(const char* command, std::span<const std::string> args) { return forward(command, args); }
int runServe(std::span<const std::string> args) { return forward("serve", args); }
int runLink(std::span<const std::string> args) { return forward("link", args); }

} // namespace k528::cli
