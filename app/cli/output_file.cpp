#include "output_file.h"

#include "cli.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace k528::cli {

namespace {

// Writes all of `text` to fd; errno is kept on failure.
bool writeAll(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0) {
            if (errno == EINTR)
                continue;
            return false;
        }
        done += static_cast<std::size_t>(n);
    }
    return true;
}

bool writeDirectly(const std::string& path, const std::string& text, std::string& error) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) {
        error = "cannot write " + path + ": " + std::strerror(errno);
        return false;
    }
    bool ok = writeAll(fd, text);
    int e = errno;
    if (::close(fd) != 0 && ok) {
        ok = false;
        e = errno;
    }
    if (!ok)
        error = "cannot write " + path + ": " + std::strerror(e);
    return ok;
}

} // namespace

bool writeOutputFile(const std::string& path, const std::string& text, std::string& error) {
    struct stat st {};
    const bool exists = ::stat(path.c_str(), &st) == 0; // follows links
    if (!exists && errno != ENOENT) {
        error = "cannot write " + path + ": " + std::strerror(errno);
        return false;
    }
    if (exists) {
        if (S_ISDIR(st.st_mode)) {
            error = "cannot write " + path + ": it is a directory; give a file name";
            return false;
        }
        if (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode))
            return writeDirectly(path, text, error);
        if (!S_ISREG(st.st_mode)) {
            error = "cannot write " + path + ": it is not a regular file, a FIFO or a character device";
            return false;
        }
    }
    // The real file: a link's target (a dangling link: the file it names).
    std::error_code ec;
    fs::path real = path;
    for (int hops = 0; hops < 40 && fs::is_symlink(real, ec); ++hops) {
        const fs::path to = fs::read_symlink(real, ec);
        if (ec)
            break;
        real = to.is_absolute() ? to : real.parent_path() / to;
    }
    const fs::path dir = real.has_parent_path() ? real.parent_path() : fs::path(".");
    std::string tmpName = ".";
    tmpName.append(real.filename().string()).append(".k528-XXXXXX");
    std::string tmp = (dir / tmpName).string();
    const int fd = ::mkstemp(tmp.data());
    if (fd < 0) {
        error = "cannot write " + path + ": cannot create a file in its folder " + dir.string() +
                ": " + std::strerror(errno);
        return false;
    }
    bool ok = writeAll(fd, text);
    int e = errno;
    if (ok && exists && ::fchmod(fd, st.st_mode & 07777) != 0) {
        ok = false;
        e = errno;
    } else if (ok && !exists) {
        // A new file gets the usual permissions (0666 less the umask), not mkstemp's 0600.
        const mode_t mask = ::umask(0);
        ::umask(mask);
        ::fchmod(fd, 0666 & ~mask);
    }
    if (ok && ::fsync(fd) != 0) {
        ok = false;
        e = errno;
    }
    if (::close(fd) != 0 && ok) {
        ok = false;
        e = errno;
    }
    if (ok && ::rename(tmp.c_str(), real.c_str()) != 0) {
        ok = false;
        e = errno;
    }
    if (!ok) {
        ::unlink(tmp.c_str());
        error = "cannot write " + path + ": " + std::strerror(e);
    }
    return ok;
}

int finishStandardOutput(int exitCode) {
    errno = 0;
    const bool flushFailed = std::fflush(stdout) != 0;
    const int flushErrno = errno;
    if (flushFailed || std::ferror(stdout)) {
        std::fprintf(stderr, "k528: cannot write standard output: %s\n",
                     flushFailed && flushErrno != 0 ? std::strerror(flushErrno)
                                                    : "a write failed");
        return ExitUsage;
    }
    return exitCode;
}

} // namespace k528::cli
