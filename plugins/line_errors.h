// Qt's socket and serial port errors as the line's failures of core's link
// catalog (core/link/line_error.h): by Qt's error code, so the command line
// and the desktop say them in their language («соединение отклонено», «порт
// не найден») instead of Qt's English errorString(); the system's own words
// only for a failure Qt has no code for. Header only, for both plugins.
#pragma once

#include "link/line_error.h"

#include <QAbstractSocket>
#include <QString>

#if __has_include(<QSerialPort>)
#include <QSerialPort>
#endif

namespace k528::linkplugin {

inline QString lineErrorText(std::string_view id, std::initializer_list<std::string_view> args = {}) {
    return QString::fromStdString(link::lineError(id, args));
}

// A socket's failure; `connectMs`: the wait for a connection, when that timed out.
inline QString socketErrorText(const QAbstractSocket& s, int connectMs = 0) {
    switch (s.error()) {
    case QAbstractSocket::ConnectionRefusedError:
        return lineErrorText("line.refused");
    case QAbstractSocket::RemoteHostClosedError:
        return lineErrorText("line.remote-closed");
    case QAbstractSocket::HostNotFoundError:
        return lineErrorText("line.host-not-found");
    case QAbstractSocket::SocketAccessError:
        return lineErrorText("line.socket-access");
    case QAbstractSocket::SocketTimeoutError:
        return connectMs > 0 ? lineErrorText("line.connect-timeout", {std::to_string(connectMs)})
                             : lineErrorText("line.socket-timeout");
    case QAbstractSocket::NetworkError:
        return lineErrorText("line.network");
    case QAbstractSocket::AddressInUseError:
        return lineErrorText("line.address-in-use");
    default:
        return lineErrorText("line.socket-other", {s.errorString().toStdString()});
    }
}

#if __has_include(<QSerialPort>)
inline QString serialErrorText(const QSerialPort& p) {
    switch (p.error()) {
    case QSerialPort::DeviceNotFoundError:
        return lineErrorText("line.port-not-found");
    case QSerialPort::PermissionError:
        return lineErrorText("line.port-permission");
    case QSerialPort::OpenError:
        return lineErrorText("line.port-open");
    case QSerialPort::NotOpenError:
        return lineErrorText("line.port-not-open");
    case QSerialPort::WriteError:
    case QSerialPort::ReadError:
        return lineErrorText("line.port-io");
    case QSerialPort::ResourceError:
        return lineErrorText("line.port-gone");
    case QSerialPort::UnsupportedOperationError:
        return lineErrorText("line.port-unsupported");
    case QSerialPort::TimeoutError:
        return lineErrorText("line.port-timeout");
    default:
        return lineErrorText("line.port-other", {p.errorString().toStdString()});
    }
}
#endif

} // namespace k528::linkplugin
