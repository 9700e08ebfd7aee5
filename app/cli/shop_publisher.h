// The shop's MQTT publisher (docs/shop.md, the contract of the topics): the
// publisher's own retained status at k528/_publisher/<client id> — a hello
// on start, a goodbye on stop, and a last will that marks it offline when it
// is gone without one —, each machine's state, retained, at
// k528/<machine>/state when it changed, and each alarm raised or cleared at
// k528/<machine>/alarms. One implementation for `k528 shop publish`
// (cmd_shop_qt.cpp) and the studio's Shop view (its setting *Publish to MQTT*).
#pragma once

#include "mqtt_client.h"
#include "shop/state.h"

#include <cstdint>
#include <string>
#include <vector>

namespace k528::shop {

class MqttPublisher {
public:
    // "<prefix>-<host>-<pid>": a client id no other publisher of this PC has.
    static std::string defaultClientId(const std::string& prefix);

    // Connects to mqtt://HOST[:PORT] (waits up to `waitMs` for the broker)
    // with the will, then publishes the hello naming `machines`. false with
    // `error` set. Blocks: the studio calls it off the window's thread.
    bool start(const std::string& url, const std::string& clientId, int intervalMs,
               const std::vector<std::string>& machines, std::string& error, int waitMs = 5000);
    // One poll's outcome of a machine (shop::Tracker::update): its state
    // when `changed`, and each alarm event. Does not wait for the broker.
    // false with `error` when a message was refused.
    bool publish(const MachineState& s, bool changed, const std::vector<AlarmEvent>& events, std::int64_t nowMs,
                 std::string& error);
    // The goodbye, then waits up to `flushMs` until the broker acknowledged
    // everything, and disconnects (no will). false when something was not
    // acknowledged. Blocks.
    bool stop(int flushMs = 3000);

    bool started() const { return started_; }
    bool connected() const { return mq_.connected(); }
    long published() const { return mq_.published(); }
    const std::string& clientId() const { return clientId_; }
    const std::string& publisherTopic() const { return publisherTopic_; }

private:
    mqtt::Publisher mq_;
    std::string clientId_;
    std::string publisherTopic_;
    bool started_ = false;
};

} // namespace k528::shop
