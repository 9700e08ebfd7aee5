// A file written whole, with the system's reason when it cannot be. Qt's
// QFileDevice::errorString() gives that reason in the C library's English
// («Permission denied», «No space left on device») whatever the window's
// language, and QFile does not give errno; core's catalog
// (util/system_texts.h) says the reason in Russian and English, as the
// command line does. The studio says it in the window's language
// (file_problem.h), k528-sheet in the command's (sheet_render.cpp).
#pragma once

#include "util/system_texts.h"

#include <QSaveFile>

namespace k528::studio {

// A QSaveFile (the file replaced only when all of it is written, at
// commit()) that keeps the reason for its first failure: errno taken right
// after the call that failed — the opening, a write (its own or a writer's
// on it, such as QPdfWriter's) or the commit — each of which fails in a
// system call and leaves its errno. It is opened unbuffered, so that a write
// reaches the system, and fails, in the call that made it rather than in a
// later flush.
class SaveFile : public QSaveFile {
public:
    explicit SaveFile(const QString& path);

    bool open(OpenMode mode) override;
    // QSaveFile::commit(), keeping why it failed.
    bool commit();
    // Why the file was not written (util::systemTexts(): the system's reason,
    // or io.write-directory / io.write-failed when Qt refused before asking
    // the system); empty when nothing failed.
    util::Message reason() const;

protected:
    qint64 writeData(const char* data, qint64 len) override;

private:
    void failed();
    bool failed_ = false;
    int err_ = 0;
};

} // namespace k528::studio
