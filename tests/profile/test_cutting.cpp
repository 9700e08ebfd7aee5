// Cutting data (profile/cutting.h): the spindle speed from the cutting speed
// and the diameter, the feed per minute, the wheel's surface speed from R207;
// the trial part's change to a tool's offset R-parameter (handbook 13.8).
#include "cli_runner.h"
#include "profile/builtin.h"
#include "profile/cutting.h"
#include "profile/tools.h"

#include <QTemporaryDir>
#include <QtTest>

#include <numbers>

using namespace k528;
using namespace k528::profile;
using namespace k528::profile::cutting;

class TestCutting : public QObject {
    Q_OBJECT
private slots:
    void spindleSpeed() {
        // v = 120 m/min at Ø40: n = 1000·120 / (π·40) = 954.93 rev/min.
        QVERIFY(qAbs(spindleSpeedRpm(120, 40) - 954.9297) < 1e-3);
        QVERIFY(qAbs(cuttingSpeedMPerMin(spindleSpeedRpm(120, 40), 40) - 120) < 1e-9);
        // Ø100 at 1000/π rev/min cuts at 100 m/min.
        QVERIFY(qAbs(cuttingSpeedMPerMin(1000 / std::numbers::pi, 100) - 100) < 1e-9);
        QVERIFY_THROWS_EXCEPTION(CuttingError, spindleSpeedRpm(120, 0));
        QVERIFY_THROWS_EXCEPTION(CuttingError, spindleSpeedRpm(-1, 40));
        QVERIFY_THROWS_EXCEPTION(CuttingError, spindleSpeedRpm(std::numeric_limits<double>::quiet_NaN(), 40));
    }

    void feed() {
        QCOMPARE(feedPerMinute(0.2, 800), 160.0);
        QVERIFY_THROWS_EXCEPTION(CuttingError, feedPerMinute(0, 800));
    }

    void wheelFromR207() {
        // The grinder's R207 = 18500 discretes of X (0.001 mm): Ø18.5 mm; at
        // 30000 rev/min its surface runs π·18.5·30000/60000 = 29.06 m/s.
        const MachineProfile g = builtin("grinder-205");
        QCOMPARE(presetR207(g), std::int64_t(18500));
        QCOMPARE(wheelDiameterMm(g, presetR207(g)), 18.5);
        QVERIFY(qAbs(wheelSurfaceSpeedMPerS(18.5, 30000) - 29.0597) < 1e-3);
        // The manual's screen УСТ 5: R207 = 560.000 mm, 1000 rev/min: 29.32 m/s.
        QVERIFY(qAbs(wheelSurfaceSpeedMPerS(560, 1000) - 29.3215) < 1e-3);
        QVERIFY_THROWS_EXCEPTION(CuttingError, presetR207(builtin("training-lathe")));
    }

    // The training lathe shows X as a diameter: a Ø40.06 turned for Ø40.00
    // takes 0.06 off tool 2's X offset R102 (1200 -> 1140 discretes).
    void trialPartOnADiameterAxis() {
        const MachineProfile p = builtin("training-lathe");
        const Tool t2 = *toolAt(tools(p), 2);
        const TrialCorrection c = trialCorrection(p, t2, catalog::Axis::X, 40.06, 40.00);
        QCOMPARE(c.rNumber, 102);
        QCOMPARE(c.oldValue, std::int64_t(1200));
        QCOMPARE(c.newValue, std::int64_t(1140));
        QVERIFY(qAbs(c.changeMm + 0.06) < 1e-9);
        // Too small a diameter: the offset grows.
        QCOMPARE(trialCorrection(p, t2, catalog::Axis::X, 39.98, 40.00).newValue, std::int64_t(1220));
        // Z: a shoulder 0.05 long of the drawing's −50 (at −49.95) — R103 −3500 -> −3550.
        const TrialCorrection z = trialCorrection(p, t2, catalog::Axis::Z, -49.95, -50.00);
        QCOMPARE(z.rNumber, 103);
        QCOMPARE(z.newValue, std::int64_t(-3550));
    }

    // A radius axis moves half the diameter's error.
    void trialPartOnARadiusAxis() {
        MachineProfile p = builtin("training-lathe");
        p.setC(7, 0);
        const Tool t1 = *toolAt(tools(p), 1);
        const TrialCorrection c = trialCorrection(p, t1, catalog::Axis::X, 40.06, 40.00);
        QCOMPARE(c.rNumber, 100);
        QCOMPARE(c.newValue, std::int64_t(-30));
    }

    void trialPartNeedsTheOffsetParameters() {
        MachineProfile p = builtin("training-lathe");
        Tool t = *toolAt(tools(p), 1);
        t.offsetR = -1;
        QVERIFY_THROWS_EXCEPTION(CuttingError, trialCorrection(p, t, catalog::Axis::X, 40.06, 40));
    }

    // `k528 db trial`: the change printed and kept as the machine's revision
    // (its note the measurement); --dry-run keeps nothing.
    void dbTrial() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString db = dir.filePath("k528.db");
        QCOMPARE(runK528({"db", "init", "--db", db}).exitCode, 0);
        const CliResult dry = runK528({"db", "trial", "training-lathe", "--db", db, "--lang", "en", "--tool", "2",
                                       "--measured-x", "40.06", "--drawing-x", "40.00", "--dry-run"});
        QVERIFY2(dry.exitCode == 0, qPrintable(dry.err));
        QVERIFY2(dry.out.contains("R102 1200 -> 1140"), qPrintable(dry.out));
        QVERIFY(runK528({"db", "export", "training-lathe", "--db", db}).out.contains("R102=1200"));
        const CliResult r = runK528({"db", "trial", "training-lathe", "--db", db, "--tool", "2", "--measured-x",
                                     "40.06", "--drawing-x", "40.00"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QString::fromUtf8("ошибка +0.060 мм: R102 1200 -> 1140")), qPrintable(r.out));
        QVERIFY(runK528({"db", "export", "training-lathe", "--db", db}).out.contains("R102=1140"));
        const CliResult history = runK528({"db", "show", "training-lathe", "--db", db, "--history", "1"});
        QVERIFY2(history.out.contains("trial part: T2 X measured 40.060 for 40.000"), qPrintable(history.out));
        // Z of tool 2: R103.
        const CliResult z = runK528({"db", "trial", "training-lathe", "--db", db, "--lang", "en", "--tool", "2",
                                     "--measured-z", "-49.95", "--drawing-z", "-50", "--dry-run"});
        QVERIFY2(z.out.contains("R103 -3500 -> -3550"), qPrintable(z.out));
        // Usage: no tool there, both axes, a size that is not a number.
        QCOMPARE(runK528({"db", "trial", "training-lathe", "--db", db, "--tool", "7", "--measured-x", "1",
                          "--drawing-x", "1"}).exitCode, 2);
        QCOMPARE(runK528({"db", "trial", "training-lathe", "--db", db, "--tool", "2", "--measured-x", "1",
                          "--drawing-z", "1"}).exitCode, 2);
        QCOMPARE(runK528({"db", "trial", "training-lathe", "--db", db, "--tool", "2", "--measured-x", "abc",
                          "--drawing-x", "1"}).exitCode, 2);
    }
};

QTEST_GUILESS_MAIN(TestCutting)
#include "test_cutting.moc"
