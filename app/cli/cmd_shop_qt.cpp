// k528 shop status|publish (cli.md, docs/shop.md), the Qt half: k528 reads
// the database (cmd_shop.cpp) and runs this with one `--line MACHINE=LINE`
// per machine. status polls every line once, at once (one worker a line),
// and prints a line (or a JSON object) per machine; --watch keeps polling and
// prints each change. publish keeps polling and publishes each machine's
// state, retained, to k528/<machine>/state and each alarm raised or cleared
// to k528/<machine>/alarms over MQTT (libmosquitto), with a last will.
#include "catalog/messages.h"
#include "cli.h"
#include "link_line.h"
#include "mqtt_client.h"
#include "shop_publisher.h"
#include "profile/line.h"
#include "db/state_times.h"
#include "shop/state.h"
#include "shop/state_time.h"
#include "shop_poll.h"
#include "util/json.h"

#include <QThread>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <mutex>
#include <optional>
#include <unistd.h>

namespace k528::cli {

namespace {

std::string clockOf(std::int64_t unixMs) { return shop::localTimeText(unixMs, "%H:%M:%S"); }

std::string stateText(const shop::MachineState& s, std::int64_t nowMs) {
    char head[160];
    std::snprintf(head, sizeof head, "%-16s %-7s %-8s", s.machine.c_str(), s.online ? "online" : "offline",
                  shop::activityName(s.activity));
    std::string t = head;
    if (s.online) {
        const link::LiveState& l = s.live;
        t += " F" + std::to_string(l.mode) + (l.pcReady ? " (РАБОТА С ПЭВМ)" : "") + ", program " +
             std::to_string(l.program) + " N" + std::to_string(l.frame);
        for (int n : l.alarms) {
            t += "; alarm " + std::to_string(n);
            if (const catalog::PositionerMessage* m = catalog::findPositionerMessage(n))
                t += " «" + std::string(m->textRu) + "»";
        }
    } else {
        t += " " + s.why;
    }
    char since[80];
    std::snprintf(since, sizeof since, "; since %s (%.1f s)", clockOf(s.sinceMs).c_str(),
                  static_cast<double>(nowMs - s.sinceMs) / 1000.0);
    return t + since + "; " + s.line;
}

bool outputLost() {
    if (std::fflush(stdout) == 0 && !std::ferror(stdout))
        return false;
    std::fprintf(stderr, "k528: cannot write standard output\n");
    std::clearerr(stdout);
    return true;
}

// The polls of every worker, handed to the main thread in order of arrival.
class Inbox {
public:
    void put(const shop::PollResult& r) {
        {
            std::lock_guard lock(m_);
            q_.push_back(r);
        }
        cv_.notify_one();
    }
    // Waits up to `ms` for results; returns what came.
    std::deque<shop::PollResult> take(int ms) {
        std::unique_lock lock(m_);
        cv_.wait_for(lock, std::chrono::milliseconds(ms), [this] { return !q_.empty(); });
        std::deque<shop::PollResult> out;
        out.swap(q_);
        return out;
    }

private:
    std::mutex m_;
    std::condition_variable cv_;
    std::deque<shop::PollResult> q_;
};

struct Options {
    std::vector<shop::LineRef> lines;
    std::vector<std::string> lineTexts;
    int timeoutMs = 200;
    int intervalMs = 1000;
    double seconds = -1;
};

} // namespace

int runShopQt(std::span<const std::string> argv) {
    const Args args(argv, {"--json", "--watch"},
                    {"--line", "--timeout-ms", "--interval-ms", "--seconds", "--mqtt", "--client-id", "--db"});
    if (!args.ok())
        return usageError(args.error());
    if (args.positional().size() != 1 || (args.positional()[0] != "status" && args.positional()[0] != "publish"))
        return usageError("shop takes status or publish");
    const bool publish = args.positional()[0] == "publish";
    Options o;
    for (const std::string& item : args.values("--line")) {
        const std::size_t eq = item.find('=');
        if (eq == std::string::npos || eq == 0)
            return usageError("--line takes MACHINE=LINE, not '" + item + "'");
        std::string error;
        const auto a = profile::parseLine(item.substr(eq + 1), error);
        if (!a)
            return usageError("machine " + item.substr(0, eq) + ": " + error);
        o.lines.push_back({item.substr(0, eq), *a});
        o.lineTexts.push_back(profile::formatLine(*a));
    }
    if (const auto t = args.value("--timeout-ms")) {
        const auto v = parseInt(*t);
        if (!v || *v < 10 || *v > 60000)
            return usageError("--timeout-ms takes 10..60000");
        o.timeoutMs = static_cast<int>(*v);
    }
    if (const auto t = args.value("--interval-ms")) {
        const auto v = parseInt(*t);
        if (!v || *v < 10 || *v > 3600000)
            return usageError("--interval-ms takes 10..3600000");
        o.intervalMs = static_cast<int>(*v);
    }
    if (const auto t = args.value("--seconds")) {
        const auto v = parseNumber(*t);
        if (!v || *v < 0)
            return usageError("--seconds takes a duration in seconds");
        o.seconds = *v;
    }
    const bool asJson = args.has("--json");
    const bool watch = args.has("--watch");
    if (!publish && args.value("--mqtt"))
        return usageError("--mqtt is an option of shop publish");
    if (publish && !args.value("--mqtt"))
        return usageError("shop publish needs --mqtt mqtt://HOST[:PORT]");
    if (!publish && !watch && (args.value("--interval-ms") || args.value("--seconds")))
        return usageError("--interval-ms and --seconds go with shop status --watch or shop publish");

    QString perror;
    shop::Poller poller(o.lines, o.timeoutMs, perror);
    if (!poller.ok()) {
        std::fprintf(stderr, "k528 shop: %s\n", perror.toUtf8().constData());
        return ExitUsage;
    }
    std::vector<shop::Tracker> trackers;
    for (std::size_t i = 0; i < o.lines.size(); ++i)
        trackers.emplace_back(o.lines[i].machine, o.lineTexts[i]);

    if (!publish && !watch) {
        const std::vector<shop::PollResult> results = poller.pollOnce();
        Json all = Json::array();
        for (const shop::PollResult& r : results) {
            std::vector<shop::AlarmEvent> events;
            trackers[r.index].update(r.online ? &r.live : nullptr, r.why, r.atMs, events);
            const shop::MachineState& s = trackers[r.index].state();
            if (asJson)
                all.push_back(shop::stateJson(s, r.atMs));
            else
                std::printf("%s\n", stateText(s, r.atMs).c_str());
        }
        if (asJson)
            std::printf("%s\n", json::dump(all).c_str());
        return outputLost() ? ExitUsage : ExitOk;
    }

    // Continuous: status --watch prints, publish publishes.
    shop::MqttPublisher mq;
    if (publish) {
        std::string error;
        std::string clientId = args.value("--client-id").value_or("");
        if (clientId.empty())
            clientId = shop::MqttPublisher::defaultClientId("k528-shop");
        if (!mqtt::parseUrl(*args.value("--mqtt"), error))
            return usageError("--mqtt: " + error);
        std::vector<std::string> names;
        for (const auto& l : o.lines)
            names.push_back(l.machine);
        if (!mq.start(*args.value("--mqtt"), clientId, o.intervalMs, names, error)) {
            std::fprintf(stderr, "k528 shop publish: cannot connect to %s: %s\n", args.value("--mqtt")->c_str(),
                         error.c_str());
            return ExitUsage;
        }
        std::fprintf(stderr, "k528 shop publish: %zu machines every %d ms to %s as %s\n", o.lines.size(),
                     o.intervalMs, args.value("--mqtt")->c_str(), clientId.c_str());
    }
    // Each machine's time in each state, added to the database's record
    // (source shop@HOST) once a minute, when a state changes and at the end.
    std::optional<db::Database> times;
    const db::Lang lang = russianCommandLine() ? db::Lang::Ru : db::Lang::En;
    const char* const timesNotKept = lang == db::Lang::Ru
                                         ? "k528 shop: время станков в каждом состоянии не записывается: %s\n"
                                         : "k528 shop: the time in each state is not kept: %s\n";
    if (const auto where = args.value("--db")) {
        try {
            times.emplace(db::Database::open(db::Location::parse(*where)));
        } catch (const db::Error& e) {
            std::fprintf(stderr, timesNotKept, e.text(lang).c_str());
        } catch (const std::exception& e) {
            std::fprintf(stderr, timesNotKept, e.what());
        }
    }
    char host[256] = {};
    if (::gethostname(host, sizeof host - 1) != 0 || !host[0])
        std::snprintf(host, sizeof host, "unknown");
    const std::string timesSource = std::string("shop@") + host;
    shop::StateTally tally;
    std::vector<std::int64_t> lastPoll(trackers.size(), 0);
    bool timesSaid = false;
    const auto writeTimes = [&](std::int64_t now) {
        tally.due(now);
        if (!times || tally.empty())
            return;
        const auto rows = tally.take(now);
        std::vector<db::StateTime> out;
        for (const auto& r : rows)
            out.push_back({r.machine, r.day, timesSource, r.state, r.ms, {}});
        try {
            db::addStateTimes(*times, out);
        } catch (const db::Error& e) {
            if (e.kind() == db::ErrorKind::Busy || e.kind() == db::ErrorKind::Io)
                tally.putBack(rows); // the next minute
            if (!timesSaid)
                std::fprintf(stderr, timesNotKept, e.text(lang).c_str());
            timesSaid = true;
        }
    };
    installStopSignals();
    Inbox inbox;
    poller.start(o.intervalMs, [&inbox](const shop::PollResult& r) { inbox.put(r); });
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    int code = ExitOk;
    std::string error;
    while (!stopRequested() && (o.seconds < 0 || elapsed() < o.seconds)) {
        for (const shop::PollResult& r : inbox.take(50)) {
            std::vector<shop::AlarmEvent> events;
            const shop::Activity before = trackers[r.index].state().activity;
            if (trackers[r.index].state().polled && lastPoll[r.index] > 0)
                tally.add(trackers[r.index].state().machine, shop::localDay(r.atMs), before,
                          r.atMs - lastPoll[r.index]);
            lastPoll[r.index] = r.atMs;
            const bool changed = trackers[r.index].update(r.online ? &r.live : nullptr, r.why, r.atMs, events);
            const shop::MachineState& s = trackers[r.index].state();
            if (s.activity != before)
                tally.changed();
            if (publish) {
                if (!mq.publish(s, changed, events, r.atMs, error))
                    std::fprintf(stderr, "k528 shop publish: %s: %s\n", s.machine.c_str(), error.c_str());
            } else {
                if (changed)
                    std::printf("%s\n", asJson ? json::dump(shop::stateJson(s, r.atMs)).c_str()
                                               : stateText(s, r.atMs).c_str());
                for (const shop::AlarmEvent& e : events)
                    if (!asJson)
                        std::printf("%s alarm %d %s at %s\n", s.machine.c_str(), e.number,
                                    e.raised ? "raised" : "cleared", clockOf(e.atMs).c_str());
                    else
                        std::printf("%s\n", json::dump(shop::alarmJson(e)).c_str());
                if ((changed || !events.empty()) && outputLost()) {
                    poller.stop();
                    writeTimes(shop::unixMsNow());
                    return ExitUsage;
                }
            }
        }
        if (tally.due(shop::unixMsNow()))
            writeTimes(shop::unixMsNow());
    }
    poller.stop();
    writeTimes(shop::unixMsNow());
    if (publish) {
        if (!mq.stop(3000)) {
            std::fprintf(stderr, "k528 shop publish: the broker did not acknowledge every message\n");
            code = ExitUsage;
        }
        std::fprintf(stderr, "k528 shop publish: stopped after %ld messages\n", mq.published());
    }
    return code;
}

} // namespace k528::cli
