#include "mqtt_client.h"

#include <mosquitto.h>

#include <chrono>
#include <mutex>
#include <thread>

namespace k528::mqtt {

namespace {

void initOnce() {
    static std::once_flag once;
    std::call_once(once, [] { mosquitto_lib_init(); });
}

bool waitFor(int ms, const auto& done) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
    while (!done()) {
        if (std::chrono::steady_clock::now() >= end)
            return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return true;
}

} // namespace

std::optional<Url> parseUrl(const std::string& text, std::string& error) {
    util::Message m;
    std::optional<Url> u = parseUrl(text, m);
    if (!u)
        error = util::systemText(m, false);
    return u;
}

std::optional<Url> parseUrl(const std::string& text, util::Message& error) {
    const std::string scheme = "mqtt://";
    if (text.rfind(scheme, 0) != 0) {
        error = util::message("mqtt.url-scheme", {text});
        return std::nullopt;
    }
    std::string rest = text.substr(scheme.size());
    if (!rest.empty() && rest.back() == '/')
        rest.pop_back();
    Url u;
    const std::size_t colon = rest.rfind(':');
    const bool v6 = !rest.empty() && rest.front() == '[';
    if (colon != std::string::npos && (!v6 || colon > rest.find(']'))) {
        const std::string port = rest.substr(colon + 1);
        int p = 0;
        for (char c : port) {
            if (c < '0' || c > '9' || p > 65535) {
                p = -1;
                break;
            }
            p = p * 10 + (c - '0');
        }
        if (port.empty() || p < 1 || p > 65535) {
            error = util::message("mqtt.url-port", {text});
            return std::nullopt;
        }
        u.port = p;
        rest = rest.substr(0, colon);
    }
    if (v6 && rest.size() >= 2 && rest.back() == ']')
        rest = rest.substr(1, rest.size() - 2);
    if (rest.empty() || rest.find_first_of("/?@ ") != std::string::npos) {
        error = util::message("mqtt.url-host", {text});
        return std::nullopt;
    }
    u.host = rest;
    return u;
}

Publisher::Publisher() { initOnce(); }

Publisher::~Publisher() {
    disconnect();
    if (m_)
        mosquitto_destroy(m_);
}

void Publisher::onConnect(mosquitto*, void* self, int rc) {
    auto* p = static_cast<Publisher*>(self);
    p->connackRc_ = rc;
    p->connected_ = rc == 0;
}

void Publisher::onDisconnect(mosquitto*, void* self, int) { static_cast<Publisher*>(self)->connected_ = false; }

void Publisher::onPublish(mosquitto*, void* self, int) { ++static_cast<Publisher*>(self)->acknowledged_; }

bool Publisher::connect(const Url& url, const std::string& clientId, const std::string& willTopic,
                        const std::string& willPayload, std::string& error, int waitMs) {
    m_ = mosquitto_new(clientId.c_str(), true, this);
    if (!m_) {
        error = "cannot create an MQTT client";
        return false;
    }
    mosquitto_int_option(m_, MOSQ_OPT_PROTOCOL_VERSION, MQTT_PROTOCOL_V311);
    mosquitto_connect_callback_set(m_, &Publisher::onConnect);
    mosquitto_disconnect_callback_set(m_, &Publisher::onDisconnect);
    mosquitto_publish_callback_set(m_, &Publisher::onPublish);
    mosquitto_reconnect_delay_set(m_, 1, 10, true);
    int rc = mosquitto_will_set(m_, willTopic.c_str(), static_cast<int>(willPayload.size()), willPayload.data(), 1, true);
    if (rc != MOSQ_ERR_SUCCESS) {
        error = std::string("the last will: ") + mosquitto_strerror(rc);
        return false;
    }
    rc = mosquitto_connect(m_, url.host.c_str(), url.port, 10);
    if (rc != MOSQ_ERR_SUCCESS) {
        error = rc == MOSQ_ERR_ERRNO ? std::string(mosquitto_strerror(rc)) : mosquitto_strerror(rc);
        return false;
    }
    rc = mosquitto_loop_start(m_);
    if (rc != MOSQ_ERR_SUCCESS) {
        error = std::string("the network thread: ") + mosquitto_strerror(rc);
        return false;
    }
    loopStarted_ = true;
    if (!waitFor(waitMs, [&] { return connackRc_.load() >= 0; })) {
        error = "the broker did not answer the connection within " + std::to_string(waitMs) + " ms";
        return false;
    }
    if (connackRc_ != 0) {
        error = std::string("the broker refused the connection: ") + mosquitto_connack_string(connackRc_);
        return false;
    }
    return true;
}

bool Publisher::publish(const std::string& topic, const std::string& payload, bool retain, std::string& error) {
    const int rc =
        mosquitto_publish(m_, nullptr, topic.c_str(), static_cast<int>(payload.size()), payload.data(), 1, retain);
    if (rc != MOSQ_ERR_SUCCESS && rc != MOSQ_ERR_NO_CONN) {
        error = mosquitto_strerror(rc);
        return false;
    }
    ++published_;
    return true;
}

bool Publisher::flush(int waitMs) {
    return waitFor(waitMs, [&] { return acknowledged_.load() >= published_.load() || !connected_; });
}

void Publisher::disconnect() {
    if (!m_ || !loopStarted_)
        return;
    mosquitto_disconnect(m_);
    mosquitto_loop_stop(m_, false);
    loopStarted_ = false;
    connected_ = false;
}

} // namespace k528::mqtt
