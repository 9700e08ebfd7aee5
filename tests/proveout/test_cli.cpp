// `k528 check --profile` and `k528 path` with the prove-out (docs/proveout.md,
// shared/spec/cli.md: diagnostics gain "rule").
#include "cli_runner.h"
#include "rig/facing.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using k528::testrig::kBadFacing;

class TestProveoutCli : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString db_; // none: the built-in machines

    QString write(const char* name, const QByteArray& text) {
        const QString path = dir_.filePath(QString::fromUtf8(name));
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly))
            qFatal("cannot write %s", name);
        f.write(text);
        return path;
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        db_ = dir_.filePath("none.db");
    }

    void checkNamesTheRuleAndTheFrame() {
        const QString file = write("face.k528", QByteArray::fromStdString(kBadFacing));
        const CliResult r = runK528({"check", "--db", db_, "--profile", "training-lathe", "--json", file});
        QCOMPARE(r.exitCode, 1);
        const QJsonArray d = QJsonDocument::fromJson(r.out.toUtf8())
                                 .object()["files"].toArray()[0].toObject()["diagnostics"].toArray();
        QCOMPARE(d.size(), 1);
        const QJsonObject f = d[0].toObject();
        QCOMPARE(f["rule"].toString(), QString("rapid-into-material"));
        QCOMPARE(f["line"].toInt(), 6);
        QCOMPARE(f["n"].toInt(), 4);
        QCOMPARE(f["severity"].toString(), QString("error"));
        QCOMPARE(f["column"].toInt(), 1);
        QCOMPARE(f["end_column"].toInt(), 15); // "N4 G0 X44 Z-20" + 1
        QVERIFY(f["message_ru"].toString().startsWith(QString::fromUtf8("Быстрый ход")));
        QCOMPARE(f["at"].toArray().size(), 2);

        const CliResult plain = runK528({"check", "--db", db_, "--profile", "training-lathe", "--lang", "en", file});
        QCOMPARE(plain.exitCode, 1);
        QVERIFY2(plain.out.contains(file + ":6:1: error: [rapid-into-material] A rapid (G00) enters"),
                 qPrintable(plain.out));
        // Without the machine: no prove-out (and no blank option).
        QCOMPARE(runK528({"check", file}).exitCode, 0);
        QCOMPARE(runK528({"check", "--blank", "UCG,2,Z-80Z0,X40X0,S0S0,0,-5", file}).exitCode, 2);
    }

    void theValidatorsDiagnosticsHaveTheirRuleToo() {
        const QString file = write("jump.k528", "%L1\nN1 GOTO 7\nN2 M30\n");
        const CliResult r = runK528({"check", "--json", file});
        QCOMPARE(r.exitCode, 1);
        const QJsonObject f = QJsonDocument::fromJson(r.out.toUtf8())
                                  .object()["files"].toArray()[0].toObject()["diagnostics"]
                                  .toArray()[0].toObject();
        QCOMPARE(f["rule"].toString(), QString("jump-target"));
    }

    void theBlankFromTheCommandLine() {
        // The file has no blank: nothing to hit; --blank gives it one.
        QByteArray text = QByteArray::fromStdString(kBadFacing);
        text.replace("; UCG,2,Z-80Z0,X40X0,S0S0,0,-5\n", "");
        const QString file = write("noblank.k528", text);
        QCOMPARE(runK528({"check", "--db", db_, "--profile", "training-lathe", file}).exitCode, 0);
        const CliResult r = runK528({"check", "--db", db_, "--profile", "training-lathe", "--blank",
                                     "UCG,2,Z-80Z0,X40X0,S0S0,0,-5", file});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.out.contains("[rapid-into-material]"));
        const CliResult bad = runK528({"check", "--db", db_, "--profile", "training-lathe", "--blank",
                                       "UCG,2,Z-80", file});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains("--blank"), qPrintable(bad.err));
    }

    void pathListsTheFindings() {
        const QString file = write("face2.k528", QByteArray::fromStdString(kBadFacing));
        const CliResult r = runK528({"path", "--db", db_, "--home", "--json", file});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        const QJsonArray d = o["diagnostics"].toArray();
        QCOMPARE(d.size(), 1);
        QCOMPARE(d[0].toObject()["rule"].toString(), QString("rapid-into-material"));
        QCOMPARE(d[0].toObject()["n"].toInt(), 4);
        // The first segment starts at the reference point (X270 Z290 on the lathe).
        const QJsonArray first = o["segments"].toArray()[0].toObject()["points"].toArray()[0].toArray();
        QCOMPARE(first[0].toDouble(), 270.0);
        QCOMPARE(first[1].toDouble(), 290.0);
        const CliResult plain = runK528({"path", "--db", db_, "--home", "--lang", "en", file});
        QVERIFY2(plain.out.contains("L1 N4 line 6 error [rapid-into-material]"), qPrintable(plain.out));
    }

    void theShippedSamplesAreClean() {
        for (const char* s : {"lathe-shaft.k528", "lathe-grooves.k528"}) {
            const CliResult r = runK528({"check", "--db", db_, "--profile", "training-lathe",
                                         QStringLiteral(K528_SOURCE_DIR "/resources/samples/") + s});
            QVERIFY2(r.exitCode == 0 && r.out.isEmpty(), qPrintable(r.out + r.err));
        }
        const CliResult g = runK528({"check", "--db", db_, "--profile", "grinder-205",
                                     QStringLiteral(K528_SOURCE_DIR "/resources/samples/grinder-bore-205.k528")});
        QVERIFY2(g.exitCode == 0 && g.out.isEmpty(), qPrintable(g.out + g.err));
    }
};

QTEST_GUILESS_MAIN(TestProveoutCli)
#include "test_cli.moc"
