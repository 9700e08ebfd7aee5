#include "modbus_tcp_plugin.h"

#include "line_errors.h"
#include "map_server.h"
#include "link/modbus_tcp.h"

#include <QModbusTcpServer>
#include <QTcpSocket>
#include <QVariant>

using namespace k528;
using namespace k528::linkplugin;

namespace {

// "HOST:PORT", "[::1]:PORT" -> host and port; false when it is not one.
bool splitAddress(const QString& address, QString& host, quint16& port) {
    const int colon = address.lastIndexOf(QLatin1Char(':'));
    if (colon <= 0)
        return false;
    host = address.left(colon);
    if (host.startsWith(QLatin1Char('[')) && host.endsWith(QLatin1Char(']')))
        host = host.mid(1, host.size() - 2);
    bool ok = false;
    const uint p = address.mid(colon + 1).toUInt(&ok);
    if (!ok || p == 0 || p > 65535 || host.isEmpty())
        return false;
    port = static_cast<quint16>(p);
    return true;
}

// The TCP connection as core's BytePort: blocking waits (the client runs on
// a worker thread or in a command), so an answer is read as soon as it comes.
class SocketPort final : public link::BytePort {
public:
    SocketPort(QString host, quint16 port, int connectMs) : host_(std::move(host)), port_(port), connectMs_(connectMs) {}
    bool open(QString& error) {
        s_.abort();
        s_.connectToHost(host_, port_);
        if (!s_.waitForConnected(connectMs_)) {
            error = socketErrorText(s_, connectMs_);
            s_.abort();
            return false;
        }
        s_.setSocketOption(QAbstractSocket::LowDelayOption, 1);
        return true;
    }
    bool write(std::span<const std::uint8_t> bytes, std::string& error) override {
        const qint64 n = s_.write(reinterpret_cast<const char*>(bytes.data()), static_cast<qint64>(bytes.size()));
        if (n != static_cast<qint64>(bytes.size()))
            return fail(error);
        while (s_.bytesToWrite() > 0)
            if (!s_.waitForBytesWritten(1000))
                return fail(error);
        return true;
    }
    bool read(link::Bytes& into, int ms, std::string& error) override {
        if (s_.bytesAvailable() == 0 && !s_.waitForReadyRead(ms) && s_.state() != QAbstractSocket::ConnectedState)
            return fail(error);
        const QByteArray got = s_.readAll();
        into.insert(into.end(), got.begin(), got.end());
        return true;
    }
    bool isOpen() const override { return s_.state() == QAbstractSocket::ConnectedState; }
    bool reopen(std::string& error) override {
        QString e;
        if (!open(e)) {
            error = e.toStdString();
            return false;
        }
        return true;
    }

private:
    bool fail(std::string& error) {
        error = socketErrorText(s_).toStdString();
        s_.abort(); // the next exchange connects again
        return false;
    }
    QString host_;
    quint16 port_;
    int connectMs_;
    QTcpSocket s_;
};

// The socket first (a base constructed before the master that uses it).
struct PortHolder {
    PortHolder(const QString& host, quint16 port, int connectMs) : port(host, port, connectMs) {}
    SocketPort port;
};

class Client final : private PortHolder, public link::TcpMaster {
public:
    Client(const QString& host, quint16 p, const LineSettings& s)
        : PortHolder(host, p, std::max(s.timeoutMs, 1000)), TcpMaster(port, link::TcpSettings{s.address, s.timeoutMs}) {}
    bool open(QString& error) { return port.open(error); }
};

class ServerBox final : public Server {
public:
    explicit ServerBox(RegisterHandler& h) : s(h) {}
    ~ServerBox() override { s.disconnectDevice(); }
    std::int64_t requests() const override { return s.requests; }
    MapServer<QModbusTcpServer, true> s;
};

QString badAddress(const QString& a) { return lineErrorText("line.bad-address", {a.toStdString()}); }

} // namespace

std::unique_ptr<ClientTransport> ModbusTcpPlugin::openClient(const LineSettings& s, QString& error) {
    QString host;
    quint16 port = 0;
    if (!splitAddress(s.port, host, port)) {
        error = badAddress(s.port);
        return nullptr;
    }
    auto c = std::make_unique<Client>(host, port, s);
    if (!c->open(error))
        return nullptr;
    return c;
}

std::unique_ptr<Server> ModbusTcpPlugin::openServer(const LineSettings& s, RegisterHandler& handler,
                                                    const QString& identity, QString& error) {
    QString host;
    quint16 port = 0;
    if (!splitAddress(s.port, host, port)) {
        error = badAddress(s.port);
        return nullptr;
    }
    auto box = std::make_unique<ServerBox>(handler);
    QModbusTcpServer& srv = box->s;
    srv.setConnectionParameter(QModbusDevice::NetworkAddressParameter, host);
    srv.setConnectionParameter(QModbusDevice::NetworkPortParameter, port);
    srv.setServerAddress(s.address);
    srv.setValue(QModbusServer::ServerIdentifier, 0x28); // the K528's number, as on RS485
    srv.setValue(QModbusServer::AdditionalData, identity.toUtf8());
    if (!srv.connectDevice()) {
        error = srv.errorString();
        return nullptr;
    }
    return box;
}
