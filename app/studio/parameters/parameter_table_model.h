// What the tables of a controller's parameters share (the machine constants,
// constants_model.h, and the R-parameters, rparams_model.h): a row a
// parameter with its number and its texts to search, column titles in the
// UI's language, live values, and a filter that narrows by the words typed
// (every one in some text of the row) and by what the table's own choice
// keeps.
#pragma once

#include <QAbstractTableModel>
#include <QSortFilterProxyModel>
#include <QStringList>
#include <cstddef>
#include <utility>

class QFont;

namespace k528::studio {

class ParameterTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    // NumberRole: the parameter's number; SearchRole: every text of the row, lower case.
    static constexpr int NumberRole = Qt::UserRole;
    static constexpr int SearchRole = Qt::UserRole + 1;

    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant headerData(int section, Qt::Orientation o, int role = Qt::DisplayRole) const override;

public slots:
    // Follows the controller: the rows whose values changed are redrawn.
    virtual void refresh() = 0;
    // The texts in the UI's language again.
    virtual void retranslate() = 0;

protected:
    ParameterTableModel(int columns, QObject* parent);
    // The titles of the columns, in their order, in the UI's language.
    virtual QStringList columnTitles() const = 0;
    // What a short title stands for, shown over its column ("" or none: the
    // title says it all).
    virtual QStringList columnToolTips() const { return {}; }
    // The value column's font (bold).
    static const QFont& valueFont();
    // The values of `now` from number `from` up to `to` (not included) that
    // differ from those `shown`, copied there: the first and the last number
    // changed ({-1, -1}: none).
    template <class Now, class Shown>
    static std::pair<int, int> takeChanged(const Now& now, Shown& shown, int from, int to) {
        std::pair<int, int> changed{-1, -1};
        for (int n = from; n < to; ++n) {
            const auto i = static_cast<std::size_t>(n);
            if (now[i] == shown[i])
                continue;
            shown[i] = static_cast<typename Shown::value_type>(now[i]);
            if (changed.first < 0)
                changed.first = n;
            changed.second = n;
        }
        return changed;
    }

private:
    int columns_;
};

class ParameterFilter : public QSortFilterProxyModel {
    Q_OBJECT
public:
    // The words of `text` (lower case): a row is kept when each is in its search text.
    void setSearch(const QString& text);
    QString search() const { return search_; }

protected:
    explicit ParameterFilter(QObject* parent);
    // Whether the table's own choice (axis, kind, …) keeps source row `row`.
    virtual bool keeps(int row, const QModelIndex& parent) const = 0;
    bool filterAcceptsRow(int row, const QModelIndex& parent) const final;

private:
    QStringList words_;
    QString search_;
};

} // namespace k528::studio
