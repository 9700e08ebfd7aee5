// The built-in machine profiles (resources/profiles/*.k528m, embedded in the
// binaries) and loading a profile by name or path.
#pragma once

#include "profile/profile.h"

#include <string>
#include <string_view>
#include <vector>

namespace k528::profile {

// Names of the built-in profiles, sorted: "grinder-205", "training-lathe".
std::vector<std::string> builtinNames();
bool isBuiltin(std::string_view name);
// The machine-file text of a built-in profile; throws FileError if unknown.
std::string_view builtinText(std::string_view name);
// A built-in profile; throws FileError if unknown (or, never for a shipped
// file, unreadable).
MachineProfile builtin(std::string_view name);

// A built-in profile when `nameOrPath` names one, otherwise the machine file
// at that path. Errors (FileError) say which built-ins exist when neither fits.
MachineProfile load(std::string_view nameOrPath);

// The profile the command line and the desktop use when none is given.
inline constexpr std::string_view kDefaultProfile = "training-lathe";

} // namespace k528::profile
