// Helpers for building a pane's widgets.
#pragma once

#include <QBoxLayout>
#include <QComboBox>
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

// The texts of `box`'s entries, in order: a choice's words, given again on
// a change of the language.
inline void setItemTexts(QComboBox* box, std::initializer_list<QString> texts) {
    int i = 0;
    for (const QString& t : texts)
        box->setItemText(i++, t);
}

// A choice of `parent` named `name` that narrows a table: `count` entries
// (their texts from setItemTexts), the index chosen going to `filter`'s
// `set` as its enum of the same order (All first, then each kind).
template <typename Filter, typename E>
QComboBox* filterChoice(QWidget* parent, const char* name, int count, Filter* filter, void (Filter::*set)(E)) {
    auto* box = namedWidget<QComboBox>(parent, name);
    for (int i = 0; i < count; ++i)
        box->addItem(QString());
    QObject::connect(box, &QComboBox::currentIndexChanged, filter,
                     [filter, set](int i) { (filter->*set)(static_cast<E>(i)); });
    return box;
}

// A pane's status line: `text`, in red when it says what went wrong.
inline void showStatus(QLabel* status, const QString& text, bool bad) {
    status->setText(text);
    status->setStyleSheet(bad ? QStringLiteral("color:#b00000;") : QString());
}

} // namespace k528::studio
