// Helpers for building a pane's widgets.
#pragma once

#include <QBoxLayout>
#include <QLabel>
#include <QString>
#include <QWidget>
#include <initializer_list>

namespace k528::studio {

// A new `W` of `parent` named `name` (the object name the tests and the
// saved settings know it by).
template <typename W> W* namedWidget(QWidget* parent, const char* name) {
    auto* w = new W(parent);
    w->setObjectName(QString::fromLatin1(name));
    return w;
}

// A row of a label, the field it names taking the room left, and the widgets
// `after` it at their own sizes.
inline QHBoxLayout* fieldRow(QLabel* label, QWidget* field, std::initializer_list<QWidget*> after) {
    auto* row = new QHBoxLayout;
    row->addWidget(label);
    row->addWidget(field, 1);
    for (QWidget* w : after)
        row->addWidget(w);
    return row;
}

// A pane's status line: `text`, in red when it says what went wrong.
inline void showStatus(QLabel* status, const QString& text, bool bad) {
    status->setText(text);
    status->setStyleSheet(bad ? QStringLiteral("color:#b00000;") : QString());
}

} // namespace k528::studio
