#include "scope/scope_dock.h"

#include "scope/scope_view.h"
#include "session/simulation_session.h"

#include <QDockWidget>
#include <QEvent>
#include <QMainWindow>

namespace k528::studio {

namespace {

class ScopeDock : public QDockWidget {
public:
    ScopeDock(QMainWindow* window, SimulationSession& session) : QDockWidget(window) {
        setObjectName("dock.scope");
        setFeatures(DockWidgetMovable | DockWidgetFloatable | DockWidgetClosable);
        auto* view = new ScopeView(this);
        view->attach(session.simulation());
        connect(&session, &SimulationSession::advanced, view, &ScopeView::refresh);
        connect(&session, &QObject::destroyed, view, [view] { view->forget(); });
        setWidget(view);
        retranslate();
    }

protected:
    void changeEvent(QEvent* e) override {
        if (e->type() == QEvent::LanguageChange)
            retranslate();
        QDockWidget::changeEvent(e);
    }

private:
    void retranslate() { setWindowTitle(ScopeView::tr("Oscilloscope")); }
};

} // namespace

QDockWidget* addScopeDock(QMainWindow* window, SimulationSession& session) {
    auto* dock = new ScopeDock(window, session);
    window->addDockWidget(Qt::BottomDockWidgetArea, dock);
    dock->hide(); // shown from the View menu; the workspaces place it
    return dock;
}

} // namespace k528::studio
