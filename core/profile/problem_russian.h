// Core's problems (problem.h) in Russian, for the command line's --lang ru:
// the Russian of each id of problemTexts(), as the desktop says it by tr()
// (studio.ui_language fails when the two differ).
#pragma once

#include "profile/problem.h"

#include <exception>
#include <string>
#include <string_view>

namespace k528::profile {

class FileError;

// The Russian of `id` ("" if unknown).
std::string_view problemRussian(std::string_view id);
// `p` in Russian or English (Problem::text()); an id without Russian says its English.
std::string problemText(const Problem& p, bool russian);
// FileError::what() ("<file>:<line>: <problem>") in a language.
std::string fileErrorText(const FileError& e, bool russian);
// An error of the profile's module in a language: a file's, the cutting
// data's, the constants calculator's, a tool's; any other exception its what().
std::string errorText(const std::exception& e, bool russian);

} // namespace k528::profile
