#include "history/history_service.h"

#include "session/shop_database.h"
#include "session/simulation_session.h"

#include <QDateTime>
#include <filesystem>

namespace k528::studio {

HistoryService::HistoryService(SimulationSession* session, const QString& path, QObject* parent)
    : QObject(parent), session_(session) {
    try {
        shop_ = ShopDatabase::at(std::filesystem::path(path.toStdString()));
        path_ = QString::fromStdString(shop_->path().string());
        shop_->useLog([](db::MessageLog&) {}); // schema 2 or an error now
    } catch (const std::exception& e) {
        error_ = databaseErrorText(e);
        shop_.reset();
    }
    if (!session_)
        return;
    machine_ = QString::fromStdString(session_->simulation().profile().name);
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
    recorder_ = std::make_unique<msglog::Recorder>(session_->controller());
    msglog::Recorder* rec = recorder_.get();
    observer_ = session_->simulation().addTickObserver([rec] { rec->observe(); });
    connect(session_, &SimulationSession::advanced, this, &HistoryService::advanced);
    connect(session_, &QObject::destroyed, this, [this] { forgetSession(); });
    sinceFlush_.start();
    recorder_->observe(); // what the machine shows already (the power-on self-test)
    advanced();
}

HistoryService::~HistoryService() {
    if (session_) {
        session_->simulation().removeTickObserver(observer_);
        disconnect(session_, nullptr, this, nullptr);
    }
    flush();
}

void HistoryService::forgetSession() {
    // The simulation is gone: keep what was seen, touch nothing of it.
    session_ = nullptr;
    if (recorder_)
        recorder_->stampDayTime(QDateTime::currentMSecsSinceEpoch(), speed_);
    flush();
}

void HistoryService::advanced() {
    if (!recorder_ || !session_)
        return;
    speed_ = session_->speed();
    recorder_->stampDayTime(QDateTime::currentMSecsSinceEpoch(), speed_);
    if (!recorder_->pending().empty() && sinceFlush_.elapsed() >= kFlushMs)
        flush();
}

void HistoryService::flush() {
    sinceFlush_.restart();
    if (!recorder_ || !shop_ || (recorder_->pending().empty() && retry_.empty()))
        return;
    if (session_)
        recorder_->stampDayTime(QDateTime::currentMSecsSinceEpoch(), session_->speed());
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
    if (!session_)
        return;
    if (recorder_)
        recorder_->noteAcknowledgement("esc-dock");
    session_->controller().escape();
    if (recorder_)
        recorder_->observe();
    session_->advance(0); // the views (the K923 too) show it at once
    flush();
}

} // namespace k528::studio
