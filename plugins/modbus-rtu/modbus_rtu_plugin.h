// The RS485 / Modbus RTU link (plugins/README.md): the client is core's
// RtuMaster (link/modbus.h) over a QSerialPort — every frame logged with its
// CRC, damaged frames counted —; the server is Qt SerialBus's
// QModbusRtuSerialServer (its bus counters answer FC 8) with the map's
// registers behind it.
#pragma once

#include "link_plugin.h"

#include <QObject>

class ModbusRtuPlugin : public QObject, public k528::linkplugin::LinkPlugin {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID K528_LINK_PLUGIN_IID FILE "modbus-rtu.json")
    Q_INTERFACES(k528::linkplugin::LinkPlugin)
public:
    QStringList ports() const override;
    std::unique_ptr<k528::linkplugin::ClientTransport> openClient(const k528::linkplugin::LineSettings& s,
                                                                  QString& error) override;
    std::unique_ptr<k528::linkplugin::Server> openServer(const k528::linkplugin::LineSettings& s,
                                                         k528::linkplugin::RegisterHandler& handler,
                                                         const QString& identity, QString& error) override;
};
