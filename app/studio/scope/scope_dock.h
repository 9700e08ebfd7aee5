// The oscilloscope's dock (dock.scope) over the controller the window shows:
// every servo tick of the simulated machine, or a real controller's live
// state at the link's rate (the view says which).
#pragma once

class QDockWidget;
class QMainWindow;

namespace k528::studio {

class ViewedController;

// Adds the dock to `window` (bottom area, its place remembered) recording
// the controller `viewed` shows and redrawing on its updates.
QDockWidget* addScopeDock(QMainWindow* window, ViewedController& viewed);

} // namespace k528::studio
