// CSV of the machine constants, and the diff of two profiles.
#include "profile/builtin.h"
#include "profile/csv.h"
#include "profile/diff.h"
#include "profile/text_format.h"

#include <QtTest>

using namespace k528;
using namespace k528::profile;

namespace {

std::string replaceOnce(std::string s, const std::string& from, const std::string& to) {
    const auto at = s.find(from);
    if (at == std::string::npos)
        throw std::runtime_error("not found: " + from);
    return s.replace(at, from.size(), to);
}

void expectCsvError(const std::string& text, int line, const std::string& says) {
    try {
        readCParamsCsv(text, "c.csv");
        QFAIL("accepted");
    } catch (const FileError& e) {
        QVERIFY2(e.line() == line, e.what());
        QVERIFY2(e.message().find(says) != std::string::npos, e.what());
    }
}

} // namespace

class TestCsvDiff : public QObject {
    Q_OBJECT
private slots:
    void csvRoundTrip() {
        for (const std::string& name : builtinNames()) {
            const MachineProfile p = builtin(name);
            const std::string csv = writeCParamsCsv(p.cValues());
            const CValues back = readCParamsCsv(csv);
            QVERIFY(std::equal(back.begin(), back.end(), p.c.begin()));
            MachineProfile q;
            q.c = back;
            QCOMPARE(writeCParamsCsv(q.cValues()), csv);
        }
    }

    void csvDialect() {
        const std::string csv = writeCParamsCsv(builtin("grinder-205").cValues());
        QVERIFY(csv.rfind("number;axis;name;value;unit\n1;X;НАЛИЧ.ОСИ;1;flag\n", 0) == 0);
        QVERIFY(csv.find("\n9;X;\"ПБТ В \"\"-\"\"\";1;flag\n") != std::string::npos);
        QVERIFY(csv.find("\n22;X;УСКОРЕНИЕ 1;2000;25600*A/Kd\n") != std::string::npos);
        QVERIFY(csv.find("\n105;;N М1;2;channel\n") != std::string::npos);
        QVERIFY(csv.find("\n97;Z;ЗНАЧЕНИЕ БТ;190000;disc\n") != std::string::npos);
        // Rows in any order, CRLF, a byte-order mark, names as the user likes.
        std::string shuffled = replaceOnce(csv, "1;X;НАЛИЧ.ОСИ;1;flag\n", "");
        shuffled += "1;X;axis present;1;\r\n";
        const CValues back = readCParamsCsv("\xEF\xBB\xBF" + shuffled);
        QCOMPARE(back[1], std::int64_t(1));
        QCOMPARE(back[97], std::int64_t(190000));
    }

    void csvErrors() {
        const std::string csv = writeCParamsCsv(builtin("grinder-205").cValues());
        expectCsvError("num;axis\n", 1, "header");
        expectCsvError(replaceOnce(csv, "\n22;X;УСКОРЕНИЕ 1;2000;", "\n22;Z;УСКОРЕНИЕ 1;2000;"), 23,
                       "axis");
        expectCsvError(replaceOnce(csv, "\n22;X;УСКОРЕНИЕ 1;2000;", "\n22;X;УСКОРЕНИЕ 1;99999;"),
                       23, "outside");
        expectCsvError(replaceOnce(csv, "\n22;X;УСКОРЕНИЕ 1;2000;", "\n22;X;УСКОРЕНИЕ 1;2 000;"),
                       23, "not a whole number");
        expectCsvError(replaceOnce(csv, "\n23;X;", "\n22;X;"), 24, "given twice");
        expectCsvError(replaceOnce(csv, "\n22;X;УСКОРЕНИЕ 1;2000;", "\n22;X;\"УСКОРЕНИЕ 1;2000;"),
                       23, "not closed");
        expectCsvError(
            replaceOnce(csv, "\n22;X;УСКОРЕНИЕ 1;2000;25600*A/Kd", "\n22;X;УСКОРЕНИЕ 1;2000"), 23,
            "5 fields");
    }

    void csvMissingRow() {
        const std::string csv = writeCParamsCsv(builtin("grinder-205").cValues());
        expectCsvError(replaceOnce(csv, "\n150;;N ручного цикла 8;0;program", ""), 0,
                       "C150 is missing");
        expectCsvError(csv + "153;;x;0;\n", 154, "not a C-parameter");
    }

    void diffOfRevisions() {
        const MachineProfile a = builtin("training-lathe");
        QVERIFY(diff(a, a).empty());
        MachineProfile b = a;
        b.title = "Lathe, revision 2";
        b.setC(22, 12000);
        b.r[204] = 20000;
        b.r.erase(13);
        b.programs[90] = replaceOnce(b.programs[90], "N2 Z=R221\n", "N2 Z=R221 FZ1000\n");
        b.messages.erase(7);
        b.plcAlarm[1] = "Патрон разжат";
        b.simulation.set("tick_ms", "2");
        b.simulation.set("x.new_key", "1");
        const std::vector<Change> d = diff(a, b);
        std::vector<std::string> keys;
        for (const Change& c : d)
            keys.push_back(c.key);
        QCOMPARE(keys, (std::vector<std::string>{"title", "C022", "R13", "R204", "L90", "#7", "A01",
                                                 "tick_ms", "x.new_key"}));
        QCOMPARE(d[1].label, std::string("УСКОРЕНИЕ 1"));
        QCOMPARE(d[1].before, std::optional<std::string>("10666"));
        QCOMPARE(d[1].after, std::optional<std::string>("12000"));
        QCOMPARE(d[2].after, std::optional<std::string>());
        QCOMPARE(d[3].before, std::optional<std::string>());
        QVERIFY(d[5].after == std::nullopt &&
                d[5].before == std::optional<std::string>("КОНТРОЛЬ РАЗМЕРА"));
        QCOMPARE(d[6].label, std::string("Z1900.0"));
        QVERIFY(d[8].section == DiffSection::Simulation && !d[8].before);

        const std::string text = formatDiff(d);
        QVERIFY2(text.find("C022 УСКОРЕНИЕ 1: 10666 -> 12000\n") != std::string::npos,
                 text.c_str());
        QVERIFY2(text.find("R204 ДИАМЕТР НОВ.КРУГА: (none) -> 20000\n") != std::string::npos,
                 text.c_str());
        QVERIFY2(text.find("L90: changed\n    - N2 Z=R221\n    + N2 Z=R221 FZ1000\n") !=
                     std::string::npos,
                 text.c_str());
        QVERIFY2(text.find("#7: КОНТРОЛЬ РАЗМЕРА -> (none)\n") != std::string::npos, text.c_str());
    }

    void diffOfTwoMachines() {
        const auto d = diff(builtin("grinder-205"), builtin("training-lathe"));
        QVERIFY(d.size() > 40);
        QCOMPARE(d[0].key, std::string("name"));
        QCOMPARE(d[0].before, std::optional<std::string>("grinder-205"));
        // Only what differs: C1 (axis present on both) is not listed.
        for (const Change& c : d)
            QVERIFY(c.key != "C001" && c.before != c.after);
        // Reordered simulation keys are no change.
        MachineProfile a = builtin("grinder-205"), b = a;
        b.simulation.clear();
        for (auto it = a.simulation.entries().rbegin(); it != a.simulation.entries().rend(); ++it)
            b.simulation.set(it->first, it->second);
        QVERIFY(diff(a, b).empty());
    }

    void lineDiffs() {
        QCOMPARE(lineDiff("a\nb\nc\n", "a\nb\nc\n"), std::string());
        QCOMPARE(lineDiff("a\nb\nc\n", "a\nx\nc\n"), std::string("  a\n- b\n+ x\n  c\n"));
        QCOMPARE(lineDiff("", "a\n"), std::string("+ a\n"));
        QCOMPARE(lineDiff("a\nb\n", "b\n"), std::string("- a\n  b\n"));
    }
};

QTEST_APPLESS_MAIN(TestCsvDiff)
#include "test_csv_diff.moc"
