// The machine file: exact round trips and rejection of every kind of bad file.
#include "catalog/cparams.h"
#include "profile/english.h"
#include "catalog/rparams.h"
#include "profile/builtin.h"
#include "profile/text_format.h"
#include "profile/tools.h"
#include "profile/validate.h"
#include "util/utf8.h"

#include <QtTest>
#include <random>

using namespace k528;
using namespace k528::profile;

namespace {

// A random text of `maxChars` characters at most from Cyrillic, Latin,
// digits and punctuation (';', '=', '#' and quotes included).
std::string randomText(std::mt19937& rng, int maxChars, bool leadingBlankOk) {
    static const std::u32string alphabet =
        U"АБВГДЕЁЖЗИЙКЛМНОПРСТУФХЦЧШЩЪЫЬЭЮЯабвгдежзийклмнопрстуфхцчшщъыьэюяABCXYZabcxyz0123456789 "
        U".,;:=#%\"'()-+/*!?<>[]«»№";
    std::uniform_int_distribution<int> len(1, maxChars);
    std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1);
    std::string out;
    const int n = len(rng);
    for (int i = 0; i < n; ++i)
        utf8::append(out, alphabet[pick(rng)]);
    while (!out.empty() && out.back() == ' ')
        out.pop_back();
    if (out.empty())
        out = "Ж";
    if (!leadingBlankOk && out.front() == ' ')
        out[0] = 'x';
    return out;
}

std::string randomProgram(std::mt19937& rng, int number) {
    std::uniform_int_distribution<int> lines(1, 30), coin(0, 3);
    std::string text;
    if (coin(rng) != 0)
        text += (coin(rng) ? "%L" : "%l") + std::to_string(number) + " (" +
                randomText(rng, 20, false) + ")\n";
    const int n = lines(rng);
    for (int i = 0; i < n; ++i) {
        switch (coin(rng)) {
        case 0:
            text += "\n"; // blank lines are kept
            break;
        case 1:
            text += "N" + std::to_string(i + 1) + " G1 X" + std::to_string(i) + ".5 FX100 ; " +
                    randomText(rng, 15, true) + "\n";
            break;
        case 2:
            text += "   " + randomText(rng, 40, true) + "  \n"; // trailing blanks are kept
            break;
        default:
            text += "R" + std::to_string(i) + "=R1+" + std::to_string(i * 7) + "\n";
            break;
        }
    }
    // Never a line starting with '[', never a second header.
    std::string safe;
    std::size_t pos = 0;
    bool first = true;
    while (pos < text.size()) {
        const auto end = text.find('\n', pos);
        std::string line = text.substr(pos, end - pos);
        pos = end + 1;
        const auto lead = line.find_first_not_of(" \t");
        if (lead != std::string::npos && line[lead] == '[')
            line[lead] = '(';
        if (!first && programHeaderNumber(line))
            line = ";" + line;
        if (line.find("%M") != std::string::npos || line.find("%m") != std::string::npos)
            line = "; messages";
        first = false;
        safe += line + "\n";
    }
    if (safe.find_first_not_of(" \t\n") == std::string::npos)
        safe += "M30\n";
    return safe;
}

MachineProfile randomProfile(std::mt19937& rng) {
    MachineProfile p;
    std::uniform_int_distribution<int> coin(0, 1), small(0, 20);
    p.name = "random-" + std::to_string(rng() % 100000);
    p.title = coin(rng) ? randomText(rng, 60, false) : std::string();
    for (const catalog::CParamDef& d : catalog::cParams()) {
        std::uniform_int_distribution<std::int64_t> v(d.min, d.max);
        p.setC(d.number, v(rng));
    }
    std::uniform_int_distribution<int> rn(0, 299);
    std::uniform_int_distribution<std::int64_t> rv(catalog::kRMin, catalog::kRMax);
    for (int i = small(rng); i > 0; --i) {
        const int n = rn(rng);
        if (!catalog::rParam(n).readOnly())
            p.r[n] = rv(rng);
    }
    std::uniform_int_distribution<int> prog(1, 99);
    for (int i = small(rng) / 4; i > 0; --i) {
        const int n = prog(rng);
        p.programs[n] = randomProgram(rng, n);
    }
    for (int i = small(rng); i > 0; --i)
        p.messages[prog(rng)] = randomText(rng, 20, true);
    for (catalog::PlcGroup g : catalog::kPlcGroups) {
        std::uniform_int_distribution<int> k(1, catalog::plcMessageCount(g));
        for (int i = small(rng) / 2; i > 0; --i)
            p.plcTexts(g)[k(rng)] = randomText(rng, 40, true);
    }
    p.simulation.setInt("tick_ms", 1 + small(rng));
    for (int i = small(rng) / 3; i > 0; --i) {
        std::string key = "k" + std::to_string(rng() % 1000) + (coin(rng) ? ".sub_key" : "");
        std::string value = randomText(rng, 30, false);
        for (auto& ch : value)
            if (ch == ';')
                ch = ',';
        while (!value.empty() && value.back() == ' ')
            value.pop_back();
        if (value.empty())
            value = "v";
        p.simulation.set(key, value);
    }
    return p;
}

// Replaces the first line equal to `from` by `to` (several lines allowed).
std::string replaceLine(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find("\n" + from + "\n");
    if (at == std::string::npos)
        throw std::runtime_error("line not found: " + from);
    return text.replace(at + 1, from.size(), to);
}

int lineOf(const std::string& text, const std::string& line) {
    const auto at = text.find("\n" + line + "\n");
    if (at == std::string::npos)
        throw std::runtime_error("line not found: " + line);
    return 2 +
           static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

} // namespace

class TestTextFormat : public QObject {
    Q_OBJECT
private slots:
    void builtinRoundTrip() {
        for (const std::string& name : builtinNames()) {
            const MachineProfile p = builtin(name);
            const std::string text = writeMachineText(p);
            const MachineProfile back = readMachineText(text);
            QCOMPARE(back, p);
            QCOMPARE(writeMachineText(back), text);
        }
    }

    void randomizedRoundTrip() {
        std::mt19937 rng(528);
        for (int i = 0; i < 300; ++i) {
            const MachineProfile p = randomProfile(rng);
            for (const Finding& f : validate(p))
                QVERIFY2(f.severity == Severity::Warning || !f.cParams.empty(),
                         formatFinding(f).c_str());
            const std::string text = writeMachineText(p);
            MachineProfile back;
            try {
                back = readMachineText(text, "random");
            } catch (const FileError& e) {
                QFAIL(e.what());
            }
            QVERIFY2(back == p, ("profile " + std::to_string(i)).c_str());
            QCOMPARE(writeMachineText(back), text);
        }
    }

    void formatDetails() {
        const std::string text = writeMachineText(builtin("grinder-205"));
        QVERIFY(text.find("\nC022=2000 ; УСКОРЕНИЕ 1\n") != std::string::npos);
        QVERIFY(text.find("\nC046=-1000 ; -ОГРАНИЧЕН\n") != std::string::npos);
        QVERIFY(text.find("\nR204=20000 ; ДИАМЕТР НОВ.КРУГА = 20.000 мм\n") != std::string::npos);
        QVERIFY(text.find("\n[program 14]\n%L14 (ПРАВКА КРУГА)\n") != std::string::npos);
        QVERIFY(text.find("\n[end program]\n") != std::string::npos);
        QVERIFY(text.find("\n#7=ПРАВКА КРУГА\n") != std::string::npos);
        QVERIFY(text.find("\nA01=") != std::string::npos);
        QVERIFY(text.find("\n[simulation]\nmachine=grinder-205\ntick_ms=1\nnesting_limit=8\n") != std::string::npos);
    }

    // Each text for people may have its English beside it (title.en=,
    // #k.en=, A01.en=, tool.n.name.en=): read, written back in place, kept
    // as settings; a reader of English gets it, of Russian the Russian.
    void englishBesideRussian() {
        const MachineProfile lathe = builtin("training-lathe");
        QCOMPARE(titleText(lathe, false), lathe.title);
        QCOMPARE(titleText(lathe, true), std::string("Training lathe with the K528-05 (X on diameter, Z)"));
        QCOMPARE(messageText(lathe, 1, false), std::string("ПОДВОД"));
        QCOMPARE(messageText(lathe, 1, true), std::string("APPROACH"));
        QCOMPARE(plcText(lathe, catalog::PlcGroup::Alarm, 1, false), std::string("Патрон не зажат"));
        QCOMPARE(plcText(lathe, catalog::PlcGroup::Alarm, 1, true), std::string("Chuck not clamped"));
        QCOMPARE(plcText(lathe, catalog::PlcGroup::Work, 32, true), std::string("Program running"));
        QCOMPARE(plcText(lathe, catalog::PlcGroup::System, 4, true), std::string("PLC module failed, slot 3"));
        QCOMPARE(toolName(lathe, tools(lathe).front(), true), std::string("Straight turning tool T15K6"));
        QCOMPARE(toolName(lathe, tools(lathe).front(), false), std::string("Резец проходной упорный Т15К6"));
        QCOMPARE(lathe.simulation.getString("text.en.a01", ""), std::string("Chuck not clamped"));
        // Every bundled machine's every text for people has its English.
        for (const std::string& name : builtinNames()) {
            const MachineProfile p = builtin(name);
            const auto has = [&](const std::string& item) {
                QVERIFY2(p.simulation.has(englishKey(item)), (name + " " + item).c_str());
            };
            has("title");
            for (const auto& [n, text] : p.messages)
                has("#" + std::to_string(n));
            for (catalog::PlcGroup g : catalog::kPlcGroups)
                for (const auto& [k, text] : p.plcTexts(g))
                    has(std::string(1, catalog::plcGroupLetter(g)) + (k < 10 ? "0" : "") + std::to_string(k));
            for (const Tool& t : tools(p))
                QVERIFY2(t.name.empty() || toolName(p, t, true) != t.name, (name + " tool " + std::to_string(t.station)).c_str());
            for (const Finding& f : validate(p))
                QVERIFY2(f.severity != Severity::Warning || formatFinding(f).find("text.en") == std::string::npos,
                         formatFinding(f).c_str());
        }
        // Written beside the Russian, never among the settings.
        const std::string text = writeMachineText(lathe);
        QVERIFY(text.find("\ntitle=Учебный токарный станок с К528-05 (X на диаметр, Z)\n"
                          "title.en=Training lathe with the K528-05 (X on diameter, Z)\n") != std::string::npos);
        QVERIFY(text.find("\n#1=ПОДВОД\n#1.en=APPROACH\n#2=ТОРЦОВКА\n") != std::string::npos);
        QVERIFY(text.find("\nA01=Патрон не зажат\nA01.en=Chuck not clamped\nA02=") != std::string::npos);
        QVERIFY(text.find("\ntool.1.name.en=Straight turning tool T15K6\n") != std::string::npos);
        QVERIFY(text.find("text.en.") == std::string::npos);
        // Without an English a reader of English gets the Russian.
        MachineProfile plain = lathe;
        QVERIFY(plain.simulation.erase(englishKey("A01")));
        QVERIFY(plain.simulation.erase(englishKey("title")));
        QCOMPARE(plcText(plain, catalog::PlcGroup::Alarm, 1, true), std::string("Патрон не зажат"));
        QCOMPARE(titleText(plain, true), lathe.title);
        QVERIFY(!(plain == lathe)); // the English is part of the machine
        const std::string plainText = writeMachineText(plain);
        QVERIFY(plainText.find("A01.en=") == std::string::npos);
        QCOMPARE(readMachineText(plainText), plain);
        // Item names and their settings.
        QCOMPARE(englishKey("#12"), std::string("text.en.m12"));
        QCOMPARE(englishKey("W05"), std::string("text.en.w05"));
        QCOMPARE(englishKey("#100"), std::string());
        QCOMPARE(englishKey("A33"), std::string());
        QCOMPARE(englishItem("text.en.s16"), std::string("S16"));
        QCOMPARE(englishItem("text.en.s17"), std::string());
    }

    // Comments are ignored, keys may be written loosely, CRLF is fine.
    void lenientReading() {
        const MachineProfile lathe = builtin("training-lathe");
        std::string text = writeMachineText(lathe);
        text = replaceLine(text, "C022=10666 ; УСКОРЕНИЕ 1",
                           "  c22 = 10666   ; whatever the comment says");
        text = replaceLine(text, "[c]", "; a comment line\n[c]\n\n");
        std::string crlf;
        for (char ch : text) {
            if (ch == '\n')
                crlf += '\r';
            crlf += ch;
        }
        QCOMPARE(readMachineText(text), lathe);
        QCOMPARE(readMachineText(crlf), lathe);
        QCOMPARE(readMachineText("\xEF\xBB\xBF" + text), lathe);
    }

    void badFilesRejectedWithTheirLine_data() {
        QTest::addColumn<QString>("from");
        QTest::addColumn<QString>("to");
        QTest::addColumn<int>("lineShift"); // the error's line relative to the replaced line
        QTest::addColumn<QString>("says");
        const auto row = [](const char* name, const char* from, const char* to, int shift,
                            const char* says) {
            QTest::newRow(name) << QString::fromUtf8(from) << QString::fromUtf8(to) << shift
                                << QString::fromUtf8(says);
        };
        row("unknown section", "[r]", "[rr]", 0, "unknown section [rr]");
        row("unknown C key", "C022=10666 ; УСКОРЕНИЕ 1", "C153=10666", 0, "unknown key 'C153'");
        row("C out of range", "C022=10666 ; УСКОРЕНИЕ 1", "C022=40000", 0,
            "outside the range 0...32767");
        row("flag out of range", "C001=1 ; НАЛИЧ.ОСИ", "C001=2", 0, "outside the range 0...1");
        row("reserved not zero", "C015=0 ; Резерв", "C015=1", 0, "outside the range 0...0");
        row("C not a number", "C022=10666 ; УСКОРЕНИЕ 1", "C022=20.5", 0, "not a whole number");
        row("C duplicate", "C023=22222 ; УСКОРЕНИЕ 2", "C023=22222\nC022=1", 1,
            "C022 is given twice");
        row("no equals", "C022=10666 ; УСКОРЕНИЕ 1", "C022 10666", 0, "expected key=value");
        row("missing C", "C015=0 ; Резерв", "", -1, "lacks C015");
        row("R read only", "R220=200000 ; MX: координата X = 200.000 мм", "R240=1", 0, "read-only");
        row("R out of 32 bits", "R220=200000 ; MX: координата X = 200.000 мм", "R220=3000000000", 0,
            "32-bit");
        row("R unknown", "R220=200000 ; MX: координата X = 200.000 мм", "R300=1", 0,
            "unknown key 'R300'");
        row("message too long", "#1=ПОДВОД", "#1=ОЧЕНЬ ДЛИННОЕ СООБЩЕНИЕ", 0, "more than 20");
        row("message number", "#1=ПОДВОД", "#100=ПОДВОД", 0, "outside #1..#99");
        row("message duplicate", "#2=ТОРЦОВКА", "#1=ТОРЦОВКА", 0, "#1 is given twice");
        row("message blank end", "#1=ПОДВОД", "#1=ПОДВОД ", 0, "ends with a blank");
        row("PLC number", "A01=Патрон не зажат", "A33=Патрон не зажат", 0, "1..32");
        row("PLC group", "A01=Патрон не зажат", "X01=Патрон не зажат", 0, "A01..A32");
        row("PLC too long", "A01=Патрон не зажат",
            "A01=Патрон не зажат, проверьте давление в цилиндре", 0, "more than 40");
        row("setting bad value", "tick_ms=1", "tick_ms=one", 0, "not a whole number");
        row("setting out of range", "tick_ms=1", "tick_ms=0", 0, "outside 1..100");
        row("setting bad key", "tick_ms=1", "Tick=1", 0, "does not start with a letter");
        row("setting duplicate", "nesting_limit=8", "tick_ms=2", 0, "tick_ms is given twice");
        row("format", "format=1", "format=2", 0, "format 2");
        row("machine key", "format=1", "format=1\nauthor=me", 1, "unknown key 'author'");
        row("bad name", "name=training-lathe", "name=Training Lathe", 0, "name 'Training Lathe'");
        row("no name", "name=training-lathe", "", -1, "no name=");
        row("duplicate section", "[r]", "[c]", 0, "[c] is given twice");
        row("stray end", "[messages]", "[end program]", 0, "without [program N]");
        row("program number", "[program 90]", "[program 100]", 0, "1..99");
        row("program header mismatch", "%L90 (ВЫХОД В ИСХОДНОЕ ПОЛОЖЕНИЕ)", "%L9 (ВЫХОД)", -1,
            "header of program L9");
        row("program duplicate", "[program 91]", "[program 90]", 0, "[program 90] is given twice");
        row("line outside section", "[end program]", "[end program]\nC001=1", 1,
            "outside any section");
        row("header without bracket", "[r]", "[r", 0, "without ']'");
        // English beside a Russian text.
        row("English without Russian", "#9.en=MACHINE WARM-UP", "#10.en=MACHINE WARM-UP", 0,
            "#10.en without its Russian #10");
        row("English too long", "#1.en=APPROACH", "#1.en=APPROACH THE PART SLOWLY", 0, "more than 20");
        row("English PLC too long", "A01.en=Chuck not clamped",
            "A01.en=Chuck not clamped: check the cylinder pressure", 0, "more than 40");
        row("English with a semicolon", "A01.en=Chuck not clamped", "A01.en=Chuck; not clamped", 0,
            "text.en.a01");
        row("English twice", "#1.en=APPROACH", "#1.en=APPROACH\n#1.en=FEED", 1, "#1.en is given twice");
        row("English among the settings", "tick_ms=1", "text.en.title=Lathe", 0,
            "text.en.title is written beside its Russian text: title.en=");
        row("English of no text", "A01.en=Chuck not clamped", "A33.en=Chuck not clamped", 0, "1..32");
    }

    void badFilesRejectedWithTheirLine() {
        QFETCH(QString, from);
        QFETCH(QString, to);
        QFETCH(int, lineShift);
        QFETCH(QString, says);
        const std::string good = writeMachineText(builtin("training-lathe"));
        const std::string f = from.toStdString();
        int expectedLine = lineOf(good, f) + lineShift;
        std::string bad;
        if (to.isEmpty()) {
            bad = good;
            bad.erase(bad.find("\n" + f + "\n") + 1, f.size() + 1);
        } else {
            bad = replaceLine(good, f, to.toStdString());
        }
        // A missing line is reported at its section's header.
        if (to.isEmpty() && f == "C015=0 ; Резерв")
            expectedLine = lineOf(good, "[c]");
        if (to.isEmpty() && f == "name=training-lathe")
            expectedLine = lineOf(good, "[machine]");
        try {
            readMachineText(bad, "bad.k528m");
            QFAIL("the bad file was accepted");
        } catch (const FileError& e) {
            QVERIFY2(e.message().find(says.toStdString()) != std::string::npos, e.what());
            QVERIFY2(
                e.line() == expectedLine,
                (std::string(e.what()) + " expected line " + std::to_string(expectedLine)).c_str());
            QVERIFY(std::string(e.what()).rfind("bad.k528m:", 0) == 0);
        }
    }

    // A program whose [end program] is missing runs into the next section:
    // the error names that line.
    void missingEndProgramNamesTheNextSection() {
        const std::string good = writeMachineText(builtin("training-lathe"));
        const std::string bad = replaceLine(good, "[end program]", "");
        try {
            readMachineText(bad);
            QFAIL("accepted");
        } catch (const FileError& e) {
            // The emptied line stays a (blank) program line: [program 90] keeps its number.
            QCOMPARE(e.line(), lineOf(good, "[program 90]"));
            QVERIFY(e.message().find("missing [end program] for program 1") != std::string::npos);
        }
    }

    void emptyAndTruncatedFiles() {
        QVERIFY_THROWS_EXCEPTION(FileError, readMachineText(""));
        QVERIFY_THROWS_EXCEPTION(FileError, readMachineText("[machine]\nformat=1\nname=a\n"));
        try {
            readMachineText("[machine]\nname=a\n[c]\n");
            QFAIL("accepted");
        } catch (const FileError& e) {
            QCOMPARE(e.line(), 1);
            QVERIFY(e.message().find("format=1") != std::string::npos);
        }
        try {
            readMachineText(writeMachineText(builtin("grinder-205")) + "[messages]\n");
            QFAIL("accepted");
        } catch (const FileError& e) {
            QVERIFY(e.message().find("[messages] is given twice") != std::string::npos);
        }
        {
            std::string bad = writeMachineText(builtin("grinder-205"));
            const auto at = bad.find("#1=ПОДВОД");
            bad.replace(at + 3, 2, "\xff\xfe"); // invalid UTF-8 in place of «П»
            const int line = 1 + static_cast<int>(std::count(
                                     bad.begin(), bad.begin() + static_cast<long>(at), '\n'));
            try {
                readMachineText(bad);
                QFAIL("accepted");
            } catch (const FileError& e) {
                QCOMPARE(e.line(), line);
                QVERIFY(e.message().find("UTF-8") != std::string::npos);
            }
        }
        try {
            readMachineText("C001=1\n");
            QFAIL("accepted");
        } catch (const FileError& e) {
            QCOMPARE(e.line(), 1);
        }
    }

    void programsAsOneFile() {
        const MachineProfile p = builtin("training-lathe");
        const std::string all = programsFileText(p);
        QVERIFY(all.rfind("%L1 (", 0) == 0);
        QVERIFY(all.find("\n%L90 (") != std::string::npos);
        QVERIFY(all.find("\n%MESSAGES\n#1=ПОДВОД\n") != std::string::npos);
        MachineProfile bare;
        bare.programs[7] = "N1 G0 X1\n";
        QCOMPARE(programsFileText(bare), std::string("%L7\nN1 G0 X1\n"));
    }
};

QTEST_APPLESS_MAIN(TestTextFormat)
#include "test_text_format.moc"
