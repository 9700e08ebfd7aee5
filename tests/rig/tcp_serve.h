// `k528 serve --tcp` on free localhost ports, for the tests of the Modbus TCP
// line and of the shop: started, waited for until they listen, stopped.
#pragma once

#include <QByteArray>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QProcess>
#include <QStringList>
#include <QTcpServer>
#include <memory>
#include <vector>

namespace k528::testrig {

// `n` distinct free ports of 127.0.0.1, below 32768 (mbpoll 1.0 reads the
// port as a signed 16-bit number: the kernel's ephemeral ports are above
// it): all held open at once while they are found, then freed. Where the
// search starts depends on the process id, so tests running at the same
// time look in different places first.
inline std::vector<quint16> freePorts(int n) {
    std::vector<std::unique_ptr<QTcpServer>> held;
    std::vector<quint16> ports;
    const int start = 20000 + static_cast<int>((QCoreApplication::applicationPid() * 97) % 10000);
    for (int k = 0; k < 12000 && static_cast<int>(ports.size()) < n; ++k) {
        const quint16 p = static_cast<quint16>(20000 + (start - 20000 + k) % 12000);
        auto s = std::make_unique<QTcpServer>();
        if (!s->listen(QHostAddress::LocalHost, p))
            continue;
        ports.push_back(p);
        held.push_back(std::move(s));
    }
    return ports;
}

inline QString address(quint16 port) { return QStringLiteral("127.0.0.1:%1").arg(port); }

// One simulated K528-05 on Modbus TCP.
class Serve {
public:
    Serve(QString cli, quint16 port) : cli_(std::move(cli)), port_(port) {}
    ~Serve() { stop(); }
    quint16 port() const { return port_; }
    QString address() const { return testrig::address(port_); }
    // Starts it and waits until it says it serves; false (with what it said) when it does not.
    bool start(const QStringList& more = {}, QByteArray* said = nullptr) {
        begin(more);
        return serving(said);
    }
    // Starts it without waiting (several started together, then each waited for).
    void begin(const QStringList& more = {}) {
        stop();
        p_.setProcessChannelMode(QProcess::SeparateChannels);
        p_.start(cli_, QStringList{"serve", "--tcp", address()} + more);
    }
    // Waits until it says it serves.
    bool serving(QByteArray* said = nullptr, int timeoutMs = 15000) {
        if (!p_.waitForStarted())
            return false;
        QByteArray text;
        QElapsedTimer t;
        t.start();
        while (!text.contains("k528 serve:") && p_.state() == QProcess::Running && t.elapsed() < timeoutMs) {
            p_.waitForReadyRead(100);
            text += p_.readAllStandardError();
        }
        if (said)
            *said = text;
        return text.contains("k528 serve:") && p_.state() == QProcess::Running;
    }
    void stop() {
        if (p_.state() == QProcess::Running) {
            p_.terminate();
            if (!p_.waitForFinished(5000)) {
                p_.kill();
                p_.waitForFinished(3000);
            }
        }
    }
    void kill() {
        if (p_.state() == QProcess::Running) {
            p_.kill();
            p_.waitForFinished(3000);
        }
    }
    QProcess& process() { return p_; }

private:
    QString cli_;
    quint16 port_;
    QProcess p_;
};

} // namespace k528::testrig
