// Export and re-import are exact: the machine file of a stored machine is the
// file it was imported from, for both built-in profiles and for full random
// machines (152 C, every writable R, 99 programs, 99 messages, 80 PLC texts).
#include "catalog/rparams.h"
#include "db/database.h"
#include "db_test_util.h"
#include "profile/builtin.h"
#include "profile/csv.h"
#include "profile/text_format.h"
#include "profile/validate.h"
#include "random_machine.h"

#include <QtTest>

using namespace k528;
using namespace k528::testing;
using profile::MachineProfile;

namespace {

db::OpenOptions unseeded() {
    auto o = testOptions();
    o.seedBuiltins = false;
    return o;
}

std::string findingsText(const std::vector<profile::Finding>& fs) {
    std::string s;
    for (const auto& f : fs)
        s += profile::formatFinding(f) + "\n";
    return s;
}

} // namespace

class TestRoundtrip : public QObject {
    Q_OBJECT
private slots:
    void builtinProfiles() {
        QTemporaryDir dir;
        db::Database d = db::Database::open(testLocation(dir, "b.db"), unseeded());
        for (const std::string& name : profile::builtinNames()) {
            const std::string text(profile::builtinText(name));
            d.createMachine(profile::readMachineText(text, name), by("import"));
            const std::string exported = profile::writeMachineText(d.loadMachine(name));
            QCOMPARE(exported, text);
            // Again, through a second machine of another name.
            MachineProfile copy = profile::readMachineText(exported, "exported");
            copy.name = name + "-copy";
            d.createMachine(copy, by("import"));
            QVERIFY(d.loadMachine(name + "-copy") == copy);
            // CSV of the constants.
            const std::string csv = profile::writeCParamsCsv(d.loadMachine(name).cValues());
            QVERIFY(profile::readCParamsCsv(csv) == profile::builtin(name).c);
        }
    }

    void fullRandomMachines_data() {
        QTest::addColumn<unsigned>("seed");
        for (unsigned s : {1u, 2u, 3u, 99u})
            QTest::newRow(std::to_string(s).c_str()) << s;
    }
    void fullRandomMachines() {
        QFETCH(unsigned, seed);
        const MachineProfile p = randomMachine(seed, "full-" + std::to_string(seed));
        // It is full and valid.
        QCOMPARE(p.r.size(), std::size_t(catalog::kRParamCount -
                                         (catalog::kRReadOnlyLast - catalog::kRReadOnlyFirst + 1)));
        QCOMPARE(p.programs.size(), std::size_t(99));
        QCOMPARE(p.messages.size(), std::size_t(99));
        QCOMPARE(p.plcAlarm.size() + p.plcWork.size() + p.plcSystem.size(), std::size_t(80));
        const auto findings = profile::validate(p);
        QVERIFY2(!profile::hasErrors(findings), findingsText(findings).c_str());
        std::size_t programBytes = 0;
        for (const auto& [n, t] : p.programs)
            programBytes += t.size();
        QVERIFY(programBytes > 50000);

        const std::string text = profile::writeMachineText(p);
        QTemporaryDir dir;
        {
            db::Database d = db::Database::open(testLocation(dir, "f.db"), unseeded());
            d.createMachine(profile::readMachineText(text, "full.k528m"), by("import"));
        }
        // Reopened: the stored machine is the file.
        db::Database d = db::Database::open(testLocation(dir, "f.db"), unseeded());
        const MachineProfile back = d.loadMachine(p.name);
        QVERIFY(back == p);
        QCOMPARE(profile::writeMachineText(back), text);
        QCOMPARE(profile::writeMachineText(d.loadMachine(p.name, 1)), text);
        QCOMPARE(profile::writeCParamsCsv(back.cValues()), profile::writeCParamsCsv(p.cValues()));
        // Re-importing the same file changes nothing; a changed one is one revision.
        QVERIFY(!d.saveMachine(p.name, profile::readMachineText(text), by("again")).changed);
        MachineProfile q = randomMachine(seed + 1000, p.name);
        const auto r = d.saveMachine(p.name, q, by("again"));
        QVERIFY(r.changed);
        QCOMPARE(r.revision, 2);
        QCOMPARE(profile::writeMachineText(d.loadMachine(p.name)), profile::writeMachineText(q));
        QCOMPARE(profile::writeMachineText(d.loadMachine(p.name, 1)), text);
    }

    // A machine with an error is refused whole: no machine, no history, no
    // audit entry.
    void badImportChangesNothing() {
        QTemporaryDir dir;
        db::Database d = db::Database::open(testLocation(dir, "bad.db"), testOptions());
        const auto auditBefore = d.audit().size();
        MachineProfile p = randomMachine(5, "bad-one");
        p.setC(70, p.cValue(18)); // both DACs on one channel: message 38
        try {
            d.createMachine(p, by("import"));
            QFAIL("a machine with an error was imported");
        } catch (const db::ValidationError& e) {
            QCOMPARE(*e.findings().front().message, 38);
        }
        QVERIFY(!d.hasMachine("bad-one"));
        QCOMPARE(d.machines().size(), std::size_t(2));
        QCOMPARE(d.audit().size(), auditBefore);
        QCOMPARE(integrityText(d), std::string());
    }
};

QTEST_APPLESS_MAIN(TestRoundtrip)
#include "test_roundtrip.moc"
