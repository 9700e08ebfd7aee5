#include "workspace/pane_dock.h"

#include <QEvent>
#include <QMainWindow>

namespace k528::studio {

PaneDock::PaneDock(QMainWindow* window, const QString& pane) : QDockWidget(window) {
    setObjectName("dock." + pane);
    setFeatures(DockWidgetMovable | DockWidgetFloatable | DockWidgetClosable);
}

void PaneDock::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange)
        retranslate();
    QDockWidget::changeEvent(e);
}

} // namespace k528::studio
