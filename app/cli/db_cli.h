// `k528 db`: the database of machines (docs/database.md). db_cli.cpp holds
// the dispatcher and the helpers the subcommands share (db_cli_util.h), one
// cmd_db_<sub>.cpp each subcommand, cmd_db_calc.cpp the C-constant calculator.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace k528::cli {

int runDb(std::span<const std::string> args);
// The usage line of `k528 db` (its subcommands, from the table runDb dispatches by).
std::string_view dbUsage();
// `k528 db calc ...` (args after "calc"); `dbPath` is "" for the default.
int runDbCalc(std::span<const std::string> args);

// Help text of `k528 db` (all subcommands and options).
extern const char* const kDbDetails;

} // namespace k528::cli
