// The dock of one pane of the main window (docs/architecture.md, "The main
// window: workspaces"): its object name `dock.<pane>`, movable, floatable and
// closable, its title and texts given again on every change of the language.
#pragma once

#include <QDockWidget>
#include <functional>

class QEvent;
class QMainWindow;

namespace k528::studio {

class PaneDock : public QDockWidget {
    Q_OBJECT
public:
    // `pane`: the name after "dock." (history, scope, …); `title`: the
    // dock's title in the language now (none: retranslate() gives it).
    PaneDock(QMainWindow* window, const QString& pane, std::function<QString()> title = {});

protected:
    // The dock's texts in the language now: its title and those of its own
    // widgets (a dock with widgets of its own overrides it and calls it once
    // itself when they are made). Called on every change of the language.
    virtual void retranslate();
    void changeEvent(QEvent* e) override;

private:
    std::function<QString()> title_;
};

} // namespace k528::studio
