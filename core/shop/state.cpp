#include "shop/state.h"

#include "catalog/messages.h"
#include "util/json.h"

#include <algorithm>
#include <ctime>

namespace k528::shop {

const char* activityName(Activity a) {
    switch (a) {
    case Activity::Offline:
        return "offline";
    case Activity::Alarm:
        return "alarm";
    case Activity::Run:
        return "run";
    case Activity::Idle:
        return "idle";
    }
    return "offline";
}

Activity activityOf(const link::LiveState& s) {
    if (s.alarm || !s.alarms.empty())
        return Activity::Alarm;
    if (s.running)
        return Activity::Run;
    return Activity::Idle;
}

Tracker::Tracker(std::string machine, std::string line) {
    s_.machine = std::move(machine);
    s_.line = std::move(line);
}

namespace {

bool samePublished(const link::LiveState& a, const link::LiveState& b) {
    return a.mode == b.mode && a.pcReady == b.pcReady && a.running == b.running && a.alarm == b.alarm &&
           a.program == b.program && a.frame == b.frame && a.alarms == b.alarms && a.message == b.message &&
           a.overridePercent == b.overridePercent;
}

} // namespace

bool Tracker::update(const link::LiveState* live, const std::string& why, std::int64_t nowMs,
                     std::vector<AlarmEvent>& events) {
    const bool first = !s_.polled;
    const MachineState before = s_;
    s_.polled = true;
    s_.polledMs = nowMs;
    if (live) {
        // Alarms against those the controller had when it last answered.
        const std::vector<int>& was = s_.everOnline ? s_.live.alarms : std::vector<int>{};
        for (int n : live->alarms)
            if (std::find(was.begin(), was.end(), n) == was.end())
                events.push_back({s_.machine, n, true, nowMs});
        for (int n : was)
            if (std::find(live->alarms.begin(), live->alarms.end(), n) == live->alarms.end())
                events.push_back({s_.machine, n, false, nowMs});
        s_.online = true;
        s_.everOnline = true;
        s_.live = *live;
        s_.why.clear();
        s_.lastSeenMs = nowMs;
        s_.activity = activityOf(*live);
    } else {
        s_.online = false;
        s_.why = why;
        s_.activity = Activity::Offline;
    }
    if (first || s_.activity != before.activity)
        s_.sinceMs = nowMs;
    if (first)
        return true;
    if (s_.online != before.online || s_.activity != before.activity)
        return true;
    return s_.online ? !samePublished(s_.live, before.live) : false;
}

std::string isoTime(std::int64_t unixMs) {
    const std::time_t secs = static_cast<std::time_t>(unixMs / 1000);
    std::tm tm{};
    gmtime_r(&secs, &tm);
    char buf[40];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
    char ms[8];
    std::snprintf(ms, sizeof ms, ".%03dZ", static_cast<int>(unixMs % 1000));
    return std::string(buf) + ms;
}

namespace {

Json alarmText(int n) {
    Json a;
    a["number"] = n;
    if (const catalog::PositionerMessage* m = catalog::findPositionerMessage(n)) {
        a["text_ru"] = std::string(m->textRu);
        a["text_en"] = std::string(m->textEn);
    } else {
        a["text_ru"] = nullptr;
        a["text_en"] = nullptr;
    }
    return a;
}

} // namespace

Json stateJson(const MachineState& s, std::int64_t nowMs) {
    Json v;
    v["machine"] = s.machine;
    v["line"] = s.line;
    v["online"] = s.online;
    v["state"] = activityName(s.activity);
    v["since"] = isoTime(s.sinceMs);
    v["seconds_in_state"] = static_cast<double>(std::max<std::int64_t>(0, nowMs - s.sinceMs) / 100) / 10.0;
    if (s.online) {
        const link::LiveState& l = s.live;
        v["mode"] = l.mode;
        v["pc_ready"] = l.pcReady;
        v["running"] = l.running;
        v["program"] = l.program;
        v["frame"] = l.frame;
        v["override"] = l.overridePercent;
        v["message"] = l.message;
        Json numbers = Json::array();
        Json texts = Json::array();
        for (int n : l.alarms) {
            numbers.push_back(n);
            texts.push_back(alarmText(n));
        }
        v["alarms"] = std::move(numbers);
        v["alarm_texts"] = std::move(texts);
    } else {
        v["why"] = s.why;
        v["last_seen"] = s.everOnline ? Json(isoTime(s.lastSeenMs)) : Json(nullptr);
    }
    return v;
}

Json alarmJson(const AlarmEvent& e) {
    Json v;
    v["machine"] = e.machine;
    v["number"] = e.number;
    v["event"] = e.raised ? "raised" : "cleared";
    const Json t = alarmText(e.number);
    v["text_ru"] = t["text_ru"];
    v["text_en"] = t["text_en"];
    v["at"] = isoTime(e.atMs);
    return v;
}

} // namespace k528::shop
