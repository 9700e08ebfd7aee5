// core/shop and profile/line.h in process: a machine's state from its polls
// (online, activity and since when, what counts as a change), the alarms
// raised and cleared, the JSON of the contract (docs/shop.md), and the
// line's text both ways.
#include "profile/line.h"
#include "shop/state.h"
#include "util/json.h"

#include <QtTest>

using namespace k528;

namespace {

link::LiveState idle(int mode = 7) {
    link::LiveState s;
    s.mode = mode;
    s.pcReady = mode == 7;
    s.program = 1;
    return s;
}

} // namespace

class TestShopState : public QObject {
    Q_OBJECT
private slots:
    void linesBothWays() {
        std::string error;
        auto a = profile::parseLine("tcp://10.0.0.21:502/3", error);
        QVERIFY2(a, error.c_str());
        QCOMPARE(a->kind, profile::LineAddress::Kind::Tcp);
        QCOMPARE(a->host, std::string("10.0.0.21"));
        QCOMPARE(a->port, 502);
        QCOMPARE(a->address, 3);
        QCOMPARE(profile::formatLine(*a), std::string("tcp://10.0.0.21:502/3"));
        QCOMPARE(profile::lineEndpoint(*a), std::string("10.0.0.21:502"));
        a = profile::parseLine("tcp://[::1]:1502", error);
        QVERIFY2(a, error.c_str());
        QCOMPARE(a->host, std::string("::1"));
        QCOMPARE(a->address, 1);
        QCOMPARE(profile::formatLine(*a), std::string("tcp://[::1]:1502/1"));
        a = profile::parseLine("serial:/dev/ttyUSB0?baud=19200&parity=even&stop_bits=2&address=7", error);
        QVERIFY2(a, error.c_str());
        QCOMPARE(a->kind, profile::LineAddress::Kind::Serial);
        QCOMPARE(a->device, std::string("/dev/ttyUSB0"));
        QCOMPARE(a->baud, 19200);
        QCOMPARE(a->parity, 'E');
        QCOMPARE(a->stopBits, 2);
        QCOMPARE(a->address, 7);
        QCOMPARE(profile::formatLine(*a),
                 std::string("serial:/dev/ttyUSB0?baud=19200&parity=even&stop_bits=2&address=7"));
        QCOMPARE(profile::formatLine(*profile::parseLine("serial:/dev/ttyS1", error)),
                 std::string("serial:/dev/ttyS1?baud=115200&parity=none&address=1"));
        for (const char* bad : {"tcp://host", "tcp://:502", "tcp://h:0/1", "tcp://h:502/248", "tcp://h:70000",
                                "serial:", "serial:/dev/x?baud=9", "serial:/dev/x?parity=mark",
                                "serial:/dev/x?speed=1", "udp://h:1", ""})
            QVERIFY2(!profile::lineError(bad).empty(), bad);
        QVERIFY(profile::lineError("tcp://h:502/248").find("1..247") != std::string::npos);
    }

    void activityAndSince() {
        shop::Tracker t("m01", "tcp://h:502/1");
        std::vector<shop::AlarmEvent> ev;
        link::LiveState s = idle();
        QVERIFY(t.update(&s, {}, 1000, ev)); // the first poll is a change
        QCOMPARE(t.state().activity, shop::Activity::Idle);
        QCOMPARE(t.state().sinceMs, std::int64_t(1000));
        QVERIFY(!t.update(&s, {}, 1100, ev)); // nothing new
        s.xCurrent = 1234;                    // the axes move: not a change of the published state
        QVERIFY(!t.update(&s, {}, 1200, ev));
        s.running = true;
        s.frame = 5;
        QVERIFY(t.update(&s, {}, 1300, ev));
        QCOMPARE(t.state().activity, shop::Activity::Run);
        QCOMPARE(t.state().sinceMs, std::int64_t(1300));
        s.frame = 6; // the frame moves: a change, the same activity since 1300
        QVERIFY(t.update(&s, {}, 1400, ev));
        QCOMPARE(t.state().sinceMs, std::int64_t(1300));
        QVERIFY(ev.empty());
        // The line is lost: offline since that poll, no alarm events; the last state kept.
        QVERIFY(t.update(nullptr, "timeout", 1500, ev));
        QCOMPARE(t.state().activity, shop::Activity::Offline);
        QCOMPARE(t.state().sinceMs, std::int64_t(1500));
        QCOMPARE(t.state().lastSeenMs, std::int64_t(1400));
        QVERIFY(!t.update(nullptr, "timeout", 1600, ev));
        QVERIFY(ev.empty());
    }

    void alarmsRaisedAndCleared() {
        shop::Tracker t("m02", "tcp://h:502/1");
        std::vector<shop::AlarmEvent> ev;
        link::LiveState s = idle();
        s.alarms = {3};
        t.update(&s, {}, 100, ev); // alarms present at the first poll are raised
        QCOMPARE(ev.size(), std::size_t(1));
        QCOMPARE(ev[0].number, 3);
        QVERIFY(ev[0].raised);
        QCOMPARE(t.state().activity, shop::Activity::Alarm);
        ev.clear();
        s.alarms = {3, 46};
        QVERIFY(t.update(&s, {}, 200, ev));
        QCOMPARE(ev.size(), std::size_t(1));
        QCOMPARE(ev[0].number, 46);
        ev.clear();
        // Offline and back: compared with what it had before it went away.
        t.update(nullptr, "timeout", 300, ev);
        s.alarms = {46};
        t.update(&s, {}, 400, ev);
        QCOMPARE(ev.size(), std::size_t(1));
        QCOMPARE(ev[0].number, 3);
        QVERIFY(!ev[0].raised);
        QCOMPARE(ev[0].atMs, std::int64_t(400));
        ev.clear();
        s.alarms.clear();
        s.alarm = false;
        t.update(&s, {}, 500, ev);
        QCOMPARE(ev.size(), std::size_t(1));
        QVERIFY(!ev[0].raised);
        QCOMPARE(t.state().activity, shop::Activity::Idle);
        QCOMPARE(t.state().sinceMs, std::int64_t(500));
    }

    void theJsonOfTheContract() {
        shop::Tracker t("m03", "tcp://h:502/1");
        std::vector<shop::AlarmEvent> ev;
        link::LiveState s = idle(2);
        s.alarms = {46};
        t.update(&s, {}, 1764770525123, ev); // 2025-12-03T14:02:05.123Z
        Json j = shop::stateJson(t.state(), 1764770527623);
        QCOMPARE(j["machine"].get<std::string>(), std::string("m03"));
        QCOMPARE(j["online"].get<bool>(), true);
        QCOMPARE(j["state"].get<std::string>(), std::string("alarm"));
        QCOMPARE(j["since"].get<std::string>(), std::string("2025-12-03T14:02:05.123Z"));
        QCOMPARE(j["seconds_in_state"].get<double>(), 2.5);
        QCOMPARE(j["mode"].get<int>(), 2);
        QCOMPARE(j["alarms"].dump(), std::string("[46]"));
        QCOMPARE(j["alarm_texts"][0]["number"].get<int>(), 46);
        QVERIFY(!j["alarm_texts"][0]["text_ru"].get<std::string>().empty());
        QVERIFY(!j.contains("why"));
        t.update(nullptr, "the controller does not answer", 1764770528000, ev);
        j = shop::stateJson(t.state(), 1764770528000);
        QCOMPARE(j["online"].get<bool>(), false);
        QCOMPARE(j["state"].get<std::string>(), std::string("offline"));
        QCOMPARE(j["why"].get<std::string>(), std::string("the controller does not answer"));
        QCOMPARE(j["last_seen"].get<std::string>(), std::string("2025-12-03T14:02:05.123Z"));
        QVERIFY(!j.contains("mode"));
        const Json e = shop::alarmJson({"m03", 46, false, 1764770529001});
        QVERIFY2(json::dump(e).starts_with("{\"machine\":\"m03\",\"number\":46,\"event\":\"cleared\","),
                 json::dump(e).c_str());
        QVERIFY(!e["text_ru"].get<std::string>().empty() && !e["text_en"].get<std::string>().empty());
        QCOMPARE(e["at"].get<std::string>(), std::string("2025-12-03T14:02:09.001Z"));
        shop::Tracker never("m04", "tcp://h:1/1");
        never.update(nullptr, "refused", 10, ev);
        QVERIFY(shop::stateJson(never.state(), 10)["last_seen"].is_null());
    }
};

QTEST_APPLESS_MAIN(TestShopState)
#include "test_shop_state.moc"
