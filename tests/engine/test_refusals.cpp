// The validator and the interpreter read one table of refused combinations
// (program/refusals.h), so they must agree frame by frame: for every
// combination of G04, X, Z, L, M02, M17 and M30 in one frame, placed in the
// main program, in the middle of a called subprogram and as a called
// subprogram's last frame, the check `k528 check` and `k528 run` do finds
// an error in that frame exactly when the controller, running the file as
// it holds it (`k528 run --no-check`), raises an alarm at that frame, and
// the alarm is one of the check's message numbers. The CLI-level twin of
// this test is cli.check_run (through the real binary, main program only).
#include "engine/program_check.h"
#include "engine/run.h"
#include "engine/self_test.h"
#include "profile/builtin.h"
#include "program/diagnostic_texts.h"
#include "program/parser.h"
#include "program/refusals.h"

#include <QtTest>
#include <set>
#include <string>

using namespace k528;

namespace {

enum : unsigned { G04 = 1, X = 2, Z = 4, L = 8, M02 = 16, M17 = 32, M30 = 64, kAll = 128 };

std::string frameText(unsigned words) {
    std::string f = "N2";
    if (words & G04)
        f += " G4";
    if (words & M02)
        f += " M2";
    if (words & M17)
        f += " M17";
    if (words & M30)
        f += " M30";
    if (words & L)
        f += " L2";
    if (words & X)
        f += " X100"; // a coordinate inside the training lathe's limits; with G04 100 s
    if (words & Z)
        f += " Z50";
    return f;
}

std::string describe(unsigned words) {
    std::string s;
    const char* names[] = {"G04", "X", "Z", "L", "M02", "M17", "M30"};
    for (int i = 0; i < 7; ++i)
        if (words & (1u << i)) {
            if (!s.empty())
                s += ' ';
            s += names[i];
        }
    return s.empty() ? "(none)" : s;
}

// Where the generated frame stands. L2 is a subprogram that returns (the
// frame's L2); L3 is the subprogram the frame stands in for the two
// subprogram places.
struct Place {
    const char* name;
    int program; // the program holding the frame
    int line;    // its line in the file
    std::string (*text)(const std::string& frame);
};

const Place kPlaces[] = {
    {"main program", 1, 3,
     [](const std::string& f) { return "%L1\nN1 G0\n" + f + "\nN3 M2\n%L2\nN1 M17\n"; }},
    {"middle of a subprogram", 3, 9,
     [](const std::string& f) {
         return "%L1\nN1 G0\nN2 L3\nN3 M2\n%L2\nN1 M17\n%L3\nN1 G0\n" + f + "\nN3 M17\n";
     }},
    {"last frame of a subprogram", 3, 9,
     [](const std::string& f) {
         return "%L1\nN1 G0\nN2 L3\nN3 M2\n%L2\nN1 M17\n%L3\nN1 G0\n" + f + "\n";
     }},
};

} // namespace

class TestRefusals : public QObject {
    Q_OBJECT
private slots:
    void checkErrsExactlyWhereRunAlarms() {
        const profile::MachineProfile prof = profile::builtin("training-lathe");
        bool intact = true;
        const program::ProgramStore machineStore = engine::loadStore(prof, intact);
        std::set<int> alarmsSeen;
        int refused = 0, passed = 0;
        for (const Place& place : kPlaces) {
            for (unsigned w = 0; w < kAll; ++w) {
                const std::string what = std::string(place.name) + ": " + describe(w);
                const std::string text = place.text(frameText(w));
                // The check `k528 check --profile` and `k528 run` do.
                const engine::FileCheck checked =
                    engine::checkFileForMachine(text, {}, prof, machineStore);
                QVERIFY2(!checked.parsed.hasErrors(), what.c_str());
                std::set<int> errors;
                bool errorInFrame = false;
                for (const program::Diagnostic& d : checked.diagnostics) {
                    if (!d.isError())
                        continue;
                    QVERIFY2(d.program == place.program && d.line == place.line,
                             (what + ": an error off the frame: " + program::diagnosticText(d, false)).c_str());
                    errorInFrame = true;
                    QVERIFY2(d.manualNumber > 0, (what + ": " + program::diagnosticText(d, false)).c_str());
                    errors.insert(d.manualNumber);
                }
                // The controller holding the file unchecked (`run --no-check`).
                const engine::RunResult r =
                    engine::runProgram(prof, checked.parsed.store, 1, engine::RunOptions{});
                bool alarmInFrame = false;
                for (const engine::AlarmView& a : r.alarms) {
                    QVERIFY2(a.program == place.program && a.line == place.line,
                             (what + ": alarm " + std::to_string(a.number) + " at L" +
                              std::to_string(a.program) + " line " + std::to_string(a.line))
                                 .c_str());
                    alarmInFrame = true;
                    QVERIFY2(errors.count(a.number),
                             (what + ": run's alarm " + std::to_string(a.number) +
                              " is not one of check's errors")
                                 .c_str());
                    alarmsSeen.insert(a.number);
                }
                QVERIFY2(errorInFrame == alarmInFrame,
                         (what + (errorInFrame ? ": check refuses the frame, run runs it"
                                               : ": check passes the frame, run raises an alarm"))
                             .c_str());
                QCOMPARE(r.status,
                         alarmInFrame ? engine::RunStatus::Alarm : engine::RunStatus::Completed);
                (errorInFrame ? refused : passed) += 1;
            }
        }
        // The set is not trivial: both outcomes occur, and every message of
        // the table is raised somewhere.
        QVERIFY(refused > 0 && passed > 0);
        for (const program::Refusal& t : program::refusals())
            QVERIFY2(alarmsSeen.count(t.message),
                     ("message " + std::to_string(t.message) + " never raised").c_str());
    }

    // A skipped frame («/ – кадр не будет обрабатываться») never raises an
    // alarm, while check reports it as if it ran: the «!» key un-skips it at
    // the panel (docs/program-language.md, «Skipped frames»). The one place
    // check errs and the controller does not.
    void skippedFrameIsCheckedButNeverRaised() {
        const profile::MachineProfile prof = profile::builtin("training-lathe");
        bool intact = true;
        const program::ProgramStore machineStore = engine::loadStore(prof, intact);
        const Place& main = kPlaces[0];
        for (unsigned w = 0; w < kAll; ++w) {
            std::string what = "skipped: ";
            what += describe(w);
            const auto errors = [&](const std::string& text) {
                std::multiset<int> e;
                for (const program::Diagnostic& d :
                     engine::checkFileForMachine(text, {}, prof, machineStore).diagnostics)
                    if (d.isError() && d.line == main.line)
                        e.insert(d.manualNumber);
                return e;
            };
            std::string frame = "/";
            frame += frameText(w);
            const std::string skipped = main.text(frame);
            QVERIFY2(errors(skipped) == errors(main.text(frameText(w))), what.c_str());
            const engine::FileCheck checked =
                engine::checkFileForMachine(skipped, {}, prof, machineStore);
            const engine::RunResult r =
                engine::runProgram(prof, checked.parsed.store, 1, engine::RunOptions{});
            QVERIFY2(r.alarms.empty(), what.c_str());
            QCOMPARE(r.status, engine::RunStatus::Completed);
        }
    }

    // The dwell's X is its time (table 5), not a coordinate: G04 X… M17 in a
    // subprogram is neither 35 (X/M17) for the check nor an alarm for the
    // controller; it dwells, then returns.
    void dwellWithM17DwellsAndReturns() {
        const profile::MachineProfile prof = profile::builtin("training-lathe");
        bool intact = true;
        const program::ProgramStore machineStore = engine::loadStore(prof, intact);
        const std::string text = "%L1\nN1 G0\nN2 L3\nN3 R1=7\nN4 M2\n%L3\nN1 G4 X2 M17\n";
        const engine::FileCheck checked = engine::checkFileForMachine(text, {}, prof, machineStore);
        QVERIFY(!checked.hasErrors());
        const engine::RunResult r =
            engine::runProgram(prof, checked.parsed.store, 1, engine::RunOptions{});
        QCOMPARE(r.status, engine::RunStatus::Completed);
        QVERIFY(r.alarms.empty());
        QCOMPARE(r.r[1], 7);     // back in L1 after the return
        QVERIFY(r.timeS >= 2.0); // the dwell took its 2 s
    }
};

QTEST_GUILESS_MAIN(TestRefusals)
#include "test_refusals.moc"
