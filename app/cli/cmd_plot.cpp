// k528 plot [options] --out FILE.png FILE — the backplot offscreen to a PNG
// (shared/spec/cli.md). The path is computed here, in the core, exactly as
// `k528 path` does it; the drawing is done by k528-plot (the VTK scene of the
// studio's backplot, app/studio/backplot/), a helper found as
// helper_path.h says, which this feeds through a pipe (toolpath/path_io.h), so that `k528`
// never loads VTK. Debian's VTK needs an X server: run under
// xvfb-run -a -s "-screen 0 1280x800x24".
#include "cli.h"
#include "cli_texts.h"
#include "helper_path.h"
#include "program_setup.h"
#include "stock/stock.h"
#include "toolpath/path_io.h"

#include <climits>
#include <cstdio>
#include <filesystem>

namespace k528::cli {

int runPlot(std::span<const std::string> argv) {
    std::vector<std::string_view> options = kSetupOptions;
    options.insert(options.end(), {"--size", "--out", "--view", "--max-frames"});
    const Args args(argv, {}, options);
    if (!args.ok())
        return usageError(args.error());
    const auto out = args.value("--out");
    if (!out || out->empty())
        return usageError(cliText("plot.out"));
    const std::string size = args.value("--size").value_or("1280x800");
    int w = 0, h = 0;
    if (std::sscanf(size.c_str(), "%dx%d", &w, &h) != 2 || w < 16 || h < 16 || w > 8192 || h > 8192)
        return usageError(cliText("plot.size", {size}));
    const std::string view = args.value("--view").value_or("xz");
    if (view != "xz" && view != "3d")
        return usageError(cliText("plot.view", {view}));
    ProgramSetup setup;
    if (const int rc = loadProgramSetup(args, setup, stdout); rc >= 0)
        return rc;
    toolpath::PathOptions po;
    po.preview.rPresets = setup.rPresets;
    if (const auto m = args.value("--max-frames")) {
        const auto v = parseInt(*m);
        if (!v || *v < 1 || *v > 100'000'000)
            return usageError(cliText("opt.max-frames", {*m}));
        po.preview.maxFrames = *v;
    }
    const toolpath::ProgrammedPath path =
        toolpath::programmedPath(setup.profile, setup.store, setup.number, po);
    // The blank kept with the file (a comment holding UCG,...).
    std::string text, ucg;
    if (readProgramFile(args.positional().front(), text))
        if (const auto b = stock::findUcg(text))
            ucg = stock::formatUcg(*b);

    const std::vector<std::string> helperArgs{"--out", *out, "--size", std::to_string(w) + "x" + std::to_string(h),
                                        "--view", view};
    if (!runHelperWithInput("k528-plot", "plot", helperArgs,
                            [&](std::FILE* f) { return toolpath::writePath(f, path, ucg); }))
        return ExitUsage;
    for (const toolpath::Segment& s : path.segments)
        if (s.outside)
            std::fprintf(stderr, "L%d N%d line %d: ВНЕ ГРАНИЦ\n", s.program, s.n, s.line);
    return path.run.status == engine::PreviewStatus::Alarm ? ExitInputErrors : ExitOk;
}

} // namespace k528::cli
