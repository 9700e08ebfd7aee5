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

} // namespace k528::cli
