#include "modbus_rtu_plugin.h"

#include "line_errors.h"
#include "map_server.h"

#include <QModbusRtuSerialServer>
#include <QSerialPort>
#include <QSerialPortInfo>
#include <QVariant>

using namespace k528;
using namespace k528::linkplugin;

namespace {

QSerialPort::Parity parityOf(char p) {
    return p == 'E' ? QSerialPort::EvenParity : p == 'O' ? QSerialPort::OddParity : QSerialPort::NoParity;
}

// The serial port as core's BytePort: blocking waits (the client runs on a
// worker thread or in a command), so an answer is read as soon as it comes.
class SerialPort final : public link::BytePort {
public:
    explicit SerialPort(const LineSettings& s) : s_(s) {}
    bool open(QString& error) {
        p_.setPortName(s_.port);
        if (!p_.open(QIODevice::ReadWrite)) {
            error = serialErrorText(p_);
            return false;
        }
        const bool ok = p_.setBaudRate(s_.baud) && p_.setDataBits(QSerialPort::Data8) &&
                        p_.setParity(parityOf(s_.parity)) &&
                        p_.setStopBits(s_.stopBits == 2 ? QSerialPort::TwoStop : QSerialPort::OneStop) &&
                        p_.setFlowControl(QSerialPort::NoFlowControl);
        if (!ok) {
            error = serialErrorText(p_);
            p_.close();
            return false;
        }
        p_.clear();
        return true;
    }
    bool write(std::span<const std::uint8_t> bytes, std::string& error) override {
        const qint64 n = p_.write(reinterpret_cast<const char*>(bytes.data()), static_cast<qint64>(bytes.size()));
        if (n != static_cast<qint64>(bytes.size()) || (p_.bytesToWrite() > 0 && !p_.waitForBytesWritten(1000)))
            return fail(error);
        return true;
    }
    bool read(link::Bytes& into, int ms, std::string& error) override {
        if (p_.bytesAvailable() == 0 && !p_.waitForReadyRead(ms) && p_.error() != QSerialPort::TimeoutError &&
            p_.error() != QSerialPort::NoError)
            return fail(error);
        p_.clearError();
        const QByteArray got = p_.readAll();
        into.insert(into.end(), got.begin(), got.end());
        return true;
    }
    bool isOpen() const override { return p_.isOpen(); }
    bool reopen(std::string& error) override {
        p_.close();
        QString e;
        if (!open(e)) {
            error = e.toStdString();
            return false;
        }
        return true;
    }

private:
    bool fail(std::string& error) {
        error = serialErrorText(p_).toStdString();
        p_.close(); // the next exchange opens it again
        return false;
    }
    LineSettings s_;
    QSerialPort p_;
};

link::RtuSettings rtuSettings(const LineSettings& s) {
    link::RtuSettings r;
    r.station = s.address;
    r.baud = s.baud;
    r.bitsPerChar = 1 + 8 + (s.parity == 'N' ? 0 : 1) + s.stopBits;
    r.timeoutMs = s.timeoutMs;
    return r;
}

// The port first (a base constructed before the master that uses it).
struct PortHolder {
    explicit PortHolder(const LineSettings& s) : port(s) {}
    SerialPort port;
};

class Client final : private PortHolder, public link::RtuMaster {
public:
    explicit Client(const LineSettings& s) : PortHolder(s), RtuMaster(port, rtuSettings(s)) {}
    bool open(QString& error) { return port.open(error); }
};

class ServerBox final : public Server {
public:
    explicit ServerBox(RegisterHandler& h) : s(h) {}
    ~ServerBox() override { s.disconnectDevice(); }
    std::int64_t requests() const override { return s.requests; }
    MapServer<QModbusRtuSerialServer> s;
};

} // namespace

QStringList ModbusRtuPlugin::ports() const {
    QStringList out;
    for (const QSerialPortInfo& p : QSerialPortInfo::availablePorts())
        out << p.systemLocation();
    return out;
}

std::unique_ptr<ClientTransport> ModbusRtuPlugin::openClient(const LineSettings& s, QString& error) {
    auto c = std::make_unique<Client>(s);
    if (!c->open(error))
        return nullptr;
    return c;
}

std::unique_ptr<Server> ModbusRtuPlugin::openServer(const LineSettings& s, RegisterHandler& handler,
                                                    const QString& identity, QString& error) {
    auto box = std::make_unique<ServerBox>(handler);
    QModbusRtuSerialServer& srv = box->s;
    srv.setConnectionParameter(QModbusDevice::SerialPortNameParameter, s.port);
    srv.setConnectionParameter(QModbusDevice::SerialBaudRateParameter, s.baud);
    srv.setConnectionParameter(QModbusDevice::SerialParityParameter, parityOf(s.parity));
    srv.setConnectionParameter(QModbusDevice::SerialDataBitsParameter, QSerialPort::Data8);
    srv.setConnectionParameter(QModbusDevice::SerialStopBitsParameter,
                               s.stopBits == 2 ? QSerialPort::TwoStop : QSerialPort::OneStop);
    srv.setServerAddress(s.address);
    srv.setValue(QModbusServer::ServerIdentifier, 0x28); // the K528's number, for a scan to tell it
    srv.setValue(QModbusServer::AdditionalData, identity.toUtf8());
    if (!srv.connectDevice()) {
        error = srv.errorString();
        return nullptr;
    }
    return box;
}
