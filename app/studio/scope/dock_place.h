// A dock that remembers its place: area, floating, size and visibility are
// kept in QSettings under "docks/<objectName>/…" and restored when the dock
// is created (the main window keeps no state of its own).
#pragma once

class QDockWidget;
class QMainWindow;

namespace k528::studio {

// Restores `dock`'s place from QSettings (or leaves it where it was added)
// and keeps it there whenever it moves, floats, closes or changes size.
void rememberDockPlace(QMainWindow* window, QDockWidget* dock);

} // namespace k528::studio
