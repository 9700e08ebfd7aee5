// The main window's workspaces on a given screen (run at 1366×768, 1920×1080
// and 2× HiDPI: the offscreen platform's screen comes from a config file,
// tests/studio/screens/): every workspace fits the screen with every control
// inside it, long texts and more docks do not widen the window, the machine's
// panel scales with the room, each workspace keeps its own layout, the first
// start chooses by the screen, and no shortcut means two actions at once.
#include "editor/debug_panel.h"
#include "editor/editor_tab.h"
#include "k923/k923_widget.h"
#include "editor/program_editor.h"
#include "language.h"
#include "machine/machine_panel.h"
#include "machine/pendant_controls.h"
#include "main_window.h"
#include "monitor/program_monitor.h"
#include "test_util.h"
#include "workspace/elided_label.h"
#include "workspace/workspaces.h"

#include "rig/widgets.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QDockWidget>
#include <QLineEdit>
#include <QMenuBar>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QShortcut>
#include <QStatusBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QMenu>
#include <QLabel>
#include <QPushButton>
#include <QMessageBox>
#include <QApplication>
#include <QTimer>
#include <QSignalSpy>
#include <QtTest>

using namespace k528::studio;

namespace {

QRect available() { return QGuiApplication::primaryScreen()->availableGeometry(); }

QString screenName() {
    const QRect a = available();
    const qreal dpr = QGuiApplication::primaryScreen()->devicePixelRatio();
    return QStringLiteral("%1x%2%3").arg(a.width()).arg(a.height()).arg(dpr > 1 ? QStringLiteral("@%1x").arg(dpr) : QString());
}

using k528::testrig::shownRect;

bool isControl(const QWidget* w) {
    return qobject_cast<const QAbstractButton*>(w) || qobject_cast<const QComboBox*>(w) ||
           qobject_cast<const QAbstractSpinBox*>(w) || qobject_cast<const QLineEdit*>(w) ||
           qobject_cast<const QAbstractSlider*>(w) || qobject_cast<const QAbstractItemView*>(w) ||
           qobject_cast<const SelectorSwitch*>(w) || qobject_cast<const HandwheelDial*>(w);
}

// Every control the user can see lies inside the screen's available area.
QStringList controlsOutside(const QMainWindow& w) {
    QStringList out;
    const QRect screen = available();
    int seen = 0;
    for (const QWidget* c : w.findChildren<QWidget*>()) {
        if (!c->isVisible() || !isControl(c) || c->window() != &w)
            continue;
        const QRect r = shownRect(c);
        if (r.isEmpty())
            continue;
        ++seen;
        if (!screen.contains(r))
            out << QStringLiteral("%1 (%2) at %3,%4 %5x%6")
                       .arg(c->objectName(), QString::fromLatin1(c->metaObject()->className()))
                       .arg(r.x())
                       .arg(r.y())
                       .arg(r.width())
                       .arg(r.height());
    }
    if (seen < 10)
        out << QStringLiteral("only %1 controls seen").arg(seen);
    return out;
}

QString sizeText(QSize s) { return QStringLiteral("%1x%2").arg(s.width()).arg(s.height()); }

void settle() {
    // Layout requests, the deferred shares and the panel's scaling.
    for (int i = 0; i < 5; ++i) {
        QCoreApplication::sendPostedEvents();
        QTest::qWait(20);
    }
}

// `w` placed on the screen and shown; true once it is exposed.
bool shown(MainWindow& w) {
    w.placeOnScreen();
    w.show();
    return QTest::qWaitForWindowExposed(&w);
}

// `w` shown in the workspace `id`, its layout settled.
bool shownIn(MainWindow& w, const QString& id) {
    if (!shown(w) || !w.workspaces()->activate(id))
        return false;
    settle();
    return true;
}


bool fits(const QMainWindow& w, QString* why) {
    const QRect a = available();
    if (!a.contains(w.frameGeometry())) {
        *why = QStringLiteral("window %1 at %2,%3 outside %4")
                   .arg(sizeText(w.frameGeometry().size()))
                   .arg(w.frameGeometry().x())
                   .arg(w.frameGeometry().y())
                   .arg(sizeText(a.size()));
        return false;
    }
    const QSize min = w.minimumSizeHint();
    if (min.width() > a.width() || min.height() > a.height()) {
        *why = QStringLiteral("minimum %1 larger than %2").arg(sizeText(min), sizeText(a.size()));
        return false;
    }
    return true;
}

// The widgets whose minimum is wider than the screen, outside any scroll
// area (what makes a window too wide).
QStringList tooWide(const QMainWindow& w) {
    QStringList out;
    for (const QWidget* c : w.findChildren<QWidget*>()) {
        if (c->isHidden() || c->minimumSizeHint().width() <= available().width())
            continue;
        bool scrolled = false;
        for (const QWidget* p = c->parentWidget(); p && p != &w; p = p->parentWidget())
            scrolled = scrolled || qobject_cast<const QAbstractScrollArea*>(p);
        if (!scrolled)
            out << QStringLiteral("%1 (%2) %3").arg(c->objectName(), QString::fromLatin1(c->metaObject()->className()),
                                                    sizeText(c->minimumSizeHint()));
    }
    return out;
}

// Why the text of `c` (a button's, a label's) is not read whole where it is
// shown, "" when it is: narrower than its text (a label that does not wrap,
// a button), shorter than its wrapped text, or cut by a widget it lies in —
// a scroll area only when it can scroll there (a dock without a horizontal
// scroll bar cuts what lies beyond its right edge for good).
QString cutText(const QWidget* c) {
    QString text;
    int need = 0;
    if (const auto* b = qobject_cast<const QAbstractButton*>(c)) {
        text = b->text();
        if (text.isEmpty()) // an icon, a key drawn by its widget
            return {};
        need = c->sizeHint().width();
        if (c->width() < need)
            return QStringLiteral("%1 px wide, needs %2").arg(c->width()).arg(need);
    } else if (const auto* l = qobject_cast<const QLabel*>(c)) {
        if (qobject_cast<const ElidedLabel*>(c)) // cut on purpose, whole in its tooltip
            return {};
        text = l->text();
        if (text.isEmpty() || l->textFormat() == Qt::RichText ||
            (l->textFormat() != Qt::PlainText && Qt::mightBeRichText(text)))
            return {}; // a picture, a rich text laid out as a document
        if (l->wordWrap()) {
            need = l->heightForWidth(l->width());
            if (c->height() < need)
                return QStringLiteral("%1 px tall, its wrapped text needs %2").arg(c->height()).arg(need);
        } else if (c->width() < (need = c->sizeHint().width())) {
            return QStringLiteral("%1 px wide, needs %2").arg(c->width()).arg(need);
        }
    }
    if (text.isEmpty())
        return {};
    const QRect full(c->mapToGlobal(QPoint(0, 0)), c->size());
    for (const QWidget* p = c->parentWidget(); p; p = p->parentWidget()) {
        const QRect in(p->mapToGlobal(QPoint(0, 0)), p->size());
        const QRect kept = full & in;
        if (kept != full) {
            const auto* area = qobject_cast<const QAbstractScrollArea*>(p->parentWidget());
            const bool viewport = area && area->viewport() == p;
            const bool acrossCut = kept.width() < full.width();
            const bool downCut = kept.height() < full.height();
            if (!viewport || (acrossCut && !area->horizontalScrollBar()->isVisible()) ||
                (downCut && !area->verticalScrollBar()->isVisible()))
                return QStringLiteral("cut by %1 (%2) to %3 of %4")
                    .arg(p->objectName(), QString::fromLatin1(p->metaObject()->className()),
                         sizeText(kept.size()), sizeText(full.size()));
            break; // it scrolls into view
        }
        if (p->isWindow())
            break;
    }
    return {};
}

// Every button's and label's text the user sees in the window, whole.
QStringList cutTexts(const QMainWindow& w, const QString& where) {
    QStringList out;
    for (const QWidget* c : w.findChildren<QWidget*>()) {
        if (!c->isVisible() || c->window() != &w || shownRect(c).isEmpty())
            continue;
        const QString why = cutText(c);
        if (!why.isEmpty()) {
            QString text;
            if (const auto* b = qobject_cast<const QAbstractButton*>(c))
                text = b->text();
            else if (const auto* l = qobject_cast<const QLabel*>(c))
                text = l->text();
            out << QStringLiteral("%1: %2 (%3) «%4»: %5")
                       .arg(where, c->objectName(), QString::fromLatin1(c->metaObject()->className()),
                            text.left(60), why);
        }
    }
    return out;
}

// A shortcut as Qt's shortcut map holds it: its keys, where it acts and
// what it is (for the message).
struct Bound {
    QKeySequence keys;
    const QWidget* scope; // nullptr: the whole window
    bool withChildren;    // the scope's children too (WidgetWithChildrenShortcut)
    QString what;
};

// Whether `w` puts an action on screen now: a visible widget of the window,
// the visible menu bar, or a menu opened from one that is.
bool liveIn(const QObject* o, const QMainWindow& win, int depth = 0) {
    if (depth > 8)
        return false;
    if (const auto* menu = qobject_cast<const QMenu*>(o)) {
        for (const QObject* a : menu->menuAction()->associatedObjects())
            if (liveIn(a, win, depth + 1))
                return true;
        return false;
    }
    const auto* w = qobject_cast<const QWidget*>(o);
    return w && w->window() == &win && w->isVisible();
}

QList<Bound> liveShortcuts(const QMainWindow& win) {
    QList<Bound> out;
    for (const QAction* a : win.findChildren<QAction*>()) {
        const QList<QKeySequence> keys = a->shortcuts();
        if (keys.isEmpty())
            continue;
        const QList<QObject*> where = a->associatedObjects();
        for (const QObject* o : where) {
            if (!liveIn(o, win))
                continue;
            const auto* w = qobject_cast<const QWidget*>(o);
            const bool windowWide = a->shortcutContext() == Qt::WindowShortcut ||
                                    a->shortcutContext() == Qt::ApplicationShortcut || qobject_cast<const QMenu*>(w) ||
                                    qobject_cast<const QMenuBar*>(w);
            for (const QKeySequence& k : keys)
                out.append({k, windowWide ? nullptr : w, a->shortcutContext() == Qt::WidgetWithChildrenShortcut,
                            QStringLiteral("%1 «%2»").arg(a->objectName(), a->text())});
            break; // one place is enough: an action is one shortcut
        }
    }
    for (const QShortcut* s : win.findChildren<QShortcut*>()) {
        const auto* w = qobject_cast<const QWidget*>(s->parent());
        if (!w || !s->isEnabled() || !liveIn(w, win))
            continue;
        const bool windowWide = s->context() == Qt::WindowShortcut || s->context() == Qt::ApplicationShortcut;
        for (const QKeySequence& k : s->keys())
            out.append({k, windowWide ? nullptr : w, s->context() == Qt::WidgetWithChildrenShortcut,
                        QStringLiteral("QShortcut %1 on %2").arg(s->objectName(), w->objectName())});
    }
    return out;
}

// Two shortcuts clash when some focus makes both of them apply.
bool overlap(const Bound& a, const Bound& b) {
    if (!a.scope || !b.scope)
        return true;
    const auto covers = [](const Bound& outer, const QWidget* w) {
        return outer.scope == w || (outer.withChildren && outer.scope->isAncestorOf(w));
    };
    return covers(a, b.scope) || covers(b, a.scope);
}

QStringList clashes(const QMainWindow& win) {
    const QList<Bound> all = liveShortcuts(win);
    QStringList out;
    for (int i = 0; i < all.size(); ++i)
        for (int j = i + 1; j < all.size(); ++j)
            if (all[i].keys == all[j].keys && overlap(all[i], all[j]))
                out << QStringLiteral("%1: %2 and %3")
                           .arg(all[i].keys.toString(), all[i].what, all[j].what);
    return out;
}

QString shotName(const QString& what) { return QStringLiteral("workspaces-%1-%2.png").arg(screenName(), what); }

} // namespace

class TestWorkspaces : public QObject {
    Q_OBJECT
    QTemporaryDir home_;
private slots:
    void initTestCase() {
        // This run's own settings: the same test runs at each screen size,
        // two at a time under ctest; sharing one file, one run's clear()
        // between another's quit and restart lost that one's layout.
        QVERIFY(home_.isValid());
        QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, home_.path());
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, home_.path());
        QCoreApplication::setOrganizationName("K528StudioTestWorkspaces");
        QSettings().clear();
        QVERIFY(setLanguage("ru"));
        qInfo("screen %s, available %s", qPrintable(screenName()), qPrintable(sizeText(available().size())));
    }
    void init() { QSettings().clear(); }

    void firstStartChoosesByTheScreen() {
        QCOMPARE(Workspaces::firstChoice(QSize(1366, 768)), QString("operator"));
        QCOMPARE(Workspaces::firstChoice(QSize(1280, 1024)), QString("operator"));
        QCOMPARE(Workspaces::firstChoice(QSize(1920, 1080)), QString("technologist"));
        MainWindow w;
        QCOMPARE(w.workspaces()->current(), Workspaces::firstChoice(available().size()));
        QCOMPARE(QSettings().value("workspaces/current").toString(), w.workspaces()->current());
        // The switch is in the menu bar's corner, one button a workspace.
        QCOMPARE(w.menuBar()->cornerWidget(Qt::TopRightCorner), w.workspaces()->switcher());
        QCOMPARE(w.workspaces()->switcher()->findChildren<QAbstractButton*>().size(), 4);
    }

    void everyWorkspaceFitsTheScreen() {
        MainWindow w;
        QVERIFY(shown(w));
        for (const WorkspaceSpec& s : w.workspaces()->specs()) {
            // Switched as a user does: the button in the menu bar's corner.
            auto* button = w.workspaces()->switcher()->findChild<QAbstractButton*>("workspaces.button." + s.id);
            QVERIFY(button);
            QVERIFY2(shownRect(button).isValid() && available().contains(shownRect(button)), qPrintable(s.id));
            QTest::mouseClick(button, Qt::LeftButton);
            QCOMPARE(w.workspaces()->current(), s.id);
            settle();
            QString why;
            QVERIFY2(fits(w, &why), qPrintable(s.id + ": " + why));
            const QStringList outside = controlsOutside(w);
            QVERIFY2(outside.isEmpty(), qPrintable(s.id + ": " + outside.join("; ")));
            // The centre: the page of the workspace, or none.
            if (s.page.isEmpty())
                QVERIFY(w.workArea()->isHidden());
            else
                QCOMPARE(w.workArea()->currentWidget()->objectName(), s.page);
            for (const DockPlace& p : s.docks) {
                auto* d = w.findChild<QDockWidget*>(p.dock);
                QVERIFY2(d, qPrintable(p.dock));
                QCOMPARE(d->isVisible(), p.shown);
            }
            K528_VERIFY_SHOT(w.grab(), shotName(s.id));
        }
    }

    // No control is squeezed below the height it needs to be read and used
    // (a pane too small scrolls instead), in each workspace and in each pane
    // it shows on demand — raised in its place, as the View menu shows it.
    void noControlIsCrushed() {
        MainWindow w;
        QVERIFY(shown(w));
        const auto crushed = [&](const QString& where) {
            QStringList out;
            for (const QWidget* c : w.findChildren<QWidget*>()) {
                if (!c->isVisible() || c->window() != &w || shownRect(c).isEmpty())
                    continue;
                if (!qobject_cast<const QComboBox*>(c) && !qobject_cast<const QAbstractSpinBox*>(c) &&
                    !qobject_cast<const QLineEdit*>(c) && !qobject_cast<const QPushButton*>(c))
                    continue;
                if (qobject_cast<const QAbstractSpinBox*>(c->parentWidget()) ||
                    qobject_cast<const QComboBox*>(c->parentWidget()))
                    continue; // a part of a control, sized by it
                const int need = c->minimumSizeHint().height();
                if (c->height() < need)
                    out << QStringLiteral("%1: %2 (%3) %4 px tall, needs %5")
                               .arg(where, c->objectName(), QString::fromLatin1(c->metaObject()->className()))
                               .arg(c->height())
                               .arg(need);
            }
            return out;
        };
        QStringList all;
        for (const WorkspaceSpec& s : w.workspaces()->specs()) {
            QVERIFY(w.workspaces()->activate(s.id));
            settle();
            all << crushed(s.id);
            for (const DockPlace& p : s.docks) {
                if (p.shown)
                    continue;
                auto* d = w.findChild<QDockWidget*>(p.dock);
                d->show();
                d->raise();
                settle();
                all << crushed(s.id + " + " + p.dock);
                // Its texts that wrap grown long (a line's state, a monitor
                // of the controller on the line): they take more lines, the
                // controls keep their height.
                const QString longText = QStringLiteral("/tmp/test_studio_scenarios-PCaiDN/opb17290, адрес 1, "
                                                        "115200 бит/с: ответов 10, без ответа 0 ")
                                             .repeated(4);
                QString table; // a rich text monitor: a table of rows that wrap
                for (int row = 0; row < 12; ++row)
                    table += QStringLiteral("<tr><td><b>Z%1</b></td><td>%2</td></tr>").arg(1000 + row).arg(longText);
                for (QLabel* l : d->findChildren<QLabel*>())
                    if (l->wordWrap() && l->isVisible())
                        l->setText(l->textFormat() == Qt::RichText ? "<table>" + table + "</table>" : longText);
                settle();
                all << crushed(s.id + " + " + p.dock + ", long texts");
            }
            w.workspaces()->resetLayout();
        }
        QVERIFY2(all.isEmpty(), qPrintable(all.join("\n")));
    }

    // The constants' and R-parameters' status line (a refusal, a revision
    // notice) stays whole in view at the bottom of its dock however short
    // the dock is: the table above it scrolls or shrinks, the line does not.
    void theStatusLineOfShortDocksStaysInView() {
        MainWindow w;
        QVERIFY(shownIn(w, QStringLiteral("operator")));
        const QString refusal = QStringLiteral(
            "база данных postgresql:///shop отказала пользователю view1: для действия «изменение станка» "
            "требуется роль k528_technologist; у пользователя: k528_viewer; ничего не записано");
        for (const char* name : {"dock.constants", "dock.rparams"}) {
            auto* d = w.findChild<QDockWidget*>(name);
            QVERIFY2(d, name);
            d->show(); // as the View menu shows it
            d->raise();
            settle();
            const QString statusName = QString::fromLatin1(name).mid(5) + QStringLiteral(".status");
            auto* status = d->findChild<QLabel*>(statusName);
            QVERIFY2(status, qPrintable(statusName));
            status->setText(refusal);
            settle();
            QVERIFY2(status->isVisible(), name);
            // Inside the dock, not clipped by a scroll area: the label's
            // rectangle is all visible, and tall enough for its wrapped text.
            const QRect inDock(status->mapTo(d, QPoint(0, 0)), status->size());
            QVERIFY2(d->rect().contains(inDock),
                     qPrintable(QStringLiteral("%1: status %2,%3 %4 outside the dock %5")
                                    .arg(name)
                                    .arg(inDock.x())
                                    .arg(inDock.y())
                                    .arg(sizeText(inDock.size()), sizeText(d->size()))));
            for (QWidget* p = status->parentWidget(); p && p != d; p = p->parentWidget()) {
                const QRect inP(status->mapTo(p, QPoint(0, 0)), status->size());
                QVERIFY2(p->rect().contains(inP), qPrintable(QStringLiteral("%1: status clipped by %2 (%3)")
                                                                 .arg(name, p->objectName(),
                                                                      QString::fromLatin1(p->metaObject()->className()))));
            }
            QVERIFY2(status->height() >= status->heightForWidth(status->width()),
                     qPrintable(QStringLiteral("%1: status %2 px tall, its text needs %3")
                                    .arg(name)
                                    .arg(status->height())
                                    .arg(status->heightForWidth(status->width()))));
            K528_VERIFY_SHOT(w.grab(), shotName(QStringLiteral("operator-%1-status").arg(QString::fromLatin1(name).mid(5))));
            d->hide();
        }
    }

    // The constants and R-parameter docks' buttons (Calculator…, Cutting
    // data…, Trial part…) in the Operator workspace, the narrowest: each is
    // shown whole inside the dock (the row wraps), none beyond its edge
    // where no one reaches it.
    void theButtonsOfShortDocksAreReachable() {
        MainWindow w;
        QVERIFY(shownIn(w, QStringLiteral("operator")));
        const auto wholeInDock = [](QWidget* x, QDockWidget* d) {
            for (QWidget* p = x->parentWidget(); p; p = p->parentWidget()) {
                const QRect inP(x->mapTo(p, QPoint(0, 0)), x->size());
                if (!p->rect().contains(inP))
                    return false;
                if (p == d)
                    return true;
            }
            return false;
        };
        const std::pair<const char*, std::vector<const char*>> docks[] = {
            {"dock.constants",
             {"constants.undo", "constants.redo", "constants.history", "constants.diff", "constants.import",
              "constants.export", "constants.calculator", "constants.cuttingData", "constants.note"}},
            {"dock.rparams",
             {"rparams.keepPreset", "rparams.removePreset", "rparams.keepAll", "rparams.applyPresets",
              "rparams.trialPart", "rparams.note"}}};
        for (const auto& [name, controls] : docks) {
            auto* d = w.findChild<QDockWidget*>(name);
            QVERIFY2(d, name);
            d->show();
            d->raise();
            settle();
            for (const char* c : controls) {
                auto* x = d->findChild<QWidget*>(QString::fromLatin1(c));
                QVERIFY2(x, c);
                QVERIFY2(x->isVisible(), c);
                QVERIFY2(wholeInDock(x, d), qPrintable(QStringLiteral("%1: %2 at %3 (%4) is cut by the dock (%5)")
                                                           .arg(QString::fromLatin1(name), QString::fromLatin1(c))
                                                           .arg(x->mapTo(d, QPoint(0, 0)).x())
                                                           .arg(sizeText(x->size()), sizeText(d->size()))));
            }
            K528_VERIFY_SHOT(w.grab(), shotName(QStringLiteral("operator-%1-buttons").arg(QString::fromLatin1(name).mid(5))));
            d->hide();
        }
    }

    // On this screen, in Russian and in English, every workspace shows each
    // button's and label's text whole: a narrow dock wraps its row of
    // buttons (the Controller's «Журнал кадров…» was cut at its right edge
    // on a shop PC's 1366 px), and the shop's sentence when no machine has a
    // line wraps rather than losing its middle.
    void everyTextIsWholeInEachLanguage() {
        QStringList all;
        for (const char* lang : {"ru", "en"}) {
            QVERIFY(setLanguage(lang));
            QSettings().remove("workspaces");
            MainWindow w;
            QVERIFY(shown(w));
            for (const WorkspaceSpec& s : w.workspaces()->specs()) {
                QVERIFY(w.workspaces()->activate(s.id));
                settle();
                const QString where = QStringLiteral("%1 %2").arg(QString::fromLatin1(lang), s.id);
                all << cutTexts(w, where);
                K528_VERIFY_SHOT(w.grab(), shotName(QStringLiteral("%1-%2-texts").arg(s.id, QString::fromLatin1(lang))));
            }
            // The Controller dock's buttons: each whole inside the dock.
            QVERIFY(w.workspaces()->activate("shop"));
            settle();
            auto* dock = w.findChild<QDockWidget*>("dock.controller");
            QVERIFY(dock && dock->isVisible());
            for (const char* name : {"controller.pull", "controller.push", "controller.saveFrames",
                                     "controller.cancel", "controller.connect"}) {
                auto* b = dock->findChild<QPushButton*>(QString::fromLatin1(name));
                QVERIFY2(b && b->isVisible(), name);
                const QRect inDock(b->mapTo(dock, QPoint(0, 0)), b->size());
                QVERIFY2(dock->rect().contains(inDock) && b->width() >= b->sizeHint().width(),
                         qPrintable(QStringLiteral("%1 %2 «%3» at %4,%5 %6 (needs %7), the dock %8")
                                        .arg(QString::fromLatin1(lang), QString::fromLatin1(name), b->text())
                                        .arg(inDock.x())
                                        .arg(inDock.y())
                                        .arg(sizeText(inDock.size()), sizeText(b->sizeHint()), sizeText(dock->size()))));
            }
            // The shop's header wraps: a sentence of several lines is shown
            // whole (as when no machine of the database has a line).
            auto* header = w.findChild<QLabel*>("shop.header");
            QVERIFY(header && header->isVisible());
            QVERIFY(header->wordWrap());
            header->setText(QStringLiteral("Ни один станок базы данных /var/lib/k528/цех-1/k528.db не хранит линию "
                                           "связи с контроллером: задайте линию станка в базе данных. ")
                                .repeated(3));
            settle();
            all << cutTexts(w, QString::fromLatin1(lang) + " shop, a long header");
            QVERIFY(header->height() >= header->heightForWidth(header->width()));
            QVERIFY(w.close());
            qInfo("%s: %lld texts cut", lang, static_cast<long long>(all.size()));
        }
        QVERIFY(setLanguage("ru"));
        for (const QString& cut : all) // each in full (a failure's message is cut short)
            qWarning("%s", qPrintable(cut));
        QVERIFY2(all.isEmpty(), qPrintable(all.join("\n")));
    }

    void longTextsAndMoreDocksDoNotWidenTheWindow() {
        MainWindow w;
        QVERIFY(shown(w));
        const QString longText =
            QStringLiteral("L1: выполняется, кадр N15 — «ЧИСТОВАЯ ОБТОЧКА ПОВЕРХНОСТИ ПОД ПОДШИПНИК» ").repeated(8);
        for (const WorkspaceSpec& s : w.workspaces()->specs()) {
            QVERIFY(w.workspaces()->activate(s.id));
            settle();
            // Whatever a label says: every label of the window, at once.
            for (QLabel* l : w.findChildren<QLabel*>())
                if (l->window() == &w)
                    l->setText(longText);
            w.statusBar()->showMessage(longText);
            settle();
            QString why;
            QVERIFY2(fits(w, &why), qPrintable(s.id + ", long labels: " + why + " " + tooWide(w).join("; ")));
            // The oscilloscope opened (it once grew the window to 3005 px),
            // then every dock at once.
            w.findChild<QDockWidget*>("dock.scope")->show();
            settle();
            QVERIFY2(fits(w, &why), qPrintable(s.id + ", oscilloscope: " + why));
            for (QDockWidget* d : w.findChildren<QDockWidget*>())
                d->show();
            settle();
            QVERIFY2(fits(w, &why), qPrintable(s.id + ", every dock: " + why));
            w.workspaces()->resetLayout();
        }
        // The elided status says the whole text in its tooltip.
        auto* status = w.programMonitor()->findChild<ElidedLabel*>("programMonitor.status");
        QVERIFY(status);
        QVERIFY(w.workspaces()->activate("operator"));
        settle();
        status->setText(longText);
        QVERIFY(status->isElided());
        QVERIFY(status->shownText().endsWith(QChar(0x2026)));
    }

    void theMachinePanelScalesWithItsRoom() {
        MainWindow w;
        QVERIFY(shownIn(w, "operator"));
        MachinePanelWidget* panel = w.machinePanel();
        const double large = panel->scale();
        QVERIFY2(large >= 0.6, qPrintable(QString::number(large)));
        // The controls follow the scale.
        auto* jog = panel->findChild<PendantButton*>("machine.jog.x+");
        QCOMPARE(jog->width(), static_cast<int>(std::lround(54 * large)));
        // A narrower dock: a smaller panel, still whole (no scroll bar).
        w.resizeDocks({w.machineDock()}, {w.machineDock()->width() * 2 / 3}, Qt::Horizontal);
        QTRY_VERIFY_WITH_TIMEOUT(panel->scale() < large, 5000);
        auto* scroll = w.machineDock()->findChild<QScrollArea*>("machinePanelScroll");
        QVERIFY(scroll);
        if (panel->scale() > 0.6) {
            settle();
            QVERIFY(!scroll->horizontalScrollBar()->isVisible());
            QVERIFY(!scroll->verticalScrollBar()->isVisible());
        }
        // The K923 scales with its dock too: its keys grow with its width.
        const int key = w.k923()->keyRect(k528::panel::Key::Enter).width();
        w.resizeDocks({w.k923Dock()}, {w.k923Dock()->width() * 2 / 3}, Qt::Horizontal);
        QTRY_VERIFY_WITH_TIMEOUT(w.k923()->keyRect(k528::panel::Key::Enter).width() < key, 5000);
    }

    // Every action of the window, in every workspace and with every page of
    // the work area: no shortcut means two actions at once (Qt says
    // «Ambiguous shortcut overload» and does neither).
    void oneActionPerShortcutInEachContext() {
        MainWindow w;
        QVERIFY(shown(w));
        int checked = 0;
        for (const WorkspaceSpec& s : w.workspaces()->specs()) {
            QVERIFY(w.workspaces()->activate(s.id));
            settle();
            for (int page = -1; page < w.workArea()->count(); ++page) {
                if (page >= 0) {
                    if (w.workArea()->isHidden())
                        break;
                    w.workArea()->setCurrentIndex(page);
                }
                // Every dock shown too: their actions join the window's.
                for (int all = 0; all < 2; ++all) {
                    if (all)
                        for (QDockWidget* d : w.findChildren<QDockWidget*>())
                            d->show();
                    settle();
                    const QStringList c = clashes(w);
                    QVERIFY2(c.isEmpty(), qPrintable(s.id + ": " + c.join("; ")));
                    checked += static_cast<int>(liveShortcuts(w).size());
                }
            }
            w.workspaces()->resetLayout();
        }
        qInfo("%d shortcuts checked", checked);
        QVERIFY(checked > 20);
        // The test sees a clash: two window-wide actions on one key.
        auto* twin = new QAction("twin", &w);
        twin->setShortcut(w.workspaces()->action("operator")->shortcut());
        w.addAction(twin);
        QVERIFY(!clashes(w).isEmpty());
        delete twin;
    }

    // Ctrl+S and Ctrl+O in the technologist's editor: the editor's Save and
    // Open, nothing else.
    void ctrlSAndCtrlOAreTheEditorsForTheTechnologist() {
        QTemporaryDir dir;
        const QString path = testutil::writeFile(dir, "part.k528", "%L1\nM30\n");
        QVERIFY(!path.isEmpty());
        MainWindow w;
        QVERIFY(shownIn(w, "technologist"));
        EditorTab* tab = w.programEditor();
        QVERIFY(tab->openFile(path));
        ProgramEditor* ed = tab->currentEditor();
        ed->setFocus();
        ed->setCursorPosition(1, 0);
        QTest::keyClicks(ed, "G1 X5 FX100");
        QTest::keyClick(ed, Qt::Key_Return);
        QVERIFY(ed->isModified());
        QTest::failOnWarning(QRegularExpression("Ambiguous shortcut"));
        QSignalSpy save(tab->saveAction(), &QAction::triggered);
        QSignalSpy keep(w.findChild<QAction*>("action.keepInDatabase"), &QAction::triggered);
        QTest::keyClick(ed, Qt::Key_S, Qt::ControlModifier);
        QCOMPARE(save.count(), 1);
        QCOMPARE(keep.count(), 0);
        QVERIFY(!ed->isModified());
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("%L1\nG1 X5 FX100\nM30\n"));
        // Ctrl+O: the editor's Open (its file dialog, closed here).
        QSignalSpy open(tab->openAction(), &QAction::triggered);
        QSignalSpy load(w.findChild<QAction*>("action.loadPrograms"), &QAction::triggered);
        QTimer::singleShot(300, &w, [] {
            if (QWidget* m = QApplication::activeModalWidget())
                m->close();
        });
        QTest::keyClick(ed, Qt::Key_O, Qt::ControlModifier);
        QCOMPARE(open.count(), 1);
        QCOMPARE(load.count(), 0);
        // F5 in the editor: the debugger's Run (its dock shown).
        w.debuggerDock()->show();
        settle();
        QAction* run = w.debuggerDock()->findChild<QAction*>("debug.run");
        QVERIFY(run);
        QSignalSpy ran(run, &QAction::triggered);
        w.activateWindow(); // after the file dialog
        QVERIFY(QTest::qWaitForWindowActive(&w));
        ed->setFocus();
        QTest::keyClick(ed, Qt::Key_F5);
        QCOMPARE(ran.count(), 1);
        tab->debugPanel()->reset();
        // In the operator's workspace they are File's again.
        QVERIFY(w.workspaces()->activate("operator"));
        settle();
        QCOMPARE(w.findChild<QAction*>("action.keepInDatabase")->shortcut(), QKeySequence(QKeySequence::Save));
        QVERIFY(tab->saveAction()->shortcut().isEmpty());
    }

    // The technologist's first start is not an empty pane: the machine's
    // sample program is open, named as a sample, its text large (most of the
    // window); the next start reopens the files open at the last close, and a
    // user who closed them all finds the editor as left.
    void theEditorStartsWithTheSampleThenTheLastFiles() {
        QTemporaryDir dir;
        const QString path = testutil::writeFile(dir, "part.k528", "%L3\nG1 X5 FX100\nM30\n");
        QVERIFY(!path.isEmpty());
        const QString sample = EditorTab::sampleFor("training-lathe");
        QVERIFY2(sample.startsWith("lathe-"), qPrintable(sample));
        QVERIFY(EditorTab::sampleFor("grinder-205").startsWith("grinder-"));
        QVERIFY(!EditorTab::sampleFor("no-such-machine").isEmpty()); // some sample all the same
        {
            MainWindow w; // the training lathe
            QVERIFY(shownIn(w, "technologist"));
            EditorTab* tab = w.programEditor();
            QCOMPARE(tab->documentCount(), 1);
            QVERIFY(tab->pathOf(0).isEmpty()); // not a file: saving asks where
            QFile shipped(QStringLiteral(K528_SOURCE_DIR "/resources/samples/") + sample);
            QVERIFY(shipped.open(QIODevice::ReadOnly));
            QCOMPARE(tab->currentEditor()->text(), QString::fromUtf8(shipped.readAll()));
            QVERIFY(!tab->currentEditor()->isModified());
            auto* tabs = tab->findChild<QTabWidget*>("editor.tabs");
            QCOMPARE(tabs->tabText(0), sample + " (пример)");
            QVERIFY(tab->outline()->topLevelItemCount() >= 1); // its programs listed
            // The text is most of the window, the outline and Problems beside it small.
            const QRect text = shownRect(tab->currentEditor()->viewport());
            QVERIFY2(text.width() >= 0.45 * available().width() && text.height() >= 0.5 * available().height(),
                     qPrintable(sizeText(text.size()) + " of " + sizeText(available().size())));
            QVERIFY2(tab->outline()->width() < text.width() / 3, qPrintable(QString::number(tab->outline()->width())));
            QVERIFY2(tab->problems()->height() < text.height() / 2,
                     qPrintable(QString::number(tab->problems()->height())));
            QVERIFY(tab->openFile(path));
            QVERIFY(w.close()); // the sample unchanged: nothing asked
        }
        {
            MainWindow w;
            EditorTab* tab = w.programEditor();
            QCOMPARE(tab->documentCount(), 1); // the file, not the sample again
            QCOMPARE(tab->pathOf(0), QFileInfo(path).absoluteFilePath());
            QVERIFY(tab->closeDocument(0));
            QVERIFY(w.close());
        }
        {
            MainWindow w;
            QCOMPARE(w.programEditor()->documentCount(), 0); // all closed: as left
            QVERIFY(w.close());
        }
        {
            QSettings().setValue("editor/open", QStringList{dir.filePath("gone.k528")});
            MainWindow w;
            QCOMPARE(w.programEditor()->documentCount(), 1); // the file is gone: the sample
            QVERIFY(w.programEditor()->pathOf(0).isEmpty());
        }
    }

    // File > Quit with a changed file asks about the file by its name — not
    // the tab's «name *» — and «Cancel» keeps the window and the edits.
    void theQuitQuestionNamesTheFileNotItsTab() {
        QTemporaryDir dir;
        const QString path = testutil::writeFile(dir, "part.k528", "%L1\nM30\n");
        QVERIFY(!path.isEmpty());
        MainWindow w;
        QVERIFY(shown(w));
        QVERIFY(w.workspaces()->activate("technologist"));
        EditorTab* tab = w.programEditor();
        QVERIFY(tab->openFile(path));
        tab->currentEditor()->insertAt("G1 X5 FX100\n", 1, 0);
        QVERIFY(tab->currentEditor()->isModified());
        auto* tabs = tab->findChild<QTabWidget*>("editor.tabs");
        QCOMPARE(tabs->tabText(tabs->currentIndex()), QString("part.k528 *"));
        // The real question, answered «Cancel»; then out of the event loop
        // File > Quit ran in (a quit that went through would end it too).
        QString asked;
        QTimer poll;
        poll.setInterval(50);
        connect(&poll, &QTimer::timeout, this, [&] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box)
                return;
            asked = box->text();
            box->button(QMessageBox::Cancel)->click();
            poll.stop();
            QTimer::singleShot(200, [] { QCoreApplication::exit(0); });
        });
        poll.start();
        QTimer::singleShot(0, &w, [&] { w.findChild<QAction*>("action.quit")->trigger(); });
        QTimer neverAsked; // stopped below: not left to end a later test's loop
        neverAsked.setSingleShot(true);
        connect(&neverAsked, &QTimer::timeout, this, [] { QCoreApplication::exit(1); });
        neverAsked.start(20000);
        QApplication::exec();
        neverAsked.stop();
        QVERIFY2(asked.contains("part.k528 ") && !asked.contains("*"), qPrintable(asked));
        QVERIFY(w.isVisible());
        QCOMPARE(tab->documentCount(), 2); // the sample and the file, its edits kept
        QVERIFY(tab->currentEditor()->isModified());
        tab->setCloseQuestion([](const QString&) { return EditorTab::CloseChoice::Discard; });
    }

    // A workspace chosen before the window is shown (--workspace) leaves no
    // layout of the first choice behind: that one is laid out anew at the
    // window's size when the user goes to it (the editor kept its room).
    void aLayoutNeverShownIsNotKept() {
        MainWindow w;
        const QString first = w.workspaces()->current();
        const QString other = first == "operator" ? "technologist" : "operator";
        QVERIFY(w.workspaces()->activate(other));
        QVERIFY(!QSettings().contains("workspaces/" + first + "/state"));
        QVERIFY(shownIn(w, "technologist"));
        auto* backplot = w.findChild<QDockWidget*>("dock.backplot");
        const double share = double(backplot->width()) / w.width();
        QVERIFY2(share > 0.3 && share < 0.46, qPrintable(QString::number(share)));
        QVERIFY(w.workArea()->width() > backplot->width());
    }

    void eachWorkspaceKeepsItsLayout() {
        {
            MainWindow w;
            QVERIFY(shownIn(w, "operator"));
            QVERIFY(w.messagesDock()->isVisible());
            w.messagesDock()->close(); // the operator closes the messages
            QVERIFY(w.workspaces()->activate("technologist"));
            settle();
            QVERIFY(w.findChild<QDockWidget*>("dock.backplot")->isVisible());
            QVERIFY(!w.k923Dock()->isVisible());
            QCOMPARE(w.workArea()->currentWidget(), static_cast<QWidget*>(w.programEditor()));
            w.debuggerDock()->show(); // the technologist opens the debugger
            QVERIFY(w.workspaces()->activate("operator"));
            settle();
            QVERIFY(!w.messagesDock()->isVisible());
            QVERIFY(!w.debuggerDock()->isVisible());
            QVERIFY(w.k923Dock()->isVisible());
            QCOMPARE(w.workArea()->currentWidget(), static_cast<QWidget*>(w.programMonitor()));
            QVERIFY(w.close());
        }
        {
            // Started again: the workspace left last, as it was left.
            MainWindow w;
            QVERIFY(shown(w));
            QCOMPARE(w.workspaces()->current(), QString("operator"));
            QVERIFY(!w.messagesDock()->isVisible());
            QVERIFY(w.workspaces()->activate("technologist"));
            settle();
            QVERIFY(w.debuggerDock()->isVisible());
            // Reset layout: the debugger back on demand.
            w.workspaces()->resetAction()->trigger();
            settle();
            QVERIFY(!w.debuggerDock()->isVisible());
            QVERIFY(w.workspaces()->activate("operator"));
            w.workspaces()->resetAction()->trigger();
            settle();
            QVERIFY(w.messagesDock()->isVisible());
            w.close();
        }
    }
};

QTEST_MAIN(TestWorkspaces)
#include "test_workspaces.moc"
