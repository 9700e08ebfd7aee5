#include "scope/scope_dock.h"

#include "controller/controller.h"
#include "controller/simulated_machine.h"
#include "controller/view_notice.h"
#include "scope/scope_view.h"
#include "workspace/pane_dock.h"

#include <QDockWidget>
#include <QElapsedTimer>
#include <QTimer>

#include <algorithm>
#include <QEvent>
#include <QMainWindow>

namespace k528::studio {

namespace {

class ScopeDock : public PaneDock {
public:
    ScopeDock(QMainWindow* window, ViewedController& viewed)
        : PaneDock(window, "scope", [] { return ScopeView::tr("Oscilloscope"); }), viewed_(viewed) {
        view_ = new ScopeView(this);
        // The charts live at most at kLiveIntervalMs (a trailing frame
        // draws what the last one skipped).
        pending_.setSingleShot(true);
        connect(&pending_, &QTimer::timeout, view_, [this] {
            sinceDraw_.restart();
            view_->refresh();
        });
        connect(&viewed, &ViewedController::changed, this, [this] { follow(); });
        // Its tab brought to the front: the picture of now (behind another
        // tab it was not drawn), once the dock has its place.
        connect(this, &QDockWidget::visibilityChanged, view_, [this](bool visible) {
            if (visible)
                QTimer::singleShot(0, view_, [v = view_] { v->refresh(); });
        });
        follow();
        // The rate line says what is sampled; the notice, a lost line.
        auto* notice = new ViewNotice(view_, this);
        notice->follow(viewed, [](Controller&) { return std::pair<ViewNotice::Level, QString>{}; });
        setWidget(notice);
    }

private:
    // The controller shown: every servo tick of the simulated machine, or
    // each poll of a real one.
    void follow() {
        Controller& c = viewed_.current();
        view_->attachController(&c);
        disconnect(updates_);
        updates_ = connect(&c, c.simulated() ? &Controller::updated : &Controller::sampled, view_, [this] {
            if (pending_.isActive())
                return;
            const qint64 since = sinceDraw_.isValid() ? sinceDraw_.elapsed() : ScopeView::kLiveIntervalMs;
            pending_.start(static_cast<int>(std::max<qint64>(0, ScopeView::kLiveIntervalMs - since)));
        });
        if (SimulatedMachine* sim = c.simulated())
            connect(sim->lifetime(), &QObject::destroyed, view_, [v = view_] { v->forget(); });
    }
    ViewedController& viewed_;
    ScopeView* view_ = nullptr;
    QMetaObject::Connection updates_;
    QTimer pending_;
    QElapsedTimer sinceDraw_;
};

} // namespace

QDockWidget* addScopeDock(QMainWindow* window, ViewedController& viewed) {
    auto* dock = new ScopeDock(window, viewed);
    window->addDockWidget(Qt::BottomDockWidgetArea, dock);
    dock->hide(); // shown from the View menu; the workspaces place it
    return dock;
}

} // namespace k528::studio
