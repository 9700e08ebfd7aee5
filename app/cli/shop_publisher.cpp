#include "shop_publisher.h"

#include "shop_poll.h"
#include "util/json.h"

#include <QHostInfo>
#include <unistd.h>

namespace k528::shop {

std::string MqttPublisher::defaultClientId(const std::string& prefix) {
    return prefix + "-" + QHostInfo::localHostName().toStdString() + "-" + std::to_string(::getpid());
}

bool MqttPublisher::start(const std::string& urlText, const std::string& clientId, int intervalMs,
                          const std::vector<std::string>& machines, std::string& error, int waitMs) {
    const auto url = mqtt::parseUrl(urlText, error);
    if (!url)
        return false;
    clientId_ = clientId;
    publisherTopic_ = "k528/_publisher/" + clientId_;
    Json will;
    will["online"] = false;
    will["client_id"] = clientId_;
    will["why"] = "the publisher is gone without a goodbye (its last will)";
    if (!mq_.connect(*url, clientId_, publisherTopic_, json::dump(will), error, waitMs))
        return false;
    Json hello;
    hello["online"] = true;
    hello["client_id"] = clientId_;
    hello["since"] = isoTime(unixMsNow());
    hello["interval_ms"] = intervalMs;
    Json names = Json::array();
    for (const std::string& m : machines)
        names.push_back(m);
    hello["machines"] = std::move(names);
    if (!mq_.publish(publisherTopic_, json::dump(hello), true, error))
        return false;
    started_ = true;
    return true;
}

bool MqttPublisher::publish(const MachineState& s, bool changed, const std::vector<AlarmEvent>& events,
                            std::int64_t nowMs, std::string& error) {
    if (!started_)
        return true;
    bool ok = true;
    if (changed && !mq_.publish("k528/" + s.machine + "/state", json::dump(stateJson(s, nowMs)), true, error))
        ok = false;
    for (const AlarmEvent& e : events)
        if (!mq_.publish("k528/" + s.machine + "/alarms", json::dump(alarmJson(e)), false, error))
            ok = false;
    return ok;
}

bool MqttPublisher::stop(int flushMs) {
    if (!started_)
        return true;
    started_ = false;
    Json bye;
    bye["online"] = false;
    bye["client_id"] = clientId_;
    bye["why"] = "stopped";
    bye["at"] = isoTime(unixMsNow());
    std::string error;
    mq_.publish(publisherTopic_, json::dump(bye), true, error);
    const bool flushed = mq_.flush(flushMs);
    mq_.disconnect();
    return flushed;
}

} // namespace k528::shop
