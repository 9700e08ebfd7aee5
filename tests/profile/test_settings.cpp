// The simulation settings: ordered storage, typed getters, the key registry.
#include "profile/settings.h"

#include <QtTest>

using namespace k528::profile;

class TestSettings : public QObject {
    Q_OBJECT
private slots:
    void orderedStorage() {
        Settings s;
        s.set("tick_ms", "1");
        s.set("x.kv", "1.5");
        s.set("nesting_limit", "8");
        s.set("x.kv", "2"); // replaced in place
        QCOMPARE(s.size(), std::size_t(3));
        QCOMPARE(s.entries()[1], (Settings::Entry{"x.kv", "2"}));
        QVERIFY(s.erase("tick_ms"));
        QVERIFY(!s.erase("tick_ms"));
        QCOMPARE(s.entries()[0].first, std::string("x.kv"));
        Settings t;
        t.set("x.kv", "2");
        t.set("nesting_limit", "8");
        QVERIFY(s == t);
        t.set("x.kv", "3");
        QVERIFY(!(s == t));
    }

    void typedGetters() {
        Settings s;
        s.setInt("a", -42);
        s.setDouble("b", 0.1);
        s.setBool("c", true);
        s.set("d", "abc");
        s.set("e", "off");
        QCOMPARE(s.getInt("a", 0), std::int64_t(-42));
        QCOMPARE(s.getDouble("b", 0), 0.1);
        QCOMPARE(s.find("b"), std::optional<std::string>("0.1"));
        QCOMPARE(s.getDouble("a", 0), -42.0);
        QCOMPARE(s.getBool("c", false), true);
        QCOMPARE(s.getBool("e", true), false);
        QCOMPARE(s.getInt("missing", 7), std::int64_t(7));
        QCOMPARE(s.getString("d", ""), std::string("abc"));
        try {
            s.getInt("d", 0);
            QFAIL("no error");
        } catch (const SettingError& e) {
            QCOMPARE(std::string(e.what()),
                     std::string("simulation setting d = 'abc': not a whole number"));
        }
        QVERIFY_THROWS_EXCEPTION(SettingError, s.getInt("b", 0));
        QVERIFY_THROWS_EXCEPTION(SettingError, s.getDouble("d", 0));
        QVERIFY_THROWS_EXCEPTION(SettingError, s.getBool("a", false));
        QVERIFY_THROWS_EXCEPTION(SettingError, s.requireInt("missing"));
        QVERIFY_THROWS_EXCEPTION(SettingError, s.requireDouble("missing"));
        QCOMPARE(s.requireDouble("b"), 0.1);
    }

    void badKeysAndValues() {
        Settings s;
        QVERIFY_THROWS_EXCEPTION(SettingError, s.set("", "1"));
        QVERIFY_THROWS_EXCEPTION(SettingError, s.set("X.kv", "1"));
        QVERIFY_THROWS_EXCEPTION(SettingError, s.set("1x", "1"));
        QVERIFY_THROWS_EXCEPTION(SettingError, s.set("a b", "1"));
        QVERIFY_THROWS_EXCEPTION(SettingError, s.set("a", "1 ; comment"));
        QVERIFY_THROWS_EXCEPTION(SettingError, s.set("a", " 1"));
        QVERIFY_THROWS_EXCEPTION(SettingError, s.set("a", "1\n2"));
        QVERIFY_THROWS_EXCEPTION(SettingError, s.setDouble("a", 1.0 / 0.0));
        QVERIFY(s.empty());
        s.set("a", "");
        QCOMPARE(s.find("a"), std::optional<std::string>(""));
    }

    void numbers() {
        QCOMPARE(parseInt("+12"), std::optional<std::int64_t>(12));
        QCOMPARE(parseInt("-9223372036854775808"), std::optional<std::int64_t>(INT64_MIN));
        QCOMPARE(parseInt("9223372036854775808"), std::optional<std::int64_t>());
        QCOMPARE(parseInt("1.0"), std::optional<std::int64_t>());
        QCOMPARE(parseInt("-"), std::optional<std::int64_t>());
        QCOMPARE(parseDouble("2.5e-3"), std::optional<double>(0.0025));
        QCOMPARE(parseDouble("nan"), std::optional<double>());
        QCOMPARE(parseDouble("1,5"), std::optional<double>());
        for (double v : {0.1, 1.0 / 3.0, 1e-7, 123456.789, -2.5})
            QCOMPARE(parseDouble(formatDouble(v)), std::optional<double>(v));
        QCOMPARE(formatDouble(10), std::string("10"));
    }

    void registry() {
        QVERIFY(findSimulationKey("tick_ms") != nullptr);
        QCOMPARE(findSimulationKey("nesting_limit")->defaultValue, std::string_view("8"));
        for (const char* axis : {"x.", "z."})
            for (const char* k : {"screw_lead_mm", "gear_ratio", "encoder_lines", "drive_max_volts",
                                  "drive_max_speed_mm_per_min", "kv", "drive_time_constant_ms"})
                QVERIFY2(findSimulationKey(std::string(axis) + k) != nullptr, k);
        for (const SimulationKey& k : simulationKeys()) {
            QVERIFY(Settings::keyError(k.key).empty());
            if (!k.defaultValue.empty())
                QVERIFY2(checkSimulationValue(k.key, k.defaultValue).empty(),
                         std::string(k.key).c_str());
        }
        QCOMPARE(checkSimulationValue("tick_ms", "5"), std::string());
        QVERIFY(!checkSimulationValue("tick_ms", "0").empty());
        QVERIFY(!checkSimulationValue("x.kv", "fast").empty());
        QCOMPARE(checkSimulationValue("unknown.key", "anything"), std::string());
    }
};

QTEST_APPLESS_MAIN(TestSettings)
#include "test_settings.moc"
