#include "workspace/pane_dock.h"

#include <QEvent>
#include <QMainWindow>

namespace k528::studio {

PaneDock::PaneDock(QMainWindow* window, const QString& pane, std::function<QString()> title)
    : QDockWidget(window), title_(std::move(title)) {
    setObjectName("dock." + pane);
    setFeatures(DockWidgetMovable | DockWidgetFloatable | DockWidgetClosable);
    PaneDock::retranslate();
}

void PaneDock::retranslate() {
    if (title_)
        setWindowTitle(title_());
}

void PaneDock::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange)
        retranslate();
    QDockWidget::changeEvent(e);
}

} // namespace k528::studio
