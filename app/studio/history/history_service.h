// The desktop's half of the message history: the process's connection to the
// database (ShopDatabase: db::defaultDatabasePath(), or a given file), a run
// of one controller, and core's msglog::Recorder on it — on every tick of
// the simulated machine (SimulatedMachine), or on every poll of a real
// controller read over the link (what its views show: msglog::Observation,
// in the PC's time; its run is named "<machine> @ <port>#<address>"). On
// each update the events get the time of day (the desktop's clock; core
// never reads one) and are written in batches, at most every kFlushMs or at
// once after an acknowledgement. The history dock reads the same log.
#pragma once

#include "db/message_log.h"
#include "msglog/recorder.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <memory>
#include <string>
#include <vector>

namespace k528::studio {

class Controller;
class ShopDatabase;
class SimulatedMachine;

class HistoryService : public QObject {
    Q_OBJECT
public:
    static constexpr int kFlushMs = 500;

    // Opens the database at `path` (a file or a URI; "": the window's,
    // ShopDatabase::current()); with a
    // controller, records its messages (while it lives). A database that
    // cannot be used is told by error() and nothing is recorded (a damaged
    // file is never changed).
    explicit HistoryService(Controller* controller, const QString& path = {},
                            QObject* parent = nullptr);
    ~HistoryService() override;

    bool isOpen() const { return shop_ != nullptr; }
    QString error() const { return error_; }
    QString databasePath() const { return path_; }
    // The connection whose message log this records (nullptr: none).
    ShopDatabase* shop() const { return shop_.get(); }
    // The machine recorded ("" without a session).
    QString machine() const { return machine_; }
    std::int64_t runId() const { return run_; }
    const msglog::Recorder* recorder() const { return recorder_.get(); }
    // The controller recorded (nullptr once it is gone).
    Controller* controller() const { return controller_; }
    // ESC can be given (the simulated machine; a real one's ESC is its K923's).
    bool canAcknowledge() const { return sim_ != nullptr; }

public slots:
    // ESC from the dock: the controller's escape() (C123..C125), as the K923 does.
    void acknowledge();
    // Writes what is pending now.
    void flush();

signals:
    // New or changed rows were written.
    void written();
    // Writing failed (said once; the events stay pending for the next try).
    void failed(const QString& message);

private:
    void advanced();
    void observeLink();
    void forgetController();

    Controller* controller_ = nullptr;
    SimulatedMachine* sim_ = nullptr;
    QElapsedTimer linkClock_; // a real controller's time: ms since the run began
    QString path_, machine_, error_;
    std::shared_ptr<ShopDatabase> shop_;
    std::unique_ptr<msglog::Recorder> recorder_;
    std::int64_t run_ = 0;
    int observer_ = 0;
    std::vector<db::MessageEvent> retry_; // a batch that could not be written yet
    QElapsedTimer sinceFlush_;
    bool failedOnce_ = false;
    double speed_ = 1.0;
};

} // namespace k528::studio
