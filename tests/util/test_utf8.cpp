#include <QtTest>

#include "util/utf8.h"

using namespace k528;

class TestUtf8 : public QObject {
    Q_OBJECT
private slots:
    void countsCharactersNotBytes() {
        QCOMPARE(utf8::length("АВТ 1"), std::size_t(5));
        QCOMPARE(std::string("АВТ 1").size(), std::size_t(8));
        QCOMPARE(utf8::length(""), std::size_t(0));
    }
    void fitsLcdWidth() {
        QCOMPARE(utf8::fitWidth("РУЧ", 5), std::string("РУЧ  "));
        QCOMPARE(utf8::fitWidth("ПАРАМЕТРЫ СТАНКА ДЛИННО", 16), std::string("ПАРАМЕТРЫ СТАНКА"));
        QCOMPARE(utf8::length(utf8::fitWidth("Ёж", 20)), std::size_t(20));
    }
    void validatesAndReplaces() {
        QVERIFY(utf8::isValid("Привязка"));
        QVERIFY(!utf8::isValid("\xC0\xAF"));         // overlong '/'
        QVERIFY(!utf8::isValid("\xED\xA0\x80"));     // surrogate
        QVERIFY(!utf8::isValid("\xD0"));             // truncated
        const auto cps = utf8::decode("a\xFF" "б");
        QCOMPARE(cps.size(), std::size_t(3));
        QCOMPARE(cps[1], char32_t(0xFFFD));
        QCOMPARE(utf8::encode(utf8::decode("Z-1065.124 Ё")), std::string("Z-1065.124 Ё"));
    }
    void upperCasesCyrillic() {
        QCOMPARE(utf8::toUpper("привязка ёж x1"), std::string("ПРИВЯЗКА ЁЖ X1"));
    }
};

QTEST_APPLESS_MAIN(TestUtf8)
#include "test_utf8.moc"
