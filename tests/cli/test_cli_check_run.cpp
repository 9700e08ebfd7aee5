// `k528 check` and `k528 run --no-check` agree (program/refusals.h): for every
// combination of G04, X, Z, L, M02, M17 and M30 in one frame, check finds an
// error in that frame exactly when the controller, running the file as it
// holds it, raises an alarm at that frame, and the alarm is one of check's
// message numbers. Also: run without --no-check refuses what check refuses;
// the dwell with M17 (docs/program-language.md) runs and is not refused.
#include "cli_runner.h"
#include "util/json.h"

#include <QTemporaryDir>
#include <QtTest>

#include <set>

using namespace k528;

namespace {

// The words of the generated frame, one bit each.
enum : unsigned { G04 = 1, X = 2, Z = 4, L = 8, M02 = 16, M17 = 32, M30 = 64, kAll = 128 };

constexpr int kFrameLine = 3; // the line of the generated frame in the file

// L1: a frame that sets G00 (no feed needed), the frame, an end. L2: a
// subprogram that returns. X100 Z50 lie inside the training lathe's limits
// (X on the diameter); with G04, X100 is a dwell of 100 s.
QByteArray programText(unsigned words) {
    QByteArray frame = "N2";
    if (words & G04)
        frame += " G4";
    if (words & M02)
        frame += " M2";
    if (words & M17)
        frame += " M17";
    if (words & M30)
        frame += " M30";
    if (words & L)
        frame += " L2";
    if (words & X)
        frame += " X100";
    if (words & Z)
        frame += " Z50";
    return "%L1\nN1 G0\n" + frame + "\nN3 M2\n%L2\nN1 M17\n";
}

QString describe(unsigned words) {
    QStringList w;
    const char* names[] = {"G04", "X", "Z", "L", "M02", "M17", "M30"};
    for (int i = 0; i < 7; ++i)
        if (words & (1u << i))
            w << names[i];
    return w.isEmpty() ? QStringLiteral("(none)") : w.join(' ');
}

} // namespace

class TestCliCheckRun : public QObject {
    Q_OBJECT
private slots:
    void checkErrsExactlyWhereRunAlarms() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QStringList files;
        for (unsigned w = 0; w < kAll; ++w) {
            const QString path = dir.filePath(QStringLiteral("c%1.k528").arg(w, 3, 10, QChar('0')));
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(programText(w));
            files << path;
        }
        // One check of all the files, against the machine run uses.
        const CliResult c = runK528(QStringList{"check", "--json", "--profile", "training-lathe"} + files);
        QVERIFY2(c.exitCode == 0 || c.exitCode == 1, qPrintable(c.err));
        const Json checked = json::parse(c.out.toStdString());
        QCOMPARE(checked.at("files").size(), std::size_t(kAll));
        int refused = 0, dwellWithM17 = 0;
        for (unsigned w = 0; w < kAll; ++w) {
            std::set<int> errors; // message numbers of check's errors in the frame
            bool errorInFrame = false;
            for (const Json& d : checked.at("files").at(w).at("diagnostics")) {
                if (d.at("severity").get<std::string>() != "error")
                    continue;
                QVERIFY2(d.at("line").get<int>() == kFrameLine,
                         qPrintable(describe(w) + ": an error off the frame: " +
                                    QString::fromStdString(d.at("message_en").get<std::string>())));
                errorInFrame = true;
                if (!d.at("manual_number").is_null())
                    errors.insert(d.at("manual_number").get<int>());
            }
            const CliResult r = runK528({"run", "--json", "--no-check", files[static_cast<int>(w)]});
            QVERIFY2(r.exitCode == 0 || r.exitCode == 1, qPrintable(describe(w) + ": " + r.err));
            const Json run = json::parse(r.out.toStdString());
            const Json& alarms = run.at("alarms");
            bool alarmInFrame = false;
            for (const Json& a : alarms) {
                QVERIFY2(!a.at("line").is_null() && a.at("line").get<int>() == kFrameLine &&
                             a.at("program").get<int>() == 1,
                         qPrintable(describe(w) + ": an alarm off the frame: " +
                                    QString::fromStdString(json::dump(a))));
                alarmInFrame = true;
                const int n = a.at("number").get<int>();
                QVERIFY2(errors.count(n),
                         qPrintable(describe(w) + QStringLiteral(": run's alarm %1 is not one of check's errors").arg(n)));
            }
            QVERIFY2(errorInFrame == alarmInFrame,
                     qPrintable(describe(w) + (errorInFrame ? ": check refuses the frame, run runs it"
                                                            : ": check passes the frame, run raises an alarm")));
            QCOMPARE(QString::fromStdString(run.at("status").get<std::string>()),
                     alarmInFrame ? QString("alarm") : QString("completed"));
            if (errorInFrame) {
                ++refused;
                // Without --no-check, run refuses the file as check does (exit 1, no run).
                const CliResult plain = runK528({"run", "--json", files[static_cast<int>(w)]});
                QCOMPARE(plain.exitCode, 1);
                QVERIFY(plain.out.isEmpty());
            }
            if ((w & (G04 | X | M17)) == (G04 | X | M17) && !(w & (Z | L | M02 | M30)))
                dwellWithM17 += errorInFrame ? 0 : 1;
        }
        QVERIFY(refused > 64); // most combinations are refused: the set is not trivial
        QCOMPARE(dwellWithM17, 1); // G04 X100 M17 dwells, then ends the main program
    }

    // The dwell with M17 in a subprogram dwells, then returns (the manual's
    // G04 takes its time in X: no coordinate, so not «35. X/M17»).
    void dwellWithM17Returns() {
        QTemporaryDir dir;
        const QString path = dir.filePath("dwell.k528");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("%L1\nN1 L2\nN2 R1=R1+1\nN3 M2\n%L2\nN1 G4 X1.5 M17\n");
        f.close();
        const CliResult c = runK528({"check", path});
        QCOMPARE(c.exitCode, 0);
        const CliResult r = runK528({"run", "--json", path});
        QCOMPARE(r.exitCode, 0);
        const Json run = json::parse(r.out.toStdString());
        QCOMPARE(run.at("r").at("1").get<int>(), 1); // came back to N2
        QVERIFY(run.at("time_s").get<double>() >= 1.5);
    }

    // --no-check still refuses a text it cannot read.
    void noCheckRefusesSyntaxErrors() {
        QTemporaryDir dir;
        const QString path = dir.filePath("bad.k528");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("%L1\nN1 G0 X=\nN2 M2\n");
        f.close();
        const CliResult r = runK528({"run", "--no-check", path});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.out.contains("error"));
    }
};

QTEST_APPLESS_MAIN(TestCliCheckRun)
#include "test_cli_check_run.moc"
