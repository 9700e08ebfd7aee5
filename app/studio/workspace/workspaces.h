// Workspaces: the main window arranged for one of its users at a time, as Qt
// Creator's modes or gmoccapy's pages do — *Operator*, *Technologist*,
// *Training* (workspace/standard_workspaces.cpp says what each shows).
//
// A workspace is data (WorkspaceSpec): which page of the work area is in the
// centre (or none), and where each dock goes in its default layout — its
// area, the dock it is split from or tabbed with, its share of the window,
// shown or only placed (shown on demand from the View menu). One set of docks
// serves every workspace; switching keeps the layout the user made in the
// workspace left (QMainWindow::saveState in QSettings under
// "workspaces/<id>/…") and restores the other's, or builds its default.
// *Reset layout* forgets the current workspace's saved layout.
//
// Adding a pane: create its dock with an object name ("dock.<name>"), then
// give it a DockPlace in the workspaces that show it. A dock no workspace
// places is kept hidden at its home area until the user shows it; a dock
// that a saved layout does not know yet (added by a later version) gets its
// default place the next time that workspace is restored. Adding a
// workspace: one more WorkspaceSpec; its switch button and menu entry follow.
#pragma once

#include <QHash>
#include <QKeySequence>
#include <QObject>
#include <QSize>
#include <QString>
#include <QStringList>
#include <vector>

class QAction;
class QActionGroup;
class QDockWidget;
class QMainWindow;
class QMenu;
class QTabWidget;
class QWidget;

namespace k528::studio {

// Where a dock goes in a workspace's default layout.
struct DockPlace {
    QString dock;                            // object name, e.g. "dock.k923"
    Qt::DockWidgetArea area = Qt::RightDockWidgetArea;
    QString beside;                          // split from this dock (placed before) …
    Qt::Orientation split = Qt::Horizontal;  // … side by side, or one above the other
    QString tabWith;                         // or a tab beside this dock (placed before)
    // Its share of the window: of the width for a dock in the left or right
    // area or split side by side, of the height for one in the top or bottom
    // area or split one above the other; 0 = what Qt gives it.
    double share = 0;
    bool shown = true;   // false: placed, hidden until the View menu shows it
    bool raised = false; // the tab on top of its tabbed group
};

struct WorkspaceSpec {
    QString id;              // "operator": its settings' key, object names
    const char* title;       // untranslated (QT_TRANSLATE_NOOP("k528::studio::Workspaces", …))
    const char* toolTip;     // the same
    QString page;            // object name of the work area's page in the centre; empty = no centre
    std::vector<DockPlace> docks; // placed in this order
    QKeySequence shortcut;
    // Which area owns the bottom corners (the left and right areas run the
    // whole height when they own them).
    Qt::DockWidgetArea bottomLeft = Qt::LeftDockWidgetArea;
    Qt::DockWidgetArea bottomRight = Qt::RightDockWidgetArea;
};

class Workspaces : public QObject {
    Q_OBJECT
public:
    // Bump when a default layout changes so much that the saved ones should go.
    static constexpr int kLayoutVersion = 2;

    Workspaces(QMainWindow* window, QTabWidget* workArea);

    void add(WorkspaceSpec spec);
    const std::vector<WorkspaceSpec>& specs() const { return specs_; }
    const WorkspaceSpec* spec(const QString& id) const;
    QString current() const { return current_; }
    QString title(const QString& id) const;

    // The control that switches them, always visible (the menu bar's corner):
    // one button a workspace.
    QWidget* switcher() const { return switcher_; }
    // View > Workspace: the workspaces and *Reset layout*.
    QMenu* menu() const { return menu_; }
    QAction* action(const QString& id) const { return actions_.value(id); }
    QAction* resetAction() const { return resetAction_; }

    // The workspace a first start chooses for a screen whose available area
    // (logical pixels) is `available`.
    static QString firstChoice(QSize available);

public slots:
    // Keeps the current layout, then shows workspace `id` as it was left, or
    // in its default layout. False for an unknown id.
    bool activate(const QString& id);
    // The current workspace in its default layout (its saved one forgotten).
    void resetLayout();
    // The current workspace laid out again, as saved or by default (after
    // the window got its size: the shares are of the window).
    void reload();
    // Keeps the current workspace's layout in the settings (on switching and
    // when the window closes).
    void save();

signals:
    void activated(const QString& id);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QDockWidget* dock(const QString& name) const;
    QList<QDockWidget*> docks() const;
    void applyDefault(const WorkspaceSpec& s);
    bool restoreSaved(const WorkspaceSpec& s);
    void place(const WorkspaceSpec& s, const DockPlace& p);
    void showPage(const WorkspaceSpec& s, const QString& page);
    void applyShares();
    void retranslate();

    QMainWindow* window_;
    QTabWidget* workArea_;
    std::vector<WorkspaceSpec> specs_;
    QString current_;
    QWidget* switcher_ = nullptr;
    QMenu* menu_ = nullptr;
    QActionGroup* group_ = nullptr;
    QHash<QString, QAction*> actions_;
    QAction* resetAction_ = nullptr;
    QAction* separator_ = nullptr;
    QString pendingShares_; // the workspace whose shares wait for the window's size
};

} // namespace k528::studio
