// The `k528` command line (shared/spec/cli.md): shared types of the
// subcommands. Each subcommand lives in its own cmd_<name>.cpp and is listed
// in commands.cpp.
#pragma once

#include <cstdio>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace k528::cli {

// Exit codes everywhere (cli.md): 0 success; 1 the input has errors
// (diagnostics printed, or the run ended in an alarm); 2 usage or I/O error.
enum Exit : int { ExitOk = 0, ExitInputErrors = 1, ExitUsage = 2 };

struct Command {
    std::string_view name;
    std::string_view usage;   // one line: "check [--json] FILE..."
    std::string_view summary; // one sentence
    std::string_view details; // option list shown by `k528 CMD --help`
    int (*run)(std::span<const std::string> args);
};

std::span<const Command> commands();

// The language of the command line's own messages (a usage error, the hint
// to the help): Russian, as every command's --lang by default, unless the
// command line asks for English (--lang en or --lang=en). main() reads it
// once from the whole command line.
bool russianCommandLine();
void readCommandLineLanguage(std::span<const std::string> args);
// Whether `args` ask for English (--lang en, --lang=en).
bool asksForEnglish(std::span<const std::string> args);

// Prints "k528: <message>" to stderr and the hint to the help in the command
// line's language; returns ExitUsage.
int usageError(std::string_view message);
// The same in Russian or English (the hint where the help is too).
int usageError(std::string_view message, bool russian);

// Prints the help of one command to `out`.
void printCommandHelp(const Command& c, std::FILE* out);

// Reads a whole file (util::readInputFile); on failure returns false and sets
// `error` to a message naming the file and the reason, in the command line's
// language (output_file.cpp).
bool readFile(const std::string& path, std::string& contents, std::string& error);
// The same for standard input (`-`).
bool readStandardInput(std::string& contents, std::string& error);

} // namespace k528::cli
