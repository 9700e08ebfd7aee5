#include <QtTest>

#include "util/json.h"
#include "util/utf8.h"

#include <cmath>
#include <cstdint>
#include <limits>

using namespace k528;

class TestJson : public QObject {
    Q_OBJECT
private slots:
    void parsesAndDumpsRoundTrip() {
        const std::string text =
            R"({"status":"completed","alarms":[{"number":46,"text_ru":"Переполнение"}],)"
            R"("time_s":6.214,"frames":12,"ok":true,"none":null,"neg":-2147483648})";
        const Json v = json::parse(text);
        QCOMPARE(json::dump(v), text);
        QCOMPARE(v.at("frames").get<std::int64_t>(), 12);
        QCOMPARE(v.at("time_s").get<double>(), 6.214);
        QCOMPARE(v.at("alarms").at(0).at("text_ru").get<std::string>(),
                 std::string("Переполнение"));
        QCOMPARE(v.at("neg").get<std::int64_t>(), -2147483648LL);
        QVERIFY(v.at("none").is_null());
        QVERIFY(!v.contains("missing"));
    }

    void integersAreExact() {
        // Beyond 2^53 a double would round: nlohmann keeps int64 and uint64.
        const std::string text = "[9007199254740993,-9223372036854775808,9223372036854775807,"
                                 "18446744073709551615,2.0]";
        const Json v = json::parse(text);
        QCOMPARE(json::dump(v),
                 std::string("[9007199254740993,-9223372036854775808,9223372036854775807,"
                             "18446744073709551615,2]"));
        QCOMPARE(v[0].get<std::int64_t>(), 9007199254740993LL);
        QCOMPARE(v[1].get<std::int64_t>(), std::numeric_limits<std::int64_t>::min());
        QVERIFY(v[2].is_number_unsigned()); // a non-negative integer reads as uint64
        QCOMPARE(v[2].get<std::int64_t>(), std::numeric_limits<std::int64_t>::max());
        QCOMPARE(v[3].get<std::uint64_t>(), std::numeric_limits<std::uint64_t>::max());
        QVERIFY(v[4].is_number_float());
        // Built values: signed, unsigned and double print as read.
        const Json built = Json::array({std::int64_t{-5}, std::size_t{7}, 0.5});
        QCOMPARE(json::dump(built), std::string("[-5,7,0.5]"));
    }

    void keepsInsertionOrderAndReplaces() {
        Json o;
        o["b"] = 1;
        o["a"] = 2;
        o["b"] = 3;
        QCOMPARE(json::dump(o), std::string(R"({"b":3,"a":2})"));
        // A key given twice in a document: its first place, its last value.
        QCOMPARE(json::dump(json::parse(R"({"z":1,"y":2,"z":3})")),
                 std::string(R"({"z":3,"y":2})"));
    }

    void prettyPrints() {
        Json o;
        o["x"] = Json::array({1, 2});
        QCOMPARE(json::dump(o, 2), std::string("{\n  \"x\": [\n    1,\n    2\n  ]\n}"));
    }

    // Without doubles and invalid UTF-8 the writer's bytes are nlohmann's own,
    // compact and pretty: the layout of --json output is nlohmann's.
    void layoutIsNlohmanns() {
        // (no raw string with \" here: moc misreads it)
        const Json v =
            json::parse(R"({"a":[],"b":{},"c":[1,{"d":null,"e":[true,false]}],)"
                        "\"f\":\"x\\ty\\u0001\\\"\",\"g\":-7,\"h\":{\"i\":{\"j\":[[]]}}}");
        for (const int indent : {-1, 0, 2, 4})
            QCOMPARE(json::dump(v, indent), v.dump(indent));
    }

    // Doubles are shortest round-trip text without nlohmann's ".0".
    void doublesDifferFromNlohmann() {
        const Json v = Json::array({100.0, 1e-7, 6.214, -0.0, 1e300, 0.1 + 0.2});
        QCOMPARE(json::dump(v), std::string("[100,1e-07,6.214,0,1e+300,0.30000000000000004]"));
        QCOMPARE(v.dump(), std::string("[100.0,1e-07,6.214,-0.0,1e+300,0.30000000000000004]"));
        QCOMPARE(json::dump(Json(std::nan(""))), std::string("null"));
    }

    void escapesAndUnescapes() {
        // (no raw string here: moc misreads \" inside raw string literals)
        const Json v = json::parse("[\"a\\\"b\\\\c\\n\\u0041\\u00e9\\ud83d\\ude00\"]");
        QCOMPARE(v[0].get<std::string>(), std::string("a\"b\\c\nAé\xF0\x9F\x98\x80"));
        QCOMPARE(json::dump(Json(std::string("tab\there\x01"))),
                 std::string("\"tab\\there\\u0001\""));
    }

    void invalidUtf8BecomesReplacementCharacters() {
        // A stray byte, a cut sequence, an overlong and a surrogate: each byte
        // that is not part of a well-formed character becomes U+FFFD.
        const std::string fffd = "\xEF\xBF\xBD";
        const auto dumped = [](const std::string& s) { return json::dump(Json(s)); };
        QCOMPARE(dumped("a\xFF" "b"), "\"a" + fffd + "b\"");
        QCOMPARE(dumped("\xD0"), "\"" + fffd + "\"");
        QCOMPARE(dumped("\xC0\x80"), "\"" + fffd + fffd + "\"");
        QCOMPARE(dumped("\xED\xA0\x80"), "\"" + fffd + fffd + fffd + "\"");
        QCOMPARE(dumped("\xF4\x90\x80\x80"),
                 "\"" + fffd + fffd + fffd + fffd + "\""); // above U+10FFFF
        // Well-formed text of 2, 3 and 4 bytes is kept as it is.
        const std::string ok = "\xD0\x96 \xE2\x82\xAC \xF0\x9F\x98\x80 \xF4\x8F\xBF\xBF";
        QCOMPARE(dumped(ok), "\"" + ok + "\"");
        // In keys too; the output reads back (it is valid JSON and valid UTF-8).
        Json o;
        o["k\xFF"] = "%\xD0\x96\xFF\xD0";
        const std::string out = json::dump(o);
        QCOMPARE(out, "{\"k" + fffd + "\":\"%\xD0\x96" + fffd + fffd + "\"}");
        QVERIFY(utf8::isValid(out));
        QCOMPARE(json::parse(out).at("k" + fffd).get<std::string>(), "%\xD0\x96" + fffd + fffd);
    }

    void shortestDoubles() {
        QCOMPARE(json::formatDouble(6.214), std::string("6.214"));
        QCOMPARE(json::formatDouble(100.0), std::string("100"));
        QCOMPARE(json::formatDouble(1e-7), std::string("1e-07"));
        QCOMPARE(json::formatDouble(-0.0), std::string("0"));
        QCOMPARE(json::formatDouble(0.1 + 0.2), std::string("0.30000000000000004"));
    }

    void reportsErrorsWithPosition_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("line");
        QTest::addColumn<int>("column");
        QTest::newRow("trailing comma") << "[1,2,]" << 1 << 6;
        QTest::newRow("second line") << "{\n \"a\" 1}" << 2 << 6;
        QTest::newRow("unterminated") << "\"abc" << 1 << 5;
        QTest::newRow("garbage after") << "{} x" << 1 << 4;
        QTest::newRow("leading zero") << "01" << 1 << 2;
        QTest::newRow("lone surrogate") << R"("\udc00")" << 1 << 8;
        QTest::newRow("empty") << "" << 1 << 1;
        QTest::newRow("line comment") << "[1] // one" << 1 << 5;
        QTest::newRow("block comment") << "/* x */ 1" << 1 << 1;
    }
    void reportsErrorsWithPosition() {
        QFETCH(QString, text);
        QFETCH(int, line);
        QFETCH(int, column);
        try {
            json::parse(text.toStdString());
            QFAIL("parse accepted invalid JSON");
        } catch (const json::ParseError& e) {
            QCOMPARE(e.line, line);
            QCOMPARE(e.column, column);
            const std::string prefix =
                "JSON line " + std::to_string(line) + ", column " + std::to_string(column) + ": ";
            QVERIFY2(std::string(e.what()).rfind(prefix, 0) == 0, e.what());
        }
    }

    void rejectsDeepNesting() {
        const std::string deep(100000, '[');
        QVERIFY_THROWS_EXCEPTION(json::ParseError, json::parse(deep));
        const auto nested = [](int n) { return std::string(n, '[') + std::string(n, ']'); };
        QCOMPARE(json::dump(json::parse(nested(256))), nested(256));
        try {
            json::parse(nested(257));
            QFAIL("parse accepted 257 levels");
        } catch (const json::ParseError& e) {
            QCOMPARE(std::string(e.what()), std::string("JSON nesting deeper than 256"));
        }
    }

    void callbackSeesTheEvents() {
        int keys = 0;
        const Json v =
            json::parse(R"({"a":{"b":1},"c":[2]})", [&](int, Json::parse_event_t e, Json&) {
                keys += e == Json::parse_event_t::key;
                return true;
            });
        QCOMPARE(keys, 3);
        QCOMPARE(json::dump(v), std::string(R"({"a":{"b":1},"c":[2]})"));
    }
};

QTEST_APPLESS_MAIN(TestJson)
#include "test_json.moc"
