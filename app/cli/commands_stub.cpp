// k528-link's copy of the one helper of commands.cpp its commands use (the
// command table itself belongs to k528).
#include "cli.h"

namespace k528::cli {

int usageError(std::string_view message) {
    return usageError(message, russianCommandLine());
}

int usageError(std::string_view message, bool russian) {
    std::fprintf(stderr, "k528: %.*s\n", static_cast<int>(message.size()), message.data());
    std::fprintf(stderr, "%s\n", russian ? "Справка: k528 --help." : "Try 'k528 --help'.");
    return ExitUsage;
}

} // namespace k528::cli
