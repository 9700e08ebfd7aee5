// The shop's poller (docs/shop.md): one worker thread per line, each with
// its own plugin client, reading the live state every interval, so a slow or
// dead line never holds up another one nor the caller. A Modbus TCP machine
// is a line of its own (a connection each, also behind one gateway); the
// machines of one serial port (an RS485 bus, stations by address) share its
// worker and are asked in turn. Used by `k528 shop` (k528-link) and meant for the studio's
// shop view. The results go to a sink called on the worker threads.
#pragma once

#include "link/client.h"
#include "link_plugins.h"
#include "profile/line.h"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

class QThread;

namespace k528::shop {

struct LineRef {
    std::string machine;
    profile::LineAddress address;
};

struct PollResult {
    std::size_t index = 0; // of the line in the poller's list
    bool online = false;
    link::LiveState live;
    std::string why; // offline: why (English, as --json and MQTT say it)
    link::Said said; // the same, said by core's link catalog (the desktop's tr())
    std::int64_t atMs = 0; // when the answer came (ms since the Unix epoch)
    double roundTripMs = 0;
};

// The plugin settings of a line; `timeoutMs` for an answer to begin.
linkplugin::LineSettings lineSettings(const profile::LineAddress& a, int timeoutMs);

std::int64_t unixMsNow();

class Poller {
public:
    // Finds the plugins the lines need; `error` says which is missing.
    Poller(std::vector<LineRef> lines, int timeoutMs, QString& error);
    ~Poller();
    bool ok() const { return ok_; }
    const std::vector<LineRef>& lines() const { return lines_; }

    // One poll of every line at once (a thread each); results in line order.
    std::vector<PollResult> pollOnce();

    // Polls every line every `intervalMs` until stop(); `sink` gets each
    // result on the line's worker thread.
    void start(int intervalMs, std::function<void(const PollResult&)> sink);
    void stop();

private:
    struct Worker;
    void pollWorker(Worker& w, const std::function<void(const PollResult&)>& sink);
    std::vector<LineRef> lines_;
    int timeoutMs_;
    bool ok_ = true;
    std::vector<linkplugin::LinkPlugin*> plugins_; // per line
    std::vector<std::unique_ptr<Worker>> workers_;
    std::vector<QThread*> threads_;
    std::atomic<bool> stopping_{false};
    std::mutex m_;
    std::condition_variable cv_;
};

} // namespace k528::shop
