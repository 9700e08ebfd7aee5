#include "history/history_model.h"

#include "session/catalog_texts.h"
#include "window_language.h"
#include "session/shop_database.h"

#include <QColor>
#include <QDateTime>
#include <algorithm>

namespace k528::studio {

namespace {

QString fromStd(const std::string& s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }

bool acknowledgeable(db::MessageSource s) {
    return s == db::MessageSource::Positioner || s == db::MessageSource::PlcAlarm ||
           s == db::MessageSource::PlcSystem;
}

// A positioner's message in the window's language (table М.1); another as
// recorded (a PLC's or a program's as the machine's author wrote it).
QString messageText(const db::MessageRecord& m) {
    if (m.source == db::MessageSource::Positioner)
        if (const QString text = positionerMessageText(m.number); !text.isEmpty())
            return text;
    return coreText(m.text, m.textEn);
}

} // namespace

HistoryModel::HistoryModel(ShopDatabase* shop, QObject* parent)
    : QAbstractTableModel(parent), shop_(shop) {}

QString HistoryModel::sourceText(db::MessageSource s) {
    switch (s) {
    case db::MessageSource::Positioner: return tr("Positioner");
    case db::MessageSource::PlcAlarm: return tr("PLC alarm");
    case db::MessageSource::PlcSystem: return tr("PLC system");
    case db::MessageSource::PlcWork: return tr("PLC work");
    case db::MessageSource::Program: return tr("Program");
    }
    return {};
}

QString HistoryModel::howText(const std::string& how) {
    if (how == "esc")
        return tr("ESC");
    if (how == "esc-dock")
        return tr("ESC from the history dock");
    if (how == "z1000.7")
        return tr("acknowledge signal Z1000.7");
    if (how == "reset")
        return tr("reset Z1000.5");
    return fromStd(how);
}

QString HistoryModel::machineTimeText(std::int64_t ms) {
    const std::int64_t s = ms / 1000;
    return QStringLiteral("%1:%2:%3.%4")
        .arg(s / 3600, 2, 10, QChar('0'))
        .arg(s / 60 % 60, 2, 10, QChar('0'))
        .arg(s % 60, 2, 10, QChar('0'))
        .arg(ms % 1000, 3, 10, QChar('0'));
}

QString HistoryModel::dayTimeText(std::int64_t unixMs) {
    return QDateTime::fromMSecsSinceEpoch(unixMs).toLocalTime().toString(
        QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz"));
}

void HistoryModel::setFilter(const db::MessageFilter& f) {
    beginResetModel();
    filter_ = f;
    rows_.clear();
    total_ = 0;
    error_.clear();
    if (shop_) {
        try {
            const auto page = shop_->useLog([&](db::MessageLog& log) {
                total_ = log.count(filter_);
                return log.page(filter_, 0, kFirstPage);
            });
            rows_.assign(page.begin(), page.end());
        } catch (const std::exception& e) {
            error_ = databaseErrorText(e);
        }
    }
    endResetModel();
}

bool HistoryModel::mayChange(const db::MessageRecord& m) const {
    return !m.clearedMs || (acknowledgeable(m.source) && !m.acknowledged());
}

void HistoryModel::refresh() {
    if (!shop_)
        return;
    try {
        db::MessageFilter newer = filter_;
        newer.afterId = rows_.empty() ? 0 : rows_.front().id;
        if (rows_.empty() && total_ > 0) {
            setFilter(filter_);
            return;
        }
        const auto added = shop_->useLog([&](db::MessageLog& log) { return log.page(newer, 0, 100000); });
        if (!added.empty()) {
            beginInsertRows({}, 0, static_cast<int>(added.size()) - 1);
            rows_.insert(rows_.begin(), added.begin(), added.end());
            total_ += static_cast<std::int64_t>(added.size());
            endInsertRows();
        }
        // The loaded rows that may have changed since (still open).
        std::vector<std::int64_t> ids;
        std::vector<int> at;
        for (int i = static_cast<int>(added.size()); i < static_cast<int>(rows_.size()); ++i)
            if (mayChange(rows_[static_cast<std::size_t>(i)])) {
                ids.push_back(rows_[static_cast<std::size_t>(i)].id);
                at.push_back(i);
            }
        if (ids.empty())
            return;
        const auto now = shop_->useLog([&](db::MessageLog& log) { return log.byIds(ids); });
        std::size_t k = 0;
        for (std::size_t j = 0; j < ids.size() && k < now.size(); ++j) {
            if (now[k].id != ids[j])
                continue;
            db::MessageRecord& r = rows_[static_cast<std::size_t>(at[j])];
            if (now[k].clearedMs != r.clearedMs || now[k].ackMs != r.ackMs) {
                r = now[k];
                emit dataChanged(index(at[j], 0), index(at[j], ColumnCount - 1));
            }
            ++k;
        }
    } catch (const std::exception& e) {
        error_ = databaseErrorText(e);
    }
}

int HistoryModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(rows_.size());
}

int HistoryModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

bool HistoryModel::canFetchMore(const QModelIndex& parent) const {
    return !parent.isValid() && shop_ && static_cast<std::int64_t>(rows_.size()) < total_;
}

void HistoryModel::fetchMore(const QModelIndex& parent) {
    if (!canFetchMore(parent))
        return;
    try {
        const std::int64_t before = rows_.empty() ? 0 : rows_.back().id;
        const auto page = shop_->useLog([&](db::MessageLog& log) { return log.page(filter_, before, kPage); });
        if (page.empty()) {
            total_ = static_cast<std::int64_t>(rows_.size());
            return;
        }
        const int first = static_cast<int>(rows_.size());
        beginInsertRows({}, first, first + static_cast<int>(page.size()) - 1);
        rows_.insert(rows_.end(), page.begin(), page.end());
        endInsertRows();
    } catch (const std::exception& e) {
        error_ = databaseErrorText(e);
    }
}

QVariant HistoryModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= static_cast<int>(rows_.size()))
        return {};
    const db::MessageRecord& m = rows_[static_cast<std::size_t>(index.row())];
    if (role == Qt::ForegroundRole) {
        if (m.source == db::MessageSource::PlcWork || m.source == db::MessageSource::Program)
            return QColor(0x1d, 0x4f, 0x91);
        if (acknowledgeable(m.source) && !m.acknowledged())
            return QColor(0xb0, 0x1c, 0x1c);
        return {};
    }
    // The tool tip shows the whole text (the column may elide it) in the
    // window's language only: a Russian window never shows the English one.
    if (role != Qt::DisplayRole && !(role == Qt::ToolTipRole && index.column() == Text))
        return {};
    switch (index.column()) {
    case Time: return dayTimeText(m.dayMs);
    case MachineTime: return machineTimeText(m.machineMs);
    case Source: return sourceText(m.source);
    case Code: return fromStd(m.code());
    case Text: return messageText(m);
    case Program:
        if (m.program <= 0)
            return QString();
        return m.line > 0 ? tr("L%1, line %2").arg(m.program).arg(m.line)
                          : tr("L%1").arg(m.program);
    case Cleared: return m.clearedMs ? machineTimeText(*m.clearedMs) : QString();
    case Acknowledged:
        if (m.acknowledged())
            return tr("%1, %2").arg(dayTimeText(*m.ackDayMs), howText(m.ackHow));
        return acknowledgeable(m.source) ? tr("not yet") : QString();
    default: return {};
    }
}

QVariant HistoryModel::headerData(int section, Qt::Orientation o, int role) const {
    if (o != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Time: return tr("Time");
    case MachineTime: return tr("Machine time");
    case Source: return tr("Source");
    case Code: return tr("No.");
    case Text: return tr("Message");
    case Program: return tr("Program");
    case Cleared: return tr("Cause gone");
    case Acknowledged: return tr("Acknowledged");
    default: return {};
    }
}

} // namespace k528::studio
