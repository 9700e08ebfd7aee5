// The C-parameter definitions of appendix Е, table Е.1.
#include "catalog/cparams.h"
#include "util/utf8.h"

#include <QtTest>
#include <set>
#include <string>

using namespace k528;
using namespace k528::catalog;

namespace {

bool isLatin(char32_t c) {
    return (c >= U'A' && c <= U'Z') || (c >= U'a' && c <= U'z');
}
bool isCyrillic(char32_t c) {
    return c >= 0x400 && c <= 0x4ff;
}

// Words (letters and digits) that mix Latin and Cyrillic letters: the OCR's
// homoglyph slips («Kд», «Tразг», «CPЗ4»).
std::string mixedWord(std::string_view text) {
    std::u32string word;
    const auto flush = [&]() -> std::string {
        bool lat = false, cyr = false;
        for (char32_t c : word) {
            lat = lat || isLatin(c);
            cyr = cyr || isCyrillic(c);
        }
        std::string w = utf8::encode(std::vector<char32_t>(word.begin(), word.end()));
        word.clear();
        return lat && cyr ? w : std::string();
    };
    for (char32_t c : utf8::decode(text)) {
        if (isLatin(c) || isCyrillic(c) || (c >= U'0' && c <= U'9')) {
            word += c;
            continue;
        }
        if (auto w = flush(); !w.empty())
            return w;
    }
    return flush();
}

} // namespace

class TestCParams : public QObject {
    Q_OBJECT
private slots:
    void allDefinitionsNumbered() {
        QCOMPARE(cParams().size(), std::size_t(152));
        for (std::size_t i = 0; i < cParams().size(); ++i)
            QCOMPARE(cParams()[i].number, int(i + 1));
        QCOMPARE(cParam(22).name, std::string_view("УСКОРЕНИЕ 1"));
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, cParam(0));
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, cParam(153));
        QVERIFY(findCParam(153) == nullptr);
        QCOMPARE(cParam(22).key(), std::string("C022"));
        QCOMPARE(cParam(152).key(), std::string("C152"));
    }

    void axesByBlock() {
        for (const CParamDef& d : cParams()) {
            const Axis expected = d.number <= 52    ? Axis::X
                                  : d.number <= 104 ? Axis::Z
                                                    : Axis::Common;
            QVERIFY2(d.axis == expected, d.key().c_str());
        }
    }

    // C(n) and C(n+52) are the same parameter for X and Z.
    void mirrorPairs() {
        for (int n = 1; n <= 52; ++n) {
            const CParamDef& x = cParam(n);
            const CParamDef& z = cParam(n + 52);
            // The names as printed: C48 «S кончика БТ», C100 «S конечника БТ».
            if (n != 48)
                QVERIFY2(x.name == z.name, x.key().c_str());
            QVERIFY2(x.nameEn == z.nameEn, x.key().c_str());
            QVERIFY2(x.kind == z.kind && x.unit == z.unit, x.key().c_str());
            QVERIFY2(x.min == z.min && x.max == z.max, x.key().c_str());
            QVERIFY2(x.address.form == z.address.form && x.address.bit == z.address.bit,
                     x.key().c_str());
            if (x.address.form != AddressForm::None)
                QVERIFY2(z.address.word == x.address.word + 50, x.key().c_str());
            QCOMPARE(counterpart(n), n + 52);
            QCOMPARE(counterpart(n + 52), n);
            QCOMPARE(axisParam(n, Axis::Z), n + 52);
        }
        QCOMPARE(counterpart(105), 0);
    }

    // Addresses grow with the number: bits of Z4100, words Z4101.., byte
    // pairs, two-word values take two words.
    void addressesIncrease() {
        long previous = -1;
        for (const CParamDef& d : cParams()) {
            const Address& a = d.address;
            long pos = 0;
            switch (a.form) {
            case AddressForm::None:
                continue;
            case AddressForm::Bit:
                pos = a.word * 100L + a.bit;
                break;
            case AddressForm::Word:
            case AddressForm::LowByte:
                pos = a.word * 100L;
                break;
            case AddressForm::HighByte:
                pos = a.word * 100L + 50;
                break;
            case AddressForm::TwoWords:
                pos = a.word * 100L;
                break;
            }
            QVERIFY2(pos > previous, d.key().c_str());
            previous = a.form == AddressForm::TwoWords ? (a.word + 1) * 100L : pos;
        }
    }

    void addressesAsPrinted() {
        QCOMPARE(cParam(1).address.text(), std::string("Z4100.0"));
        QCOMPARE(cParam(14).address.text(), std::string("Z4100.13"));
        QCOMPARE(cParam(15).address.text(), std::string("Z4100.14"));
        QCOMPARE(cParam(17).address.text(), std::string("Z4101")); // printed «41 01»
        QCOMPARE(cParam(22).address.text(), std::string("Z4106"));
        QCOMPARE(cParam(40).address.text(), std::string("Z4124, Z4125"));
        QCOMPARE(cParam(48).address.text(), std::string("Z4140, Z4141"));
        QCOMPARE(cParam(53).address.text(), std::string("Z4150.0"));
        QCOMPARE(cParam(91).address.text(), std::string("Z4173"));
        QCOMPARE(cParam(92).address.text(), std::string("Z4174, Z4175")); // printed «Z4173, Z4174»
        QCOMPARE(cParam(93).address.text(), std::string("Z4176, Z4177"));
        QCOMPARE(cParam(100).address.text(), std::string("Z4190, Z4191"));
        QCOMPARE(cParam(105).address.text(), std::string("Z4200"));
        QCOMPARE(cParam(107).address.text(), std::string("Z4202, Мл.байт"));
        QCOMPARE(cParam(108).address.text(), std::string("Z4202, Ст.байт"));
        QCOMPARE(cParam(108).address.textEn(), std::string("Z4202 high byte"));
        QCOMPARE(cParam(122).address.text(), std::string("Z4209, Ст.байт"));
        QCOMPARE(cParam(125).address.text(), std::string("Z4210.2"));
        QCOMPARE(cParam(139).address.text(), std::string("Z4211, Мл.байт"));
        QCOMPARE(cParam(150).address.text(), std::string("Z4216, Ст.байт"));
        QCOMPARE(cParam(49).address.text(), std::string());
        QCOMPARE(cParam(151).address.text(), std::string());
    }

    void namesAsPrinted() {
        const std::pair<int, std::string_view> names[] = {
            {1, "НАЛИЧ.ОСИ"},
            {4, "0.0001"},
            {7, "ИНД.ДИАМЕТР"},
            {9, "ПБТ В \"-\""},
            {14, "Контр.ДОС в останове"},
            {17, "N ДОС"},
            {19, "L ИМП.ДОС"},
            {21, "T контроля ДОС"},
            {26, "К(СКОР)"},
            {27, "К(ОШИБ)"},
            {37, "S до поиска 0-метки"},
            {38, "S поиска 0-метки"},
            {42, "F УСК.АВТ."},
            {46, "-ОГРАНИЧЕН"},
            {48, "S кончика БТ"}, // as printed in its row (C100: «конечника»)
            {78, "К(СКОР)"},
            {100, "S конечника БТ"},
            {105, "N М1"},
            {107, "N Б.ВХ. X1"},
            {122, "N Б.ВХ. Z8"},
            {123, "ESC=сброс в исх.сост"},
            {124, "ESC =квитир.авар.БЦС"}, // as printed: exactly 20 characters
            {125, "ESC =квитир.сист.БЦС"}, // printed with 21: the blank after «=» goes
            {139, "Корректор по L1"},
            {143, "N ручного цикла 1"},
            {150, "N ручного цикла 8"},
            {151, "Резерв"},
        };
        for (const auto& [n, name] : names)
            QVERIFY2(cParam(n).name == name, cParam(n).key().c_str());
    }

    // The panel shows a name on one LCD line of 20 characters.
    void namesAndHintsFitTheLcd() {
        for (const CParamDef& d : cParams()) {
            QVERIFY2(utf8::length(d.name) <= 20, d.key().c_str());
            QVERIFY2(utf8::length(d.hintRu) <= 20, d.key().c_str());
            QVERIFY2(utf8::length(d.hintEn) <= 20, d.key().c_str());
            QVERIFY2(!d.name.empty() && !d.nameEn.empty(), d.key().c_str());
        }
    }

    void textsCleanOfMarkupAndOcrSlips() {
        for (const CParamDef& d : cParams()) {
            const std::string key = d.key();
            QVERIFY2(!d.descriptionRu.empty() && !d.descriptionEn.empty(), key.c_str());
            for (std::string_view text : {d.descriptionRu, d.name, d.hintRu}) {
                QVERIFY2(utf8::isValid(text), key.c_str());
                for (std::string_view bad :
                     {"<p>", "<b>", "</", "<math", "\\text", "_{", "^{", "  ", "кончик"})
                    // C48 prints «кончик» in its name and description (the manual's letters).
                    if (!(d.number == 48 && bad == "кончик"))
                        QVERIFY2(text.find(bad) == std::string_view::npos,
                                 (key + ": " + std::string(bad)).c_str());
                const std::string mixed = mixedWord(text);
                QVERIFY2(mixed.empty(), (key + ": mixed-script word " + mixed).c_str());
                QVERIFY2(text.find("CP3") == std::string_view::npos,
                         key.c_str()); // Latin module names
                QVERIFY2(text.find("СР32.03") == std::string_view::npos, key.c_str());
            }
        }
        QVERIFY(cParam(70).descriptionRu.find("СМ32.03") != std::string_view::npos);
        QVERIFY(cParam(107).descriptionRu.find("«быстрого входа» Вх1") != std::string_view::npos);
        QVERIFY(cParam(22).descriptionRu.find("0,8533 * Vmax / Тразг") != std::string_view::npos);
        QVERIFY(cParam(22).descriptionRu.find("м/сек²") != std::string_view::npos);
        QVERIFY(cParam(78).descriptionRu.find("Ke – коэффициент усиления по ошибке") !=
                std::string_view::npos);
    }

    void rangesPrintedAndDecided() {
        const struct {
            int n;
            std::int64_t min, max;
        } ranges[] = {
            {1, 0, 1},
            {17, 1, 4},
            {18, 1, 4},
            {19, 1, 32767},
            {20, 1, 32767},
            {21, 0, 32767},
            {22, 0, 32767},
            {29, 0, 2047},
            {30, 0, 32767},
            {31, 1, 255},
            {32, 0, 2500},
            {33, 1, 255},
            {34, -2047, 2047},
            {35, 0, 255},
            {36, 0, 2500},
            {39, -32767, 32767},
            {40, 0, 1200000},
            {44, 0, 1200000},
            {45, -9999999, 9999999},
            {47, -9999999, 9999999},
            {105, 1, 4},
            {106, 1, 4},
            {107, 0, 10},
            {114, 0, 10},
            {115, 0, 9},
            {122, 0, 9},
            {123, 0, 1},
            {139, 0, 10},
            {142, 0, 10},
            {143, 0, 99},
            {150, 0, 99},
            {15, 0, 0},
            {49, 0, 0},
            {126, 0, 0},
            {152, 0, 0},
        };
        for (const auto& r : ranges) {
            QVERIFY2(cParam(r.n).min == r.min && cParam(r.n).max == r.max,
                     cParam(r.n).key().c_str());
            QVERIFY(cParam(r.n).inRange(r.min) && cParam(r.n).inRange(r.max));
            QVERIFY(!cParam(r.n).inRange(r.max + 1) && !cParam(r.n).inRange(r.min - 1));
        }
    }

    void kindsAndUnits() {
        int reserved = 0, flags = 0;
        for (const CParamDef& d : cParams()) {
            if (d.kind == Kind::Reserved) {
                ++reserved;
                QVERIFY2(d.min == 0 && d.max == 0 && d.name == "Резерв", d.key().c_str());
            }
            if (d.kind == Kind::Flag) {
                ++flags;
                QVERIFY2(d.min == 0 && d.max == 1 && d.unit == Unit::Flag, d.key().c_str());
            }
        }
        // 15, 16, 49..52 per axis; 126..138, 151, 152.
        QCOMPARE(reserved, 2 * 6 + 13 + 2);
        QCOMPARE(flags, 2 * 14 + 3); // 1..14 per axis, 123..125
        // Note * of table Е.1: internal units.
        for (int n : {30, 31, 33, 82, 83, 85})
            QVERIFY(cParam(n).unit == Unit::InternalUnits);
        QVERIFY(cParam(40).unit == Unit::Speed && cParam(22).unit == Unit::Accel);
        QVERIFY(cParam(17).kind == Kind::Code && cParam(139).kind == Kind::Code);
        QVERIFY(cParam(143).unit == Unit::ProgramNumber);
        QCOMPARE(unitSymbol(Unit::Speed), std::string_view("10*disc/min"));
        QVERIFY(!unitRu(Unit::InternalUnits).empty() && !unitEn(Unit::InternalUnits).empty());
    }

    void notesForFixes() {
        for (int n : {17, 48, 70, 92, 105, 123, 124, 125})
            QVERIFY2(!cParam(n).note.empty(), cParam(n).key().c_str());
    }

    void lookUpByName() {
        QCOMPARE(findCParamByName("УСКОРЕНИЕ 1", Axis::X)->number, 22);
        QCOMPARE(findCParamByName("УСКОРЕНИЕ 1", Axis::Z)->number, 74);
        QCOMPARE(findCParamByName("K(СКОР)", Axis::Z)->number, 78); // Latin K
        QCOMPARE(findCParamByName("n дос", Axis::X)->number, 17);
        QCOMPARE(findCParamByName("N M2", Axis::Common)->number, 106); // Latin M
        QCOMPARE(findCParamByName("ESC =сброс в исх.сост", Axis::Common)->number, 123);
        QCOMPARE(findCParamByName("ОТМ=КВИТ.С.", Axis::Common)->number, 125);
        QCOMPARE(findCParamByName("S кончика БТ", Axis::Z)->number, 100);
        QCOMPARE(findCParamByName("S кончика БТ", Axis::X)->number, 48);
        QCOMPARE(findCParamByName("S конечника БТ", Axis::X)->number, 48);
        QCOMPARE(findCParamByName("S конечника БТ", Axis::Z)->number, 100);
        QVERIFY(findCParamByName("НЕТ ТАКОГО", Axis::X) == nullptr);
        QVERIFY(findCParamByName("Резерв", Axis::X) == nullptr);
    }
};

QTEST_APPLESS_MAIN(TestCParams)
#include "test_cparams.moc"
