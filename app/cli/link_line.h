// The line options of `k528 serve` and `k528 link` (cli.md): --port DEVICE
// [--address A] [--baud B] [--parity none|even|odd] [--stop-bits 1|2].
#pragma once

#include "args.h"
#include "link_plugins.h"

#include <optional>
#include <string>
#include <vector>

namespace k528::cli {

inline const std::vector<std::string_view> kLineOptions = {"--port", "--address", "--baud", "--parity", "--stop-bits"};

// The settings, or nullopt after a usage message on stderr.
std::optional<linkplugin::LineSettings> lineSettings(const Args& args);

// Ends the Qt event loop on SIGINT / SIGTERM; stopRequested() polls it.
void installStopSignals();
bool stopRequested();

} // namespace k528::cli
