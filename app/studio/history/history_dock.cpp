#include "history/history_dock.h"
#include "session/file_problem.h"

#include "database/database_ui.h"

#include "history/history_model.h"
#include "history/history_service.h"
#include "controller/controller.h"
#include "controller/view_notice.h"
#include "session/core_texts.h"
#include "session/shop_database.h"
#include "widgets.h"
#include "workspace/pane_dock.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QEvent>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QMessageBox>
#include <QPointer>
#include <QProgressDialog>
#include <QPushButton>
#include <QSaveFile>
#include <QStackedWidget>
#include <QTableView>
#include <QThread>
#include <QTimer>
#include <QVBoxLayout>
#include <filesystem>
#include <map>

namespace k528::studio {

HistoryView::HistoryView(HistoryService& service, QWidget* parent)
    : QWidget(parent), service_(service) {
    setObjectName("history");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    searchLabel_ = new QLabel(this);
    search_ = namedWidget<QLineEdit>(this, "history.search");
    search_->setClearButtonEnabled(true);
    source_ = namedWidget<QComboBox>(this, "history.source");
    for (int i = 0; i <= db::kMessageSourceCount; ++i)
        source_->addItem(QString());
    unacked_ = namedWidget<QCheckBox>(this, "history.unacknowledged");
    allMachines_ = namedWidget<QCheckBox>(this, "history.allMachines");
    ack_ = namedWidget<QPushButton>(this, "history.acknowledge");
    csv_ = namedWidget<QPushButton>(this, "history.csv");
    layout->addLayout(fieldRow(searchLabel_, search_, {source_, unacked_, allMachines_, ack_, csv_}));

    model_ = new HistoryModel(service_.shop(), this);
    table_ = new QTableView(this);
    table_->setObjectName("history.table");
    table_->setModel(model_);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setAlternatingRowColors(true);
    table_->setWordWrap(false);
    table_->verticalHeader()->hide();
    table_->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 4);
    table_->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    const int digit = fontMetrics().horizontalAdvance(QLatin1Char('0'));
    const int widths[HistoryModel::ColumnCount] = {24, 13, 12, 5, 40, 14, 13, 30};
    for (int c = 0; c < HistoryModel::ColumnCount; ++c)
        table_->setColumnWidth(c, widths[c] * digit);
    layout->addWidget(table_, 1);
    status_ = new QLabel(this);
    status_->setObjectName("history.status");
    status_->setWordWrap(true);
    layout->addWidget(status_);

    searchDelay_ = new QTimer(this);
    searchDelay_->setSingleShot(true);
    searchDelay_->setInterval(250);
    connect(searchDelay_, &QTimer::timeout, this, &HistoryView::applyFilter);
    connect(search_, &QLineEdit::textChanged, searchDelay_, qOverload<>(&QTimer::start));
    connect(source_, &QComboBox::currentIndexChanged, this, &HistoryView::applyFilter);
    connect(unacked_, &QCheckBox::toggled, this, &HistoryView::applyFilter);
    connect(allMachines_, &QCheckBox::toggled, this, &HistoryView::applyFilter);
    connect(ack_, &QPushButton::clicked, &service_, &HistoryService::acknowledge);
    connect(csv_, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export the message history"),
                                                          "messages.csv", tr("CSV (*.csv)"));
        if (!path.isEmpty())
            exportCsv(path);
    });
    connect(&service_, &HistoryService::written, this, [this] {
        model_->refresh();
        updateStatus();
    });
    connect(&service_, &HistoryService::failed, this, [this](const QString& m) {
        status_->setText(tr("The messages could not be written (they are kept and written "
                            "later): %1").arg(m));
    });
    connect(model_, &QAbstractItemModel::rowsInserted, this, &HistoryView::updateStatus);
    ack_->setEnabled(service_.recorder() != nullptr && service_.canAcknowledge());
    csv_->setEnabled(service_.isOpen());
    retranslate();
    applyFilter();
}

HistoryView::~HistoryView() {
    if (worker_) {
        exportCancel_ = true;
        worker_->wait();
    }
}

db::MessageFilter HistoryView::filter() const {
    db::MessageFilter f;
    if (!allMachines_->isChecked())
        f.machine = service_.machine().toStdString();
    f.search = search_->text().trimmed().toStdString();
    if (source_->currentIndex() > 0)
        f.source = static_cast<db::MessageSource>(source_->currentIndex() - 1);
    f.unacknowledgedOnly = unacked_->isChecked();
    return f;
}

void HistoryView::applyFilter() {
    searchDelay_->stop();
    model_->setFilter(filter());
    updateStatus();
}

void HistoryView::updateStatus() {
    if (!service_.isOpen()) {
        status_->setText(tr("No message history: %1").arg(service_.error()));
        return;
    }
    if (!model_->error().isEmpty()) {
        status_->setText(model_->error());
        return;
    }
    int current = 0;
    if (const msglog::Recorder* r = service_.recorder())
        for (const msglog::OpenMessage& m : r->open())
            if (m.source != db::MessageSource::PlcWork && m.source != db::MessageSource::Program)
                ++current;
    status_->setText(tr("%1 messages (%2 loaded); %3 waiting for acknowledgement. Database: %4")
                         .arg(model_->total())
                         .arg(model_->rowCount())
                         .arg(current)
                         .arg(service_.databasePath()));
}

QString HistoryView::writeCsv(const QString& dbPath, const db::MessageFilter& f,
                              const QString& path, std::atomic<std::int64_t>* done,
                              std::atomic<bool>* cancel, std::int64_t* rows) {
    std::int64_t n = 0;
    try {
        // The window's connection, a page at a time: the recorder and the
        // dock write and read between the pages.
        const auto shop = ShopDatabase::atText(dbPath);
        SaveFile out(path);
        if (!out.open(QIODevice::WriteOnly))
            return tr("Cannot write %1: %2").arg(path, fileProblem(out));
        QByteArray buf = QByteArray::fromStdString(db::MessageLog::csvHeader() + "\r\n");
        bool stopped = false;
        for (std::int64_t before = 0; !stopped;) {
            const auto page = shop->useLog([&](db::MessageLog& log) { return log.page(f, before, 2000); });
            if (page.empty())
                break;
            before = page.back().id;
            for (const db::MessageRecord& m : page) {
                buf += QByteArray::fromStdString(db::MessageLog::csvRow(m));
                buf += "\r\n";
                ++n;
                if (buf.size() > (1 << 16)) {
                    out.write(buf);
                    buf.clear();
                }
                if (done)
                    done->store(n);
                if (cancel && cancel->load()) {
                    stopped = true;
                    break;
                }
            }
        }
        if (stopped) {
            out.cancelWriting();
            return tr("The export was cancelled; %1 was left as it was.").arg(path);
        }
        out.write(buf);
        if (!out.commit())
            return tr("Cannot write %1: %2").arg(path, fileProblem(out));
    } catch (const std::exception& e) {
        return tr("Cannot export to %1: %2").arg(path, coreErrorText(e));
    }
    if (rows)
        *rows = n;
    return {};
}

bool HistoryView::exportCsv(const QString& path, bool quiet) {
    if (worker_ || !service_.isOpen())
        return false;
    service_.flush(); // what the recorder saw belongs in the file too
    const db::MessageFilter f = filter();
    const std::int64_t total = model_->total();
    const QString dbPath = service_.databasePath();
    exportDone_ = 0;
    exportCancel_ = false;
    auto result = std::make_shared<std::pair<QString, std::int64_t>>();
    worker_ = QThread::create([this, dbPath, f, path, result] {
        result->first = writeCsv(dbPath, f, path, &exportDone_, &exportCancel_, &result->second);
    });
    QPointer<QProgressDialog> progress;
    if (!quiet) {
        progress = new QProgressDialog(tr("Exporting the message history…"), tr("Cancel"), 0,
                                       static_cast<int>(std::min<std::int64_t>(total, INT32_MAX)),
                                       this);
        progress->setObjectName("history.exportProgress");
        progress->setWindowModality(Qt::WindowModal);
        progress->setMinimumDuration(300);
        connect(progress, &QProgressDialog::canceled, this, [this] { exportCancel_ = true; });
    }
    auto* tick = new QTimer(this);
    connect(tick, &QTimer::timeout, this, [this, progress] {
        if (progress)
            progress->setValue(static_cast<int>(std::min<std::int64_t>(exportDone_.load(), progress->maximum())));
    });
    tick->start(100);
    connect(worker_, &QThread::finished, this, [this, tick, progress, path, result, quiet] {
        tick->deleteLater();
        if (progress)
            progress->deleteLater();
        worker_->deleteLater();
        worker_ = nullptr;
        if (!quiet) {
            if (result->first.isEmpty())
                status_->setText(tr("%1 messages exported to %2").arg(result->second).arg(path));
            else
                QMessageBox::warning(this, tr("Export the message history"), result->first);
        }
        emit exported(path, result->second, result->first);
    });
    worker_->start();
    return true;
}

void HistoryView::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) {
        retranslate();
        model_->headerDataChanged(Qt::Horizontal, 0, HistoryModel::ColumnCount - 1);
        updateStatus();
    }
    QWidget::changeEvent(e);
}

void HistoryView::retranslate() {
    searchLabel_->setText(tr("Search"));
    search_->setPlaceholderText(tr("text or number, e.g. 37 or A03"));
    source_->setItemText(0, tr("All sources"));
    for (int i = 0; i < db::kMessageSourceCount; ++i)
        source_->setItemText(i + 1, HistoryModel::sourceText(static_cast<db::MessageSource>(i)));
    unacked_->setText(tr("Not acknowledged"));
    allMachines_->setText(tr("All machines"));
    ack_->setText(tr("Acknowledge (ESC)"));
    ack_->setToolTip(service_.canAcknowledge() || !service_.recorder()
                         ? tr("Acknowledges the current messages as ESC on the K923 does "
                              "(C123 reset, C124 faults, C125 system messages)")
                         : tr("A real controller's messages are acknowledged on its own K923 (ESC): the link "
                              "carries no keys"));
    csv_->setText(tr("Export CSV…"));
}

namespace {

// One page of the history a controller shown: the simulated one's, and each
// real controller's from when it was first shown until it is disconnected.
class HistoryDock : public PaneDock {
public:
    HistoryDock(QMainWindow* window, ViewedController& viewed, const QString& dbPath)
        : PaneDock(window, "history", [] { return HistoryView::tr("Message history"); }), viewed_(viewed),
          dbPath_(dbPath) {
        pages_ = new QStackedWidget(this);
        pages_->setObjectName("history.pages");
        auto* notice = new ViewNotice(pages_, this);
        notice->follow(viewed, [](Controller& c) -> std::pair<ViewNotice::Level, QString> {
            if (c.simulated())
                return {ViewNotice::Level::None, {}};
            return {ViewNotice::Level::Info,
                    HistoryView::tr("The messages of the controller on the line, recorded as they are read (every "
                                    "%1 ms) with this PC's time; they are acknowledged on its own K923.")
                        .arg(qRound(1000.0 / c.capabilities().liveRateHz))};
        });
        setWidget(notice);
        connect(&viewed, &ViewedController::changed, this, [this] { showController(viewed_.current()); });
        showController(viewed.current());
        // File > Database…: the window's database is another one; the
        // history records into it and shows its messages (a dock given a
        // database of its own keeps it).
        if (dbPath_.isEmpty())
            connect(DatabaseWatch::instance(), &DatabaseWatch::switched, this, [this] { followDatabase(); });
    }
    ~HistoryDock() override {
        for (auto& [c, page] : pages)
            delete page.view; // the view before its service
    }

private:
    struct Page {
        HistoryService* service = nullptr;
        HistoryView* view = nullptr;
    };
    Page makePage(Controller& c) {
        Page p;
        p.service = new HistoryService(&c, dbPath_, this);
        p.view = new HistoryView(*p.service, pages_);
        pages_->addWidget(p.view);
        return p;
    }
    static void dropPage(QStackedWidget* stack, const Page& p) {
        stack->removeWidget(p.view);
        delete p.view;     // the view before its service
        delete p.service;  // writes what is pending into its database
    }
    void showController(Controller& c) {
        auto it = pages.find(&c);
        if (it == pages.end()) {
            it = pages.emplace(&c, makePage(c)).first;
            if (!c.simulated()) // a real controller: its page goes with it (its run is kept)
                connect(&c, &QObject::destroyed, this, [this, key = &c] {
                    const auto gone = pages.find(key);
                    if (gone == pages.end())
                        return;
                    const Page p = gone->second;
                    pages.erase(gone);
                    dropPage(pages_, p);
                });
        }
        pages_->setCurrentWidget(it->second.view);
    }
    // Each controller's run ends in the database it was recorded into and a
    // new one begins in the window's database now.
    void followDatabase() {
        for (auto& [c, page] : pages) {
            const Page old = page;
            page = makePage(*c);
            dropPage(pages_, old);
        }
        if (const auto it = pages.find(&viewed_.current()); it != pages.end())
            pages_->setCurrentWidget(it->second.view);
    }
    ViewedController& viewed_;
    QString dbPath_;
    QStackedWidget* pages_ = nullptr;
    std::map<Controller*, Page> pages;
};

} // namespace

QDockWidget* addHistoryDock(QMainWindow* window, ViewedController& viewed, const QString& dbPath) {
    auto* dock = new HistoryDock(window, viewed, dbPath);
    window->addDockWidget(Qt::BottomDockWidgetArea, dock);
    dock->hide(); // shown from the View menu; the workspaces place it
    return dock;
}

} // namespace k528::studio
