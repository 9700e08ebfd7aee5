#include "editor/problems_model.h"

#include "language.h"

#include <QColor>

namespace k528::studio {

void ProblemsModel::setDiagnostics(const std::vector<program::Diagnostic>* diagnostics) {
    beginResetModel();
    diagnostics_ = diagnostics;
    endResetModel();
}

void ProblemsModel::setTexts(const QStringList& headers, const QString& error, const QString& warning) {
    headers_ = headers;
    error_ = error;
    warning_ = warning;
    emit headerDataChanged(Qt::Horizontal, 0, columnCount() - 1);
    if (rowCount() > 0)
        emit dataChanged(index(0, 0), index(rowCount() - 1, columnCount() - 1));
}

int ProblemsModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() || !diagnostics_ ? 0 : static_cast<int>(diagnostics_->size());
}

int ProblemsModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : 5; }

QVariant ProblemsModel::data(const QModelIndex& index, int role) const {
    if (!diagnostics_ || !index.isValid() || index.row() >= rowCount())
        return {};
    const program::Diagnostic& d = (*diagnostics_)[static_cast<std::size_t>(index.row())];
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case 0: return d.isError() ? error_ : warning_;
        case 1: return d.program > 0 ? QStringLiteral("L%1").arg(d.program) : QString();
        case 2: return QString::number(d.line);
        case 3: return d.manualNumber > 0 ? QStringLiteral("[M%1]").arg(d.manualNumber, 2, 10, QChar('0')) : QString();
        case 4: {
            const std::string& t = currentLanguage() == QStringLiteral("ru") ? d.messageRu : d.messageEn;
            return QString::fromUtf8(t.data(), static_cast<qsizetype>(t.size()));
        }
        default: return {};
        }
    case Qt::ForegroundRole:
        if (index.column() == 0)
            return d.isError() ? QColor(0xc0, 0, 0) : QColor(0xa0, 0x60, 0);
        return {};
    case kLineRole: return d.line;
    case kColumnRole: return d.column;
    default: return {};
    }
}

QVariant ProblemsModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation == Qt::Horizontal && role == Qt::DisplayRole && section >= 0 && section < headers_.size())
        return headers_.at(section);
    return {};
}

} // namespace k528::studio
