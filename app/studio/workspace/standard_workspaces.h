// The four workspaces of K528 Studio and their default layouts:
//   Operator      — the K923 large on the left, the program being run in the
//                   centre, the machine's panel on the right, the messages and
//                   axes below the program; the controller on demand.
//   Technologist  — the editor in the centre (files, outline, Problems), the
//                   backplot beside it with the prove-out a tab behind it;
//                   the debugger, the controller, the
//                   messages, R-parameters and constants on demand.
//   Training      — no centre: the K923 and the machine's panel side by side
//                   (the messages below the panel), the backplot and the
//                   oscilloscope on the right: one above the other on a
//                   desk's screen, two tabs on a shop PC's.
//   Shop          — the machines of the database on their lines, a tile
//                   each, the alarms and today's time in each state in the
//                   centre; the Controller dock beside it shows the machine
//                   clicked.
// The shares fit the screen: the K923's width follows from the height it
// gets (workspace/workspaces.h says how a layout is built and kept).
#pragma once

#include "workspace/workspaces.h"

namespace k528::studio {

// For a screen whose available area (logical pixels) is `available`.
std::vector<WorkspaceSpec> standardWorkspaces(QSize available);

} // namespace k528::studio
