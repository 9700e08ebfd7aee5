// k528 — the command line of K528 Studio (shared/spec/cli.md).
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "cli.h"
#include "util/version.h"

using namespace k528::cli;

namespace {

void printVersion() {
    std::printf("k528 %s (K528 Studio)\n", k528::version_string);
}

void printHelp() {
    std::printf("Usage: k528 COMMAND [OPTIONS] [ARGS]\n"
                "       k528 --version | --help\n\n"
                "The command line of K528 Studio, a workstation for the Konstar K528-05\n"
                "two-axis positioning controller and its K923 operator panel.\n\n"
                "Commands:\n");
    for (const auto& c : commands())
        std::printf("  %-10.*s %.*s\n", static_cast<int>(c.name.size()), c.name.data(),
                    static_cast<int>(c.summary.size()), c.summary.data());
    std::printf("\nOptions:\n"
                "  --version  print the version and exit\n"
                "  --help     print this help and exit\n\n"
                "'k528 COMMAND --help' describes one command.\n"
                "Exit codes: 0 success; 1 the input has errors (diagnostics printed, or the run\n"
                "ended in an alarm); 2 usage or I/O error.\n");
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        printHelp();
        return ExitUsage;
    }
    const std::string first = argv[1];
    if (first == "--version" || first == "version") {
        printVersion();
        return ExitOk;
    }
    if (first == "--help" || first == "-h" || first == "help") {
        if (first == "help" && argc > 2) {
            for (const auto& c : commands())
                if (c.name == argv[2]) {
                    printCommandHelp(c, stdout);
                    return ExitOk;
                }
            return usageError(std::string("unknown command '") + argv[2] + "'");
        }
        printHelp();
        return ExitOk;
    }
    for (const auto& c : commands()) {
        if (c.name != first)
            continue;
        std::vector<std::string> args(argv + 2, argv + argc);
        for (const auto& a : args)
            if (a == "--help" || a == "-h") {
                printCommandHelp(c, stdout);
                return ExitOk;
            }
        return c.run(args);
    }
    if (first.rfind("-", 0) == 0)
        return usageError("unknown option " + first);
    return usageError("unknown command '" + first + "'");
}
