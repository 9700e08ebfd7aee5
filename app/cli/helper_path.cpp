#include "helper_path.h"
#include "cli.h"
#include "cli_texts.h"
#include "util/system_texts.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#ifndef K528_HELPER_DIR_FROM_BIN
#error "K528_HELPER_DIR_FROM_BIN (the helper folder relative to the program folder) comes from CMake"
#endif

namespace k528::cli {

namespace {
// The system's reason for `errnum` in the command line's language.
std::string reason(int errnum) { return util::systemText(util::systemError(errnum), russianCommandLine()); }
} // namespace

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
    return text.empty() ? cliText("helper.unknown-folder") : text;
}

bool runHelperWithInput(std::string_view name, std::string_view command, const std::vector<std::string>& args,
                        const std::function<bool(std::FILE*)>& write) {
    const std::string helper = findHelper(name).string();
    if (helper.empty()) {
        std::fprintf(stderr, "k528: %s\n",
                     cliText("helper.missing", {std::string(command), std::string(name), helperSearchText(name)}).c_str());
        return false;
    }
    int fd[2];
    if (pipe(fd) != 0) {
        std::fprintf(stderr, "k528: %s\n", cliText("helper.cannot-start", {"pipe", reason(errno)}).c_str());
        return false;
    }
    std::fflush(stdout);
    const pid_t pid = fork();
    if (pid < 0) {
        std::fprintf(stderr, "k528: %s\n", cliText("helper.cannot-start", {"fork", reason(errno)}).c_str());
        close(fd[0]);
        close(fd[1]);
        return false;
    }
    if (pid == 0) {
        dup2(fd[0], STDIN_FILENO);
        close(fd[0]);
        close(fd[1]);
        std::vector<const char*> argv{helper.c_str()};
        for (const std::string& a : args)
            argv.push_back(a.c_str());
        argv.push_back(nullptr);
        execv(helper.c_str(), const_cast<char* const*>(argv.data()));
        std::fprintf(stderr, "k528: %s\n", cliText("helper.cannot-run", {helper, reason(errno)}).c_str());
        _exit(2);
    }
    close(fd[0]);
    std::signal(SIGPIPE, SIG_IGN);
    std::FILE* pipeOut = fdopen(fd[1], "wb");
    const bool written = pipeOut && write(pipeOut);
    if (pipeOut)
        std::fclose(pipeOut);
    else
        close(fd[1]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status))
        std::fprintf(stderr, "k528: %s\n", cliText("helper.abnormal", {helper}).c_str());
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 && written;
}

} // namespace k528::cli
