// The interface of a controller-link plugin (plugins/README.md): a Qt plugin
// loaded with QPluginLoader whose metadata (the JSON of Q_PLUGIN_METADATA)
// carries "name", "version", "api" and "transport". The host refuses a
// plugin with another IID or another "api" (k528::linkplugin::load).
//
// The plugin opens the line — a serial port for RS485 — and gives core's
// Modbus client over it (link::ModbusMaster: RTU framing, every frame
// logged, the wire counted), so the client procedures of core/link run
// over it; and a server that answers a line from a RegisterHandler (the
// host wraps core's ControllerImage). A Modbus TCP line is the same
// ModbusMaster with MBAP framing over a socket: the procedures, the
// counters and the frame log do not change. The plugin links Qt only; the
// parts of core it uses are header-only or compiled into it (link/modbus.cpp).
#pragma once

#include "link/modbus.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <QtPlugin>
#include <cstdint>
#include <memory>

namespace k528::linkplugin {

// 2: the client is core's ModbusMaster (frame log, damaged frames, FC 17),
// the server names itself (FC 17).
inline constexpr int kApi = 2;

struct LineSettings {
    QString port; // a serial device; HOST:PORT for Modbus TCP (plugin modbus-tcp)
    int baud = 115200;
    char parity = 'N'; // N, E, O
    int stopBits = 1;
    int address = 1;
    int timeoutMs = 200; // for an answer to begin; a scan waits this long at each address
};

using RegisterHandler = link::modbus::RegisterHandler;
using WireCount = link::WireCount;
using ClientTransport = link::ModbusMaster;

class Server {
public:
    virtual ~Server() = default;
    virtual std::int64_t requests() const = 0;
};

class LinkPlugin {
public:
    virtual ~LinkPlugin() = default;
    // The serial ports the system has (for a menu and `k528 link --list`).
    virtual QStringList ports() const = 0;
    // nullptr and `error` set when the port does not open. A port that fails
    // later (a USB adapter pulled) is opened again by the client at its next
    // exchange.
    virtual std::unique_ptr<ClientTransport> openClient(const LineSettings& s, QString& error) = 0;
    // Serves `handler` on the line until destroyed; needs a running Qt event
    // loop. Function 8 (echo, the bus counters 10..18) and 17 (`identity`
    // as the additional data of the server id) are answered too.
    virtual std::unique_ptr<Server> openServer(const LineSettings& s, RegisterHandler& handler,
                                               const QString& identity, QString& error) = 0;
};

} // namespace k528::linkplugin

#define K528_LINK_PLUGIN_IID "io.github.k528studio.LinkPlugin/1"
Q_DECLARE_INTERFACE(k528::linkplugin::LinkPlugin, K528_LINK_PLUGIN_IID)
