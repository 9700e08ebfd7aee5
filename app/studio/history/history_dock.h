// The message history dock (dock.history): every message of the viewed
// controller's positioner and PLC kept in the database (HistoryService), newest first,
// searchable (text or number), by source, only the unacknowledged, this
// machine or all; the current ones acknowledged with «ESC» as the K923 does;
// CSV export on a worker thread with progress.
#pragma once

#include "db/message_log.h"

#include <QWidget>
#include <atomic>
#include <functional>

class QCheckBox;
class QComboBox;
class QDockWidget;
class QLabel;
class QLineEdit;
class QMainWindow;
class QPushButton;
class QTableView;
class QThread;
class QTimer;

namespace k528::studio {

class HistoryModel;
class HistoryService;
class ViewedController;

class HistoryView : public QWidget {
    Q_OBJECT
public:
    // Over `service` (not owned; it outlives the view or is its child).
    explicit HistoryView(HistoryService& service, QWidget* parent = nullptr);
    ~HistoryView() override;

    HistoryModel* model() const { return model_; }
    QTableView* table() const { return table_; }
    QLineEdit* searchBox() const { return search_; }
    QPushButton* acknowledgeButton() const { return ack_; }
    // The filter of the controls.
    db::MessageFilter filter() const;
    // Applies the controls now (the search box waits a moment after typing).
    void applyFilter();

    // Starts the CSV export of the filtered rows to `path` on a worker thread
    // (a progress dialog unless `quiet`); exported() tells the end.
    bool exportCsv(const QString& path, bool quiet = false);
    bool exporting() const { return worker_ != nullptr; }

    // The export itself (any thread): its own connection to `dbPath`; writes
    // to `path` through a temporary file, so a failure or a cancel leaves
    // what was there. Returns "" or the error; `rows` the rows written.
    static QString writeCsv(const QString& dbPath, const db::MessageFilter& f, const QString& path,
                            std::atomic<std::int64_t>* done, std::atomic<bool>* cancel,
                            std::int64_t* rows);

signals:
    void exported(const QString& path, qint64 rows, const QString& error);

protected:
    void changeEvent(QEvent* e) override;

private:
    void retranslate();
    void updateStatus();

    HistoryService& service_;
    HistoryModel* model_ = nullptr;
    QTableView* table_ = nullptr;
    QLineEdit* search_ = nullptr;
    QComboBox* source_ = nullptr;
    QCheckBox* unacked_ = nullptr;
    QCheckBox* allMachines_ = nullptr;
    QPushButton* ack_ = nullptr;
    QPushButton* csv_ = nullptr;
    QLabel* status_ = nullptr;
    QLabel* searchLabel_ = nullptr;
    QTimer* searchDelay_ = nullptr;
    QThread* worker_ = nullptr;
    std::atomic<std::int64_t> exportDone_{0};
    std::atomic<bool> exportCancel_{false};
};

// Adds the dock to `window` (bottom area, its place remembered) recording
// the messages of each controller `viewed` shows (the simulated one from the
// start, a real one from when it is first shown) into the database at
// `dbPath` ("": the default), and showing the one shown.
QDockWidget* addHistoryDock(QMainWindow* window, ViewedController& viewed, const QString& dbPath = {});

} // namespace k528::studio
