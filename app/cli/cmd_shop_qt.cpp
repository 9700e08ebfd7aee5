// k528 shop status|publish (cli.md, docs/shop.md), the Qt half: k528 reads
// the database (cmd_shop.cpp) and runs this with one `--line MACHINE=LINE`
// per machine. status polls every line once, at once (one worker a line),
// and prints a line (or a JSON object) per machine; --watch keeps polling and
// prints each change. publish keeps polling and publishes each machine's
// state, retained, to k528/<machine>/state and each alarm raised or cleared
// to k528/<machine>/alarms over MQTT (libmosquitto), with a last will.
#include "catalog/messages.h"
#include "cli.h"
#include "cli_texts.h"
#include "link_line.h"
#include "mqtt_client.h"
#include "output_file.h"
#include "shop_publisher.h"
#include "profile/line.h"
#include "db/state_times.h"
#include "shop/state.h"
#include "shop/state_time.h"
#include "shop_poll.h"
#include "util/json.h"
#include "util/utf8.h"

#include <QThread>
#include <algorithm>
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

// `s` padded with blanks to `width` characters (UTF-8: a Russian word is
// wider in bytes than in characters).
std::string padded(std::string s, std::size_t width) {
    const std::size_t n = utf8::length(s);
    return n >= width ? s : s + std::string(width - n, ' ');
}

std::string activityWord(shop::Activity a) {
    switch (a) {
    case shop::Activity::Offline: return cliText("shop.offline");
    case shop::Activity::Alarm: return cliText("shop.alarm");
    case shop::Activity::Run: return cliText("shop.run");
    case shop::Activity::Idle: return cliText("shop.idle");
    }
    return cliText("shop.offline");
}

// One machine's state on a line in the command's language; `said` is why it is
// offline as core's link catalog says it (s.why is its English, for --json).
std::string stateText(const shop::MachineState& s, std::int64_t nowMs, const link::Said& said) {
    const bool ru = russianCommandLine();
    // Each column as wide as its longest word in this language.
    std::size_t onlineWidth = 0, activityWidth = 0;
    for (const std::string& w : {cliText("shop.online"), cliText("shop.offline")})
        onlineWidth = std::max(onlineWidth, utf8::length(w));
    for (shop::Activity a : {shop::Activity::Offline, shop::Activity::Alarm, shop::Activity::Run, shop::Activity::Idle})
        activityWidth = std::max(activityWidth, utf8::length(activityWord(a)));
    std::string t = padded(s.machine, 16) + " " +
                    padded(s.online ? cliText("shop.online") : cliText("shop.offline"), onlineWidth) + " " +
                    padded(activityWord(s.activity), activityWidth + 1);
    if (s.online) {
        const link::LiveState& l = s.live;
        // The mode is the panel's own name, Russian in either language (as core's link texts say it).
        t += cliText("shop.live", {std::to_string(l.mode), l.pcReady ? " (РАБОТА С ПЭВМ)" : "",
                                   std::to_string(l.program), std::to_string(l.frame)});
        for (int n : l.alarms) {
            t += cliText("shop.live-alarm", {std::to_string(n)});
            if (const catalog::PositionerMessage* m = catalog::findPositionerMessage(n))
                t += " «" + std::string(ru ? m->textRu : m->textEn) + "»";
        }
    } else {
        t += " " + (said.id.empty() ? s.why : link::render(said, ru));
    }
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.1f", static_cast<double>(nowMs - s.sinceMs) / 1000.0);
    return t + cliText("shop.since", {clockOf(s.sinceMs), seconds}) + "; " + s.line;
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
                    {"--line", "--timeout-ms", "--interval-ms", "--seconds", "--mqtt", "--client-id", "--db", "--lang"});
    if (!args.ok())
        return usageError(args.error());
    if (args.positional().size() != 1 || (args.positional()[0] != "status" && args.positional()[0] != "publish"))
        return usageError(cliText("shop.usage.sub"));
    const bool publish = args.positional()[0] == "publish";
    Options o;
    for (const std::string& item : args.values("--line")) {
        const std::size_t eq = item.find('=');
        if (eq == std::string::npos || eq == 0)
            return usageError(cliText("shop.usage.line", {item}));
        profile::Problem error;
        const auto a = profile::parseLine(item.substr(eq + 1), error);
        if (!a)
            return usageError(cliText("shop.usage.line-machine",
                                      {item.substr(0, eq), profile::problemText(error, russianCommandLine())}));
        o.lines.push_back({item.substr(0, eq), *a});
        o.lineTexts.push_back(profile::formatLine(*a));
    }
    if (const auto t = args.value("--timeout-ms")) {
        const auto v = parseInt(*t);
        if (!v || *v < 10 || *v > 60000)
            return usageError(cliText("opt.timeout"));
        o.timeoutMs = static_cast<int>(*v);
    }
    if (const auto t = args.value("--interval-ms")) {
        const auto v = parseInt(*t);
        if (!v || *v < 10 || *v > 3600000)
            return usageError(cliText("shop.usage.interval"));
        o.intervalMs = static_cast<int>(*v);
    }
    if (const auto t = args.value("--seconds")) {
        const auto v = parseNumber(*t);
        if (!v || *v < 0)
            return usageError(cliText("opt.seconds"));
        o.seconds = *v;
    }
    const bool asJson = args.has("--json");
    const bool watch = args.has("--watch");
    if (!publish && args.value("--mqtt"))
        return usageError(cliText("shop.usage.mqtt-status"));
    if (publish && !args.value("--mqtt"))
        return usageError(cliText("shop.usage.mqtt"));
    if (!publish && !watch && (args.value("--interval-ms") || args.value("--seconds")))
        return usageError(cliText("shop.usage.watch"));

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
                std::printf("%s\n", stateText(s, r.atMs, r.said).c_str());
        }
        if (asJson)
            std::printf("%s\n", json::dump(all).c_str());
        return standardOutputLost() ? ExitUsage : ExitOk;
    }

    // Continuous: status --watch prints, publish publishes.
    shop::MqttPublisher mq;
    if (publish) {
        std::string error;
        std::string clientId = args.value("--client-id").value_or("");
        if (clientId.empty())
            clientId = shop::MqttPublisher::defaultClientId("k528-shop");
        if (util::Message bad; !mqtt::parseUrl(*args.value("--mqtt"), bad))
            return usageError("--mqtt: " + util::systemText(bad, russianCommandLine()));
        std::vector<std::string> names;
        for (const auto& l : o.lines)
            names.push_back(l.machine);
        if (!mq.start(*args.value("--mqtt"), clientId, o.intervalMs, names, error)) {
            std::fprintf(stderr, "%s\n", cliText("shop.publish.no-broker", {*args.value("--mqtt"), error}).c_str());
            return ExitUsage;
        }
        std::fprintf(stderr, "%s\n",
                     cliText("shop.publish.start", {std::to_string(o.lines.size()), std::to_string(o.intervalMs),
                                                    *args.value("--mqtt"), clientId})
                         .c_str());
    }
    // Each machine's time in each state, added to the database's record
    // (source shop@HOST) once a minute, when a state changes and at the end.
    std::optional<db::Database> times;
    const db::Lang lang = russianCommandLine() ? db::Lang::Ru : db::Lang::En;
    const auto timesNotKept = [](const std::string& why) {
        std::fprintf(stderr, "%s\n", cliText("shop.times-not-kept", {why}).c_str());
    };
    if (const auto where = args.value("--db")) {
        try {
            times.emplace(db::Database::open(db::Location::parse(*where)));
        } catch (const db::Error& e) {
            timesNotKept(e.text(lang));
        } catch (const std::exception& e) {
            timesNotKept(e.what());
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
                timesNotKept(e.text(lang));
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
                                               : stateText(s, r.atMs, r.said).c_str());
                for (const shop::AlarmEvent& e : events)
                    if (!asJson)
                        std::printf("%s\n", (e.raised ? cliText("shop.alarm-raised", {s.machine, std::to_string(e.number),
                                                                                         clockOf(e.atMs)})
                                                       : cliText("shop.alarm-cleared", {s.machine, std::to_string(e.number),
                                                                                          clockOf(e.atMs)}))
                                                .c_str());
                    else
                        std::printf("%s\n", json::dump(shop::alarmJson(e)).c_str());
                if ((changed || !events.empty()) && standardOutputLost()) {
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
            std::fprintf(stderr, "%s\n", cliText("shop.publish.unacknowledged").c_str());
            code = ExitUsage;
        }
        std::fprintf(stderr, "%s\n", cliText("shop.publish.stopped", {std::to_string(mq.published())}).c_str());
    }
    return code;
}

} // namespace k528::cli
