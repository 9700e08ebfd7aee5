// `k528 path` gives each program's cycle time (docs/cli-decisions.md): the
// program run on the simulated machine as `k528 run` runs it. For every
// sample and every golden case with a machine, path's "cycle_time_s" is
// within 2 % of run's "time_s" (the bound; being the same run, they
// are equal); a program that ends in an alarm has none and says so; a dwell
// added to a program adds its seconds to the cycle.
#include "cli_runner.h"
#include "util/json.h"

#include <QDir>
#include <QTemporaryDir>
#include <QtTest>

using namespace k528;

namespace {

struct Case {
    QString file;
    QStringList args; // the machine
};

QList<Case> cases() {
    const QString samples = QStringLiteral(K528_SOURCE_DIR "/resources/samples/");
    const QString golden = QStringLiteral(K528_SOURCE_DIR "/tests/programs/");
    return {
        {samples + "lathe-shaft.k528", {"--profile", "training-lathe"}},
        {samples + "lathe-grooves.k528", {"--profile", "training-lathe"}},
        {samples + "grinder-bore-205.k528", {"--profile", "grinder-205"}},
        {golden + "manual-cycles-programs/program.k528", {"--profile", "training-lathe"}},
    };
}

Json jsonOf(const CliResult& r, const QString& what) {
    if (r.out.isEmpty())
        QTest::qFail(qPrintable(what + " printed nothing: " + r.err), __FILE__, __LINE__);
    return json::parse(r.out.toStdString());
}

} // namespace

class TestCliCycleTime : public QObject {
    Q_OBJECT
private slots:
    void pathCycleTimeIsRunTime_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QStringList>("args");
        for (const Case& c : cases())
            QTest::newRow(qPrintable(QFileInfo(c.file).dir().dirName() + "/" + QFileInfo(c.file).fileName()))
                << c.file << c.args;
    }
    void pathCycleTimeIsRunTime() {
        QFETCH(QString, file);
        QFETCH(QStringList, args);
        QVERIFY(QFileInfo::exists(file));
        const CliResult p = runK528(QStringList{"path", "--json"} + args + QStringList{file});
        QVERIFY2(p.exitCode == 0, qPrintable(p.err));
        const Json path = jsonOf(p, "path");
        const CliResult r = runK528(QStringList{"run", "--json"} + args + QStringList{file});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const Json run = jsonOf(r, "run");
        QCOMPARE(QString::fromStdString(run.at("status").get<std::string>()), QString("completed"));
        QCOMPARE(QString::fromStdString(path.at("cycle_run").get<std::string>()), QString("completed"));
        QVERIFY2(path.at("cycle_time_s").is_number(), json::dump(path.at("cycle_time_s")).c_str());
        const double cycle = path.at("cycle_time_s").get<double>();
        const double ran = run.at("time_s").get<double>();
        qInfo("%s: cycle %.3f s, run %.3f s", qPrintable(QFileInfo(file).fileName()), cycle, ran);
        QVERIFY(ran > 0);
        QVERIFY2(std::abs(cycle - ran) <= 0.02 * ran, qPrintable(QString("%1 against %2").arg(cycle).arg(ran)));
    }

    // A dwell of 7 s added before the end adds 7 s (the tick: 1 ms).
    void aDwellAddsItsSeconds() {
        QTemporaryDir dir;
        const QString a = dir.filePath("a.k528"), b = dir.filePath("b.k528");
        auto write = [](const QString& path, const QByteArray& text) {
            QFile f(path);
            return f.open(QIODevice::WriteOnly) && f.write(text) == text.size();
        };
        QVERIFY(write(a, "%L1\nN1 G0 X40 Z2\nN2 G1 Z-10 FZ200\nN3 G0 Z2\nN4 M2\n"));
        QVERIFY(write(b, "%L1\nN1 G0 X40 Z2\nN2 G1 Z-10 FZ200\nN3 G0 Z2\nN4 G4 X7\nN5 M2\n"));
        const Json pa = jsonOf(runK528({"path", "--json", "--profile", "training-lathe", a}), "path a");
        const Json pb = jsonOf(runK528({"path", "--json", "--profile", "training-lathe", b}), "path b");
        QVERIFY(pa.at("cycle_time_s").is_number() && pb.at("cycle_time_s").is_number());
        const double added = pb.at("cycle_time_s").get<double>() - pa.at("cycle_time_s").get<double>();
        QVERIFY2(std::abs(added - 7.0) < 0.05, qPrintable(QString::number(added)));
        // The feed of 200 mm/min over 12 mm of Z takes 3.6 s: the figure is
        // the machine's, not a count of frames.
        QVERIFY(pa.at("cycle_time_s").get<double>() > 3.6);
    }

    // An M00 is continued by the run at once (an operator's push: the button
    // released, then pressed), by `k528 run` too with its default --m0-wait 0.
    void anM00IsContinued() {
        QTemporaryDir dir;
        const QString file = dir.filePath("m0.k528");
        {
            QFile f(file);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("%L1\nN1 R1=1\nN2 M0\nN3 R2=2\nN4 M2\n");
        }
        const Json path = jsonOf(runK528({"path", "--json", file}), "path");
        QCOMPARE(QString::fromStdString(path.at("cycle_run").get<std::string>()), QString("completed"));
        QVERIFY(path.at("cycle_time_s").is_number() && path.at("cycle_time_s").get<double>() < 1.0);
        const Json run = jsonOf(runK528({"run", "--json", "--max-seconds", "10", file}), "run");
        QCOMPARE(QString::fromStdString(run.at("status").get<std::string>()), QString("completed"));
    }

    // A program that ends in an alarm has no cycle time, and says why.
    void anAlarmHasNoCycleTime() {
        const QString file = QStringLiteral(K528_SOURCE_DIR "/tests/programs/nesting-limit-48/program.k528");
        const CliResult p = runK528({"path", "--json", file});
        const Json path = jsonOf(p, "path");
        QVERIFY(path.at("cycle_time_s").is_null());
        QCOMPARE(QString::fromStdString(path.at("cycle_run").get<std::string>()), QString("not_run"));
        const CliResult plain = runK528({"path", "--lang", "en", file});
        QVERIFY2(plain.out.contains("cycle time: none"), qPrintable(plain.out));
    }
};

QTEST_GUILESS_MAIN(TestCliCycleTime)
#include "test_cli_cycle_time.moc"
