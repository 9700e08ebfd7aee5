#include <QtTest>

#include "cli_runner.h"
#include "util/version.h"

class TestCliBasics : public QObject {
    Q_OBJECT
private slots:
    void version() {
        const auto r = runK528({"--version"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out, QString("k528 %1 (K528 Studio)\n").arg(k528::version_string));
    }
    void help() {
        const auto r = runK528({"--help"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.startsWith("Usage: k528 COMMAND"));
        QVERIFY(r.out.contains("Exit codes: 0 success"));
    }
    void noArgumentsIsUsageError() {
        const auto r = runK528({});
        QCOMPARE(r.exitCode, 2);
    }
    void unknownCommandIsUsageError() {
        const auto r = runK528({"frobnicate"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains("unknown command 'frobnicate'"));
        const auto o = runK528({"--frobnicate"});
        QCOMPARE(o.exitCode, 2);
        QVERIFY(o.err.contains("unknown option --frobnicate"));
    }
};

QTEST_GUILESS_MAIN(TestCliBasics)
#include "test_cli_basics.moc"
