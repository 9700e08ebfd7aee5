#include "history/history_service.h"

#include "controller/controller.h"
#include "controller/simulated_machine.h"
#include "machine/simulation.h"
#include "session/shop_database.h"

#include <QDateTime>
#include <filesystem>

namespace k528::studio {

namespace {

// The name of a real controller's runs: its machine, where it is on the line.
QString runName(const Controller& c) {
    return QString::fromStdString(c.profile().name) + QStringLiteral(" @ ") + c.where();
}

} // namespace

HistoryService::HistoryService(Controller* controller, const QString& path, QObject* parent)
    : QObject(parent), controller_(controller) {
    try {
        shop_ = ShopDatabase::atText(path);
        path_ = QString::fromStdString(shop_->location().text());
        shop_->useLog([](db::MessageLog&) {}); // schema 2 or an error now
    } catch (const std::exception& e) {
        error_ = databaseErrorText(e);
        shop_.reset();
    }
    if (!controller_)
        return;
    sim_ = controller_->simulated();
    machine_ = sim_ ? QString::fromStdString(sim_->simulation().profile().name) : runName(*controller_);
    if (shop_) {
        try {
            run_ = shop_->useLog([&](db::MessageLog& log) {
                return log.beginRun(machine_.toStdString(), QDateTime::currentMSecsSinceEpoch());
            });
        } catch (const std::exception& e) {
            error_ = databaseErrorText(e);
            shop_.reset();
        }
    }
    sinceFlush_.start();
    if (sim_) {
        recorder_ = std::make_unique<msglog::Recorder>(sim_->simulation().controller());
        msglog::Recorder* rec = recorder_.get();
        observer_ = sim_->simulation().addTickObserver([rec] { rec->observe(); });
        connect(controller_, &Controller::updated, this, &HistoryService::advanced);
        connect(sim_->lifetime(), &QObject::destroyed, this, [this] { forgetController(); });
        recorder_->observe(); // what the machine shows already (the power-on self-test)
        advanced();
        return;
    }
    // A real controller: what its views show, at each poll, in the PC's time.
    recorder_ = std::make_unique<msglog::Recorder>(controller_->profile(), controller_->state().words.word(1000));
    linkClock_.start();
    connect(controller_, &Controller::updated, this, &HistoryService::observeLink);
    connect(controller_, &QObject::destroyed, this, [this] { forgetController(); });
    observeLink();
}

HistoryService::~HistoryService() {
    if (sim_)
        sim_->simulation().removeTickObserver(observer_);
    if (controller_)
        disconnect(controller_, nullptr, this, nullptr);
    flush();
}

void HistoryService::forgetController() {
    // The controller is gone: keep what was seen, touch nothing of it.
    sim_ = nullptr;
    controller_ = nullptr;
    if (recorder_)
        recorder_->stampDayTime(QDateTime::currentMSecsSinceEpoch(), speed_);
    flush();
}

void HistoryService::observeLink() {
    if (!recorder_ || !controller_ || sim_)
        return;
    const ControllerState& s = controller_->state();
    if (!s.connected) // a lost line shows nothing new: its messages are not gone
        return;
    msglog::Observation o;
    o.timeMs = linkClock_.elapsed();
    o.z1000 = s.words.word(1000);
    o.alarms = s.alarms;
    o.plc = s.plcMessages;
    o.program = s.program;
    recorder_->observe(o);
    advanced();
}

void HistoryService::advanced() {
    if (!recorder_ || !controller_)
        return;
    speed_ = sim_ ? sim_->speed() : 1.0;
    recorder_->stampDayTime(QDateTime::currentMSecsSinceEpoch(), speed_);
    if (!recorder_->pending().empty() && sinceFlush_.elapsed() >= kFlushMs)
        flush();
}

void HistoryService::flush() {
    sinceFlush_.restart();
    if (!recorder_ || !shop_ || (recorder_->pending().empty() && retry_.empty()))
        return;
    if (controller_)
        recorder_->stampDayTime(QDateTime::currentMSecsSinceEpoch(), sim_ ? sim_->speed() : 1.0);
    std::vector<db::MessageEvent> events = std::move(retry_);
    retry_.clear();
    std::vector<db::MessageEvent> more = recorder_->takeEvents();
    events.insert(events.end(), std::make_move_iterator(more.begin()),
                  std::make_move_iterator(more.end()));
    try {
        shop_->useLog([&](db::MessageLog& log) { log.write(run_, events); });
        failedOnce_ = false;
        emit written();
    } catch (const std::exception& e) {
        // Kept in front of anything newer for the next try: nothing is lost.
        if (!failedOnce_)
            emit failed(databaseErrorText(e));
        failedOnce_ = true;
        retry_ = std::move(events);
    }
}

void HistoryService::acknowledge() {
    if (!sim_)
        return;
    if (recorder_)
        recorder_->noteAcknowledgement("esc-dock");
    sim_->simulation().controller().escape();
    if (recorder_)
        recorder_->observe();
    sim_->showNow(); // the views (the K923 too) show it at once
    flush();
}

} // namespace k528::studio
