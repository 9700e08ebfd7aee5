#include "modbus_rtu_plugin.h"

#include <QEventLoop>
#include <QModbusRtuSerialClient>
#include <QModbusRtuSerialServer>
#include <QSerialPort>
#include <QSerialPortInfo>
#include <QTimer>
#include <QVariant>

using namespace k528;
using namespace k528::linkplugin;

namespace {

QSerialPort::Parity parityOf(char p) {
    return p == 'E' ? QSerialPort::EvenParity : p == 'O' ? QSerialPort::OddParity : QSerialPort::NoParity;
}

template <class Device> void configure(Device& d, const LineSettings& s) {
    d.setConnectionParameter(QModbusDevice::SerialPortNameParameter, s.port);
    d.setConnectionParameter(QModbusDevice::SerialBaudRateParameter, s.baud);
    d.setConnectionParameter(QModbusDevice::SerialParityParameter, parityOf(s.parity));
    d.setConnectionParameter(QModbusDevice::SerialDataBitsParameter, QSerialPort::Data8);
    d.setConnectionParameter(QModbusDevice::SerialStopBitsParameter,
                             s.stopBits == 2 ? QSerialPort::TwoStop : QSerialPort::OneStop);
}

quint16 be16(const QByteArray& d, int at) {
    return static_cast<quint16>((static_cast<quint8>(d.at(at)) << 8) | static_cast<quint8>(d.at(at + 1)));
}

class Client final : public ClientTransport {
public:
    Client(const LineSettings& s) : s_(s) {
        configure(c_, s);
        c_.setTimeout(s.timeoutMs);
        c_.setNumberOfRetries(0); // the Link retries and counts
    }
    bool open(QString& error) {
        if (!c_.connectDevice()) {
            error = c_.errorString();
            return false;
        }
        if (c_.state() != QModbusDevice::ConnectedState) {
            QEventLoop loop;
            QObject::connect(&c_, &QModbusDevice::stateChanged, &loop, [&](QModbusDevice::State st) {
                if (st == QModbusDevice::ConnectedState || st == QModbusDevice::UnconnectedState)
                    loop.quit();
            });
            QTimer::singleShot(2000, &loop, &QEventLoop::quit);
            loop.exec();
        }
        if (c_.state() != QModbusDevice::ConnectedState) {
            error = c_.errorString().isEmpty() ? QStringLiteral("cannot open ") + s_.port : c_.errorString();
            return false;
        }
        return true;
    }
    ~Client() override { c_.disconnectDevice(); }

    link::Reply read(int first, int count, std::vector<std::uint16_t>& out) override {
        count_(link::readFrameBytes(count));
        QModbusDataUnit unit(QModbusDataUnit::HoldingRegisters, first, static_cast<quint16>(count));
        return finish(c_.sendReadRequest(unit, s_.address), &out);
    }
    link::Reply write(int first, std::span<const std::uint16_t> values) override {
        count_(link::writeFrameBytes(static_cast<int>(values.size())));
        QModbusDataUnit unit(QModbusDataUnit::HoldingRegisters, first,
                             QList<quint16>(values.begin(), values.end()));
        QModbusReply* r = c_.sendWriteRequest(unit, s_.address);
        std::vector<std::uint16_t> none;
        link::Reply rep = finish(r, nullptr, [&](const QModbusResponse& raw) -> QString {
            // Qt 6.4 does not check FC 16's echo: the address and count must be ours.
            const QByteArray d = raw.data();
            if (raw.functionCode() == QModbusPdu::WriteMultipleRegisters &&
                (d.size() < 4 || be16(d, 0) != first || be16(d, 2) != values.size()))
                return QStringLiteral("FC 16 echo does not match the request");
            if (raw.functionCode() == QModbusPdu::WriteSingleRegister &&
                (d.size() < 4 || be16(d, 0) != first || be16(d, 2) != values[0]))
                return QStringLiteral("FC 06 echo does not match the request");
            return {};
        });
        return rep;
    }
    link::Reply writeRead(int wf, std::span<const std::uint16_t> values, int rf, int rc,
                          std::vector<std::uint16_t>& out) override {
        count_(link::writeReadFrameBytes(static_cast<int>(values.size()), rc));
        QModbusDataUnit rd(QModbusDataUnit::HoldingRegisters, rf, static_cast<quint16>(rc));
        QModbusDataUnit wr(QModbusDataUnit::HoldingRegisters, wf, QList<quint16>(values.begin(), values.end()));
        return finish(c_.sendReadWriteRequest(rd, wr, s_.address), &out);
    }
    link::Reply echo(std::uint16_t value) override {
        count_(link::echoFrameBytes());
        QModbusRequest req(QModbusRequest::Diagnostics, quint16(0x0000), quint16(value));
        QModbusReply* r = c_.sendRawRequest(req, s_.address);
        if (!r)
            return link::Reply::lost(c_.errorString().toStdString());
        if (!r->isFinished()) {
            QEventLoop loop;
            QObject::connect(r, &QModbusReply::finished, &loop, &QEventLoop::quit);
            loop.exec();
        }
        // Qt 6.4 marks a good FC 8 answer "invalid response": judge the raw answer.
        const QModbusResponse raw = r->rawResult();
        const QModbusDevice::Error err = r->error();
        r->deleteLater();
        if (raw.functionCode() == QModbusPdu::Diagnostics && raw.data().size() == 4)
            return be16(raw.data(), 0) == 0 && be16(raw.data(), 2) == value ? link::Reply::good()
                                                                           : link::Reply::bad("the echo differs");
        if (raw.isException())
            return link::Reply::exceptionCode(static_cast<int>(raw.exceptionCode()));
        if (err == QModbusDevice::TimeoutError)
            return link::Reply::lost("timeout");
        return link::Reply::lost("no echo");
    }
    WireCount wire() const override { return wire_; }

private:
    void count_(link::FrameBytes f) {
        wire_.bytes += f.request + f.reply;
        wire_.frames += 2;
        ++wire_.transactions;
    }
    template <class Check = std::nullptr_t>
    link::Reply finish(QModbusReply* r, std::vector<std::uint16_t>* out, Check check = nullptr) {
        if (!r)
            return link::Reply::lost(c_.errorString().toStdString());
        if (!r->isFinished()) {
            QEventLoop loop;
            QObject::connect(r, &QModbusReply::finished, &loop, &QEventLoop::quit);
            loop.exec();
        }
        link::Reply rep;
        switch (r->error()) {
        case QModbusDevice::NoError:
            if (out) {
                const QList<quint16> values = r->result().values(); // a copy: one list for begin and end
                out->assign(values.begin(), values.end());
            }
            if constexpr (!std::is_same_v<Check, std::nullptr_t>) {
                const QString bad = check(r->rawResult());
                if (!bad.isEmpty())
                    rep = link::Reply::bad(bad.toStdString());
            }
            break;
        case QModbusDevice::ProtocolError:
            rep = link::Reply::exceptionCode(static_cast<int>(r->rawResult().exceptionCode()));
            break;
        case QModbusDevice::TimeoutError:
            rep = link::Reply::lost("timeout");
            break;
        default:
            rep = link::Reply::lost(r->errorString().toStdString());
            break;
        }
        r->deleteLater();
        return rep;
    }
    LineSettings s_;
    QModbusRtuSerialClient c_;
    WireCount wire_;
};

// QModbusRtuSerialServer with the map behind it: FC 3, 6, 16 and 23 go to
// the handler (its exceptions 02/03/06 as Qt's exception responses); the
// rest (FC 8 echo, unknown functions) is Qt's.
class MapServer final : public QModbusRtuSerialServer {
public:
    explicit MapServer(RegisterHandler& h) : h_(h) {}
    std::int64_t requests = 0;

protected:
    QModbusResponse processRequest(const QModbusPdu& request) override {
        ++requests;
        const QByteArray d = request.data();
        const auto fc = request.functionCode();
        auto fail = [&](int code) {
            return QModbusExceptionResponse(fc, static_cast<QModbusExceptionResponse::ExceptionCode>(code));
        };
        auto registers = [&](const std::vector<std::uint16_t>& v) {
            QByteArray out;
            out.append(static_cast<char>(v.size() * 2));
            for (std::uint16_t w : v) {
                out.append(static_cast<char>(w >> 8));
                out.append(static_cast<char>(w & 0xFF));
            }
            return QModbusResponse(fc, out);
        };
        auto values = [&](int at, int n) {
            std::vector<std::uint16_t> v;
            for (int i = 0; i < n; ++i)
                v.push_back(be16(d, at + 2 * i));
            return v;
        };
        switch (fc) {
        case QModbusPdu::ReadHoldingRegisters: {
            if (d.size() != 4)
                return fail(3);
            std::vector<std::uint16_t> v;
            if (const int e = h_.read(be16(d, 0), be16(d, 2), v))
                return fail(e);
            return registers(v);
        }
        case QModbusPdu::WriteSingleRegister: {
            if (d.size() != 4)
                return fail(3);
            const std::uint16_t v[] = {be16(d, 2)};
            if (const int e = h_.write(be16(d, 0), v))
                return fail(e);
            return QModbusResponse(fc, d);
        }
        case QModbusPdu::WriteMultipleRegisters: {
            if (d.size() < 5 || d.size() != 5 + static_cast<quint8>(d.at(4)) || static_cast<quint8>(d.at(4)) != 2 * be16(d, 2))
                return fail(3);
            const std::vector<std::uint16_t> v = values(5, be16(d, 2));
            if (const int e = h_.write(be16(d, 0), v))
                return fail(e);
            return QModbusResponse(fc, d.left(4));
        }
        case QModbusPdu::ReadWriteMultipleRegisters: {
            if (d.size() < 9 || d.size() != 9 + static_cast<quint8>(d.at(8)) || static_cast<quint8>(d.at(8)) != 2 * be16(d, 6))
                return fail(3);
            const std::vector<std::uint16_t> w = values(9, be16(d, 6));
            if (const int e = h_.write(be16(d, 4), w)) // the write first (Modbus spec)
                return fail(e);
            std::vector<std::uint16_t> v;
            if (const int e = h_.read(be16(d, 0), be16(d, 2), v))
                return fail(e);
            return registers(v);
        }
        default:
            return QModbusRtuSerialServer::processRequest(request);
        }
    }

private:
    RegisterHandler& h_;
};

class ServerBox final : public Server {
public:
    explicit ServerBox(RegisterHandler& h) : s(h) {}
    ~ServerBox() override { s.disconnectDevice(); }
    std::int64_t requests() const override { return s.requests; }
    MapServer s;
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
                                                    QString& error) {
    auto box = std::make_unique<ServerBox>(handler);
    configure(box->s, s);
    box->s.setServerAddress(s.address);
    if (!box->s.connectDevice()) {
        error = box->s.errorString();
        return nullptr;
    }
    return box;
}
