// The Shop workspace's page (object name "shopView"): every machine of the
// database that keeps its controller's line (shop/shop_machines.h), as a
// tile — its name and line, what it does (run, idle, alarm, offline) and
// since when, its mode, program and frame, its alarms with their texts, its
// last transfer on record —, the alarms raised and cleared since the view
// began polling, with their time, and a bar chart of today's time in each
// state per machine.
//
// The machines are polled by the shop's poller (app/cli/shop_poll.h, the
// one `k528 shop` uses: a worker thread per line) and tracked by core's
// shop::Tracker, so the window never waits for a line. The poller runs only
// while the page is shown (or while the studio publishes to MQTT); a tile
// redraws when its machine's state changed, the times once a second while
// shown. A click on a tile connects the Controller dock to that machine's
// line: every view of the window then shows it.
//
// *Publish to MQTT* (a setting, kept): the states and alarms go to an MQTT
// broker as `k528 shop publish` sends them (app/cli/shop_publisher.h, the
// same publisher), so an operator's PC feeds the shop's dashboard; the
// poller then runs whether the page is shown or not.
#pragma once

#include "link/link_texts.h"
#include "shop/shop_machines.h"
#include "shop/state.h"
#include "shop/state_time.h"

#include <QFrame>
#include <QHash>
#include <QWidget>
#include <array>
#include <atomic>
#include <memory>
#include <vector>

class QChart;
class QChartView;
class QScrollArea;
class QBarSet;
class QBarCategoryAxis;
class QValueAxis;
class QLabel;
class QPushButton;
class QTimer;
class QTreeWidget;
class QThread;
class QGroupBox;
class QCheckBox;
class QLineEdit;
class QSplitter;

namespace k528::shop {
class Poller;
struct PollResult;
class MqttPublisher;
} // namespace k528::shop

namespace k528::studio {

class MainWindow;

// One machine's tile (object name "shop.tile.<machine>").
class ShopTile : public QFrame {
    Q_OBJECT
public:
    ShopTile(const ShopMachine& machine, QWidget* parent);
    const QString& machine() const { return machine_; }
    // Shows `s` (only what changed is set again).
    void showState(const shop::MachineState& s, std::int64_t nowMs);
    // Why the line is offline, by the link's ids (said in the window's language).
    void setOfflineReason(const link::Said& why) { why_ = why; }
    // The time in this state at `nowMs`.
    void showTime(std::int64_t nowMs);
    void setLastTransfer(const QString& text);
    void setCurrent(bool current);
    void retranslate();
    // What the tile says, for tests and screenshots.
    QString stateText() const;
    QString modeText() const;
    QString alarmsText() const;
    // Why the line does not answer (the mode's tooltip), "" while it answers.
    QString offlineReason() const;

signals:
    void clicked(const QString& machine);

protected:
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    void setIf(QLabel* label, const QString& text);
    QString machine_;
    shop::MachineState state_;
    link::Said why_;
    bool shown_ = false;
    bool current_ = false;
    QString transfer_;
    QLabel* name_ = nullptr;
    QLabel* state_label_ = nullptr;
    QLabel* line_ = nullptr;
    QLabel* mode_ = nullptr;
    QLabel* program_ = nullptr;
    QLabel* alarms_ = nullptr;
    QLabel* since_ = nullptr;
    QLabel* transferLabel_ = nullptr;
    QString styleShown_;
};

class ShopView : public QWidget {
    Q_OBJECT
public:
    explicit ShopView(MainWindow* window);
    ~ShopView() override;

    ShopTile* tile(const QString& machine) const;
    std::vector<ShopTile*> tiles() const { return tiles_; }
    const shop::MachineState* state(const QString& machine) const;
    QTreeWidget* alarmList() const { return alarms_; }
    QChartView* chartView() const { return chartView_; }
    bool polling() const { return poller_ != nullptr; }
    // Publishing to MQTT: the check box, the broker's mqtt://HOST[:PORT].
    QCheckBox* publishBox() const { return publish_; }
    QLineEdit* brokerBox() const { return broker_; }
    bool publishing() const { return mqtt_ != nullptr; }
    QString publishState() const;
    // Today's milliseconds in each state (run, idle, alarm, offline) of `machine`.
    std::array<std::int64_t, 4> today(const QString& machine) const;
    // How often each line is polled.
    static constexpr int kIntervalMs = 250;
    static constexpr int kTimeoutMs = 200;

public slots:
    // The database's machines read again (the tiles rebuilt).
    void reload();
    // Starts or stops publishing to the broker the box names (connects off
    // the window's thread; publishingChanged() tells).
    void setPublishing(bool on);

signals:
    // A machine's state changed (after its tile shows it).
    void machineChanged(const QString& machine);
    // A poll came back (any machine).
    void polled();
    void publishingChanged(bool on);

protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void build();
    void retranslate();
    void startPolling();
    void stopPolling();
    void apply(const shop::PollResult& r);
    void tick();
    void updateChart(bool force = false);
    void readTransfers();
    void tileClicked(const QString& machine);
    void markCurrent();
    void setPublishState(const QString& text, const QString& detail = {});
    void retirePublisher(std::shared_ptr<shop::MqttPublisher> p);
    // Says the publisher's goodbye (retained offline) and waits for it: at
    // the end of the application's event loop and when the view goes.
    void goodbye();
    // Today's time in each state: this studio's record read from the
    // database (reload), and what was counted since written to it (once a
    // minute, when a state changes, when polling stops and at the end).
    void readStateTimes();
    void writeStateTimes();

    MainWindow* window_;
    std::vector<ShopMachine> machines_;
    std::vector<shop::Tracker> trackers_;
    std::vector<ShopTile*> tiles_;
    // Today (local day) per machine: ms in each activity, and the last poll.
    std::vector<std::array<std::int64_t, 4>> today_;
    std::vector<std::int64_t> lastPollMs_;
    qint64 day_ = 0; // the local day's Julian number
    shop::StateTally tally_;  // counted since the last write to the database
    std::string timesSource_; // "studio@HOST": this studio's rows of state_times
    std::unique_ptr<shop::Poller> poller_;
    std::shared_ptr<std::atomic<int>> generation_ = std::make_shared<std::atomic<int>>(0);
    std::vector<QThread*> retiring_; // pollers being stopped off the window's thread
    QString dbError_;
    QLabel* header_ = nullptr;
    QPushButton* reload_ = nullptr;
    QWidget* tileArea_ = nullptr;
    QGroupBox* alarmsBox_ = nullptr;
    QGroupBox* chartBox_ = nullptr;
    QTreeWidget* alarms_ = nullptr;
    QScrollArea* chartScroll_ = nullptr;
    QChartView* chartView_ = nullptr;
    QChart* chart_ = nullptr;
    std::array<QBarSet*, 4> sets_{};
    QBarCategoryAxis* machinesAxis_ = nullptr;
    QValueAxis* minutesAxis_ = nullptr;
    std::vector<std::array<int, 4>> chartShown_; // minutes shown per machine and state
    QTimer* clock_ = nullptr;
    QCheckBox* publish_ = nullptr;
    QLineEdit* broker_ = nullptr;
    QLabel* brokerCaption_ = nullptr;
    QLabel* publishState_ = nullptr;
    std::shared_ptr<shop::MqttPublisher> mqtt_;       // publishing
    std::shared_ptr<shop::MqttPublisher> connecting_; // connecting
    std::vector<QThread*> stopping_;                  // saying goodbye
    int publishKind_ = 0; // 0 off, 1 connecting, 2 on, 3 refused
    QString publishDetail_;
    QSplitter* split_ = nullptr;
    bool sized_ = false;
};

} // namespace k528::studio
