// The backplot dock of the main window: the programmed path of a program of
// the session's store (the engine's preview), the actual path of a run on the
// simulated machine, and the stock of the blank given as UCG text.
#pragma once

class QMainWindow;
class QDockWidget;

namespace k528::studio {
class SimulationSession;
namespace backplot {

// Builds the dock (object name "dock.backplot") and adds it to `window`.
QDockWidget* addBackplotDock(QMainWindow* window, SimulationSession& session);

} // namespace backplot
} // namespace k528::studio
