// The Problems list's model: a table over the current editor's
// diagnostics (severity, program, line, [Mnn], text), read in place, then
// the prove-out's findings of the file (severity, program, line, the rule's
// id, «N4: text»). A new validation resets it in constant time; the view
// asks only for the rows it shows, so 9000 problems of a big file cost
// nothing while typing.
#pragma once

#include "program/diagnostic.h"

#include <QAbstractTableModel>
#include <QFontMetrics>
#include <QStringList>
#include <vector>

namespace k528::proveout {
struct Finding;
}

namespace k528::studio {

class ProblemsModel : public QAbstractTableModel {
    Q_OBJECT
public:
    using QAbstractTableModel::QAbstractTableModel;
    static constexpr int kLineRole = Qt::UserRole;
    static constexpr int kColumnRole = Qt::UserRole + 1;
    // A finding's row: its rule id ("rapid-into-material") and its index in
    // the findings (-1 and "" on a diagnostic's row).
    static constexpr int kRuleRole = Qt::UserRole + 2;
    static constexpr int kFindingRole = Qt::UserRole + 3;

    // The diagnostics shown (owned by the editor; nullptr = none). Call again
    // after they changed.
    void setDiagnostics(const std::vector<program::Diagnostic>* diagnostics);
    // The prove-out's findings shown after them (owned by the editor; nullptr = none).
    void setFindings(const std::vector<proveout::Finding>* findings);
    // The texts of the header and of the two severities (translated by the tab).
    void setTexts(const QStringList& headers, const QString& error, const QString& warning);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // The width the Code column needs to show every row's code whole, in
    // `metrics`: measured once per distinct code (a file of 9000 problems
    // has a few dozen), so the view need not lay out every row as
    // QHeaderView::ResizeToContents does after each validation.
    int widestCode(const QFontMetrics& metrics) const;

private:
    int diagnosticRows() const;
    QVariant findingData(int i, int column, int role) const;
    const std::vector<program::Diagnostic>* diagnostics_ = nullptr;
    const std::vector<proveout::Finding>* findings_ = nullptr;
    QStringList headers_;
    QString error_, warning_;
};

} // namespace k528::studio
