// k528 plot [options] --out FILE.png FILE — the backplot offscreen to a PNG
// (shared/spec/cli.md). The path is computed here, in the core, exactly as
// `k528 path` does it; the drawing is done by k528-plot (the VTK scene of the
// studio's backplot, app/studio/backplot/), a helper found as
// helper_path.h says, which this feeds through a pipe (toolpath/path_io.h), so that `k528`
// never loads VTK. Debian's VTK needs an X server: run under
// xvfb-run -a -s "-screen 0 1280x800x24".
#include "cli.h"
#include "helper_path.h"
#include "program_setup.h"
#include "stock/stock.h"
#include "toolpath/path_io.h"

#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>

namespace k528::cli {

int runPlot(std::span<const std::string> argv) {
    std::vector<std::string_view> options = kSetupOptions;
    options.insert(options.end(), {"--size", "--out", "--view", "--max-frames"});
    const Args args(argv, {}, options);
    if (!args.ok())
        return usageError(args.error());
    const auto out = args.value("--out");
    if (!out || out->empty())
        return usageError("plot needs --out FILE.png");
    const std::string size = args.value("--size").value_or("1280x800");
    int w = 0, h = 0;
    if (std::sscanf(size.c_str(), "%dx%d", &w, &h) != 2 || w < 16 || h < 16 || w > 8192 || h > 8192)
        return usageError("--size is WxH with 16..8192 pixels each, not '" + size + "'");
    const std::string view = args.value("--view").value_or("xz");
    if (view != "xz" && view != "3d")
        return usageError("--view is xz or 3d, not '" + view + "'");
    ProgramSetup setup;
    if (const int rc = loadProgramSetup(args, setup, stdout); rc >= 0)
        return rc;
    toolpath::PathOptions po;
    po.preview.rPresets = setup.rPresets;
    if (const auto m = args.value("--max-frames")) {
        const auto v = parseInt(*m);
        if (!v || *v < 1 || *v > 100'000'000)
            return usageError("--max-frames needs a whole number 1..100000000, not '" + *m + "'");
        po.preview.maxFrames = *v;
    }
    const toolpath::ProgrammedPath path =
        toolpath::programmedPath(setup.profile, setup.store, setup.number, po);
    // The blank kept with the file (a comment holding UCG,...).
    std::string text, ucg;
    if (readProgramFile(args.positional().front(), text))
        if (const auto b = stock::findUcg(text))
            ucg = stock::formatUcg(*b);

    const std::string renderer = findHelper("k528-plot").string();
    if (renderer.empty()) {
        std::fprintf(stderr, "k528: plot needs the renderer k528-plot (built with the desktop program; looked for %s)\n",
                     helperSearchText("k528-plot").c_str());
        return ExitUsage;
    }
    int fd[2];
    if (pipe(fd) != 0) {
        std::fprintf(stderr, "k528: pipe: %s\n", std::strerror(errno));
        return ExitUsage;
    }
    const pid_t pid = fork();
    if (pid < 0) {
        std::fprintf(stderr, "k528: fork: %s\n", std::strerror(errno));
        return ExitUsage;
    }
    if (pid == 0) {
        dup2(fd[0], STDIN_FILENO);
        close(fd[0]);
        close(fd[1]);
        std::string sz = std::to_string(w) + "x" + std::to_string(h);
        const char* a[] = {renderer.c_str(), "--out", out->c_str(), "--size", sz.c_str(),
                           "--view",         view.c_str(), nullptr};
        execv(renderer.c_str(), const_cast<char* const*>(a));
        std::fprintf(stderr, "k528: cannot run %s: %s\n", renderer.c_str(), std::strerror(errno));
        _exit(ExitUsage);
    }
    close(fd[0]);
    std::signal(SIGPIPE, SIG_IGN);
    std::FILE* pipeOut = fdopen(fd[1], "wb");
    const bool written = pipeOut && toolpath::writePath(pipeOut, path, ucg);
    if (pipeOut)
        std::fclose(pipeOut);
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !written) {
        if (!WIFEXITED(status))
            std::fprintf(stderr, "k528: the renderer %s stopped abnormally\n", renderer.c_str());
        return ExitUsage;
    }
    for (const toolpath::Segment& s : path.segments)
        if (s.outside)
            std::fprintf(stderr, "L%d N%d line %d: ВНЕ ГРАНИЦ\n", s.program, s.n, s.line);
    return path.run.status == engine::PreviewStatus::Alarm ? ExitInputErrors : ExitOk;
}

} // namespace k528::cli
