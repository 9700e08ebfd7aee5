#include "workspace/standard_workspaces.h"

#include "k923/k923_layout.h"

#include <QCoreApplication>
#include <algorithm>

namespace k528::studio {

std::vector<WorkspaceSpec> standardWorkspaces(QSize available) {
    const double w = std::max(800, available.width());
    const double h = std::max(600, available.height());
    // The K923's share of the width when it has the window's height (less
    // the title bar, menu, status bar and its dock's title).
    const auto k923Share = [&](double most) {
        return std::min(most, (h - 130) * K923Layout::aspect() / w);
    };
    const auto place = [](const char* dock, Qt::DockWidgetArea area, double share = 0) {
        DockPlace p;
        p.dock = QString::fromLatin1(dock);
        p.area = area;
        p.share = share;
        return p;
    };
    const auto beside = [](const char* dock, const char* other, Qt::Orientation split, double share) {
        DockPlace p;
        p.dock = QString::fromLatin1(dock);
        p.beside = QString::fromLatin1(other);
        p.split = split;
        p.share = share;
        return p;
    };
    const auto tab = [](const char* dock, const char* with, bool shown = true) {
        DockPlace p;
        p.dock = QString::fromLatin1(dock);
        p.tabWith = QString::fromLatin1(with);
        p.shown = shown;
        return p;
    };
    const auto hidden = [](DockPlace p) {
        p.shown = false;
        return p;
    };
    const auto raised = [](DockPlace p) {
        p.raised = true;
        return p;
    };

    std::vector<WorkspaceSpec> out;

    WorkspaceSpec op;
    op.id = QStringLiteral("operator");
    op.title = QT_TRANSLATE_NOOP("k528::studio::Workspaces", "Operator");
    op.toolTip = QT_TRANSLATE_NOOP("k528::studio::Workspaces",
                                   "At the machine: the K923, the machine's panel, the program being run, "
                                   "the messages and the axes");
    op.page = QStringLiteral("programMonitor");
    op.shortcut = QKeySequence(Qt::CTRL | Qt::Key_F1);
    op.docks = {
        place("dock.k923", Qt::LeftDockWidgetArea, k923Share(0.30)),
        raised(place("dock.machine", Qt::RightDockWidgetArea, 0.36)),
        beside("dock.axes", "dock.machine", Qt::Vertical, 0.36), // split before any tab joins
        tab("dock.controller", "dock.machine", false),
        place("dock.messages", Qt::BottomDockWidgetArea, 0.25),
        tab("dock.history", "dock.messages", false),
        tab("dock.training", "dock.controller", false),
    };
    out.push_back(op);

    WorkspaceSpec tech;
    tech.id = QStringLiteral("technologist");
    tech.title = QT_TRANSLATE_NOOP("k528::studio::Workspaces", "Technologist");
    tech.toolTip = QT_TRANSLATE_NOOP("k528::studio::Workspaces",
                                     "Programs: the editor with its problems and outline, the backplot; the "
                                     "debugger and the controller from the View menu");
    tech.page = QStringLiteral("programEditorTab");
    tech.shortcut = QKeySequence(Qt::CTRL | Qt::Key_F2);
    tech.docks = {
        raised(place("dock.backplot", Qt::RightDockWidgetArea, 0.38)),
        hidden(beside("dock.debugger", "dock.backplot", Qt::Vertical, 0.5)),
        tab("dock.controller", "dock.debugger", false),
        tab("dock.proveout", "dock.backplot"), // behind the backplot; after the split (a tab takes no split)
        hidden(place("dock.messages", Qt::BottomDockWidgetArea, 0.22)),
        tab("dock.axes", "dock.messages", false),
        tab("dock.history", "dock.messages", false),
        tab("dock.scope", "dock.messages", false),
        hidden(place("dock.rparams", Qt::LeftDockWidgetArea, 0.3)),
        tab("dock.constants", "dock.rparams", false),
        tab("dock.training", "dock.proveout", false),
    };
    out.push_back(tech);

    WorkspaceSpec train;
    train.id = QStringLiteral("training");
    train.title = QT_TRANSLATE_NOOP("k528::studio::Workspaces", "Training");
    train.toolTip = QT_TRANSLATE_NOOP("k528::studio::Workspaces",
                                      "Learning the machine: the machine's panel, the K923, the backplot and "
                                      "the oscilloscope");
    train.page = QString(); // no centre: the panes share the window
    train.shortcut = QKeySequence(Qt::CTRL | Qt::Key_F3);
    const double k = k923Share(0.28);
    // The machine's panel keeps its shape (it is as tall as its width
    // allows): the messages take the rest of its column. On a shop PC's
    // screen the oscilloscope is a tab of the right column (split, its charts
    // had no room for their scales); on a desk's, a tab of the messages.
    const bool roomForBoth = h >= 900;
    train.docks = {
        place("dock.k923", Qt::LeftDockWidgetArea, k),
        beside("dock.machine", "dock.k923", Qt::Horizontal, 0.30),
        raised(beside("dock.messages", "dock.machine", Qt::Vertical, 0.45)),
        tab("dock.axes", "dock.messages", false),
        raised(place("dock.backplot", Qt::RightDockWidgetArea, std::max(0.3, 1.0 - k - 0.30))),
        // The backplot's column is the training course's too, whose task,
        // part and grade need its whole height (split, it had a strip of it).
        roomForBoth ? tab("dock.scope", "dock.messages") : tab("dock.scope", "dock.backplot"),
        // The course's exercise, its drawing and the grade beside the backplot.
        tab("dock.training", "dock.backplot"),
    };
    out.push_back(train);

    WorkspaceSpec shopSpec;
    shopSpec.id = QStringLiteral("shop");
    shopSpec.title = QT_TRANSLATE_NOOP("k528::studio::Workspaces", "Shop");
    shopSpec.toolTip = QT_TRANSLATE_NOOP("k528::studio::Workspaces",
                                         "The shop floor: a tile per machine of the database on its line, the "
                                         "alarms as they come, today's time in each state; the controller of the "
                                         "machine clicked beside it");
    shopSpec.page = QStringLiteral("shopView");
    shopSpec.shortcut = QKeySequence(Qt::CTRL | Qt::Key_F4);
    // The docks of the machine shown are tabs of the Controller dock (or
    // placed as the operator has them), so that showing them all at once
    // stacks none above another.
    shopSpec.docks = {
        raised(place("dock.controller", Qt::RightDockWidgetArea, w < 1600 ? 0.30 : 0.26)),
        tab("dock.machine", "dock.controller", false),
        tab("dock.axes", "dock.controller", false),
        tab("dock.training", "dock.controller", false),
        hidden(place("dock.messages", Qt::BottomDockWidgetArea, 0.25)),
        tab("dock.history", "dock.messages", false),
        hidden(place("dock.k923", Qt::LeftDockWidgetArea, k923Share(0.30))),
    };
    out.push_back(shopSpec);
    return out;
}

} // namespace k528::studio
