// k528 setup-sheet [options] --out FILE.pdf FILE — the setup sheet (карта
// наладки, handbook 14.3; shared/spec/cli.md, docs/cli-decisions.md): the
// machine, the blank, the tools with their stations and offsets, the
// programs with their cycle times, the R-parameters to preset. The content
// is core's (proveout/setup_sheet.h); the PDF is written by k528-sheet (Qt's
// QTextDocument and QPdfWriter, app/studio/sheet/), a helper found as
// helper_path.h says, which this feeds the sheet as JSON through a pipe, so
// that `k528` never loads Qt.
#include "cli.h"
#include "cli_texts.h"
#include "helper_path.h"
#include "program_setup.h"
#include "proveout/setup_sheet.h"
#include "proveout_cli.h"

#include <cstdio>
#include <filesystem>

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
        return usageError(cliText("sheet.out"));
    ProgramSetup setup;
    if (const int rc = loadProgramSetup(args, setup, asJson ? stderr : stdout); rc >= 0)
        return rc;
    std::optional<stock::Blank> blank;
    if (!blankFor(args, setup.text, blank))
        return ExitUsage;
    proveout::SetupSheet sheet;
    const bool made = withMachineData(setup.lang, [&] {
        sheet = proveout::setupSheet(setup.profile, setup.store, setup.text,
                                     std::filesystem::path(args.positional().front()).filename().string(),
                                     setup.rPresets, blank, !args.has("--no-cycle-times"));
    });
    if (!made)
        return ExitUsage;
    const std::string text = proveout::sheetJson(sheet);
    if (asJson)
        std::fprintf(stdout, "%s\n", text.c_str());
    if (!out || out->empty())
        return ExitOk;

    const std::vector<std::string> helperArgs{"--out", *out, "--lang", setup.lang == Lang::Ru ? "ru" : "en"};
    const bool done = runHelperWithInput("k528-sheet", "setup-sheet", helperArgs, [&](std::FILE* f) {
        return std::fwrite(text.data(), 1, text.size(), f) == text.size();
    });
    if (!done)
        return ExitUsage;
    return ExitOk;
}

} // namespace k528::cli
