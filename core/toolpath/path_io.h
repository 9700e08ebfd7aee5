// A programmed path (and the blank of its file, as UCG text) in a compact
// binary stream: `k528 plot` computes the path in the core and hands it to
// the renderer process k528-plot (VTK, app/cli/plot/) through a pipe, so that
// `k528` itself never loads VTK (its start stays fast).
// Format: "K528PATH2\n", then little-endian fields in the order of the
// structs (docs/backplot.md).
#pragma once

#include "toolpath/programmed_path.h"

#include <cstdio>
#include <string>

namespace k528::toolpath {

bool writePath(std::FILE* out, const ProgrammedPath& p, const std::string& ucg);
// False with `error` set on a malformed stream.
bool readPath(std::FILE* in, ProgrammedPath& p, std::string& ucg, std::string& error);

} // namespace k528::toolpath
