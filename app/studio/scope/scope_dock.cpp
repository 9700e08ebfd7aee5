#include "scope/scope_dock.h"

#include "scope/scope_view.h"
#include "session/simulation_session.h"

#include <QDockWidget>
#include <QElapsedTimer>
#include <QTimer>

#include <algorithm>
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
        // The charts live at most at kLiveIntervalMs (a trailing frame
        // draws what the last one skipped).
        pending_.setSingleShot(true);
        connect(&pending_, &QTimer::timeout, view, [this, view] {
            sinceDraw_.restart();
            view->refresh();
        });
        connect(&session, &SimulationSession::advanced, view, [this] {
            if (pending_.isActive())
                return;
            const qint64 since = sinceDraw_.isValid() ? sinceDraw_.elapsed() : ScopeView::kLiveIntervalMs;
            pending_.start(static_cast<int>(std::max<qint64>(0, ScopeView::kLiveIntervalMs - since)));
        });
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
    QTimer pending_;
    QElapsedTimer sinceDraw_;
};

} // namespace

QDockWidget* addScopeDock(QMainWindow* window, SimulationSession& session) {
    auto* dock = new ScopeDock(window, session);
    window->addDockWidget(Qt::BottomDockWidgetArea, dock);
    dock->hide(); // shown from the View menu; the workspaces place it
    return dock;
}

} // namespace k528::studio
