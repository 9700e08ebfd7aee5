// The dock of one pane of the main window (docs/architecture.md, "The main
// window: workspaces"): its object name `dock.<pane>`, movable, floatable and
// closable, its texts given again on every change of the language.
#pragma once

#include <QDockWidget>

class QEvent;
class QMainWindow;

namespace k528::studio {

class PaneDock : public QDockWidget {
    Q_OBJECT
public:
    // `pane`: the name after "dock." (history, scope, …).
    PaneDock(QMainWindow* window, const QString& pane);

protected:
    // The dock's texts in the language now: its title and those of its own
    // widgets. Called on every change of the language; a dock calls it once
    // itself when its widgets are made.
    virtual void retranslate() = 0;
    void changeEvent(QEvent* e) override;
};

} // namespace k528::studio
