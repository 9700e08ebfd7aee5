// The Modbus TCP link (plugins/README.md): a serial-to-Ethernet gateway in
// Modbus TCP mode in front of the K528-05's RS485 line (the unit id is the
// station address), or `k528 serve --tcp`. The line's `port` is HOST:PORT.
// The client is core's TcpMaster (link/modbus_tcp.h: MBAP framing, every
// frame logged) over a QTcpSocket; the server is Qt SerialBus's
// QModbusTcpServer with the map's registers behind it.
#pragma once

#include "link_plugin.h"

#include <QObject>

class ModbusTcpPlugin : public QObject, public k528::linkplugin::LinkPlugin {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID K528_LINK_PLUGIN_IID FILE "modbus-tcp.json")
    Q_INTERFACES(k528::linkplugin::LinkPlugin)
public:
    QStringList ports() const override { return {}; } // a network line has no ports to list
    std::unique_ptr<k528::linkplugin::ClientTransport> openClient(const k528::linkplugin::LineSettings& s,
                                                                  QString& error) override;
    std::unique_ptr<k528::linkplugin::Server> openServer(const k528::linkplugin::LineSettings& s,
                                                         k528::linkplugin::RegisterHandler& handler,
                                                         const QString& identity, QString& error) override;
};
