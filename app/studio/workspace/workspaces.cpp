#include "workspace/workspaces.h"

#include <QAction>
#include <QActionGroup>
#include <QCoreApplication>
#include <QDockWidget>
#include <QEvent>
#include <QHBoxLayout>
#include <QMainWindow>
#include <QMenu>
#include <QSettings>
#include <QTabWidget>
#include <QTimer>
#include <QToolButton>

namespace k528::studio {

namespace {

QString key(const QString& id, const char* what) {
    return QStringLiteral("workspaces/%1/%2").arg(id, QLatin1String(what));
}

bool horizontalShare(const DockPlace& p) {
    if (!p.beside.isEmpty())
        return p.split == Qt::Horizontal;
    return p.area == Qt::LeftDockWidgetArea || p.area == Qt::RightDockWidgetArea;
}

} // namespace

Workspaces::Workspaces(QMainWindow* window, QTabWidget* workArea)
    : QObject(window), window_(window), workArea_(workArea) {
    setObjectName("workspaces");
    switcher_ = new QWidget(window);
    switcher_->setObjectName("workspaces.switcher");
    auto* row = new QHBoxLayout(switcher_);
    row->setContentsMargins(4, 0, 4, 0);
    row->setSpacing(2);
    menu_ = new QMenu(window);
    menu_->setObjectName("menu.workspace");
    group_ = new QActionGroup(this);
    group_->setExclusive(true);
    separator_ = menu_->addSeparator();
    resetAction_ = menu_->addAction(QString(), this, &Workspaces::resetLayout);
    resetAction_->setObjectName("action.workspace.reset");
    window_->installEventFilter(this);
    retranslate();
}

void Workspaces::add(WorkspaceSpec spec) {
    auto* a = new QAction(window_);
    a->setObjectName("action.workspace." + spec.id);
    a->setCheckable(true);
    a->setShortcut(spec.shortcut);
    a->setShortcutContext(Qt::WindowShortcut);
    group_->addAction(a);
    const QString id = spec.id;
    connect(a, &QAction::triggered, this, [this, id] { activate(id); });
    menu_->insertAction(separator_, a);
    window_->addAction(a); // its shortcut works wherever the window has the focus
    auto* b = new QToolButton(switcher_);
    b->setObjectName("workspaces.button." + id);
    b->setDefaultAction(a);
    b->setToolButtonStyle(Qt::ToolButtonTextOnly);
    b->setAutoRaise(true);
    b->setFocusPolicy(Qt::NoFocus);
    static_cast<QHBoxLayout*>(switcher_->layout())->addWidget(b);
    actions_.insert(id, a);
    specs_.push_back(std::move(spec));
    retranslate();
}

const WorkspaceSpec* Workspaces::spec(const QString& id) const {
    for (const WorkspaceSpec& s : specs_)
        if (s.id == id)
            return &s;
    return nullptr;
}

QString Workspaces::title(const QString& id) const {
    const WorkspaceSpec* s = spec(id);
    return s ? QCoreApplication::translate("k528::studio::Workspaces", s->title) : QString();
}

QString Workspaces::firstChoice(QSize available) {
    // A shop PC (1366×768, 1280×1024…) stands at the machine: the operator's
    // panel. A larger screen is an office desk: the technologist's editor.
    return available.width() < 1600 || available.height() < 900 ? QStringLiteral("operator")
                                                                 : QStringLiteral("technologist");
}

QDockWidget* Workspaces::dock(const QString& name) const {
    return name.isEmpty() ? nullptr : window_->findChild<QDockWidget*>(name, Qt::FindDirectChildrenOnly);
}

QList<QDockWidget*> Workspaces::docks() const {
    return window_->findChildren<QDockWidget*>(QString(), Qt::FindDirectChildrenOnly);
}

bool Workspaces::activate(const QString& id) {
    const WorkspaceSpec* s = spec(id);
    if (!s)
        return false;
    if (id == current_) {
        actions_.value(id)->setChecked(true);
        return true;
    }
    save();
    current_ = id;
    QSettings().setValue("workspaces/current", id);
    window_->setUpdatesEnabled(false);
    if (!restoreSaved(*s))
        applyDefault(*s);
    window_->setUpdatesEnabled(true);
    actions_.value(id)->setChecked(true);
    emit activated(id);
    return true;
}

void Workspaces::resetLayout() {
    const WorkspaceSpec* s = spec(current_);
    if (!s)
        return;
    QSettings settings;
    for (const char* what : {"state", "docks", "page"})
        settings.remove(key(s->id, what));
    window_->setUpdatesEnabled(false);
    applyDefault(*s);
    window_->setUpdatesEnabled(true);
}

void Workspaces::reload() {
    const WorkspaceSpec* s = spec(current_);
    if (!s)
        return;
    window_->setUpdatesEnabled(false);
    if (!restoreSaved(*s))
        applyDefault(*s);
    window_->setUpdatesEnabled(true);
}

void Workspaces::save() {
    // A layout the user has not seen (the window not shown yet, at its first
    // size) is not theirs to keep.
    if (current_.isEmpty() || !window_->isVisible())
        return;
    QSettings s;
    s.setValue(key(current_, "state"), window_->saveState(kLayoutVersion));
    QStringList names;
    for (QDockWidget* d : docks())
        names << d->objectName();
    s.setValue(key(current_, "docks"), names);
    s.setValue(key(current_, "page"), workArea_->isHidden() || !workArea_->currentWidget()
                                          ? QString()
                                          : workArea_->currentWidget()->objectName());
}

void Workspaces::showPage(const WorkspaceSpec& s, const QString& page) {
    (void)s;
    QWidget* w = page.isEmpty() ? nullptr : workArea_->findChild<QWidget*>(page);
    if (w && workArea_->indexOf(w) >= 0) {
        workArea_->setCurrentWidget(w);
        workArea_->show();
    } else {
        // No centre: the docks share the whole window.
        workArea_->hide();
    }
}

void Workspaces::place(const WorkspaceSpec& s, const DockPlace& p) {
    (void)s;
    QDockWidget* d = dock(p.dock);
    if (!d)
        return;
    if (QDockWidget* t = dock(p.tabWith); t && window_->dockWidgetArea(t) != Qt::NoDockWidgetArea)
        window_->tabifyDockWidget(t, d);
    else if (QDockWidget* b = dock(p.beside); b && window_->dockWidgetArea(b) != Qt::NoDockWidgetArea)
        window_->splitDockWidget(b, d, p.split);
    else
        window_->addDockWidget(p.area, d,
                               p.area == Qt::TopDockWidgetArea || p.area == Qt::BottomDockWidgetArea
                                   ? Qt::Horizontal
                                   : Qt::Vertical);
    d->setVisible(p.shown);
}

void Workspaces::applyDefault(const WorkspaceSpec& s) {
    window_->setCorner(Qt::BottomLeftCorner, s.bottomLeft);
    window_->setCorner(Qt::BottomRightCorner, s.bottomRight);
    const QList<QDockWidget*> all = docks();
    for (QDockWidget* d : all) {
        if (d->isFloating())
            d->setFloating(false);
        window_->removeDockWidget(d);
    }
    QStringList placed;
    for (const DockPlace& p : s.docks) {
        place(s, p);
        placed << p.dock;
    }
    // The docks this workspace does not use: hidden at their home.
    for (QDockWidget* d : all)
        if (!placed.contains(d->objectName())) {
            const QVariant home = d->property("k528.homeArea");
            window_->addDockWidget(home.isValid() ? static_cast<Qt::DockWidgetArea>(home.toInt())
                                                  : Qt::RightDockWidgetArea,
                                   d);
            d->hide();
        }
    for (const DockPlace& p : s.docks)
        if (QDockWidget* d = dock(p.dock); d && p.raised && p.shown)
            d->raise();
    showPage(s, s.page);
    pendingShares_ = s.id;
    if (window_->isVisible()) {
        applyShares();
        // Once more when the layout has settled (the centre shown or hidden).
        QTimer::singleShot(0, this, [this, id = s.id] {
            if (current_ == id) {
                pendingShares_ = id;
                applyShares();
            }
        });
    }
}

void Workspaces::applyShares() {
    const WorkspaceSpec* s = spec(pendingShares_);
    pendingShares_.clear();
    if (!s)
        return;
    QList<QDockWidget*> hDocks, vDocks;
    QList<int> hSizes, vSizes;
    const QSize size = window_->size();
    for (const DockPlace& p : s->docks) {
        QDockWidget* d = dock(p.dock);
        if (!d || p.share <= 0 || !p.shown || !p.tabWith.isEmpty() || d->isHidden())
            continue;
        if (horizontalShare(p)) {
            hDocks << d;
            hSizes << static_cast<int>(p.share * size.width());
        } else {
            vDocks << d;
            vSizes << static_cast<int>(p.share * size.height());
        }
    }
    if (!hDocks.isEmpty())
        window_->resizeDocks(hDocks, hSizes, Qt::Horizontal);
    if (!vDocks.isEmpty())
        window_->resizeDocks(vDocks, vSizes, Qt::Vertical);
}

bool Workspaces::restoreSaved(const WorkspaceSpec& s) {
    QSettings settings;
    const QByteArray state = settings.value(key(s.id, "state")).toByteArray();
    if (state.isEmpty())
        return false;
    const QStringList known = settings.value(key(s.id, "docks")).toStringList();
    window_->setCorner(Qt::BottomLeftCorner, s.bottomLeft);
    window_->setCorner(Qt::BottomRightCorner, s.bottomRight);
    // What the state does not mention stays hidden.
    for (QDockWidget* d : docks())
        d->hide();
    if (!window_->restoreState(state, kLayoutVersion))
        return false;
    // Docks added since the layout was kept: their default place.
    for (const DockPlace& p : s.docks)
        if (!known.contains(p.dock))
            place(s, p);
    showPage(s, settings.value(key(s.id, "page"), s.page).toString());
    return true;
}

bool Workspaces::eventFilter(QObject* watched, QEvent* e) {
    if (watched == window_) {
        if (e->type() == QEvent::LanguageChange)
            retranslate();
        else if (e->type() == QEvent::Show && !pendingShares_.isEmpty())
            QTimer::singleShot(0, this, [this] { applyShares(); });
    }
    return QObject::eventFilter(watched, e);
}

void Workspaces::retranslate() {
    menu_->setTitle(tr("&Workspace"));
    resetAction_->setText(tr("&Reset layout"));
    resetAction_->setToolTip(tr("The current workspace's docks where they were at first"));
    switcher_->setToolTip(tr("Workspace: the window arranged for its user"));
    for (const WorkspaceSpec& s : specs_)
        if (QAction* a = actions_.value(s.id)) {
            a->setText(QCoreApplication::translate("k528::studio::Workspaces", s.title));
            a->setToolTip(QCoreApplication::translate("k528::studio::Workspaces", s.toolTip));
        }
}

} // namespace k528::studio
