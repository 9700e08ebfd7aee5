// The backplot dock of the main window: the programmed path of a program of
// the controller the window shows (the engine's preview; a real controller's
// program read from it when shown), the actual path growing live — every
// tick of the simulated machine, or a real controller's live positions at
// each poll of the link — a run simulated on demand, and the stock of the
// blank given as UCG text.
#pragma once

class QMainWindow;
class QDockWidget;

namespace k528::studio {
class ViewedController;
namespace backplot {

// Builds the dock (object name "dock.backplot") and adds it to `window`.
QDockWidget* addBackplotDock(QMainWindow* window, ViewedController& viewed);

} // namespace backplot
} // namespace k528::studio
