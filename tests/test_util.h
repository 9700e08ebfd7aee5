// Small helpers of the Qt tests: files in a test's folder, a signal awaited.
#pragma once

#include <QFile>
#include <QSignalSpy>
#include <QString>
#include <QTemporaryDir>

namespace testutil {

// The file `name` in `dir` holding `bytes` as they are: its path, empty
// when it cannot be written.
inline QString writeBytes(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes) {
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate) || f.write(bytes) != bytes.size())
        return {};
    return path;
}

// The file `name` in `dir` holding `text` (UTF-8): its path, empty when it
// cannot be written.
inline QString writeFile(const QTemporaryDir& dir, const QString& name, const QString& text) {
    return writeBytes(dir, name, text.toUtf8());
}

// The text of a file (UTF-8), empty when it cannot be read.
inline QString readFile(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

// True once `spy` has caught its signal, waited for up to `ms`.
inline bool finished(QSignalSpy& spy, int ms) {
    if (spy.isEmpty())
        spy.wait(ms);
    return !spy.isEmpty();
}

} // namespace testutil
