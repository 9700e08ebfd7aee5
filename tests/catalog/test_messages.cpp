// Messages of appendix М and the message groups of section 2.3.
#include "catalog/messages.h"
#include "util/utf8.h"

#include <QtTest>
#include <regex>
#include <set>
#include <string>

using namespace k528;
using namespace k528::catalog;

class TestMessages : public QObject {
    Q_OBJECT
private slots:
    void all64WithTexts() {
        QCOMPARE(positionerMessages().size(), std::size_t(64));
        for (std::size_t i = 0; i < 64; ++i) {
            const PositionerMessage& m = positionerMessages()[i];
            QCOMPARE(m.number, int(i + 1));
            QVERIFY2(!m.textRu.empty() && !m.commentRu.empty(), std::to_string(m.number).c_str());
            QVERIFY2(!m.textEn.empty() && !m.commentEn.empty(), std::to_string(m.number).c_str());
            QVERIFY(utf8::isValid(m.textRu) && utf8::isValid(m.commentRu));
            // Two LCD lines of 20 characters, number included.
            QVERIFY2(utf8::length(m.panelText()) <= 40, m.panelText().c_str());
        }
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, positionerMessage(65));
        QVERIFY(findPositionerMessage(0) == nullptr);
    }

    void textsAsOnThePanel() {
        QCOMPARE(positionerMessage(13).textRu,
                 std::string_view("Ошибка коэфф.преобразования ДОС (X)"));
        QCOMPARE(positionerMessage(13).panelText(),
                 std::string("13.Ошибка коэфф.преобразования ДОС (X)"));
        QCOMPARE(positionerMessage(8).textRu, std::string_view("Контроль полож/зажима оси X"));
        QCOMPARE(positionerMessage(12).textRu, std::string_view("Программный конечный выключ.(X)"));
        QCOMPARE(positionerMessage(14).textRu, std::string_view("Отказ СР52.05 в БП"));
        QCOMPARE(positionerMessage(15).textRu, std::string_view("Разрушены С-параметры"));
        // Quotes as table М.1 prints them: «» for 9..11, straight for 26/27.
        QCOMPARE(positionerMessage(9).textRu, std::string_view("Аварийный «СТОП» от ПЛК"));
        QCOMPARE(positionerMessage(10).textRu, std::string_view("Конечник оси X в «-»"));
        QCOMPARE(positionerMessage(11).textRu, std::string_view("Конечник оси X в «+»"));
        QCOMPARE(positionerMessage(26).textRu, std::string_view("Конечник оси Z в \"-\""));
        // The blank after the number's dot where table М.1 prints one.
        QCOMPARE(positionerMessage(37).panelText(), std::string("37. Ошибка N ДОС"));
        QCOMPARE(positionerMessage(38).panelText(), std::string("38. Ошибка N ЦАП"));
        QCOMPARE(positionerMessage(39).panelText(), std::string("39.Ошибка N маховика"));
        QCOMPARE(positionerMessage(14).panelText(), std::string("14. Отказ СР52.05 в БП"));
        QCOMPARE(positionerMessage(47).panelText(), std::string("47. G?"));
        QCOMPARE(positionerMessage(54).panelText(), std::string("54.Дублирование номеров кадров"));
        QCOMPARE(positionerMessage(64).panelText(), std::string("64. G04/L"));
        // One rule for every line with a number: Russian as the panel, English always with the blank.
        QCOMPARE(numberedMessage(39, positionerMessage(39).textRu, true), positionerMessage(39).panelText());
        QCOMPARE(numberedMessage(39, "Handwheel N error", false), std::string("39. Handwheel N error"));
        QCOMPARE(numberedMessage(54, "x", false), std::string("54. x"));
        QCOMPARE(positionerMessage(41).textRu, std::string_view("Нет \"0\"-метки"));
        QCOMPARE(positionerMessage(46).textRu, std::string_view("Переполнение"));
        QCOMPARE(positionerMessage(47).textRu, std::string_view("G?"));
        QCOMPARE(positionerMessage(63).textRu, std::string_view("G04/X/Z"));
        QCOMPARE(positionerMessage(43).textRu, std::string_view("D круга > Dmax"));
        QCOMPARE(positionerMessage(33).commentRu, std::string_view("Ошибка в УП"));
        // No OCR line-break hyphens, no leading blanks; typographic quotes
        // only where table М.1 prints them (9, 10, 11).
        const std::regex brokenWord("[а-яА-Я]- [а-я]");
        for (const PositionerMessage& m : positionerMessages()) {
            const std::string t(m.textRu);
            QVERIFY2(!std::regex_search(t, brokenWord), t.c_str());
            QVERIFY2(t.front() != ' ', t.c_str());
            if (m.number < 9 || m.number > 11)
                QVERIFY2(t.find("«") == std::string::npos && t.find("»") == std::string::npos,
                         t.c_str());
        }
    }

    void axisPairs() {
        const std::pair<int, int> pairs[] = {
            {1, 17},  {4, 20},  {5, 21},  {6, 22},  {7, 23},  {8, 24},  {10, 26}, {11, 27},
            {12, 28}, {13, 29}, {16, 32}, {33, 49}, {34, 50}, {35, 51}, {36, 52}, {56, 57}};
        std::set<int> paired;
        for (const auto& [x, z] : pairs) {
            QCOMPARE(messageCounterpart(x), z);
            QCOMPARE(messageCounterpart(z), x);
            QVERIFY(positionerMessage(x).axis == Axis::X);
            QVERIFY(positionerMessage(z).axis == Axis::Z);
            QCOMPARE(messageForAxis(x, Axis::Z), z);
            QCOMPARE(messageForAxis(x, Axis::X), x);
            // Same text with the axis letter changed (10/11 print «», 26/27 "").
            std::string xt(positionerMessage(x).textRu);
            for (auto& ch : xt)
                if (ch == 'X')
                    ch = 'Z';
            std::string plain; // « and » (two bytes each in UTF-8) as "
            for (std::size_t i = 0; i < xt.size();) {
                const bool quote = xt.compare(i, 2, "«") == 0 || xt.compare(i, 2, "»") == 0;
                plain += quote ? '"' : xt[i];
                i += quote ? 2 : 1;
            }
            xt = plain;
            QCOMPARE(xt, std::string(positionerMessage(z).textRu));
            paired.insert(x);
            paired.insert(z);
        }
        for (const PositionerMessage& m : positionerMessages())
            if (!paired.contains(m.number)) {
                QCOMPARE(m.counterpart, 0);
                QVERIFY(m.axis == Axis::Common);
                QCOMPARE(messageForAxis(m.number, Axis::Z), m.number);
            }
    }

    void groups() {
        for (int n : {13, 15, 29, 37, 38, 39})
            QVERIFY(positionerMessage(n).group == MessageGroup::Configuration);
        for (int n : {33, 45, 46, 47, 48, 53, 54, 58, 64})
            QVERIFY(positionerMessage(n).group == MessageGroup::Program);
        QCOMPARE(messageGroupName(MessageGroup::Homing), std::string_view("homing"));
    }

    void panelOwnMessages() {
        QCOMPARE(panelMessages().size(), std::size_t(7));
        QCOMPARE(panelMessage(PanelMessageId::PlcStop).textRu,
                 std::string_view("Режим ПЛК СТОП !"));
        QCOMPARE(panelMessage(PanelMessageId::InputError).textRu, std::string_view("ОШИБКА ВВОДА"));
        QCOMPARE(panelMessage(PanelMessageId::NoPositionerLink).textRu,
                 std::string_view("НЕТ СВЯЗИ С БП"));
        for (const PanelMessage& m : panelMessages())
            QVERIFY(utf8::length(m.textRu) <= 20 && !m.commentRu.empty() && !m.textEn.empty());
    }

    void plcGroups() {
        QCOMPARE(plcMessageCount(PlcGroup::Alarm), 32);
        QCOMPARE(plcMessageCount(PlcGroup::Work), 32);
        QCOMPARE(plcMessageCount(PlcGroup::System), 16);
        QCOMPARE(plcMessageAddress(PlcGroup::Alarm, 1), std::string("Z1900.0"));
        QCOMPARE(plcMessageAddress(PlcGroup::Alarm, 16), std::string("Z1900.15"));
        QCOMPARE(plcMessageAddress(PlcGroup::Alarm, 17), std::string("Z1901.0"));
        QCOMPARE(plcMessageAddress(PlcGroup::Alarm, 32), std::string("Z1901.15"));
        QCOMPARE(plcMessageAddress(PlcGroup::Work, 1), std::string("Z1902.0"));
        QCOMPARE(plcMessageAddress(PlcGroup::Work, 32), std::string("Z1903.15"));
        QCOMPARE(plcMessageAddress(PlcGroup::System, 1), std::string("Z1307.0"));
        QCOMPARE(plcMessageAddress(PlcGroup::System, 16), std::string("Z1307.15"));
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, plcMessageAddress(PlcGroup::System, 17));
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, plcMessageAddress(PlcGroup::Alarm, 0));
        QCOMPARE(plcGroupLetter(PlcGroup::Work), 'W');
        QCOMPARE(kTechMessageMaxChars, 20);
        QCOMPARE(kPlcMessageMaxChars, 40);
    }
};

QTEST_APPLESS_MAIN(TestMessages)
#include "test_messages.moc"
