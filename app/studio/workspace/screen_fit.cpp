#include "workspace/screen_fit.h"

#include <QAbstractScrollArea>
#include <QDockWidget>
#include <QGuiApplication>
#include <QScreen>
#include <QScrollArea>
#include <QVBoxLayout>
#include <QVariant>
#include <QWidget>
#include <QWindow>

namespace k528::studio {

QScrollArea* scrollInside(QDockWidget* dock) {
    QWidget* content = dock->widget();
    if (!content || qobject_cast<QAbstractScrollArea*>(content))
        return nullptr;
    auto* scroll = new QScrollArea(dock);
    scroll->setObjectName(dock->objectName() + ".scroll");
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidgetResizable(true);
    QWidget* kept = takeKeptInView(content, dock);
    scroll->setWidget(content); // takes it out of the dock
    if (!kept) {
        dock->setWidget(scroll);
        return scroll;
    }
    auto* frame = new QWidget(dock);
    frame->setObjectName(dock->objectName() + ".frame");
    auto* layout = new QVBoxLayout(frame);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(scroll, 1);
    layout->addWidget(kept);
    dock->setWidget(frame);
    return scroll;
}

QWidget* takeKeptInView(QWidget* content, QWidget* parent) {
    QWidget* kept = nullptr;
    for (QWidget* c : content->findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly))
        if (c->property(kKeptInView).toBool())
            kept = c;
    if (!kept)
        return nullptr;
    // In a holder with the content's margins at the sides and the bottom.
    auto* holder = new QWidget(parent);
    holder->setObjectName(kept->objectName() + ".kept");
    auto* layout = new QVBoxLayout(holder);
    const QMargins m = content->layout() ? content->layout()->contentsMargins() : QMargins();
    layout->setContentsMargins(m.left(), 2, m.right(), m.bottom());
    kept->setParent(holder); // out of the content's layout
    layout->addWidget(kept);
    kept->show();
    return holder;
}

QRect availableArea(const QWidget* w) {
    QScreen* s = w ? w->screen() : nullptr;
    if (!s)
        s = QGuiApplication::primaryScreen();
    return s ? s->availableGeometry() : QRect(0, 0, 1366, 768);
}

void keepInside(QWidget* window, const QRect& area) {
    if (area.isEmpty())
        return;
    // The frame (title bar, borders) the window manager adds, once known.
    const QRect frame = window->frameGeometry();
    const QRect client = window->geometry();
    const QMargins m(client.left() - frame.left(), client.top() - frame.top(), frame.right() - client.right(),
                     frame.bottom() - client.bottom());
    const QSize most(area.width() - m.left() - m.right(), area.height() - m.top() - m.bottom());
    window->setMaximumSize(QSize(std::max(most.width(), 200), std::max(most.height(), 150)));
    QRect g = client;
    g.setSize(g.size().boundedTo(window->maximumSize()));
    if (g.right() + m.right() > area.right())
        g.moveRight(area.right() - m.right());
    if (g.bottom() + m.bottom() > area.bottom())
        g.moveBottom(area.bottom() - m.bottom());
    if (g.left() - m.left() < area.left())
        g.moveLeft(area.left() + m.left());
    if (g.top() - m.top() < area.top())
        g.moveTop(area.top() + m.top());
    if (g != client)
        window->setGeometry(g);
}

} // namespace k528::studio
