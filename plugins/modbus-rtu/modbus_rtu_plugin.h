// The RS485 / Modbus RTU link (plugins/README.md): Qt SerialBus does the
// framing (QModbusRtuSerialClient, QModbusRtuSerialServer); this file only
// maps requests to the map's registers and checks replies.
#pragma once

#include "../link_plugin.h"

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
                                                         QString& error) override;
};
