// What the tests of the studio's windows measure of a widget on the screen.
#pragma once

#include <QPoint>
#include <QRect>
#include <QWidget>

namespace k528::testrig {

// The part of `w` its parents let show, in global coordinates (empty:
// hidden behind a tab, scrolled out of its pane).
inline QRect shownRect(const QWidget* w) {
    QRect r(w->mapToGlobal(QPoint(0, 0)), w->size());
    for (const QWidget* p = w->parentWidget(); p; p = p->parentWidget()) {
        r &= QRect(p->mapToGlobal(QPoint(0, 0)), p->size());
        if (p->isWindow())
            break;
    }
    return r;
}

} // namespace k528::testrig
