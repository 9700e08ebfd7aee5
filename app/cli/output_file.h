// Writing a file a command produces (`db export --out`, `format --in-place`):
// one place that follows symbolic links, keeps permissions, never replaces a
// device node and says why a write failed (the system's errno text, naming
// the file the user gave, never a temporary one). docs/cli-decisions.md.
#pragma once

#include <cstdio>
#include <string>
#include <sys/types.h>

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
// On failure returns false with `error` = "cannot write <path>: <why>" in the
// command line's language (util/system_texts.h's io.cannot-write).
bool writeOutputFile(const std::string& path, const std::string& text, std::string& error);

// The same for a file written piece by piece through stdio (`run --trace`, of
// a length not known in advance): open() gives a FILE* writing to a temporary
// file beside the real path (or directly to a FIFO or a character device);
// commit() flushes, syncs, closes and renames it over the real path. The first
// failing write's errno is kept, so the message has the system's reason even
// when stdio found the failure long before commit(). Not committed (an error,
// an exception): the temporary file is removed and the old file stays whole.
class OutputStream {
public:
    OutputStream() = default;
    OutputStream(const OutputStream&) = delete;
    OutputStream& operator=(const OutputStream&) = delete;
    ~OutputStream();

    // false with `error` = "cannot write <path>: <why>".
    bool open(const std::string& path, std::string& error);
    std::FILE* file() const { return file_; }
    // false with `error` = "cannot write <path>: <why>"; the target is untouched then.
    bool commit(std::string& error);

private:
    static ssize_t cookieWrite(void* self, const char* data, std::size_t size);
    void abandon();

    std::string path_; // as the user gave it
    std::string real_; // a link's target
    std::string tmp_;  // "" when written directly
    int fd_ = -1;
    std::FILE* file_ = nullptr;
    int firstErrno_ = 0;
    bool existed_ = false;
    mode_t mode_ = 0;
};

// Flushes standard output and says a lost write (a full disk, /dev/full, a
// closed pipe) on stderr: «k528: cannot write standard output: <why>» in the
// command line's language, with the system's reason. The one place that says
// it: at the end of every command (finishStandardOutput) and in the commands
// that print as they go and must stop at the first lost line (link watch,
// link scan, shop status). True when the write was lost; the stream's error
// is cleared then, so the loss is said once and the exit status tells the rest.
bool standardOutputLost();

// Everything a command printed reaches standard output, or the run fails:
// main() of k528 and of k528-link. Returns `exitCode`, or ExitUsage (2)
// after standardOutputLost() said why.
int finishStandardOutput(int exitCode);

} // namespace k528::cli
