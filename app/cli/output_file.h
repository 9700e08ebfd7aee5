// Writing a file a command produces (`db export --out`, `format --in-place`):
// one place that follows symbolic links, keeps permissions, never replaces a
// device node and says why a write failed (the system's errno text, naming
// the file the user gave, never a temporary one). docs/cli-decisions.md.
#pragma once

#include <string>

namespace k528::cli {

// Writes `text` to `path`:
//  - a symbolic link is followed: the file it points to is written, the link
//    stays a link;
//  - a regular file (or a new one) is written beside its real path and renamed
//    over it, so a failure leaves the old contents whole; it keeps its
//    permissions;
//  - a FIFO or a character device (/dev/stdout, /dev/full, a pipe) is written
//    directly, never replaced;
//  - a directory, a block device or a socket is refused.
// On failure returns false with `error` = "cannot write <path>: <why>".
bool writeOutputFile(const std::string& path, const std::string& text, std::string& error);

// Everything a command printed reaches standard output, or the run fails:
// the one place that flushes it and checks for a lost write (a full disk,
// /dev/full, a closed pipe) — main() of k528 and of k528-link. Returns
// `exitCode`, or ExitUsage (2) after «k528: cannot write standard output: …».
int finishStandardOutput(int exitCode);

} // namespace k528::cli
