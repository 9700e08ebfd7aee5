// Program language speed:
//  - parse + validate a full store, 99 programs x 999 frames (target <= 50 ms);
//  - re-check one 999-frame program after a one-character edit, as the
//    editor does on every keystroke: parse that program's text, put it into
//    the store, update the call graph, validate it (target <= 2 ms).
// The store is generated (seeded, tests/program/random_program.h) and
// written in canonical form with comments; it is valid (no errors).
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "program/formatter.h"
#include "program/parser.h"
#include "program/validator.h"
#include "random_program.h"
#include "report.h"
#include "stats.h"

using namespace k528;
using namespace k528::program;

int main(int argc, char** argv) {
    const int storeRuns = argc > 1 ? std::atoi(argv[1]) : 15;
    const int editRuns = argc > 2 ? std::atoi(argv[2]) : 300;

    testing::GeneratorOptions go;
    go.validOnly = true;
    testing::ProgramGenerator gen(528, go);
    const ProgramStore generated = gen.store(kMaxPrograms, kMaxFrames);
    const std::string text = format(generated);

    // Full store.
    std::vector<double> ms;
    std::size_t frames = 0;
    std::size_t errors = 0;
    std::size_t warnings = 0;
    for (int i = 0; i < storeRuns; ++i) {
        const double t0 = bench::nowSeconds();
        const ParseResult parsed = parse(text);
        const auto diags = validate(parsed.store);
        const double t1 = bench::nowSeconds();
        ms.push_back((t1 - t0) * 1000.0);
        frames = 0;
        for (const Program& p : parsed.store.programs())
            frames += p.frames.size();
        errors = countErrors(parsed.diagnostics) + countErrors(diags);
        warnings = diags.size() - countErrors(diags);
    }
    std::printf("store: %zu programs, %zu frames, %.1f MB of text; %zu errors, %zu warnings\n",
                generated.size(), frames, static_cast<double>(text.size()) / 1e6, errors, warnings);
    if (errors != 0 || frames != static_cast<std::size_t>(kMaxPrograms) * kMaxFrames) {
        std::fprintf(stderr, "bench_program: the generated store does not read back as a valid store\n");
        return 2;
    }

    // One program, edited one character at a time.
    ParseResult base = parse(text);
    ProgramStore& store = base.store;
    CallGraph graph(store);
    const int number = 50;
    ProgramStore one;
    Program copy = *store.find(number);
    one.insert(copy);
    one.headerless = true;
    std::string programText = format(one);
    std::vector<std::size_t> digits; // positions of digits: edits keep the text valid
    for (std::size_t i = 0; i < programText.size(); ++i)
        if (programText[i] >= '1' && programText[i] <= '8' && i > 0 && programText[i - 1] >= '0' &&
            programText[i - 1] <= '9')
            digits.push_back(i);
    std::vector<double> editMs;
    std::size_t lastDiags = 0;
    testing::Rng rng(7);
    ParseOptions po;
    po.programNumber = number;
    for (int i = 0; i < editRuns; ++i) {
        const std::size_t at = digits[static_cast<std::size_t>(rng.below(static_cast<int>(digits.size())))];
        programText[at] = programText[at] == '8' ? '1' : static_cast<char>(programText[at] + 1);
        const double t0 = bench::nowSeconds();
        ParseResult edited = parse(programText, po);
        Program* p = edited.store.find(number);
        if (!p)
            return 2;
        graph.update(*p);
        store.insert(std::move(*p));
        const auto diags = validateProgram(store, number, graph);
        const double t1 = bench::nowSeconds();
        editMs.push_back((t1 - t0) * 1000.0);
        lastDiags = diags.size() + edited.diagnostics.size();
    }
    std::printf("edit: program L%d, %zu frames, %zu bytes; %zu diagnostics after the last edit\n", number,
                store.find(number)->frames.size(), programText.size(), lastDiags);

    bench::Report r;
    r.figure("program.store_parse_validate (99x999)", bench::median(ms), "ms", 50, bench::Better::Lower);
    r.figure("program.edit_recheck (1x999, median)", bench::median(editMs), "ms", 2, bench::Better::Lower);
    r.figure("program.edit_recheck (1x999, p95)", bench::percentile(editMs, 95), "ms", 4,
             bench::Better::Lower);
    return r.exitCode();
}
