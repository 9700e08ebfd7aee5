// `k528 run --from` (docs/cli-decisions.md): the rebuilt state is printed
// before the run (JSON: "from"), a subprogram's frame is named L<n>:N<k>
// with --pass K, and the run ends as the run from the beginning; frames
// that do not exist, are not reached or lie inside an oscillation are
// refused with a reason.
#include "cli_runner.h"
#include "util/json.h"

#include <QtTest>

using namespace k528;

namespace {

const QString kShaft = QStringLiteral(K528_SOURCE_DIR "/resources/samples/lathe-shaft.k528");
const QString kGrinder = QStringLiteral(K528_SOURCE_DIR "/resources/samples/grinder-bore-205.k528");

} // namespace

class CliRunFrom : public QObject {
    Q_OBJECT
private slots:
    void jsonHasTheStateAndTheSameEnd() {
        const CliResult full = runK528({"run", "--json", kShaft});
        QCOMPARE(full.exitCode, 0);
        const CliResult from = runK528({"run", "--json", "--from", "L2:N2", "--pass", "3", kShaft});
        QVERIFY2(from.exitCode == 0, qPrintable(from.err));
        const Json a = json::parse(full.out.toStdString());
        const Json b = json::parse(from.out.toStdString());
        QCOMPARE(b.at("status").get<std::string>(), std::string("completed"));
        const Json& f = b.at("from");
        QCOMPARE(f.at("program").get<int>(), 2);
        QCOMPARE(f.at("n").get<int>(), 2);
        QCOMPARE(f.at("pass").get<int>(), 3);
        QCOMPARE(f.at("call_stack").size(), std::size_t{1});
        QCOMPARE(f.at("modal").at("motion").get<std::string>(), std::string("G00"));
        QCOMPARE(f.at("r").at("10").get<long long>(), 34000LL);
        QCOMPARE(f.at("m_functions").size(), std::size_t{2});
        QCOMPARE(f.at("approach").size(), std::size_t{3});
        QCOMPARE(f.at("approach").at(0).at("axis").get<std::string>(), std::string("X"));
        QCOMPARE(f.at("approach").at(1).at("axis").get<std::string>(), std::string("Z"));
        for (const char* r : {"10", "11", "12", "13"})
            QCOMPARE(b.at("r").at(r).get<long long>(), a.at("r").at(r).get<long long>());
        QVERIFY(b.at("frames").get<long long>() < a.at("frames").get<long long>());
        for (const char* ax : {"X", "Z"})
            QVERIFY(std::abs(b.at("axes").at(ax).at("current").get<double>() - a.at("axes").at(ax).at("current").get<double>()) <
                    0.02);
    }

    void plainPrintsTheStateFirst() {
        const CliResult r = runK528({"run", "--lang", "en", "--from", "11", "--pass", "2", kShaft});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.startsWith("start      before L1 N11"), qPrintable(r.out));
        for (const char* line : {"modal      G00", "R set      R10=36000", "M again    M3 M8", "approach   X"})
            QVERIFY2(r.out.contains(line), qPrintable(r.out));
        QVERIFY(r.out.indexOf("approach") < r.out.indexOf("status     completed"));
    }

    void refusals() {
        const CliResult none = runK528({"run", "--from", "77", kShaft, "--lang", "en"});
        QCOMPARE(none.exitCode, 2);
        QVERIFY2(none.err.contains("has no frame N77"), qPrintable(none.err));
        const CliResult noneRu = runK528({"run", "--from", "77", kShaft});
        QVERIFY2(noneRu.err.contains(QStringLiteral("--from 77: в L1 нет кадра N77")), qPrintable(noneRu.err));
        const CliResult bad = runK528({"run", "--from", "L2:x", kShaft});
        QCOMPARE(bad.exitCode, 2);
        const CliResult pass = runK528({"run", "--pass", "2", kShaft});
        QCOMPARE(pass.exitCode, 2);
        const CliResult never = runK528({"run", "--from", "L2:N2", "--pass", "6", kShaft, "--lang", "en"});
        QCOMPARE(never.exitCode, 1);
        QVERIFY2(never.err.contains("the program never reaches L2 N2 for the 6. time (its preview ended: completed)"),
                 qPrintable(never.err));
        const CliResult neverRu = runK528({"run", "--from", "L2:N2", "--pass", "6", kShaft});
        QCOMPARE(neverRu.exitCode, 1);
        QVERIFY2(neverRu.err.contains(QStringLiteral("программа не доходит до L2 N2 в 6-й раз (её предпросмотр "
                                                     "закончился: программа выполнена до конца)")),
                 qPrintable(neverRu.err));
        const CliResult osc = runK528({"run", "--profile", "grinder-205", "--from", "N6", kGrinder, "--lang", "en"});
        QCOMPARE(osc.exitCode, 1);
        QVERIFY2(osc.err.contains("oscillates"), qPrintable(osc.err));
        const CliResult oscRu = runK528({"run", "--profile", "grinder-205", "--from", "N6", kGrinder});
        QCOMPARE(oscRu.exitCode, 1);
        QVERIFY2(oscRu.err.contains(QStringLiteral("осциллирует")), qPrintable(oscRu.err));
    }

    void helpNamesIt() {
        const CliResult r = runK528({"run", "--help"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains("--from N"));
        QVERIFY(r.out.contains("--pass K"));
    }
};

QTEST_GUILESS_MAIN(CliRunFrom)
#include "test_cli_run_from.moc"
