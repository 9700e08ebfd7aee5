// Where k528 finds its helper programs (k528-link, k528-plot). They are not
// commands of their own, so a package installs them in a private folder
// (/usr/lib/k528studio), not on the PATH; in the build tree they sit next to
// k528 (build/bin). Both places are relative to k528's own file, so an
// unpacked package and a relocated install work as well.
#pragma once

#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace k528::cli {

// The places looked at, in order, for the helper `name`: k528's folder (the
// build tree), then the installed helper folder. Empty when k528 cannot tell
// where its own file is.
std::vector<std::filesystem::path> helperCandidates(std::string_view name);

// The first candidate that is an executable file, or an empty path.
std::filesystem::path findHelper(std::string_view name);

// The candidates as "a, b" for an error message.
std::string helperSearchText(std::string_view name);

// Runs the helper `name` with `args`, handing it on its standard input what
// `write` writes (the renderers k528-plot and k528-sheet read what to draw
// from there). `command` is the k528 command that needs it ("plot"), for the
// message when the helper is missing. True when the helper took all of it and
// exited 0; otherwise it (or this) has said why on stderr.
bool runHelperWithInput(std::string_view name, std::string_view command, const std::vector<std::string>& args,
                        const std::function<bool(std::FILE*)>& write);

} // namespace k528::cli
