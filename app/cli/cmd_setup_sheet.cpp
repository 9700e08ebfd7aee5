// k528 setup-sheet [options] --out FILE.pdf FILE — the setup sheet (карта
// наладки, handbook 14.3; shared/spec/cli.md, docs/cli-decisions.md): the
// machine, the blank, the tools with their stations and offsets, the
// programs with their cycle times, the R-parameters to preset. The content
// is core's (proveout/setup_sheet.h); the PDF is written by k528-sheet (Qt's
// QTextDocument and QPdfWriter, app/studio/sheet/), a helper found as
// helper_path.h says, which this feeds the sheet as JSON through a pipe, so
// that `k528` never loads Qt.
#include "cli.h"
#include "helper_path.h"
#include "plc/description.h"
#include "program_setup.h"
#include "proveout/setup_sheet.h"
#include "proveout_cli.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>

namespace k528::cli {

int runSetupSheet(std::span<const std::string> argv) {
    std::vector<std::string_view> options = kSetupOptions;
    options.insert(options.end(), {"--out", kBlankOption});
    const Args args(argv, {"--json", "--no-cycle-times"}, options);
    if (!args.ok())
        return usageError(args.error());
    const bool asJson = args.has("--json");
    const auto out = args.value("--out");
    if ((!out || out->empty()) && !asJson)
        return usageError("setup-sheet needs --out FILE.pdf (or --json)");
    ProgramSetup setup;
    if (const int rc = loadProgramSetup(args, setup, asJson ? stderr : stdout); rc >= 0)
        return rc;
    std::optional<stock::Blank> blank;
    if (!blankFor(args, setup.text, blank))
        return ExitUsage;
    proveout::SetupSheet sheet;
    try {
        sheet = proveout::setupSheet(setup.profile, setup.store, setup.text,
                                     std::filesystem::path(args.positional().front()).filename().string(),
                                     setup.rPresets, blank, !args.has("--no-cycle-times"));
    } catch (const plc::DescriptionError& e) {
        std::fprintf(stderr, "k528: machine description %s\n", e.what());
        return ExitUsage;
    } catch (const profile::ToolError& e) {
        std::fprintf(stderr, "k528: the machine's tools: %s\n", e.what());
        return ExitUsage;
    }
    const std::string text = proveout::sheetJson(sheet);
    if (asJson)
        std::fprintf(stdout, "%s\n", text.c_str());
    if (!out || out->empty())
        return ExitOk;

    const std::string renderer = findHelper("k528-sheet").string();
    if (renderer.empty()) {
        std::fprintf(stderr,
                     "k528: setup-sheet needs the renderer k528-sheet (built with the desktop program; looked for %s)\n",
                     helperSearchText("k528-sheet").c_str());
        return ExitUsage;
    }
    int fd[2];
    if (pipe(fd) != 0) {
        std::fprintf(stderr, "k528: pipe: %s\n", std::strerror(errno));
        return ExitUsage;
    }
    std::fflush(stdout);
    const pid_t pid = fork();
    if (pid < 0) {
        std::fprintf(stderr, "k528: fork: %s\n", std::strerror(errno));
        return ExitUsage;
    }
    if (pid == 0) {
        dup2(fd[0], STDIN_FILENO);
        close(fd[0]);
        close(fd[1]);
        const char* lang = setup.lang == Lang::Ru ? "ru" : "en";
        const char* a[] = {renderer.c_str(), "--out", out->c_str(), "--lang", lang, nullptr};
        execv(renderer.c_str(), const_cast<char* const*>(a));
        std::fprintf(stderr, "k528: cannot run %s: %s\n", renderer.c_str(), std::strerror(errno));
        _exit(ExitUsage);
    }
    close(fd[0]);
    std::signal(SIGPIPE, SIG_IGN);
    std::FILE* pipeOut = fdopen(fd[1], "wb");
    const bool written = pipeOut && std::fwrite(text.data(), 1, text.size(), pipeOut) == text.size();
    if (pipeOut)
        std::fclose(pipeOut);
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !written) {
        if (!WIFEXITED(status))
            std::fprintf(stderr, "k528: the renderer %s stopped abnormally\n", renderer.c_str());
        return ExitUsage;
    }
    return ExitOk;
}

} // namespace k528::cli
