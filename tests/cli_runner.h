// Runs the built `k528` command line in tests and captures what it prints.
#pragma once

#include <QProcess>
#include <QString>
#include <QStringList>

struct CliResult {
    int exitCode = -1;
    QString out;
    QString err;
};

inline CliResult runK528(const QStringList& args, const QByteArray& stdinData = {},
                         const QString& workDir = {}) {
    QProcess p;
    if (!workDir.isEmpty())
        p.setWorkingDirectory(workDir);
    p.start(QStringLiteral(K528_CLI), args);
    if (!p.waitForStarted())
        return {};
    if (!stdinData.isEmpty())
        p.write(stdinData);
    p.closeWriteChannel();
    p.waitForFinished(600000);
    CliResult r;
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

// Runs any program (`k528`, mbpoll…) with a time limit: one that does not end
// in time is killed, and its result says "timeout" on err with exitCode -1.
inline CliResult runProgram(const QString& program, const QStringList& args, int timeoutMs) {
    QProcess p;
    p.start(program, args);
    CliResult r;
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished();
        r.err = QStringLiteral("timeout");
        return r;
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

// Runs `k528` with its standard output sent to the file `outFile` (e.g.
// /dev/full) and returns the exit code and what it printed on stderr.
inline CliResult runK528ToFile(const QStringList& args, const QString& outFile,
                               const QString& program = QStringLiteral(K528_CLI),
                               const QStringList& programPrefix = {}) {
    QProcess p;
    p.setStandardOutputFile(outFile);
    p.start(programPrefix.isEmpty() ? program : programPrefix.front(),
            programPrefix.isEmpty() ? args : programPrefix.mid(1) + QStringList{program} + args);
    if (!p.waitForStarted())
        return {};
    p.closeWriteChannel();
    p.waitForFinished(600000);
    CliResult r;
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}
