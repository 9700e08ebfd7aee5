// A small MQTT publisher over libmosquitto (docs/shop.md): connects to
// mqtt://HOST[:PORT] with a last will, publishes (QoS 1, retained or not)
// from any thread, reconnects by itself (libmosquitto's network thread), and
// says goodbye cleanly.
#pragma once

#include "util/system_texts.h"

#include <atomic>
#include <optional>
#include <string>

struct mosquitto;

namespace k528::mqtt {

struct Url {
    std::string host;
    int port = 1883;
};
// mqtt://HOST[:PORT]; nullopt with `error` (a mqtt.url-* text of
// util/system_texts.h) when it is not one.
std::optional<Url> parseUrl(const std::string& text, util::Message& error);
// The same with the error in English.
std::optional<Url> parseUrl(const std::string& text, std::string& error);

class Publisher {
public:
    Publisher();
    ~Publisher();
    Publisher(const Publisher&) = delete;
    Publisher& operator=(const Publisher&) = delete;

    // Connects and waits for the broker's answer (up to `waitMs`); the will
    // (retained, QoS 1) is what the broker publishes when this client is gone
    // without a goodbye. false with `error` set.
    bool connect(const Url& url, const std::string& clientId, const std::string& willTopic,
                 const std::string& willPayload, std::string& error, int waitMs = 5000);
    // QoS 1. false with `error` when libmosquitto refuses it (not when the
    // broker is away: it is then sent after the reconnection).
    bool publish(const std::string& topic, const std::string& payload, bool retain, std::string& error);
    // Waits until every message published so far is acknowledged (up to `waitMs`).
    bool flush(int waitMs);
    // Publishes nothing more; disconnects (no will).
    void disconnect();
    bool connected() const { return connected_; }
    long published() const { return published_; }

private:
    static void onConnect(mosquitto*, void* self, int rc);
    static void onDisconnect(mosquitto*, void* self, int rc);
    static void onPublish(mosquitto*, void* self, int mid);
    mosquitto* m_ = nullptr;
    std::atomic<bool> connected_{false};
    std::atomic<int> connackRc_{-1};
    std::atomic<long> published_{0}, acknowledged_{0};
    bool loopStarted_ = false;
};

} // namespace k528::mqtt
