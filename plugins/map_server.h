// A Qt SerialBus server (QModbusRtuSerialServer, QModbusTcpServer) with the
// map behind it: FC 3, 6, 16 and 23 go to the host's handler (core's
// modbus::serveRegisters); FC 8 (echo, bus counters) and 17 (server id) are
// Qt's. Shared by the plugins (header-only: each compiles its own copy).
#pragma once

#include "link_plugin.h"

#include <QModbusPdu>
#include <QModbusServer>
#include <cstdint>

namespace k528::linkplugin {

// `ownDiagnostics`: FC 8 (echo, the counters of a serial line) and FC 17
// answered here, for a server whose Qt class refuses them (Qt's TCP server:
// the Modbus spec makes them serial-line functions, but a gateway passes them
// on to the RS485 station behind it, and `k528 serve --tcp` plays that
// station). The counters: bus and server messages (every request to this
// station), bus exceptions (answered with an exception); the serial faults
// (CRC errors, overruns) cannot happen on TCP and stay 0.
template <class QtServer, bool ownDiagnostics = false> class MapServer : public QtServer {
public:
    explicit MapServer(RegisterHandler& h) : h_(h) {}
    std::int64_t requests = 0;

protected:
    QModbusResponse processRequest(const QModbusPdu& request) override {
        ++requests;
        const QModbusResponse r = answer(request);
        if constexpr (ownDiagnostics) {
            ++busMessages_;
            if (r.isException())
                ++busExceptions_;
        }
        return r;
    }

private:
    QModbusResponse answer(const QModbusPdu& request) {
        const auto fc = request.functionCode();
        if constexpr (ownDiagnostics) {
            if (fc == QModbusPdu::Diagnostics)
                return diagnostics(request);
            if (fc == QModbusPdu::ReportServerId) {
                QByteArray d;
                const QByteArray extra = QtServer::value(QModbusServer::AdditionalData).toByteArray();
                d.append(char(2 + extra.size()));
                d.append(char(QtServer::value(QModbusServer::ServerIdentifier).toInt()));
                d.append(char(0xFF)); // run indicator: on
                d.append(extra);
                return QModbusResponse(fc, d);
            }
        }
        if (fc != QModbusPdu::ReadHoldingRegisters && fc != QModbusPdu::WriteSingleRegister &&
            fc != QModbusPdu::WriteMultipleRegisters && fc != QModbusPdu::ReadWriteMultipleRegisters)
            return QtServer::processRequest(request);
        link::Bytes pdu{static_cast<std::uint8_t>(fc)};
        const QByteArray d = request.data();
        pdu.insert(pdu.end(), d.begin(), d.end());
        const link::Bytes answer = link::modbus::serveRegisters(pdu, h_);
        if (answer[0] & 0x80)
            return QModbusExceptionResponse(fc, static_cast<QModbusExceptionResponse::ExceptionCode>(answer[1]));
        return QModbusResponse(fc, QByteArray(reinterpret_cast<const char*>(answer.data()) + 1,
                                              static_cast<qsizetype>(answer.size()) - 1));
    }

    QModbusResponse diagnostics(const QModbusPdu& request) {
        const QByteArray d = request.data();
        if (d.size() != 4)
            return QModbusExceptionResponse(request.functionCode(), QModbusExceptionResponse::IllegalDataValue);
        const int sub = (std::uint8_t(d[0]) << 8) | std::uint8_t(d[1]);
        std::uint16_t value = 0;
        switch (sub) {
        case link::modbus::ReturnQueryData:
            return QModbusResponse(request.functionCode(), d);
        case link::modbus::ClearCounters:
            busMessages_ = busExceptions_ = 0;
            value = (std::uint8_t(d[2]) << 8) | std::uint8_t(d[3]);
            break;
        case link::modbus::BusMessages:
        case link::modbus::ServerMessages:
            value = static_cast<std::uint16_t>(busMessages_ + 1); // this request counts
            break;
        case link::modbus::BusExceptions:
            value = static_cast<std::uint16_t>(busExceptions_);
            break;
        case link::modbus::BusCommunicationErrors:
        case link::modbus::ServerNoResponse:
        case link::modbus::ServerNak:
        case link::modbus::ServerBusy:
        case link::modbus::BusCharacterOverrun:
            break;
        default:
            return QModbusExceptionResponse(request.functionCode(), QModbusExceptionResponse::IllegalFunction);
        }
        QByteArray out = d.left(2);
        out.append(char(value >> 8));
        out.append(char(value & 0xFF));
        return QModbusResponse(request.functionCode(), out);
    }

    RegisterHandler& h_;
    std::int64_t busMessages_ = 0, busExceptions_ = 0;
};

} // namespace k528::linkplugin
