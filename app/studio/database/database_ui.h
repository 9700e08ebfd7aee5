// The shop's database in the window: *File > Database…* (a path, `sqlite:PATH`
// or a libpq URI `postgresql://…`; a password never: ~/.pgpass, PGPASSFILE or
// a service file), the database named in the title and the status bar, and
// other PCs' revisions seen live (DatabaseWatch: PostgreSQL LISTEN/NOTIFY,
// SQLite's PRAGMA data_version, checked on a timer of kPollMs, never per
// frame). Every access goes through the process's connection (ShopDatabase).
#pragma once

#include <QDialog>
#include <QObject>
#include <QString>
#include <QStringList>
#include <exception>
#include <map>
#include <mutex>
#include <set>
#include <string>

class QComboBox;
class QLabel;
class QMainWindow;
class QMenu;
class QAction;
class QTimer;

namespace k528::studio {

// The reason a database cannot be opened, in the window's language (the
// server's or the file's own words after it).
QString databaseOpenError(const QString& location, const std::exception& e);

// Opens `location` and makes it the window's database (ShopDatabase::choose),
// remembered for the next start. Returns "" or why not; the database open
// before stays the window's then.
QString openDatabase(const QString& location);

// The database to start with: `commandLine` (--db) if given, else $K528_DB
// if set, else the one chosen last time (when it still opens; else the
// default and `warning` says why).
void chooseStartDatabase(const QString& commandLine, QString* warning = nullptr);

// The databases chosen before, newest first.
QStringList recentDatabases();

// *File > Database…*: the location, the recent ones, a file to browse for.
class DatabaseDialog : public QDialog {
    Q_OBJECT
public:
    explicit DatabaseDialog(QWidget* parent = nullptr);
    QString location() const;
    void setLocation(const QString& location);
    // OK: opens the location; a failure is said in the dialog, which stays.
    void accept() override;
    QString error() const;

private:
    void fitTexts();
    QLabel* explain_;
    QComboBox* location_;
    QLabel* error_;
};

// A revision made by another process or PC.
struct RevisionElsewhere {
    QString machine;
    int revision = 0;
    QString author, at, summary;
    QString text() const; // for the status bar, in the window's language
};

class DatabaseWatch : public QObject {
    Q_OBJECT
public:
    static constexpr int kPollMs = 1000;
    static DatabaseWatch* instance();

public slots:
    // Looks once now (the timer does it every kPollMs).
    void check();

signals:
    // Another database was chosen (File > Database…).
    void switched(const QString& location);
    void revision(const k528::studio::RevisionElsewhere& r);

private:
    explicit DatabaseWatch(QObject* parent);
    void restart();
    friend QString openDatabase(const QString&);

    QTimer* timer_;
    QString watching_;                    // the location whose revisions are known
    std::map<std::string, int> known_;    // machine -> revision seen
    int backoff_ = 0;                     // ticks to skip after the database failed
};

// Adds *Database…* to `fileMenu` before `before`, the database's name to the
// status bar and other PCs' revisions as status messages.
void installDatabaseUi(QMainWindow* window, QMenu* fileMenu, QAction* before);
// "K528 Studio — <database>", in the window's language.
QString databaseWindowTitle();

} // namespace k528::studio

class QTableWidget;

namespace k528::studio {

// *File > Transfers…*: the transfer log of the window's database (time,
// user, PC, machine, controller, direction, what moved, result), newest
// first, for one machine or all.
class TransfersDialog : public QDialog {
    Q_OBJECT
public:
    explicit TransfersDialog(const QString& machine, QWidget* parent = nullptr);
    QTableWidget* table() const { return table_; }
    QComboBox* machineFilter() const { return machine_; }
    // Reads the log again (the filter's machine; "" all).
    void refresh();

private:
    QComboBox* machine_;
    QTableWidget* table_;
    QLabel* status_;
};

} // namespace k528::studio
