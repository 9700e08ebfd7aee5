// The profile module's errors in Russian or English, for the command line's
// --lang: a file's (FileError), the cutting data's, the constants
// calculator's, a tool's; each says its problem from problemTexts(), as the
// desktop says it by tr() (studio.ui_language fails when the two differ).
#pragma once

#include "profile/problem.h"

#include <exception>
#include <string>

namespace k528::profile {

class FileError;

// FileError::what() ("<file>:<line>: <problem>") in a language.
std::string fileErrorText(const FileError& e, bool russian);
// An error of the profile's module in a language: a file's, the cutting
// data's, the constants calculator's, a tool's; any other exception its what().
std::string errorText(const std::exception& e, bool russian);

} // namespace k528::profile
