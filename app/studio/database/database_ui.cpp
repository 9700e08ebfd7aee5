#include "database/database_ui.h"
#include "session/core_texts.h"

#include "db/database.h"
#include "db/location.h"
#include "session/shop_database.h"

#include <QAction>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <QVBoxLayout>
#include <QHeaderView>
#include <QTableWidget>
#include <algorithm>

namespace k528::studio {

namespace {

constexpr const char* kLocationKey = "database/location";
constexpr const char* kRecentKey = "database/recent";
constexpr int kRecentCount = 8;
constexpr int kBackoffTicks = 10; // a database that failed: tried again after 10 s

QString fromStd(const std::string& s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

void remember(const QString& location) {
    QSettings s;
    s.setValue(kLocationKey, location);
    QStringList recent = s.value(kRecentKey).toStringList();
    recent.removeAll(location);
    recent.prepend(location);
    while (recent.size() > kRecentCount)
        recent.removeLast();
    s.setValue(kRecentKey, recent);
}

// The status bar's permanent label: the database open, kept in the window's language.
class DatabaseLabel : public QLabel {
public:
    explicit DatabaseLabel(QWidget* parent) : QLabel(parent) {
        setObjectName("status.database");
        refresh();
    }
    void refresh() {
        const QString where = ShopDatabase::currentText();
        setText(QCoreApplication::translate("k528::studio::DatabaseUi", "Database: %1").arg(QFontMetrics(font()).elidedText(where, Qt::ElideMiddle, 360)));
        setToolTip(where);
    }

protected:
    void changeEvent(QEvent* e) override {
        if (e->type() == QEvent::LanguageChange)
            refresh();
        QLabel::changeEvent(e);
    }
};

} // namespace

QString databaseOpenError(const QString& location, const std::exception& e) {
    const auto* error = dynamic_cast<const db::Error*>(&e);
    if (!error)
        return QCoreApplication::translate("k528::studio::DatabaseUi", "The database %1 cannot be opened: %2").arg(location, QString::fromUtf8(e.what()));
    if (error->kind() == db::ErrorKind::ReadOnly)
        return databaseErrorText(e);
    const QString why = databaseErrorKindText(error->kind());
    const QString detail = databaseErrorDetail(e);
    if (detail.isEmpty())
        return QCoreApplication::translate("k528::studio::DatabaseUi", "The database %1 cannot be opened: %2.").arg(location, why);
    return QCoreApplication::translate("k528::studio::DatabaseUi", "The database %1 cannot be opened: %2.\nDetails: %3").arg(location, why, detail);
}

QString openDatabase(const QString& given) {
    const QString location = given.trimmed();
    if (location.isEmpty())
        return QCoreApplication::translate("k528::studio::DatabaseUi", "Name a database: a file path, sqlite:PATH or postgresql://HOST/NAME.");
    db::Location where;
    try {
        where = db::Location::parse(location.toStdString());
        ShopDatabase::at(where)->use([](db::Database& d) { return d.schemaVersion(); });
    } catch (const std::exception& e) {
        return databaseOpenError(location, e);
    }
    ShopDatabase::choose(where);
    remember(location);
    DatabaseWatch* w = DatabaseWatch::instance();
    w->restart();
    emit w->switched(QString::fromStdString(where.text()));
    return {};
}

void chooseStartDatabase(const QString& commandLine, QString* warning) {
    if (!commandLine.isEmpty()) {
        ShopDatabase::choose(db::Location::parse(commandLine.toStdString())); // main() says a bad one
        return;
    }
    if (!qEnvironmentVariableIsEmpty("K528_DB"))
        return; // ShopDatabase::current() reads it
    const QString remembered = QSettings().value(kLocationKey).toString();
    if (remembered.isEmpty())
        return;
    try {
        const db::Location where = db::Location::parse(remembered.toStdString());
        ShopDatabase::at(where);
        ShopDatabase::choose(where);
    } catch (const std::exception& e) {
        if (warning)
            *warning = databaseOpenError(remembered, e);
    }
}

QStringList recentDatabases() {
    return QSettings().value(kRecentKey).toStringList();
}

QString databaseWindowTitle() {
    return QCoreApplication::translate("k528::studio::DatabaseUi", "K528 Studio — %1").arg(ShopDatabase::currentText());
}

// The dialog.

DatabaseDialog::DatabaseDialog(QWidget* parent) : QDialog(parent) {
    setObjectName("dialog.database");
    setWindowTitle(QCoreApplication::translate("k528::studio::DatabaseUi", "Database"));
    auto* explain = new QLabel(
        QCoreApplication::translate("k528::studio::DatabaseUi", "The database of machines, programs and their history: a file on this PC (a path, or "
           "sqlite:PATH), or the shop's PostgreSQL server (postgresql://HOST/NAME, "
           "postgresql:///NAME, postgresql://?service=shop). The password is never written here: "
           "the server's password is read from ~/.pgpass (PGPASSFILE) or a service file."),
        this);
    explain->setWordWrap(true);
    location_ = new QComboBox(this);
    location_->setObjectName("database.location");
    location_->setEditable(true);
    location_->setInsertPolicy(QComboBox::NoInsert);
    location_->addItems(recentDatabases());
    location_->setMinimumContentsLength(48);
    location_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    location_->setCurrentText(ShopDatabase::currentText());
    auto* browse = new QPushButton(QCoreApplication::translate("k528::studio::DatabaseUi", "File..."), this);
    browse->setObjectName("database.browse");
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString file = QFileDialog::getSaveFileName(
            this, QCoreApplication::translate("k528::studio::DatabaseUi", "Database file"), QFileInfo(location_->currentText()).absolutePath(),
            QCoreApplication::translate("k528::studio::DatabaseUi", "K528 Studio databases (*.db *.sqlite);;All files (*)"), nullptr,
            QFileDialog::DontConfirmOverwrite);
        if (!file.isEmpty())
            location_->setCurrentText(file);
    });
    auto* row = new QHBoxLayout;
    row->addWidget(location_, 1);
    row->addWidget(browse);
    error_ = new QLabel(this);
    error_->setObjectName("database.error");
    error_->setWordWrap(true);
    error_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    error_->setStyleSheet(QStringLiteral("color:#b00000;"));
    error_->hide();
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(QCoreApplication::translate("k528::studio::DatabaseUi", "Open"));
    connect(buttons, &QDialogButtonBox::accepted, this, &DatabaseDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(explain);
    layout->addLayout(row);
    layout->addWidget(error_);
    layout->addWidget(buttons);
    // The wrapped texts get the height they need at the dialog's width.
    setMinimumWidth(640);
    layout->setSizeConstraint(QLayout::SetMinimumSize);
    explain_ = explain;
    fitTexts();
}

void DatabaseDialog::fitTexts() {
    const int width = std::max(minimumWidth(), this->width()) - 2 * 12;
    explain_->setMinimumHeight(explain_->heightForWidth(width));
    if (error_->isVisible())
        error_->setMinimumHeight(error_->heightForWidth(width));
    adjustSize();
}

QString DatabaseDialog::location() const {
    return location_->currentText().trimmed();
}

void DatabaseDialog::setLocation(const QString& location) {
    location_->setCurrentText(location);
}

QString DatabaseDialog::error() const {
    return error_->isVisible() || !error_->text().isEmpty() ? error_->text() : QString();
}

void DatabaseDialog::accept() {
    const QString why = openDatabase(location());
    if (!why.isEmpty()) {
        error_->setText(why);
        error_->show();
        fitTexts();
        return;
    }
    error_->clear();
    QDialog::accept();
}

// Revisions made elsewhere.

QString RevisionElsewhere::text() const {
    return QCoreApplication::translate("k528::studio::DatabaseUi", "%1 changed on another PC: revision %2 by %3 at %4 (%5)")
        .arg(machine)
        .arg(revision)
        .arg(author, at, summary);
}

DatabaseWatch* DatabaseWatch::instance() {
    static DatabaseWatch* w = new DatabaseWatch(qApp);
    return w;
}

DatabaseWatch::DatabaseWatch(QObject* parent) : QObject(parent), timer_(new QTimer(this)) {
    timer_->setInterval(kPollMs);
    connect(timer_, &QTimer::timeout, this, &DatabaseWatch::check);
    timer_->start();
    QTimer::singleShot(0, this, &DatabaseWatch::check); // starts watching
}

void DatabaseWatch::restart() {
    watching_.clear();
    known_.clear();
    backoff_ = 0;
    check();
}

void DatabaseWatch::check() {
    if (backoff_ > 0) {
        --backoff_;
        return;
    }
    std::shared_ptr<ShopDatabase> shop;
    try {
        shop = ShopDatabase::at();
    } catch (const std::exception&) {
        backoff_ = kBackoffTicks; // the window says why where it uses the database
        return;
    }
    const QString where = QString::fromStdString(shop->location().text());
    std::vector<RevisionElsewhere> seen;
    try {
        const bool asked = shop->tryUse([&](db::Database& d) {
            const bool fresh = where != watching_;
            const bool changed = d.changedElsewhere();
            if (!fresh && !changed)
                return;
            std::map<std::string, int> now;
            for (const db::MachineInfo& m : d.machines())
                now[m.name] = m.revision;
            if (!fresh) {
                for (const auto& [name, revision] : now) {
                    const auto before = known_.find(name);
                    const int from = before == known_.end() ? 0 : before->second;
                    if (revision <= from)
                        continue;
                    for (const db::RevisionInfo& r : d.revisions(name)) {
                        if (r.revision <= from)
                            break;
                        if (shop->isOwn(name, r.revision))
                            continue;
                        seen.push_back({fromStd(name), r.revision, fromStd(r.author), fromStd(r.at),
                                        revisionNoteText(r.summary)});
                        break; // the newest one made elsewhere
                    }
                }
            }
            watching_ = where;
            known_ = std::move(now);
        });
        if (!asked)
            return; // a worker holds the connection: the next tick
    } catch (const std::exception&) {
        backoff_ = kBackoffTicks;
        return;
    }
    for (const RevisionElsewhere& r : seen)
        emit revision(r);
}

// The transfer log.

TransfersDialog::TransfersDialog(const QString& machine, QWidget* parent) : QDialog(parent) {
    setObjectName("dialog.transfers");
    setWindowTitle(QCoreApplication::translate("k528::studio::DatabaseUi", "Transfers"));
    machine_ = new QComboBox(this);
    machine_->setObjectName("transfers.machine");
    machine_->addItem(QCoreApplication::translate("k528::studio::DatabaseUi", "every machine"), QString());
    try {
        for (const db::MachineInfo& m : ShopDatabase::at()->use([](db::Database& d) { return d.machines(); }))
            machine_->addItem(fromStd(m.name), fromStd(m.name));
    } catch (const std::exception&) {
        // refresh() says why
    }
    machine_->setCurrentIndex(std::max(0, machine_->findData(machine)));
    table_ = new QTableWidget(0, 8, this);
    table_->setObjectName("transfers.table");
    table_->setHorizontalHeaderLabels({
        QCoreApplication::translate("k528::studio::DatabaseUi", "Time"),
        QCoreApplication::translate("k528::studio::DatabaseUi", "User"),
        QCoreApplication::translate("k528::studio::DatabaseUi", "PC"),
        QCoreApplication::translate("k528::studio::DatabaseUi", "Machine"),
        QCoreApplication::translate("k528::studio::DatabaseUi", "Controller"),
        QCoreApplication::translate("k528::studio::DatabaseUi", "Direction"),
        QCoreApplication::translate("k528::studio::DatabaseUi", "What moved"),
        QCoreApplication::translate("k528::studio::DatabaseUi", "Result"),
    });
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->verticalHeader()->hide();
    status_ = new QLabel(this);
    auto* row = new QHBoxLayout;
    row->addWidget(new QLabel(QCoreApplication::translate("k528::studio::DatabaseUi", "Machine:"), this));
    row->addWidget(machine_);
    row->addStretch(1);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(row);
    layout->addWidget(table_, 1);
    layout->addWidget(status_);
    layout->addWidget(buttons);
    connect(machine_, &QComboBox::currentIndexChanged, this, &TransfersDialog::refresh);
    resize(900, 420);
    refresh();
}

void TransfersDialog::refresh() {
    std::vector<db::TransferEntry> log;
    db::TransferFilter f;
    f.machine = machine_->currentData().toString().toStdString();
    try {
        log = ShopDatabase::at()->use([&](db::Database& d) { return d.transfers(f); });
    } catch (const std::exception& e) {
        status_->setText(databaseErrorText(e));
        table_->setRowCount(0);
        return;
    }
    table_->setRowCount(static_cast<int>(log.size()));
    for (int i = 0; i < static_cast<int>(log.size()); ++i) {
        const db::TransferEntry& t = log[static_cast<std::size_t>(i)];
        QStringList moved;
        for (const db::TransferItem& item : t.items)
            moved << (item.kind == "program" ? QStringLiteral("L%1").arg(item.number) : fromStd(item.kind).toUpper()) +
                         QStringLiteral(" ") + fromStd(item.crc32) + QStringLiteral(" ") + fromStd(item.state);
        const QString direction = t.direction == "push"
                                      ? QCoreApplication::translate("k528::studio::DatabaseUi", "push")
                                      : QCoreApplication::translate("k528::studio::DatabaseUi", "pull");
        const QString result = t.result == "ok"        ? QCoreApplication::translate("k528::studio::DatabaseUi", "ok")
                               : t.result == "partial" ? QCoreApplication::translate("k528::studio::DatabaseUi", "partial")
                                                       : QCoreApplication::translate("k528::studio::DatabaseUi", "failed");
        const QStringList cells = {fromStd(t.at),         fromStd(t.user),      fromStd(t.host),
                                   fromStd(t.machine),    fromStd(t.controller), direction,
                                   moved.join(QStringLiteral(", ")), result};
        for (int c = 0; c < cells.size(); ++c)
            table_->setItem(i, c, new QTableWidgetItem(cells[c]));
        table_->item(i, 7)->setToolTip(fromStd(t.detail));
    }
    table_->resizeColumnsToContents();
    status_->setText(QCoreApplication::translate("k528::studio::DatabaseUi", "%1 transfers").arg(log.size()));
}

void installDatabaseUi(QMainWindow* window, QMenu* fileMenu, QAction* before) {
    auto* action = new QAction(window);
    action->setObjectName("action.database");
    fileMenu->insertAction(before, action);
    auto* transfers = new QAction(window);
    transfers->setObjectName("action.transfers");
    fileMenu->insertAction(before, transfers);
    QObject::connect(transfers, &QAction::triggered, window, [window] {
        // The window's machine first (the filter offers every machine).
        auto* d = new TransfersDialog(window->property("k528.machineName").toString(), window);
        d->setAttribute(Qt::WA_DeleteOnClose);
        d->show();
    });
    auto* label = new DatabaseLabel(window);
    window->statusBar()->addPermanentWidget(label);
    struct Texts : QObject {
        QAction* action;
        QAction* transfers;
        Texts(QObject* parent, QAction* a, QAction* t) : QObject(parent), action(a), transfers(t) {
            parent->installEventFilter(this);
            retranslate();
        }
        void retranslate() {
            action->setText(QCoreApplication::translate("k528::studio::DatabaseUi", "&Database..."));
            transfers->setText(QCoreApplication::translate("k528::studio::DatabaseUi", "&Transfers..."));
        }
        bool eventFilter(QObject*, QEvent* e) override {
            if (e->type() == QEvent::LanguageChange)
                retranslate();
            return false;
        }
    };
    new Texts(window, action, transfers);
    QObject::connect(action, &QAction::triggered, window, [window] {
        DatabaseDialog dialog(window);
        dialog.exec();
    });
    DatabaseWatch* watch = DatabaseWatch::instance();
    QObject::connect(watch, &DatabaseWatch::switched, label, [window, label](const QString& where) {
        label->refresh();
        window->setWindowTitle(databaseWindowTitle());
        window->statusBar()->showMessage(QCoreApplication::translate("k528::studio::DatabaseUi", "Database %1 open").arg(where), 10000);
    });
    QObject::connect(watch, &DatabaseWatch::revision, window, [window](const RevisionElsewhere& r) {
        window->statusBar()->showMessage(r.text(), 30000);
    });
}

} // namespace k528::studio
