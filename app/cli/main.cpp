// k528 — the command line of K528 Studio (shared/spec/cli.md).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include <unistd.h>

#include "cli.h"
#include "cli_texts.h"
#include "output_file.h"
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

int dispatch(int argc, char** argv) {
    const bool ru = russianCommandLine();
    if (argc < 2) {
        printHelp();
        return ExitUsage;
    }
    const std::string first = argv[1];
    if (first == "--version" || first == "version") {
        if (argc > 2)
            return usageError(cliText("cli.no-args", {first, argv[2]}, ru));
        printVersion();
        return ExitOk;
    }
    if (first == "--help" || first == "-h" || first == "help") {
        if (first != "help" && argc > 2)
            return usageError(cliText("cli.no-args", {first, argv[2]}, ru));
        if (first == "help" && argc > 3)
            return usageError(cliText("cli.help-one", {argv[3]}, ru));
        if (first == "help" && argc > 2) {
            for (const auto& c : commands())
                if (c.name == argv[2]) {
                    printCommandHelp(c, stdout);
                    return ExitOk;
                }
            return usageError(cliText("cli.unknown-command", {argv[2]}, ru));
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
        return usageError(cliText("opt.unknown", {first}, ru));
    return usageError(cliText("cli.unknown-command", {first}, ru));
}

} // namespace

// No command ends on an uncaught exception: whatever escapes a command
// becomes one message and exit code 2.
int main(int argc, char** argv) {
    // Output to a file or a pipe is kept whole until the end (16 MiB, far more
    // than any command prints; pages are touched only as they fill), so that
    // a lost write is seen by finishStandardOutput() with its reason.
    if (!::isatty(STDOUT_FILENO)) {
        static char buffer[std::size_t{16} << 20];
        std::setvbuf(stdout, buffer, _IOFBF, sizeof buffer);
    }
    int rc = ExitUsage;
    readCommandLineLanguage(std::vector<std::string>(argv + 1, argv + argc));
    const bool ru = russianCommandLine();
    try {
        rc = dispatch(argc, argv);
    } catch (const std::bad_alloc&) {
        std::fflush(stdout);
        const std::string_view said = cliWords("cli.no-memory", ru);
        std::fprintf(stderr, "%.*s\n", static_cast<int>(said.size()), said.data());
        return ExitUsage;
    } catch (const std::exception& e) {
        std::fflush(stdout);
        std::fprintf(stderr, "%s\n", cliText("cli.internal", {e.what()}, ru).c_str());
        return ExitUsage;
    } catch (...) {
        std::fflush(stdout);
        std::fprintf(stderr, "%s\n", cliText("cli.internal-unknown", {}, ru).c_str());
        return ExitUsage;
    }
    return finishStandardOutput(rc);
}
