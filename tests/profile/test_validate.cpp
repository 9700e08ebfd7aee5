// Validation: every value against its definition and the cross-checks that
// give the manual's messages; each check triggered, and a near miss not.
#include "profile/builtin.h"
#include "profile/validate.h"

#include <QtTest>

using namespace k528;
using namespace k528::profile;

namespace {

const MachineProfile& lathe() {
    static const MachineProfile p = builtin("training-lathe");
    return p;
}

MachineProfile with(std::initializer_list<std::pair<int, std::int64_t>> values) {
    MachineProfile p = lathe();
    for (const auto& [n, v] : values)
        p.setC(n, v);
    return p;
}

std::string dump(const std::vector<Finding>& fs) {
    std::string s;
    for (const auto& f : fs)
        s += formatFinding(f) + "\n";
    return s.empty() ? "(no findings)" : s;
}

// Exactly one finding, with this severity, message and C numbers.
void expectOne(const MachineProfile& p, Severity sev, std::optional<int> message,
               std::vector<int> cs) {
    const auto fs = validate(p);
    QVERIFY2(fs.size() == 1, dump(fs).c_str());
    QVERIFY2(fs[0].severity == sev, dump(fs).c_str());
    QVERIFY2(fs[0].message == message, dump(fs).c_str());
    QVERIFY2(fs[0].cParams == cs, dump(fs).c_str());
    QVERIFY(!fs[0].textRu.empty() && !fs[0].textEn.empty());
    // Said by core's catalog of problems: the id the desktop translates, and
    // both texts rendered from it (no pair written beside the check).
    QVERIFY2(problemTexts().find(fs[0].problem.id) != nullptr, fs[0].problem.id.c_str());
    QCOMPARE(fs[0].textRu, problemText(fs[0].problem, true));
    QCOMPARE(fs[0].textEn, problemText(fs[0].problem, false));
}

void expectNone(const MachineProfile& p) {
    const auto fs = validate(p);
    QVERIFY2(fs.empty(), dump(fs).c_str());
}

} // namespace

class TestValidate : public QObject {
    Q_OBJECT
private slots:
    void builtinsAreClean() {
        expectNone(lathe());
        expectNone(builtin("grinder-205"));
    }

    void rangeOfEveryValue() {
        expectOne(with({{31, 0}}), Severity::Error, 15, {31});    // ДОПУСК ПОЗ. 1..255
        expectOne(with({{139, 11}}), Severity::Error, 15, {139}); // override code
        expectOne(with({{126, 1}}), Severity::Error, 15, {126});  // reserved
        expectNone(with({{31, 255}, {83, 1}}));
    }

    void oneDiscretePerAxis() {
        expectOne(with({{5, 0}}), Severity::Error, 15, {4, 5, 6});
        expectOne(with({{56, 1}}), Severity::Error, 15, {56, 57, 58});
        expectNone(with({{4, 1}, {5, 0}})); // 0.0001 instead of 0.001
        // An absent axis is not checked.
        MachineProfile p = with({{53, 0}, {57, 0}});
        const auto fs = validate(p);
        for (const auto& f : fs)
            QVERIFY2(f.cParams != std::vector<int>({56, 57, 58}), dump(fs).c_str());
    }

    void encoderRatio() {
        expectOne(with({{19, 0}}), Severity::Error, 13, {19});
        expectOne(with({{20, 40000}}), Severity::Error, 13, {20});
        expectOne(with({{72, 0}}), Severity::Error, 29, {72});
        expectOne(with({{71, 3}, {72, 2}}), Severity::Warning, std::nullopt, {71, 72});
        expectNone(with({{19, 32767}, {20, 32767}}));
        expectNone(with({{71, 1}, {72, 32767}}));
    }

    void encoderChannels() {
        expectOne(with({{17, 5}}), Severity::Error, 37, {17});
        expectOne(with({{69, 1}}), Severity::Error, 37, {17, 69}); // both encoders on channel 1
        // Near miss: the same channel, but Z is absent.
        const auto fs = validate(with({{53, 0}, {69, 1}}));
        for (const auto& f : fs)
            QVERIFY2(f.message != 37, dump(fs).c_str());
    }

    void dacChannels() {
        expectOne(with({{70, 1}}), Severity::Error, 38, {18, 70});
        expectOne(with({{18, 0}}), Severity::Error, 38, {18});
        expectNone(with({{70, 3}}));
    }

    void handwheelChannels() {
        expectOne(with({{106, 2}}), Severity::Error, 39, {105, 106});
        expectOne(with({{105, 7}}), Severity::Error, 39, {105});
        expectOne(with({{105, 1}, {106, 2}}), Severity::Error, 39,
                  {17, 105}); // handwheel 1 on X's encoder
        expectNone(with({{105, 4}, {106, 2}})); // swapped: still free channels
    }

    void dacLimitAgainstDacMax() {
        expectOne(with({{28, 2000}}), Severity::Error, 6, {28, 29});
        expectOne(with({{80, 2046}}), Severity::Error, 22, {80, 81});
        expectOne(with({{28, 2353}}), Severity::Warning, std::nullopt, {28, 29}); // 14.9 % above
        expectOne(with({{28, 2457}}), Severity::Warning, std::nullopt, {28, 29}); // 20.03 % above
        expectOne(with({{28, 2047}}), Severity::Warning, std::nullopt, {28, 29}); // equal
        expectNone(with({{28, 2354}}));                                           // 15 %
        expectNone(with({{28, 2456}}));                                           // 20 %
        expectOne(with({{81, 0}}), Severity::Warning, std::nullopt, {81});
    }

    void manualCyclePrograms() {
        expectOne(with({{144, 5}}), Severity::Warning, 45, {144});
        expectNone(with({{144, 1}})); // L1 exists
    }

    void otherChecks() {
        expectOne(with({{46, 272000}}), Severity::Error, std::nullopt, {46, 47});
        expectOne(with({{45, 280000}}), Severity::Warning, std::nullopt, {45, 46, 47});
        expectNone(with({{10, 0}, {45, 280000}})); // soft limits off
        expectOne(with({{22, 0}}), Severity::Warning, std::nullopt, {22});
        expectOne(with({{96, 300000}}), Severity::Warning, std::nullopt, {95, 96});
        expectOne(with({{108, 3}}), Severity::Warning, std::nullopt, {107, 108});
        expectNone(with({{111, 7}}));
    }

    void otherSections() {
        MachineProfile p = lathe();
        p.r[240] = 1;
        p.messages[5] = "ЭТО СЛИШКОМ ДЛИННОЕ СООБЩЕНИЕ";
        p.plcWork[33] = "x";
        p.programs[2] = "[x]\n";
        p.simulation.set("tick_ms", "0");
        p.simulation.set("x.screw_lead", "5");
        p.name = "Bad Name";
        const auto fs = validate(p);
        std::vector<std::string> subjects;
        for (const auto& f : fs)
            subjects.push_back(f.subject);
        QCOMPARE(subjects,
                 (std::vector<std::string>{"R240", "L2", "#5", "W33", "simulation tick_ms",
                                           "simulation x.screw_lead", "name"}));
        QVERIFY(hasErrors(fs));
        QVERIFY(fs[5].severity == Severity::Warning); // unknown key: maybe a typo
        QCOMPARE(fs[5].problem.id, std::string("check.setting-unknown"));
        QCOMPARE(fs[5].textRu, std::string("Параметр моделирования x.screw_lead не из реестра (опечатка?)"));
        QCOMPARE(fs[6].problem.id, std::string("name.start"));
    }

    // The cross-checks' texts, each from its id: the manual's names of the
    // constants in Russian, the English names in English; a per cent sign
    // kept.
    void findingsAreSaidByTheirIds() {
        auto fs = validate(with({{69, 1}})); // both encoders on channel 1
        QVERIFY2(fs.size() == 1, dump(fs).c_str());
        QCOMPARE(fs[0].problem.id, std::string("check.encoders-channel"));
        QCOMPARE(fs[0].textEn, std::string("Both encoders are on channel 1 (C017,C069)"));
        QVERIFY2(fs[0].textRu.starts_with("Оба ДОС подключены к одному каналу 1 («"), fs[0].textRu.c_str());
        fs = validate(with({{28, 2353}})); // 14.9 % above
        QVERIFY2(fs.size() == 1, dump(fs).c_str());
        QCOMPARE(fs[0].problem.id, std::string("check.dac-limit-margin"));
        QVERIFY2(fs[0].textEn.find("is not 15-20 % above DAC MAX") != std::string::npos, fs[0].textEn.c_str());
        QVERIFY2(fs[0].textRu.find("не на 15-20 % выше МАКС.ЦАП") != std::string::npos, fs[0].textRu.c_str());
    }

    void programTextChecks() {
        QCOMPARE(checkProgram(3, "%L3 (x)\nN1 G0 X1\n"), std::string());
        QCOMPARE(checkProgram(3, "N1 G0 X1\n"), std::string()); // no header: the number is the key
        QVERIFY(!checkProgram(3, "%L4\nN1\n").empty());
        QVERIFY(!checkProgram(3, "%L3\nN1\n%L5\n").empty());
        QVERIFY(!checkProgram(3, "N1 G0 X1").empty()); // no final line break
        QVERIFY(!checkProgram(3, "N1\r\n").empty());
        QVERIFY(!checkProgram(3, "N1\n%MESSAGES\n").empty());
        QVERIFY(!checkProgram(3, "\n\n").empty());
        QVERIFY(!checkProgram(3, "N1\n  [end program]\n").empty());
        QVERIFY(!checkProgram(0, "N1\n").empty());
        QCOMPARE(programHeaderNumber("  %l12 (title)"), std::optional<int>(12));
        QCOMPARE(programHeaderNumber("%L"), std::optional<int>());
        QCOMPARE(programHeaderNumber("N1 %L3"), std::optional<int>());
    }
};

QTEST_APPLESS_MAIN(TestValidate)
#include "test_validate.moc"
