#include "scope/dock_place.h"

#include <QDockWidget>
#include <QEvent>
#include <QMainWindow>
#include <QSettings>

namespace k528::studio {

namespace {

QString key(const QDockWidget* dock, const char* what) {
    return QStringLiteral("docks/%1/%2").arg(dock->objectName(), QLatin1String(what));
}

void save(QMainWindow* window, QDockWidget* dock) {
    QSettings s;
    s.setValue(key(dock, "area"), static_cast<int>(window->dockWidgetArea(dock)));
    s.setValue(key(dock, "floating"), dock->isFloating());
    s.setValue(key(dock, "geometry"), dock->saveGeometry());
    s.setValue(key(dock, "visible"), !dock->isHidden());
}

class PlaceKeeper : public QObject {
public:
    PlaceKeeper(QMainWindow* w, QDockWidget* d) : QObject(d), window_(w), dock_(d) {
        d->installEventFilter(this);
    }
    bool eventFilter(QObject* o, QEvent* e) override {
        if (o == dock_ && (e->type() == QEvent::Move || e->type() == QEvent::Resize ||
                           e->type() == QEvent::Hide || e->type() == QEvent::Show))
            if (window_->isVisible())
                save(window_, dock_);
        return false;
    }

private:
    QMainWindow* window_;
    QDockWidget* dock_;
};

} // namespace

void rememberDockPlace(QMainWindow* window, QDockWidget* dock) {
    QSettings s;
    if (s.contains(key(dock, "area"))) {
        const auto area = static_cast<Qt::DockWidgetArea>(s.value(key(dock, "area")).toInt());
        if (area != Qt::NoDockWidgetArea && area != window->dockWidgetArea(dock))
            window->addDockWidget(area, dock);
        dock->setFloating(s.value(key(dock, "floating")).toBool());
        if (dock->isFloating())
            dock->restoreGeometry(s.value(key(dock, "geometry")).toByteArray());
        dock->setVisible(s.value(key(dock, "visible"), true).toBool());
    }
    QObject::connect(dock, &QDockWidget::dockLocationChanged, dock,
                     [window, dock] { save(window, dock); });
    QObject::connect(dock, &QDockWidget::topLevelChanged, dock,
                     [window, dock] { save(window, dock); });
    new PlaceKeeper(window, dock);
}

} // namespace k528::studio
