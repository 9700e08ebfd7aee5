// k528-link's copy of the one helper of commands.cpp its commands use (the
// command table itself belongs to k528).
#include "cli.h"
#include "cli_texts.h"

namespace k528::cli {

int usageError(std::string_view message) {
    return usageError(message, russianCommandLine());
}

int usageError(std::string_view message, bool russian) {
    std::fprintf(stderr, "k528: %.*s\n", static_cast<int>(message.size()), message.data());
    std::fprintf(stderr, "%s\n", cliText("cli.try-help", {}, russian).c_str());
    return ExitUsage;
}

} // namespace k528::cli
