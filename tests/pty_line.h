// A serial line for the tests of the RS485 link: two ptys joined by socat
// (their ends links in a test's folder), and `k528 serve` on one end;
// started, waited for until they are there, stopped, and the ports' lock
// files (/run/lock/LCK..<name>, left by a process stopped with a port open)
// removed.
#pragma once

#include <QByteArray>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTest>

namespace ptytest {

inline void removeLock(const QString& port) {
    if (!port.isEmpty())
        QFile::remove("/run/lock/LCK.." + QFileInfo(port).fileName());
}

// Waits up to `ms` for `done`, the events processed meanwhile.
template <typename Done> bool waitFor(Done done, int ms) {
    QElapsedTimer t;
    t.start();
    while (!done()) {
        if (t.elapsed() >= ms)
            return false;
        QTest::qWait(50);
    }
    return true;
}

// Two ptys joined by socat: a() and b(), `<folder>/<prefix>a<pid>` and
// `<folder>/<prefix>b<pid>` (tests running at once never share a name).
class PtyPair {
public:
    ~PtyPair() { stop(); }
    // True once both ends exist (within `ms`).
    bool start(const QString& folder, const QString& prefix, int ms = 5000) {
        const QString tag = QString::number(QCoreApplication::applicationPid());
        a_ = folder + "/" + prefix + "a" + tag;
        b_ = folder + "/" + prefix + "b" + tag;
        socat_.start("socat", {"pty,raw,echo=0,link=" + a_, "pty,raw,echo=0,link=" + b_});
        if (!socat_.waitForStarted())
            return false;
        return waitFor([this] { return QFile::exists(a_) && QFile::exists(b_); }, ms);
    }
    void stop() {
        if (socat_.state() != QProcess::NotRunning) {
            socat_.terminate();
            socat_.waitForFinished(3000);
        }
        removeLocks();
    }
    void removeLocks() const {
        removeLock(a_);
        removeLock(b_);
    }
    const QString& a() const { return a_; }
    const QString& b() const { return b_; }

private:
    QProcess socat_;
    QString a_, b_;
};

// `k528 serve --port <port>` with more arguments (`--keys`, `--profile`…).
class Serve {
public:
    ~Serve() { stop(); }
    // True once it says it serves (within `ms`); else said() has what it printed.
    bool start(const QString& port, const QStringList& args, int ms = 10000) {
        stop();
        port_ = port;
        said_.clear();
        p_.start(QStringLiteral(K528_CLI), QStringList{"serve", "--port", port} + args);
        if (!p_.waitForStarted())
            return false;
        waitFor([this] {
            return (said_ += p_.readAllStandardError()).contains("k528 serve:") ||
                   p_.state() != QProcess::Running;
        }, ms);
        return p_.state() == QProcess::Running;
    }
    // Stopped, its port's lock file removed.
    void stop() {
        if (p_.state() != QProcess::NotRunning) {
            p_.terminate();
            p_.waitForFinished(5000);
        }
        removeLock(port_);
    }
    bool running() const { return p_.state() == QProcess::Running; }
    const QByteArray& said() const { return said_; }

private:
    QProcess p_;
    QString port_;
    QByteArray said_;
};

} // namespace ptytest
