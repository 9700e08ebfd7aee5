// The message history as a table, read lazily: the count and the newest page
// when the filter is set, further pages as the view scrolls (fetchMore), new
// rows on top and the rows still open re-read when the recorder wrote
// (refresh). So 100,000 stored messages open as fast as a few hundred.
#pragma once

#include "db/message_log.h"

#include <QAbstractTableModel>
#include <deque>

namespace k528::studio {

class ShopDatabase;

class HistoryModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Time, MachineTime, Source, Code, Text, Program, Cleared, Acknowledged, ColumnCount };
    static constexpr int kFirstPage = 200;
    static constexpr int kPage = 1000;

    // `shop`: the connection whose message log is shown (nullptr: none).
    explicit HistoryModel(ShopDatabase* shop, QObject* parent = nullptr);

    // A new filter: the count and the first page (or the error).
    void setFilter(const db::MessageFilter& f);
    const db::MessageFilter& filter() const { return filter_; }
    // Rows written since: new ones on top, open ones re-read.
    void refresh();
    // Matching rows in the database (rowCount() is what is loaded).
    std::int64_t total() const { return total_; }
    const db::MessageRecord& record(int row) const { return rows_[static_cast<std::size_t>(row)]; }
    QString error() const { return error_; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation o, int role = Qt::DisplayRole) const override;
    bool canFetchMore(const QModelIndex& parent) const override;
    void fetchMore(const QModelIndex& parent) override;

    // Texts shared with the CSV export and the tests.
    static QString sourceText(db::MessageSource s);
    static QString howText(const std::string& how);
    static QString machineTimeText(std::int64_t ms);
    static QString dayTimeText(std::int64_t unixMs);

private:
    bool mayChange(const db::MessageRecord& m) const;
    ShopDatabase* shop_;
    db::MessageFilter filter_;
    std::deque<db::MessageRecord> rows_; // newest first
    std::int64_t total_ = 0;
    QString error_;
};

} // namespace k528::studio
