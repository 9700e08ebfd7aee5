#include "util/input_file.h"

#include <cerrno>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace k528::util {

namespace {

Message kindOf(mode_t mode) {
    if (S_ISDIR(mode))
        return message("io.kind.directory");
    if (S_ISCHR(mode))
        return message("io.kind.character-device");
    if (S_ISBLK(mode))
        return message("io.kind.block-device");
    if (S_ISFIFO(mode))
        return message("io.kind.fifo");
    if (S_ISSOCK(mode))
        return message("io.kind.socket");
    return message("io.kind.other");
}

Message tooLarge(std::size_t maxBytes) { return message("io.too-large", {std::to_string(maxBytes >> 20)}); }

// Reads fd to its end, at most maxBytes; false with `error` (the reason)
// set otherwise.
bool readAll(int fd, std::string& contents, Message& error, std::size_t maxBytes,
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
                error = systemError(errno);
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
        error = message("io.no-memory");
        return false;
    }
    contents = std::move(buf);
    return true;
}

} // namespace

bool readInputFile(const std::string& path, std::string& contents, Message& error, std::size_t maxBytes) {
    Message why;
    const char* verb = "io.cannot-read";
    // O_NONBLOCK: opening a FIFO must not wait for a writer before it is refused.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    struct stat st {};
    if (fd < 0) {
        const int e = errno;
        if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
            why = message("io.directory");
        } else {
            verb = "io.cannot-open";
            why = systemError(e);
        }
    } else if (::fstat(fd, &st) != 0) {
        why = systemError(errno);
    } else if (!S_ISREG(st.st_mode)) {
        why = message("io.not-regular", {}, {kindOf(st.st_mode)});
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
    error = message(verb, {path}, {std::move(why)});
    return false;
}

bool readInputFile(const std::string& path, std::string& contents, std::string& error, std::size_t maxBytes) {
    Message m;
    if (readInputFile(path, contents, m, maxBytes))
        return true;
    error = systemText(m, false);
    return false;
}

bool readInputStream(std::FILE* in, std::string& contents, Message& error, std::size_t maxBytes) {
    Message why;
    if (readAll(::fileno(in), contents, why, maxBytes, 0))
        return true;
    error = message("io.cannot-read-stdin", {}, {std::move(why)});
    return false;
}

} // namespace k528::util
