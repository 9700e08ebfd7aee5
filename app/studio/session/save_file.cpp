#include "session/save_file.h"

#include <QFileInfo>
#include <cerrno>

namespace k528::studio {

SaveFile::SaveFile(const QString& path) : QSaveFile(path) {}

void SaveFile::failed() {
    if (failed_)
        return; // the first failure is why; the calls after it fail because of it
    failed_ = true;
    err_ = errno;
}

bool SaveFile::open(OpenMode mode) {
    errno = 0;
    const bool ok = QSaveFile::open(mode | QIODevice::Unbuffered);
    if (!ok)
        failed();
    return ok;
}

qint64 SaveFile::writeData(const char* data, qint64 len) {
    errno = 0;
    const qint64 n = QSaveFile::writeData(data, len);
    if (n < 0)
        failed();
    return n;
}

bool SaveFile::commit() {
    errno = 0;
    const bool ok = QSaveFile::commit();
    if (!ok)
        failed();
    return ok;
}

util::Message SaveFile::reason() const {
    if (!failed_)
        return {};
    if (err_ != 0)
        return util::systemError(err_);
    // Refused before any system call: Qt's own checks of the path.
    return util::message(QFileInfo(fileName()).isDir() ? "io.write-directory" : "io.write-failed");
}

} // namespace k528::studio
