// An MQTT broker for a test: mosquitto on a localhost port (as root it
// listens on localhost only with -p), waited for until it accepts, stopped
// with the test; and mosquitto_sub to read what was published.
#pragma once

#include <QElapsedTimer>
#include <QProcess>
#include <QStandardPaths>
#include <QString>
#include <QStringList>
#include <QTcpSocket>
#include <QThread>

namespace k528::testrig {

// Both mosquitto and mosquitto_sub are installed.
inline bool mosquittoInstalled() {
    return !QStandardPaths::findExecutable("mosquitto").isEmpty() &&
           !QStandardPaths::findExecutable("mosquitto_sub").isEmpty();
}

class MqttBroker {
public:
    ~MqttBroker() { stop(); }
    // Starts mosquitto on `port` and waits until it accepts a connection;
    // false when it did not within `timeoutMs`.
    bool start(quint16 port, int timeoutMs = 10000) {
        port_ = port;
        p_.start("mosquitto", {"-p", QString::number(port)});
        if (!p_.waitForStarted())
            return false;
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < timeoutMs) {
            QTcpSocket s;
            s.connectToHost("127.0.0.1", port);
            if (s.waitForConnected(200))
                return true;
            QThread::msleep(50);
        }
        return false;
    }
    void stop() {
        if (p_.state() != QProcess::NotRunning) {
            p_.terminate();
            p_.waitForFinished(5000);
        }
    }
    quint16 port() const { return port_; }
    QString url() const { return "mqtt://127.0.0.1:" + QString::number(port_); }
    // Starts mosquitto_sub -v on `topic` until `count` messages came or `seconds` passed.
    void subscribe(QProcess& sub, const QString& topic, int count, int seconds) const {
        sub.start("mosquitto_sub", {"-h", "127.0.0.1", "-p", QString::number(port_), "-t", topic, "-v", "-C",
                                    QString::number(count), "-W", QString::number(seconds)});
    }
    // The same, returning once the broker has acknowledged the subscription
    // (mosquitto_sub -d says "received SUBACK"), so that what is published
    // next reaches it; what it printed so far (debug lines among the
    // messages: read them with the topic's prefix) into `out`. False if no
    // acknowledgement came within `ms`.
    bool subscribeAcknowledged(QProcess& sub, const QString& topic, int count, int seconds, QByteArray& out,
                               int ms = 10000) const {
        // Line-buffered (coreutils' stdbuf): into a pipe mosquitto_sub flushes
        // only after a message, and a topic with none retained would hide
        // the acknowledgement until the first.
        sub.start("stdbuf", {"-oL", "mosquitto_sub", "-d", "-h", "127.0.0.1", "-p", QString::number(port_), "-t", topic,
                             "-v", "-C", QString::number(count), "-W", QString::number(seconds)});
        if (!sub.waitForStarted())
            return false;
        QElapsedTimer t;
        t.start();
        while (!out.contains("received SUBACK") && t.elapsed() < ms && sub.state() == QProcess::Running) {
            sub.waitForReadyRead(50);
            out += sub.readAllStandardOutput();
        }
        return out.contains("received SUBACK");
    }

private:
    QProcess p_;
    quint16 port_ = 0;
};

} // namespace k528::testrig
