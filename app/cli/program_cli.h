// Shared by `k528 check` and `k528 format` (cmd_check.cpp, cmd_format.cpp):
// reading a program file and printing diagnostics in the plain format of
// shared/spec/cli.md.
#pragma once

#include <cstdio>
#include <optional>
#include <span>
#include <exception>
#include <string>
#include <vector>

#include "program/diagnostic.h"

namespace k528::plc {
class DescriptionError;
} // namespace k528::plc

namespace k528::cli {

enum class Lang { Ru, En };

// "k528: machine description FILE: PATH: what is wrong" on stderr, in `lang`.
void printDescriptionError(const plc::DescriptionError& e, Lang lang);
// "k528: the machine's tools: what is wrong" on stderr, in `lang`.
void printToolError(const std::exception& e, Lang lang);

// "ru" / "en" -> Lang; false for anything else.
bool parseLang(const std::string& text, Lang& lang);

// Reads FILE, or standard input for "-". On failure prints "k528: <why>"
// to stderr and returns false.
bool readProgramFile(const std::string& path, std::string& contents);

// The name a file is reported under ("<stdin>" for "-").
std::string displayName(const std::string& path);

// One line per diagnostic: "FILE:LINE:COL: error|warning: [M<nn>] text".
void printDiagnostics(std::FILE* out, const std::string& file,
                      const std::vector<program::Diagnostic>& diagnostics, Lang lang);

// Parses --number N (1..99); prints a usage error and returns false when bad.
bool parseProgramNumber(const std::optional<std::string>& value, int& number);

int runCheck(std::span<const std::string> args);
int runFormat(std::span<const std::string> args);
int runRun(std::span<const std::string> args); // cmd_run.cpp

} // namespace k528::cli
