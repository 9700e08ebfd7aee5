#include "editor/problems_model.h"

#include "proveout/proveout.h"
#include "session/core_texts.h"
#include "session/diagnostic_texts.h"

#include <QColor>

#include <algorithm>
#include <set>
#include <utility>

namespace k528::studio {

namespace {

// The Code column of a diagnostic: the controller's message number, then the rule's short name.
QString diagnosticCode(int manualNumber, program::Rule rule) {
    return manualNumber > 0 ? QStringLiteral("[M%1] ").arg(manualNumber, 2, 10, QChar('0')) + ruleName(rule)
                            : ruleName(rule);
}

} // namespace

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

void ProblemsModel::setFindings(const std::vector<proveout::Finding>* findings) {
    beginResetModel();
    findings_ = findings;
    endResetModel();
}

int ProblemsModel::diagnosticRows() const { return diagnostics_ ? static_cast<int>(diagnostics_->size()) : 0; }

int ProblemsModel::rowCount(const QModelIndex& parent) const {
    if (parent.isValid())
        return 0;
    return diagnosticRows() + (findings_ ? static_cast<int>(findings_->size()) : 0);
}

int ProblemsModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : 5; }

QVariant ProblemsModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    if (index.row() >= diagnosticRows())
        return findingData(index.row() - diagnosticRows(), index.column(), role);
    const program::Diagnostic& d = (*diagnostics_)[static_cast<std::size_t>(index.row())];
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case 0: return d.isError() ? error_ : warning_;
        case 1: return d.program > 0 ? QStringLiteral("L%1").arg(d.program) : QString();
        case 2: return QString::number(d.line);
        case 3: return diagnosticCode(d.manualNumber, d.rule);
        case 4: return diagnosticText(d);
        default: return {};
        }
    case Qt::ToolTipRole:
        if (index.column() == 3) { // the rule's id, as docs/program-language.md and `k528 check --json` name it
            const std::string_view id = program::ruleId(d.rule);
            return QString::fromUtf8(id.data(), static_cast<qsizetype>(id.size()));
        }
        if (index.column() == 4) // the whole text where the column cuts it
            return diagnosticText(d);
        return {};
    case Qt::ForegroundRole:
        if (index.column() == 0)
            return d.isError() ? QColor(0xc0, 0, 0) : QColor(0xa0, 0x60, 0);
        return {};
    case kLineRole: return d.line;
    case kColumnRole: return d.column;
    case kFindingRole: return -1;
    default: return {};
    }
}

QVariant ProblemsModel::findingData(int i, int column, int role) const {
    const proveout::Finding& f = (*findings_)[static_cast<std::size_t>(i)];
    const std::string_view rule = proveout::ruleId(f.rule);
    switch (role) {
    case Qt::DisplayRole:
        switch (column) {
        case 0: return f.isError() ? error_ : warning_;
        case 1: return QStringLiteral("L%1").arg(f.program);
        case 2: return QString::number(f.line);
        case 3: return ruleName(f.rule);
        case 4: {
            QString t = QStringLiteral("N%1: ").arg(f.n) + findingText(f);
            if (f.occurrences > 1)
                t += QStringLiteral(" (×%1)").arg(f.occurrences);
            return t;
        }
        default: return {};
        }
    case Qt::ToolTipRole:
        if (column == 3)
            return tr("The rule of the prove-out the frame breaks (the blank, the chuck, the tools): %1")
                .arg(QString::fromUtf8(rule.data(), static_cast<qsizetype>(rule.size())));
        if (column == 4) // the whole text where the column cuts it
            return findingData(i, column, Qt::DisplayRole);
        return {};
    case Qt::ForegroundRole:
        if (column == 0)
            return f.isError() ? QColor(0xc0, 0, 0) : QColor(0xa0, 0x60, 0);
        return {};
    case kLineRole: return f.line;
    case kColumnRole: return 1;
    case kRuleRole: return QString::fromUtf8(rule.data(), static_cast<qsizetype>(rule.size()));
    case kFindingRole: return i;
    default: return {};
    }
}

int ProblemsModel::widestCode(const QFontMetrics& metrics) const {
    std::set<std::pair<int, program::Rule>> diagnosticCodes; // (message number, rule)
    if (diagnostics_)
        for (const program::Diagnostic& d : *diagnostics_)
            diagnosticCodes.emplace(d.manualNumber, d.rule);
    int widest = 0;
    for (const auto& [number, rule] : diagnosticCodes)
        widest = std::max(widest, metrics.horizontalAdvance(diagnosticCode(number, rule)));
    std::set<proveout::Rule> findingRules;
    if (findings_)
        for (const proveout::Finding& f : *findings_)
            if (findingRules.insert(f.rule).second)
                widest = std::max(widest, metrics.horizontalAdvance(ruleName(f.rule)));
    return widest;
}

QVariant ProblemsModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation == Qt::Horizontal && role == Qt::DisplayRole && section >= 0 && section < headers_.size())
        return headers_.at(section);
    return {};
}

} // namespace k528::studio
