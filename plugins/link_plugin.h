// The interface of a controller-link plugin (plugins/README.md): a Qt plugin
// loaded with QPluginLoader whose metadata (the JSON of Q_PLUGIN_METADATA)
// carries "name", "version", "api" and "transport". The host refuses a
// plugin with another IID or another "api" (k528::linkplugin::load).
//
// The plugin gives a client transport (core's link::RegisterTransport, so the
// client procedures of core/link run over it) and a server that answers a
// line from a RegisterHandler (the host wraps core's ControllerImage). The
// plugin links Qt only: everything of core it uses is header-only here.
#pragma once

#include "link/transport.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <QtPlugin>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace k528::linkplugin {

inline constexpr int kApi = 1;

struct LineSettings {
    QString port;
    int baud = 115200;
    char parity = 'N'; // N, E, O
    int stopBits = 1;
    int address = 1;
    int timeoutMs = 200;
};

// The controller's side of a line: each returns a Modbus exception code (0 = none).
class RegisterHandler {
public:
    virtual ~RegisterHandler() = default;
    virtual int read(int first, int count, std::vector<std::uint16_t>& out) = 0;
    virtual int write(int first, std::span<const std::uint16_t> values) = 0;
};

// Bytes and frames a transport put on the line, both directions.
struct WireCount {
    std::int64_t bytes = 0, frames = 0, transactions = 0;
};

class ClientTransport : public link::RegisterTransport {
public:
    virtual WireCount wire() const = 0;
};

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
    // nullptr and `error` set when the port does not open.
    virtual std::unique_ptr<ClientTransport> openClient(const LineSettings& s, QString& error) = 0;
    // Serves `handler` on the line until destroyed; needs a running Qt event loop.
    virtual std::unique_ptr<Server> openServer(const LineSettings& s, RegisterHandler& handler,
                                               QString& error) = 0;
};

} // namespace k528::linkplugin

#define K528_LINK_PLUGIN_IID "io.github.k528studio.LinkPlugin/1"
Q_DECLARE_INTERFACE(k528::linkplugin::LinkPlugin, K528_LINK_PLUGIN_IID)
