// A program file checked for the machine it is meant for, as `k528 check
// --profile`, `k528 run` and the desktop's «load programs» do it: the
// machine's limits and feeds (soft limits C46/C47, F УСК.АВТ. C42, the
// coordinate components preset in R224..R231, the discretes, the nesting
// limit) as validation options, and the file's programs validated over the
// machine's store — its programs and messages underneath, the file's
// replacing those of the same number — reporting only the file's findings.
#pragma once

#include "profile/profile.h"
#include "program/parser.h"
#include "program/validator.h"

#include <set>
#include <string_view>
#include <vector>

namespace k528::engine {

// The validation options of a machine (program-language.md, «against a
// machine's constants»).
program::ValidateOptions validateOptionsFor(const profile::MachineProfile& p);

struct FileCheck {
    program::ParseResult parsed;                  // the file's programs and messages
    std::set<int> programs;                       // their numbers
    std::vector<program::Diagnostic> diagnostics; // syntax, or the rules over the store
    bool hasErrors() const { return program::hasErrors(diagnostics); }
};

// Parses `text`; without syntax errors validates its programs over `machineStore`.
FileCheck checkFileForMachine(std::string_view text, const program::ParseOptions& parseOptions,
                              const profile::MachineProfile& machine,
                              const program::ProgramStore& machineStore);

} // namespace k528::engine
