#include "parameters/parameter_table_model.h"

#include <QFont>

namespace k528::studio {

ParameterTableModel::ParameterTableModel(int columns, QObject* parent)
    : QAbstractTableModel(parent), columns_(columns) {}

int ParameterTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : columns_;
}

QVariant ParameterTableModel::headerData(int section, Qt::Orientation o, int role) const {
    if (o != Qt::Horizontal || (role != Qt::DisplayRole && role != Qt::ToolTipRole))
        return QAbstractTableModel::headerData(section, o, role);
    const QStringList titles = role == Qt::DisplayRole ? columnTitles() : columnToolTips();
    return section >= 0 && section < titles.size() && !titles[section].isEmpty() ? QVariant(titles[section])
                                                                                 : QVariant();
}

const QFont& ParameterTableModel::valueFont() {
    static const QFont bold = [] {
        QFont f;
        f.setBold(true);
        return f;
    }();
    return bold;
}

ParameterFilter::ParameterFilter(QObject* parent) : QSortFilterProxyModel(parent) {}

void ParameterFilter::setSearch(const QString& text) {
    search_ = text;
    words_ = text.toLower().split(QLatin1Char(' '), Qt::SkipEmptyParts);
    invalidateFilter();
}

bool ParameterFilter::filterAcceptsRow(int row, const QModelIndex& parent) const {
    if (!keeps(row, parent))
        return false;
    if (words_.isEmpty())
        return true;
    const QString hay = sourceModel()->index(row, 0, parent).data(ParameterTableModel::SearchRole).toString();
    for (const QString& w : words_)
        if (!hay.contains(w))
            return false;
    return true;
}

} // namespace k528::studio
