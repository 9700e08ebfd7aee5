#include <QtTest>

#include "util/json.h"
#include "util/utf8.h"

using namespace k528;

class TestJson : public QObject {
    Q_OBJECT
private slots:
    void parsesAndDumpsRoundTrip() {
        const std::string text =
            R"({"status":"completed","alarms":[{"number":46,"text_ru":"Переполнение"}],)"
            R"("time_s":6.214,"frames":12,"ok":true,"none":null,"neg":-2147483648})";
        const json::Value v = json::parse(text);
        QCOMPARE(v.dump(), text);
        QCOMPARE(v.find("frames")->asInt(), 12);
        QCOMPARE(v.find("time_s")->asDouble(), 6.214);
        QCOMPARE(v.find("alarms")->asArray().at(0).find("text_ru")->asString(), std::string("Переполнение"));
        QCOMPARE(v.find("neg")->asInt(), -2147483648LL);
        QVERIFY(v.find("none")->isNull());
        QVERIFY(v.find("missing") == nullptr);
    }

    void keepsInsertionOrderAndReplaces() {
        json::Value o;
        o.set("b", 1);
        o.set("a", 2);
        o.set("b", 3);
        QCOMPARE(o.dump(), std::string(R"({"b":3,"a":2})"));
    }

    void prettyPrints() {
        json::Value o;
        o.set("x", json::Array{1, 2});
        QCOMPARE(o.dump(2), std::string("{\n  \"x\": [\n    1,\n    2\n  ]\n}"));
    }

    void escapesAndUnescapes() {
        // (no raw string here: moc misreads \" inside raw string literals)
        const json::Value v = json::parse("[\"a\\\"b\\\\c\\n\\u0041\\u00e9\\ud83d\\ude00\"]");
        QCOMPARE(v.asArray()[0].asString(), std::string("a\"b\\c\nAé\xF0\x9F\x98\x80"));
        QCOMPARE(json::Value(std::string("tab\there\x01")).dump(), std::string("\"tab\\there\\u0001\""));
    }

    void invalidUtf8BecomesReplacementCharacters() {
        // A stray byte, a cut sequence, an overlong and a surrogate: each byte
        // that is not part of a well-formed character becomes U+FFFD.
        const std::string fffd = "\xEF\xBF\xBD";
        QCOMPARE(json::Value(std::string("a\xFF" "b")).dump(), "\"a" + fffd + "b\"");
        QCOMPARE(json::Value(std::string("\xD0")).dump(), "\"" + fffd + "\"");
        QCOMPARE(json::Value(std::string("\xC0\x80")).dump(), "\"" + fffd + fffd + "\"");
        QCOMPARE(json::Value(std::string("\xED\xA0\x80")).dump(), "\"" + fffd + fffd + fffd + "\"");
        QCOMPARE(json::Value(std::string("\xF4\x90\x80\x80")).dump(), "\"" + fffd + fffd + fffd + fffd + "\""); // above U+10FFFF
        // Well-formed text of 2, 3 and 4 bytes is kept as it is.
        const std::string ok = "\xD0\x96 \xE2\x82\xAC \xF0\x9F\x98\x80 \xF4\x8F\xBF\xBF";
        QCOMPARE(json::Value(ok).dump(), "\"" + ok + "\"");
        // The output reads back (it is valid JSON and valid UTF-8).
        const std::string out = json::Value(std::string("%\xD0\x96\xFF\xD0")).dump();
        QVERIFY(utf8::isValid(out));
        QCOMPARE(json::parse(out).asString(), "%\xD0\x96" + fffd + fffd);
    }

    void shortestDoubles() {
        QCOMPARE(json::formatDouble(6.214), std::string("6.214"));
        QCOMPARE(json::formatDouble(100.0), std::string("100"));
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
        }
    }

    void rejectsDeepNesting() {
        const std::string deep(100000, '[');
        QVERIFY_THROWS_EXCEPTION(json::ParseError, json::parse(deep));
    }

    void typeMismatchThrows() {
        const json::Value v = json::parse("\"x\"");
        QVERIFY_THROWS_EXCEPTION(std::runtime_error, v.asInt());
        QCOMPARE(json::parse("2.0").asInt(), 2);
        QVERIFY_THROWS_EXCEPTION(std::runtime_error, json::parse("2.5").asInt());
    }
};

QTEST_APPLESS_MAIN(TestJson)
#include "test_json.moc"
