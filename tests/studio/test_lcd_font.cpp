// The K923 LCD character generator (core/panel/lcd_font): coverage of every
// text the manual puts on the panel, glyph sanity, look-alikes, placeholder.
#include "catalog/cparams.h"
#include "catalog/messages.h"
#include "panel/lcd_font.h"
#include "util/utf8.h"

#include <QtTest>
#include <set>
#include <string>

using k528::panel::Glyph;

namespace {

QString show(char32_t cp) {
    return QStringLiteral("U+%1 '%2'")
        .arg(static_cast<uint>(cp), 4, 16, QChar('0'))
        .arg(QString::fromUcs4(&cp, 1));
}

// The texts of the manual's screens (section 2.6), as the LCD shows them
// (the OCR's letter spacing removed).
const char* const kManualScreens[] = {
    // passwords, service indication
    "ПАРОЛЬ ?",
    ">",
    "> 1 - СООБЩЕНИЯ",
    "2 - НЕИСПРАВНОСТИ",
    "3 - СИСТЕМА",
    "4 - ДИАГНОСТИКА",
    "ABS_X   12.346",
    "ERR_X   -0.024",
    "DAC_X   1026",
    "PLS_X   0",
    "ABS_Z",
    "ERR_Z",
    "DAC_Z",
    "PLS_Z",
    "*",
    "!",
    "?",
    // АВТ
    "АВТ      1    100%",
    "Строка сообщения из УП",
    "Строка сообщений из УП",
    "*X  234.567 -110.000",
    "Z -1065.124   0.000",
    "*X  234.567 F= 10.00",
    "Z -1065.124 F=1000.",
    // РУЧ
    "РУЧ 1         100%",
    "R98=-12345",
    ">R99=5034",
    "R100=0",
    // ПБТ
    "ПБТ X         100%",
    "X   234.567#3.124",
    "*Z-1065.124#5.050",
    // УСТ
    "УСТ ПРЕДУСТАНОВКИ",
    "> 1 - КООРД.И СМЕЩЕНИЯ",
    "2 - ИСХОДНОЕ",
    "3 - ПОДНАЛАДКА",
    "4 - ПРАВКА",
    "5 - ШЛИФ.КРУГ",
    "6 - АЛМАЗ",
    "7 - ОСЦИЛЛЯЦИЯ",
    "8 - СКОРОСТИ",
    "9 - ОСЕВАЯ",
    "УСТ1 КООРД.И СМЕЩ.X",
    "Поясняющий текст",
    ">X=1205.124",
    "R224= -12.356",
    "R226=   1.234",
    "R228=-1043.038",
    "R230=   5.124",
    "ТЕКУЩАЯ КООРДИНАТА",
    "СУММА ПРАВОК",
    "КОРРЕКЦИЯ",
    "СМЕЩЕНИЕ НУЛЯ",
    "СМЕЩЕНИЕ МАХОВИКОМ",
    "УСТ2 ИСХОДНОЕ      X",
    "> R220=  12.356",
    "R221= 214.484",
    "MX: координата X",
    "MZ: координата Z",
    "MX: -123.456",
    "УСТ3 ПОДНАЛАДКА    Х",
    "> R218= 12",
    "R219= 21",
    "УСТ4 ПРАВКА ПЕРИФ.",
    "УСТ4 ПРАВКА ТОРЦА",
    "> R210= 0.030",
    "R212= 100.00",
    "DX ЧЕРН.ПРАВКИ",
    "DX ЧИСТ.ПРАВКИ",
    "FZ ЧЕРН.ПРАВКИ",
    "FZ ЧИСТ.ПРАВКИ",
    "DZ ЧЕРН.ПРАВКИ",
    "DZ ЧИСТ.ПРАВКИ",
    "FX ЧЕРН.ПРАВКИ",
    "FX ЧИСТ.ПРАВКИ",
    "УСТ5 ШЛИФ.КРУГ",
    "> R204= 600.000",
    "ДИАМЕТР НОВ.КРУГА",
    "MIN ДИАМЕТР КРУГА",
    "MAX ДИАМЕТР КРУГА",
    "ТЕК.ДИАМЕТР КРУГА",
    "УСТ6 АЛМАЗ",
    "NZ АЛМАЗА",
    "УСТ7 ОСЦИЛЛЯЦИЯ X",
    "УСТ7 ОСЦИЛЛЯЦИЯ Z",
    "-MX: координата X",
    "+MX: координата X",
    "-MZ: координата Z",
    "+MZ: координата Z",
    "СКОРОСТЬ ОСЦИЛЛЯЦИИ",
    "ЗАДЕРЖКА РЕВЕРСА,СЕК",
    "-РЕВЕРС ТОЧНО",
    "+РЕВЕРС ТОЧНО",
    "ТОЧКА ЗАВЕРШЕНИЯ",
    "ХОДЫ ВЫХАЖИВАНИЯ",
    "УСТ8 ДОП.СКОРОСТИ X",
    "ДОП.СКОРОСТЬ 1",
    "ДОП.СКОРОСТЬ 4",
    "УСТ9 ОСЕВ.ОРИЕНТАЦИЯ",
    "РАССТОЯНИЕ КРУГ-ЩУП",
    "НАПРАВЛЕНИЕ ОРИЕНТ.",
    "СМЕЩЕНИЕ ПОЗ.НАЧАЛА",
    "ДОПУСК",
    "СКОРОСТЬ НАЧАЛА",
    "СКОРОСТЬ ОКОНЧАНИЯ",
    "X-ПОЗИЦИЯ",
    "Z-ПОЗИЦИЯ",
    "R165= -1",
    // ПАР
    "ПАРАМЕТРЫ СТАНКА",
    "Наименование параметра",
    "N005 >X=   0.001",
    "N057  Z=   0.001",
    "№123  1234.567",
    // УП
    "РЕДАКТИРОВАНИЕ УП",
    "ПРОГРАММА 7",
    "> КАТАЛОГ",
    "ОЧИСТИТЬ УП",
    "УП ЗАПОРЧЕНА",
    "L1",
    "L21",
    "> L34",
    "N12 G  G  G  #",
    "M  M  M  L",
    "X5.342    F=50.00",
    "Z-1234.678F=1000.00",
    "N12  R123",
    "=R1",
    "+12",
    "N202 IF R1>0",
    "GOTO 301",
    "N207 GOTO 33",
    "/N12",
    "N G G G #",
    "Укажите тип кадра",
    "1-вычислит.кадр",
    "2-кадр усл.перехода",
    "3-кадр безусл.перех",
    "R123=R1+12",
    "R5=R1*2/R3-4",
    // ДАН
    "УПРАВЛЕНИЕ ДАННЫМИ",
    "> ОЧИСТКА С-ПАРАМ",
    "ОЧИСТКА R-ПАРАМ",
    "РАБОТА С ПЭВМ",
    // symbols the texts use: arrows of the marker keys, quotes, degrees, sign
    "▲ ▼ ◀ ►",
    "◄ ▶",
    "«-»",
    "\"+\"",
    "°",
    "±0.010",
    "█",
};

} // namespace

class TestLcdFont : public QObject {
    Q_OBJECT
private slots:
    void coversPrintableAscii() {
        for (char32_t c = 0x20; c <= 0x7E; ++c)
            QVERIFY2(k528::panel::lcdCanShow(c), qPrintable(show(c)));
    }
    void coversCyrillic() {
        for (char32_t c = U'А'; c <= U'я'; ++c) // U+0410..U+044F: А..Я, а..я
            QVERIFY2(k528::panel::lcdCanShow(c), qPrintable(show(c)));
        QVERIFY(k528::panel::lcdCanShow(U'Ё'));
        QVERIFY(k528::panel::lcdCanShow(U'ё'));
    }
    void coversTheScreenSymbols() {
        for (char32_t c : std::u32string(U"▲▼◀►◄▶№°«»█±½←→↑↓"))
            QVERIFY2(k528::panel::lcdCanShow(c), qPrintable(show(c)));
    }
    void coversEveryTextOfTheManualsScreens() {
        for (const char* text : kManualScreens) {
            const auto bad = k528::panel::lcdFirstUnsupported(text);
            QVERIFY2(!bad, qPrintable(QString::fromUtf8(text) + ": " + show(bad.value_or(0))));
        }
    }
    void coversEveryCatalogTextShownOnThePanel() {
        int texts = 0;
        const auto check = [&texts](std::string_view text, const QString& where) {
            ++texts;
            const auto bad = k528::panel::lcdFirstUnsupported(text);
            QVERIFY2(!bad, qPrintable(
                               where + " «" +
                               QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size())) +
                               "»: " + show(bad.value_or(0))));
        };
        for (const auto& c : k528::catalog::cParams()) {
            check(c.name, QStringLiteral("C%1 name").arg(c.number));
            check(c.nameEn, QStringLiteral("C%1 English name").arg(c.number));
            check(c.hintRu, QStringLiteral("C%1 hint").arg(c.number));
            check(c.hintEn, QStringLiteral("C%1 English hint").arg(c.number));
        }
        for (const auto& m : k528::catalog::positionerMessages()) {
            check(m.panelText(), QStringLiteral("message %1").arg(m.number));
            check(m.textEn, QStringLiteral("message %1 (English)").arg(m.number));
        }
        for (const auto& m : k528::catalog::panelMessages()) {
            check(m.textRu, QStringLiteral("panel message"));
            check(m.textEn, QStringLiteral("panel message (English)"));
        }
        QVERIFY(texts > 600);
    }

    void glyphsFitFiveBySeven() {
        for (char32_t c : k528::panel::lcdCharacters()) {
            const Glyph g = *k528::panel::lcdGlyph(c);
            for (std::uint8_t row : g.rows)
                QVERIFY2((row & ~0x1Fu) == 0, qPrintable(show(c)));
            if (c == U'█')
                continue; // the block fills the whole cell, cursor line included
            QVERIFY2(g.rows[7] == 0, qPrintable(show(c) + " uses the cursor line"));
            if (c != U' ')
                QVERIFY2(g.litDots() > 0, qPrintable(show(c) + " is empty"));
        }
        QCOMPARE(k528::panel::lcdBlockGlyph().litDots(), 40);
        QCOMPARE(*k528::panel::lcdGlyph(U'█'), k528::panel::lcdBlockGlyph());
        QCOMPARE(k528::panel::lcdGlyph(U' ')->litDots(), 0);
    }

    void distinctCharactersHaveDistinctGlyphs() {
        // Only the declared look-alikes share a glyph: Cyrillic letters drawn
        // as the Latin letter of the same form, as in the real Cyrillic ROMs.
        std::set<std::pair<char32_t, char32_t>> declared;
        for (const auto& [c, latin] : k528::panel::lcdLookAlikes()) {
            QVERIFY2(c >= 0x400 && c <= 0x4FF, qPrintable(show(c) + " is not Cyrillic"));
            QVERIFY2(latin < 0x80, qPrintable(show(latin) + " is not Latin"));
            declared.insert({c, latin});
        }
        const std::set<std::pair<char32_t, char32_t>> expected = {
            {U'А', U'A'}, {U'В', U'B'}, {U'Е', U'E'}, {U'К', U'K'}, {U'М', U'M'}, {U'Н', U'H'},
            {U'О', U'O'}, {U'Р', U'P'}, {U'С', U'C'}, {U'Т', U'T'}, {U'Х', U'X'}, {U'а', U'a'},
            {U'е', U'e'}, {U'о', U'o'}, {U'р', U'p'}, {U'с', U'c'}, {U'у', U'y'}, {U'х', U'x'},
        };
        QVERIFY(declared == expected);

        const auto chars = k528::panel::lcdCharacters();
        QVERIFY(chars.size() > 95 + 66 + 10);
        for (std::size_t i = 0; i < chars.size(); ++i) {
            for (std::size_t j = i + 1; j < chars.size(); ++j) {
                if (*k528::panel::lcdGlyph(chars[i]) != *k528::panel::lcdGlyph(chars[j]))
                    continue;
                const bool ok =
                    declared.count({chars[i], chars[j]}) || declared.count({chars[j], chars[i]});
                QVERIFY2(ok,
                         qPrintable(show(chars[i]) + " and " + show(chars[j]) + " look the same"));
            }
        }
        // Digits and the letters they could be taken for.
        for (auto [a, b] : {std::pair{U'0', U'О'},
                            {U'3', U'З'},
                            {U'6', U'б'},
                            {U'4', U'Ч'},
                            {U'b', U'Ь'},
                            {U'n', U'п'}})
            QVERIFY2(*k528::panel::lcdGlyph(a) != *k528::panel::lcdGlyph(b),
                     qPrintable(show(a) + show(b)));
    }

    void glyphsAreTheDesignedOnes() {
        // A few glyphs written out here again: a slip in the table shows.
        const auto rows = [](std::initializer_list<const char*> lines) {
            Glyph g;
            int y = 0;
            for (const char* line : lines) {
                for (int x = 0; x < 5; ++x)
                    if (line[x] == '#')
                        g.rows[static_cast<std::size_t>(y)] |=
                            static_cast<std::uint8_t>(1u << (4 - x));
                ++y;
            }
            return g;
        };
        QCOMPARE(*k528::panel::lcdGlyph(U'A'),
                 rows({".###.", "#...#", "#...#", "#...#", "#####", "#...#", "#...#", "....."}));
        QCOMPARE(*k528::panel::lcdGlyph(U'Ж'),
                 rows({"#.#.#", "#.#.#", "#.#.#", ".###.", "#.#.#", "#.#.#", "#.#.#", "....."}));
        QCOMPARE(*k528::panel::lcdGlyph(U'Я'),
                 rows({".####", "#...#", "#...#", ".####", "..#.#", ".#..#", "#...#", "....."}));
        QCOMPARE(*k528::panel::lcdGlyph(U'д'),
                 rows({".....", ".....", "..##.", ".#.#.", ".#.#.", "#####", "#...#", "....."}));
        QCOMPARE(*k528::panel::lcdGlyph(U'▲'),
                 rows({".....", ".....", "..#..", ".###.", "#####", ".....", ".....", "....."}));
        QVERIFY(k528::panel::lcdGlyph(U'A')->dot(0, 1));
        QVERIFY(!k528::panel::lcdGlyph(U'A')->dot(0, 0));
        QVERIFY(!k528::panel::lcdGlyph(U'A')->dot(5, 1)); // outside the cell
    }

    void variantsAreDrawnAsTheRomCharacter() {
        QCOMPARE(*k528::panel::lcdGlyph(U'◄'), *k528::panel::lcdGlyph(U'◀'));
        QCOMPARE(*k528::panel::lcdGlyph(U'▶'), *k528::panel::lcdGlyph(U'►'));
        QCOMPARE(*k528::panel::lcdGlyph(U'–'), *k528::panel::lcdGlyph(U'-'));
        QCOMPARE(*k528::panel::lcdGlyph(U'”'), *k528::panel::lcdGlyph(U'"'));
        QCOMPARE(*k528::panel::lcdGlyph(U'\u00A0'), *k528::panel::lcdGlyph(U' '));
        QCOMPARE(k528::panel::lcdCanonical(U'Q'), U'Q');
    }

    void unknownCharactersShowAPlaceholder() {
        for (char32_t c : std::u32string(U"€ΩЇ\u2603\t\n"))
            QVERIFY2(!k528::panel::lcdCanShow(c), qPrintable(show(c)));
        const Glyph box = k528::panel::lcdPlaceholderGlyph();
        QCOMPARE(k528::panel::lcdGlyphOrPlaceholder(U'€'), box);
        QCOMPARE(k528::panel::lcdGlyphOrPlaceholder(U'Ж'), *k528::panel::lcdGlyph(U'Ж'));
        QVERIFY(box.litDots() >= 16);
        for (char32_t c : k528::panel::lcdCharacters())
            QVERIFY2(*k528::panel::lcdGlyph(c) != box,
                     qPrintable(show(c) + " looks like the placeholder"));
        QCOMPARE(k528::panel::lcdFirstUnsupported("АВТ € 100%"), std::optional<char32_t>(U'€'));
        QCOMPARE(k528::panel::lcdFirstUnsupported("\xFF"), std::optional<char32_t>(U'\uFFFD'));
        QVERIFY(!k528::panel::lcdFirstUnsupported(""));
    }
};

QTEST_APPLESS_MAIN(TestLcdFont)
#include "test_lcd_font.moc"
