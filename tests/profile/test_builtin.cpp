// The built-in profiles: grinder-205 is appendix Ж value by value, the
// training lathe is what docs/training-lathe.md derives with the calculator.
#include "catalog/cparams.h"
#include "profile/builtin.h"
#include "profile/calculator.h"
#include "profile/text_format.h"
#include "profile/validate.h"

#include <QtTest>
#include <filesystem>
#include <fstream>

using namespace k528;
using namespace k528::profile;
using catalog::Axis;

namespace {

// Table Ж.1, column «Вводимое значение», typed from the manual (not from the
// profile file): X 1..52, Z 53..104, common 105..152.
// clang-format off
const std::int64_t kAppendixZh[153] = {
    0,
    /*  1..13 */ 1, 0, 0, 0, 1, 0, 1, 0, 1, 1, 0, 0, 1,
    /* 14..21 */ 1, 0, 0, 1, 1, 1, 2, 2500,
    /* 22..29 */ 2000, 4000, 1, 0, 262, 26, 2395, 2047,
    /* 30..39 */ 1000, 10, 800, 20, 0, 0, 400, 0, 0, 0,
    /* 40..48 */ 500000, 800000, 500000, 5000, 500, 0, -1000, 40000, 0,
    /* 49..52 */ 0, 0, 0, 0,
    /* 53..65 */ 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0,
    /* 66..73 */ 1, 0, 0, 3, 2, 1, 2, 2500,
    /* 74..81 */ 4445, 17780, 0, 5, 131, 13, 2395, 2047,
    /* 82..91 */ 1000, 10, 800, 20, 0, 0, 400, 0, 0, 0,
    /* 92..100 */ 500000, 600000, 500000, 5000, 500, 190000, -1000, 200000, 0,
    /* 101..104 */ 0, 0, 0, 0,
    /* 105..106 */ 2, 4,
    /* 107..114 */ 3, 4, 5, 6, 7, 8, 9, 10,
    /* 115..122 */ 3, 4, 5, 6, 0, 0, 0, 0,
    /* 123..125 */ 1, 1, 1,
    /* 126..138 */ 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    /* 139..142 */ 0, 4, 7, 10,
    /* 143..150 */ 11, 0, 0, 14, 0, 0, 0, 0,
    /* 151..152 */ 0, 0,
};
// clang-format on

std::string findingsText(const std::vector<Finding>& fs) {
    std::string s;
    for (const auto& f : fs)
        s += formatFinding(f) + "\n";
    return s;
}

} // namespace

class TestBuiltin : public QObject {
    Q_OBJECT
private slots:
    void names() {
        QCOMPARE(builtinNames(), (std::vector<std::string>{"grinder-205", "training-lathe"}));
        QVERIFY(isBuiltin("grinder-205") && !isBuiltin("grinder"));
        QVERIFY(isBuiltin(kDefaultProfile));
    }

    void grinderIsAppendixZh() {
        const MachineProfile p = builtin("grinder-205");
        QCOMPARE(p.name, std::string("grinder-205"));
        for (int n = 1; n <= 152; ++n)
            QVERIFY2(p.cValue(n) == kAppendixZh[n],
                     (catalog::cParam(n).key() + " = " + std::to_string(p.cValue(n)) +
                      ", appendix Ж " + std::to_string(kAppendixZh[n]))
                         .c_str());
        // The manual cycles of Ж (C143 = 11, C146 = 14) have their programs.
        QVERIFY(p.programs.contains(11) && p.programs.contains(14));
        const auto findings = validate(p);
        QVERIFY2(findings.empty(), findingsText(findings).c_str());
    }

    // The simulation data of the grinder are the physical data appendix Ж
    // states, and give its constants back.
    void grinderPhysicsGiveItsConstants() {
        const MachineProfile p = builtin("grinder-205");
        for (Axis a : {Axis::X, Axis::Z}) {
            const calc::AxisDesign d = calc::designFromSettings(p, a);
            QCOMPARE(d.screwLeadMm, 5.0);
            QCOMPARE(d.encoderLines, std::int64_t(2500));
            const auto ratio =
                calc::encoderRatio(d.screwLeadMm, d.gearRatio, d.encoderLines, d.scale);
            QCOMPARE(ratio.l, axisValue(p, a, 19));
            QCOMPARE(ratio.n, axisValue(p, a, 20));
            const double vmax = d.driveMaxSpeedMmPerMin / 1000.0;
            QCOMPARE(calc::speedGain(d.driveMaxVolts, vmax, d.scale), axisValue(p, a, 26));
            QCOMPARE(calc::errorGain(d.kv, d.driveMaxVolts, vmax, d.scale), axisValue(p, a, 27));
            QCOMPARE(calc::dacLimit(axisValue(p, a, 29)), axisValue(p, a, 28));
        }
        QCOMPARE(p.simulation.getInt("tick_ms", 0), std::int64_t(1));
        QCOMPARE(p.simulation.getInt("nesting_limit", 0), std::int64_t(8));
    }

    void latheFromTheCalculator() {
        const MachineProfile p = builtin("training-lathe");
        // Design inputs of docs/training-lathe.md.
        calc::AxisDesign x = calc::designFromSettings(p, Axis::X);
        x.feedNormalMmPerMin = 1500;
        x.feedRapidMmPerMin = 5000;
        x.feedAutoRapidMmPerMin = 5000;
        x.feedHomeStartMmPerMin = 1500;
        x.feedHomeCreepMmPerMin = 100;
        x.accel1 = {calc::AccelSpec::By::RunUp, 5000, 200, 0, 0, false};
        x.accel2 = calc::AccelSpec{calc::AccelSpec::By::Braking, 5000, 0, 4, 0, false};
        calc::AxisDesign z = calc::designFromSettings(p, Axis::Z);
        z.feedNormalMmPerMin = 2000;
        z.feedRapidMmPerMin = 6000;
        z.feedAutoRapidMmPerMin = 6000;
        z.feedHomeStartMmPerMin = 2000;
        z.feedHomeCreepMmPerMin = 150;
        z.accel1 = {calc::AccelSpec::By::RunUp, 6000, 250, 0, 0, false};
        z.accel2 = calc::AccelSpec{calc::AccelSpec::By::Braking, 6000, 0, 5, 0, false};
        for (auto [axis, design] : {std::pair{Axis::X, x}, std::pair{Axis::Z, z}}) {
            const calc::AxisConstants k = calc::designAxis(design);
            for (const auto& [n, v] : k.values)
                QVERIFY2(axisValue(p, axis, n) == v,
                         (catalog::cParam(catalog::axisParam(n, axis)).key() + ": profile " +
                          std::to_string(axisValue(p, axis, n)) + ", calculator " +
                          std::to_string(v))
                             .c_str());
        }
        QCOMPARE(p.cValue(19), std::int64_t(1));
        QCOMPARE(p.cValue(20), std::int64_t(2));
        QCOMPARE(p.cValue(71), std::int64_t(5));
        QCOMPARE(p.cValue(72), std::int64_t(8));
    }

    void latheIsARealisticLathe() {
        const MachineProfile p = builtin("training-lathe");
        const auto findings = validate(p);
        QVERIFY2(findings.empty(), findingsText(findings).c_str());
        QCOMPARE(p.cValue(7), std::int64_t(1)); // X on the diameter
        QCOMPARE(p.cValue(59), std::int64_t(0));
        QCOMPARE(p.cValue(9), std::int64_t(0)); // homing in "+"
        QCOMPARE(p.cValue(61), std::int64_t(0));
        for (Axis a : {Axis::X, Axis::Z}) {
            const calc::AxisSummary s = calc::summarizeAxis(p, a);
            QVERIFY(s.scale.discrete == units::Discrete::Mm0_001);
            QVERIFY(s.feedAutoRapidMmPerMin >= 4000 && s.feedAutoRapidMmPerMin <= 6000);
            QVERIFY(s.feedNormalMmPerMin >= 1000 && s.feedNormalMmPerMin <= 2000);
            QVERIFY(s.accel1MPerS2 > 0.2 && s.accel1MPerS2 < 1.0);
            QVERIFY(s.runUpToAutoRapidMs > 100 && s.runUpToAutoRapidMs < 400);
            QVERIFY(s.emergencyBrakingFromRapidMm < 6);
            QVERIFY(s.feedHomeCreepMmPerMin < s.feedHomeStartMmPerMin);
            QVERIFY(s.homeValueMm > s.limitMinusMm && s.homeValueMm < s.limitPlusMm);
            QVERIFY(s.motionMmPerPulse < 0.001); // finer than a discrete
        }
        // Override keys and cycles.
        QCOMPARE(p.cValue(139), std::int64_t(0));
        QCOMPARE(p.cValue(142), std::int64_t(10));
        QVERIFY(p.programs.contains(static_cast<int>(p.cValue(143))));
        QVERIFY(p.programs.contains(static_cast<int>(p.cValue(148))));
        QVERIFY(!p.plcAlarm.empty() && !p.plcWork.empty() && !p.messages.empty());
    }

    // The shipped files are canonical: reading and writing gives them back.
    void builtinFilesAreCanonical() {
        for (const std::string& name : builtinNames()) {
            const std::string_view text = builtinText(name);
            const MachineProfile p = readMachineText(text, name);
            QCOMPARE(writeMachineText(p), std::string(text));
            QCOMPARE(readMachineText(writeMachineText(p)), p);
        }
    }

    void loadByNameOrPath() {
        QCOMPARE(load("grinder-205"), builtin("grinder-205"));
        const auto dir = std::filesystem::path(K528_BINARY_DIR) / "tests" / "profile";
        std::filesystem::create_directories(dir);
        const auto path = dir / "load-test.k528m";
        MachineProfile p = builtin("training-lathe");
        p.name = "my-lathe";
        writeMachineFile(path, p);
        QCOMPARE(load(path.string()), p);
        try {
            load("no-such-machine");
            QFAIL("no error");
        } catch (const FileError& e) {
            QVERIFY(std::string(e.what()).find("grinder-205, training-lathe") != std::string::npos);
        }
        try {
            builtin("lathe");
            QFAIL("no error");
        } catch (const FileError& e) {
            QVERIFY(std::string(e.what()).find("built-in") != std::string::npos);
        }
        std::ofstream(dir / "bad.k528m") << "[machine]\nformat=1\nname=x\n[c]\nC001=7\n";
        try {
            load((dir / "bad.k528m").string());
            QFAIL("no error");
        } catch (const FileError& e) {
            QCOMPARE(e.line(), 5);
        }
        std::filesystem::remove(path);
        std::filesystem::remove(dir / "bad.k528m");
    }
};

QTEST_APPLESS_MAIN(TestBuiltin)
#include "test_builtin.moc"
