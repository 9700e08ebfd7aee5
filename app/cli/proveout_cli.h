// What `k528 check --profile` and `k528 path` share of the prove-out
// (core/proveout, docs/proveout.md): the blank (--blank UCG,… or the file's
// `UCG,` comment), the findings as JSON diagnostics with their "rule", and as
// plain lines.
#pragma once

#include "args.h"
#include "program_cli.h"
#include "proveout/proveout.h"
#include "util/json_fwd.h"

#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace k528::cli {

inline constexpr std::string_view kBlankOption = "--blank";

// The blank: --blank, else the first `UCG,` of the file's text, else none.
// False (after printing the reason) when either is malformed.
bool blankFor(const Args& args, std::string_view fileText, std::optional<stock::Blank>& blank);

// A finding as a diagnostic of `k528 check --json` (and `path --json`):
// line, column 1 .. the end of the frame's line (`fileText`), severity,
// "rule", program, n, at [x, z], occurrences, message_ru/en.
Json findingJson(const proveout::Finding& f, std::string_view fileText, bool inFile);

// "FILE:LINE:1: error: [rule] text" (check) — the frame's line when in the file.
void printFinding(std::FILE* out, const std::string& file, const proveout::Finding& f,
                  bool inFile, Lang lang);

// Calls `prove` (the prove-out, the setup sheet: what reads the machine's
// description and its tools). A description or a tool table they cannot use
// is told on standard error ("k528: machine description …", "k528: the
// machine's tools: …"), as `k528 check --profile` and `k528 setup-sheet`
// both say it, and gives false.
bool withMachineData(const std::function<void()>& prove);

} // namespace k528::cli
