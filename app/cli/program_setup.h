// What `k528 path` and `k528 plot` share with `k528 run`: the machine profile
// with --param overrides, --r presets, the program file checked against the
// machine's store, and the program to start (--program N, else the first).
#pragma once

#include "args.h"
#include "program_cli.h"
#include "profile/profile.h"
#include "program/model.h"
#include "program/parser.h"

#include <cstdint>
#include <map>

namespace k528::cli {

struct ProgramSetup {
    profile::MachineProfile profile;
    program::ProgramStore store;
    int number = 0;
    std::map<int, std::int64_t> rPresets;
    Lang lang = Lang::Ru;
    std::string text; // the program file's text
};

// The options this reads (add them to the command's Args).
inline const std::vector<std::string_view> kSetupOptions = {"--profile", "--db",     "--program",
                                                           "--param",   "--r",      "--number",
                                                           "--lang"};

// --param N=V into the profile's C-parameters (each checked) and --r N=V
// into `rPresets` (writable R, 32-bit). Returns -1, else the exit code after
// printing the reason.
int applyParameterOptions(const Args& args, profile::MachineProfile& profile,
                          std::map<int, std::int64_t>& rPresets);

// --lang, --number, the machine profile (--profile, --db) with its --param
// overrides, and the --r presets. Returns -1, else the exit code after
// printing the reason.
int readProgramOptions(const Args& args, Lang& lang, program::ParseOptions& parseOptions,
                       profile::MachineProfile& profile, std::map<int, std::int64_t>& rPresets);

// Fills `out` from `args` (one positional FILE). Returns -1 on success, else
// the exit code after printing the reason (diagnostics to `diagOut`).
int loadProgramSetup(const Args& args, ProgramSetup& out, std::FILE* diagOut);

} // namespace k528::cli
