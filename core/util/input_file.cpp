#include "util/input_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace k528::util {

namespace {

std::string kindOf(mode_t mode) {
    if (S_ISDIR(mode))
        return "a directory";
    if (S_ISCHR(mode))
        return "a character device";
    if (S_ISBLK(mode))
        return "a block device";
    if (S_ISFIFO(mode))
        return "a FIFO (named pipe)";
    if (S_ISSOCK(mode))
        return "a socket";
    return "not a regular file";
}

std::string mib(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

std::string tooLarge(std::size_t maxBytes) {
    return "it is larger than " + mib(maxBytes) +
           ", the most k528 reads (a K528-05 holds at most 99 programs of 999 frames, "
           "about 3 MB of text)";
}

// Reads fd to its end, at most maxBytes; false with `error` (the reason)
// set otherwise.
bool readAll(int fd, std::string& contents, std::string& error, std::size_t maxBytes,
             std::size_t sizeHint) {
    std::string buf;
    try {
        buf.reserve(sizeHint + 1);
        char chunk[1 << 16];
        for (;;) {
            const ssize_t n = ::read(fd, chunk, sizeof chunk);
            if (n < 0) {
                if (errno == EINTR)
                    continue;
                error = std::strerror(errno);
                return false;
            }
            if (n == 0)
                break;
            if (buf.size() + static_cast<std::size_t>(n) > maxBytes) {
                error = tooLarge(maxBytes);
                return false;
            }
            buf.append(chunk, static_cast<std::size_t>(n));
        }
    } catch (const std::bad_alloc&) {
        error = "not enough memory";
        return false;
    }
    contents = std::move(buf);
    return true;
}

} // namespace

bool readInputFile(const std::string& path, std::string& contents, std::string& error,
                   std::size_t maxBytes, std::string* reason) {
    std::string why;
    const char* verb = "cannot read ";
    // O_NONBLOCK: opening a FIFO must not wait for a writer before it is refused.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    struct stat st {};
    if (fd < 0) {
        const int e = errno;
        if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
            why = "it is a directory";
        } else {
            verb = "cannot open ";
            why = std::strerror(e);
        }
    } else if (::fstat(fd, &st) != 0) {
        why = std::strerror(errno);
    } else if (!S_ISREG(st.st_mode)) {
        why = "it is " + kindOf(st.st_mode) +
              ", not a regular file (k528 reads program and machine files only)";
    } else if (static_cast<unsigned long long>(st.st_size) > maxBytes) {
        why = tooLarge(maxBytes);
    } else {
        // Back to blocking reads for the regular file.
        ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
        if (readAll(fd, contents, why, maxBytes, static_cast<std::size_t>(st.st_size))) {
            ::close(fd);
            return true;
        }
    }
    if (fd >= 0)
        ::close(fd);
    error = verb + path + ": " + why;
    if (reason)
        *reason = why;
    return false;
}

bool readInputStream(std::FILE* in, const std::string& name, std::string& contents,
                     std::string& error, std::size_t maxBytes) {
    std::string why;
    if (readAll(::fileno(in), contents, why, maxBytes, 0))
        return true;
    error = "cannot read " + name + ": " + why;
    return false;
}

} // namespace k528::util
