// The oscilloscope's dock (dock.scope) over the window's simulated machine.
#pragma once

class QDockWidget;
class QMainWindow;

namespace k528::studio {

class SimulationSession;

// Adds the dock to `window` (bottom area, its place remembered) recording
// every servo tick of `session`'s machine and redrawing on advanced().
QDockWidget* addScopeDock(QMainWindow* window, SimulationSession& session);

} // namespace k528::studio
