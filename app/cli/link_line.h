// The line options of `k528 serve` and `k528 link` (cli.md): --port DEVICE
// [--address A] [--baud B] [--parity none|even|odd] [--stop-bits 1|2], or
// --tcp HOST:PORT [--address A] (Modbus TCP: the unit id is the address).
#pragma once

#include "args.h"
#include "link_plugins.h"

#include <optional>
#include <string>
#include <vector>

namespace k528::cli {

inline const std::vector<std::string_view> kLineOptions = {"--port", "--tcp", "--address", "--baud", "--parity",
                                                           "--stop-bits"};

// The settings, or nullopt after a usage message on stderr. For --tcp the
// settings' `port` is HOST:PORT.
std::optional<linkplugin::LineSettings> lineSettings(const Args& args);
// The plugin of the line the options name: "modbus-tcp" for --tcp, else "modbus-rtu".
bool isTcpLine(const Args& args);
inline QString linePlugin(const Args& args) {
    return isTcpLine(args) ? QStringLiteral("modbus-tcp") : QStringLiteral("modbus-rtu");
}

// Ends the Qt event loop on SIGINT / SIGTERM; stopRequested() polls it.
void installStopSignals();
bool stopRequested();

} // namespace k528::cli
