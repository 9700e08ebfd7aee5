#include "output_file.h"

#include "cli.h"
#include "util/input_file.h"
#include "util/system_texts.h"

#include <cerrno>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <string_view>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace k528::cli {

namespace {

// Writes all of `text` to fd; errno is kept on failure.
bool writeAll(int fd, std::string_view text) {
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

// "cannot write <path>: <why>" in the command line's language.
std::string cannotWrite(const std::string& path, util::Message why) {
    return util::systemText(util::message("io.cannot-write", {path}, {std::move(why)}), russianCommandLine());
}

} // namespace

OutputStream::~OutputStream() {
    abandon();
}

void OutputStream::abandon() {
    if (file_)
        std::fclose(file_);
    file_ = nullptr;
    if (fd_ >= 0)
        ::close(fd_);
    fd_ = -1;
    if (!tmp_.empty())
        ::unlink(tmp_.c_str());
    tmp_.clear();
}

ssize_t OutputStream::cookieWrite(void* self, const char* data, std::size_t size) {
    auto* o = static_cast<OutputStream*>(self);
    if (!writeAll(o->fd_, std::string_view(data, size))) {
        if (o->firstErrno_ == 0)
            o->firstErrno_ = errno;
        return -1;
    }
    return static_cast<ssize_t>(size);
}

bool OutputStream::open(const std::string& path, std::string& error) {
    abandon();
    path_ = path;
    firstErrno_ = 0;
    const auto fail = [&](util::Message why) {
        error = cannotWrite(path, std::move(why));
        abandon();
        return false;
    };
    struct stat st {};
    existed_ = ::stat(path.c_str(), &st) == 0; // follows links
    if (!existed_ && errno != ENOENT)
        return fail(util::systemError(errno));
    mode_ = st.st_mode;
    bool direct = false;
    if (existed_) {
        if (S_ISDIR(st.st_mode))
            return fail(util::message("io.write-directory"));
        direct = S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode);
        if (!direct && !S_ISREG(st.st_mode))
            return fail(util::message("io.write-kind"));
    }
    if (direct) {
        // A FIFO or a device (/dev/stdout, /dev/full, a pipe) is written, never replaced.
        fd_ = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
        if (fd_ < 0)
            return fail(util::systemError(errno));
    } else {
        // The real file: a link's target (a dangling link: the file it names).
        std::error_code ec;
        fs::path real = path;
        for (int hops = 0; hops < 40 && fs::is_symlink(real, ec); ++hops) {
            const fs::path to = fs::read_symlink(real, ec);
            if (ec)
                break;
            real = to.is_absolute() ? to : real.parent_path() / to;
        }
        real_ = real.string();
        const fs::path dir = real.has_parent_path() ? real.parent_path() : fs::path(".");
        std::string tmpName = ".";
        tmpName.append(real.filename().string()).append(".k528-XXXXXX");
        std::string tmp = (dir / tmpName).string();
        fd_ = ::mkstemp(tmp.data());
        if (fd_ < 0)
            return fail(util::message("io.create-in-folder", {dir.string()}, {util::systemError(errno)}));
        tmp_ = tmp;
    }
    const cookie_io_functions_t io{nullptr, &OutputStream::cookieWrite, nullptr, nullptr};
    file_ = ::fopencookie(this, "w", io);
    if (!file_)
        return fail(util::systemError(errno));
    return true;
}

bool OutputStream::commit(std::string& error) {
    if (!file_) {
        error = cannotWrite(path_, util::message("io.not-open"));
        return false;
    }
    errno = 0;
    int e = 0;
    const bool flushFailed = std::fflush(file_) != 0 || std::ferror(file_);
    if (flushFailed)
        e = firstErrno_ != 0 ? firstErrno_ : errno;
    std::fclose(file_); // the cookie has nothing to close; the descriptor is ours
    file_ = nullptr;
    bool ok = !flushFailed;
    if (ok && !tmp_.empty()) {
        if (existed_ && ::fchmod(fd_, mode_ & 07777) != 0) {
            ok = false;
            e = errno;
        } else if (!existed_) {
            // A new file gets the usual permissions (0666 less the umask), not mkstemp's 0600.
            const mode_t mask = ::umask(0);
            ::umask(mask);
            ::fchmod(fd_, 0666 & ~mask);
        }
        if (ok && ::fsync(fd_) != 0) {
            ok = false;
            e = errno;
        }
    }
    if (::close(fd_) != 0 && ok) {
        ok = false;
        e = errno;
    }
    fd_ = -1;
    if (ok && !tmp_.empty() && ::rename(tmp_.c_str(), real_.c_str()) != 0) {
        ok = false;
        e = errno;
    }
    if (ok)
        tmp_.clear(); // renamed: nothing to remove
    else
        error = cannotWrite(path_, e != 0 ? util::systemError(e) : util::message("io.write-failed"));
    abandon();
    return ok;
}

bool writeOutputFile(const std::string& path, const std::string& text, std::string& error) {
    OutputStream out;
    if (!out.open(path, error))
        return false;
    std::fwrite(text.data(), 1, text.size(), out.file());
    return out.commit(error);
}

bool readFile(const std::string& path, std::string& contents, std::string& error) {
    util::Message m;
    if (util::readInputFile(path, contents, m))
        return true;
    error = util::systemText(m, russianCommandLine());
    return false;
}

bool readStandardInput(std::string& contents, std::string& error) {
    util::Message m;
    if (util::readInputStream(stdin, contents, m))
        return true;
    error = util::systemText(m, russianCommandLine());
    return false;
}

bool standardOutputLost() {
    errno = 0;
    const bool flushFailed = std::fflush(stdout) != 0;
    const int flushErrno = errno;
    if (!flushFailed && !std::ferror(stdout))
        return false;
    // A write that failed before this flush (stdio flushes a full buffer by
    // itself) left no errno to read here: its reason is lost, only the fact is not.
    const util::Message why = flushFailed && flushErrno != 0 ? util::systemError(flushErrno)
                                                             : util::message("io.write-failed");
    std::fprintf(stderr, "k528: %s\n",
                 util::systemText(util::message("io.cannot-write-stdout", {}, {why}), russianCommandLine()).c_str());
    std::clearerr(stdout);
    return true;
}

int finishStandardOutput(int exitCode) {
    return standardOutputLost() ? ExitUsage : exitCode;
}

} // namespace k528::cli
