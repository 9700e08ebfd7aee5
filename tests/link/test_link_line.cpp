// The link with real parts: a socat pty pair for the RS485 line, `k528
// serve` on one end; mbpoll (a Modbus master we did not write) and `k528
// link` on the other; SIGKILL of a push mid-transfer; the plugin loader
// refusing foreign plugins.
#include "cli_runner.h"
#include "link_plugins.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>
#include <csignal>

namespace {

const QString kCli = QStringLiteral(K528_CLI);

using Run = CliResult;

Run run(const QString& program, const QStringList& args, int timeoutMs = 30000) {
    return runProgram(program, args, timeoutMs);
}

} // namespace

class TestLinkLine : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QProcess socat_, serve_;
    QString a_, b_;

    void removeLocks() {
        for (const QString& p : {a_, b_})
            QFile::remove("/run/lock/LCK.." + QFileInfo(p).fileName());
    }
    void startServe(const QString& keys) {
        stopServe();
        serve_.start(kCli, {"serve", "--port", a_, "--keys", keys});
        QVERIFY(serve_.waitForStarted());
        QByteArray said;
        QTRY_VERIFY_WITH_TIMEOUT((said += serve_.readAllStandardError()).contains("k528 serve:") ||
                                     serve_.state() != QProcess::Running,
                                 10000);
        QCOMPARE(serve_.state(), QProcess::Running);
    }
    void stopServe() {
        if (serve_.state() == QProcess::Running) {
            serve_.terminate();
            serve_.waitForFinished(5000);
        }
        removeLocks();
    }
    Run link(QStringList args) {
        args.prepend(b_);
        args.prepend("--port");
        args.prepend("link");
        return run(kCli, args);
    }
    Run mbpoll(QStringList args) {
        QStringList all = {"-m", "rtu", "-b", "115200", "-P", "none", "-a", "1", "-0", "-1", "-o", "0.5"};
        all += args;
        return run("mbpoll", all, 10000);
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        const QString tag = QString::number(QCoreApplication::applicationPid());
        a_ = dir_.filePath("k528a" + tag);
        b_ = dir_.filePath("k528b" + tag);
        socat_.start("socat", {"pty,raw,echo=0,link=" + a_, "pty,raw,echo=0,link=" + b_});
        QVERIFY(socat_.waitForStarted());
        QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(a_) && QFile::exists(b_), 5000);
    }
    void cleanupTestCase() {
        stopServe();
        socat_.terminate();
        socat_.waitForFinished(3000);
        removeLocks();
    }

    void mbpollReadsAndWrites() {
        startServe("F7 1 1 1 1 ENTER DOWN DOWN ENTER");
        // C40 F ОБЫЧНАЯ X of training-lathe at Z4124/Z4125 (32-bit, low word first).
        Run r = mbpoll({"-r", "4124", "-c", "1", "-t", "4:int", b_});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains("[4124]: \t150000"), qPrintable(r.out));
        // Live state: mode 7.
        r = mbpoll({"-r", "6000", "-c", "1", "-t", "4", b_});
        QVERIFY2(r.out.contains("[6000]: \t7"), qPrintable(r.out));
        // Write R5 = 1234 (5010) and read it back with k528 link pull.
        r = mbpoll({"-r", "5010", "-t", "4", b_, "1234"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        r = mbpoll({"-r", "5010", "-c", "1", "-t", "4", b_});
        QVERIFY2(r.out.contains("[5010]: \t1234"), qPrintable(r.out));
        // 02 outside the writable map, 03 a value outside its range.
        r = mbpoll({"-r", "5300", "-t", "4", b_, "7"});
        QVERIFY2(r.err.contains("Illegal data address") || r.out.contains("Illegal data address"), qPrintable(r.out + r.err));
        r = mbpoll({"-r", "4101", "-t", "4", b_, "9"});
        QVERIFY2(r.err.contains("Illegal data value") || r.out.contains("Illegal data value"), qPrintable(r.out + r.err));
    }

    void pullAndPush() {
        startServe("F7 1 1 1 1 ENTER DOWN DOWN ENTER");
        const QString file = dir_.filePath("pulled.k528m");
        Run r = link({"pull", "--out", file});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QString text;
        {
            QFile f(file);
            QVERIFY(f.open(QIODevice::ReadOnly));
            text = QString::fromUtf8(f.readAll());
        }
        QVERIFY(text.contains("[program 1]"));
        // A bad constant: refused before anything is sent (exit 1).
        QString bad = text;
        bad.replace(QRegularExpression("\nC017=\\d+"), "\nC017=9");
        const QString badFile = dir_.filePath("bad.k528m");
        {
            QFile f(badFile);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(bad.toUtf8());
        }
        r = link({"push", badFile});
        QVERIFY2(r.exitCode == 1, qPrintable(r.err));
        // A changed program goes in and reads back the same.
        QString changed = text;
        changed.replace("[end program]", "N998 G4 X1.5\n[end program]");
        const QString changedFile = dir_.filePath("changed.k528m");
        {
            QFile f(changedFile);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(changed.toUtf8());
        }
        r = link({"push", changedFile});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        QVERIFY(r.out.contains("written and verified"));
        r = link({"pull", "--out", dir_.filePath("again.k528m")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile again(dir_.filePath("again.k528m"));
        QVERIFY(again.open(QIODevice::ReadOnly));
        QVERIFY(QString::fromUtf8(again.readAll()).contains("N998 G4 X1.5"));
    }

    void pushOutsideF7IsRefused() {
        startServe("");
        Run r = link({"status", "--json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(r.out.contains("\"mode\":2"));
        const QString file = dir_.filePath("pulled.k528m");
        QVERIFY(QFile::exists(file));
        r = link({"push", file});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("РАБОТА С ПЭВМ"), qPrintable(r.err));
        // Exception 06 on the line: a register write outside F7.
        r = mbpoll({"-r", "5010", "-t", "4", b_, "5"});
        QVERIFY2((r.out + r.err).contains("busy"), qPrintable(r.out + r.err));
    }

    void noAnswerIsExit2() {
        stopServe();
        Run r = run(kCli, {"link", "--port", b_, "--timeout-ms", "50", "ping"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("does not answer"), qPrintable(r.err));
    }

    void sigkillMidPushLeavesTheProgram() {
        startServe("F7 1 1 1 1 ENTER DOWN DOWN ENTER");
        const QString file = dir_.filePath("pulled.k528m");
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(f.readAll());
        f.close();
        // A new, long program 50 (many windows); the push is killed on the way.
        QString big = "[program 50]\n%L50 (long)\n";
        for (int i = 1; i <= 900; ++i)
            big += QStringLiteral("N%1 G1 X%2 FX100\n").arg(i).arg(i % 50);
        big += "[end program]\n";
        QString changed = text;
        changed.insert(changed.indexOf("[program "), big);
        const QString bigFile = dir_.filePath("big.k528m");
        {
            QFile o(bigFile);
            QVERIFY(o.open(QIODevice::WriteOnly));
            o.write(changed.toUtf8());
        }
        int killedMidway = 0;
        for (int delayMs : {20, 40, 80, 120, 160}) {
            QProcess push;
            push.start(kCli, {"link", "--port", b_, "push", bigFile});
            QVERIFY(push.waitForStarted());
            QTest::qWait(delayMs);
            if (push.state() == QProcess::Running) {
                ::kill(static_cast<pid_t>(push.processId()), SIGKILL);
                ++killedMidway;
            }
            push.waitForFinished(5000);
            removeLocks();
            const QString now = dir_.filePath("now.k528m");
            Run r = link({"pull", "--out", now});
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            QFile b(now);
            QVERIFY(b.open(QIODevice::ReadOnly));
            const QString sb = QString::fromUtf8(b.readAll());
            // Program 50 is absent, or whole: never a part.
            if (sb.contains("[program 50]"))
                QVERIFY(sb.contains("N900 G1 X0 FX100"));
            // Delete it again for the next round by pushing nothing of it: a
            // fresh serve is simpler.
            startServe("F7 1 1 1 1 ENTER DOWN DOWN ENTER");
        }
        QVERIFY(killedMidway > 0);
        // And the push, run again to the end, succeeds.
        Run r = link({"push", bigFile});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        QVERIFY(r.out.contains("program 50"));
        QVERIFY(killedMidway > 0);
    }

    void pullFromAForeignController() {
        stopServe();
        QProcess py;
        py.start("/usr/bin/python3", {QStringLiteral(K528_SOURCE_DIR "/tests/link/foreign_controller.py"), a_});
        QVERIFY(py.waitForStarted());
        const QString file = dir_.filePath("foreign.k528m");
        Run r;
        for (int i = 0; i < 30; ++i) { // the interpreter takes a moment to open the port
            r = link({"pull", "--out", file});
            if (r.exitCode == 0)
                break;
            QTest::qWait(200);
        }
        py.kill();
        py.waitForFinished(3000);
        removeLocks();
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(f.readAll());
        QVERIFY2(text.contains("C040=123456"), qPrintable(text.left(400)));
        QVERIFY(text.contains("C017=2"));
        QVERIFY(text.contains("C001=1"));
        QVERIFY(text.contains("C007=1"));
        QVERIFY(text.contains("R5=-7"));
    }

    void foreignPluginsAreRefused() {
        const auto wrongIid = k528::linkplugin::loadFile(QStringLiteral(K528_FAKE_IID_PLUGIN));
        QVERIFY(!wrongIid.plugin);
        QVERIFY2(wrongIid.refused.contains("IID"), qPrintable(wrongIid.refused));
        const auto wrongApi = k528::linkplugin::loadFile(QStringLiteral(K528_FAKE_API_PLUGIN));
        QVERIFY(!wrongApi.plugin);
        QVERIFY2(wrongApi.refused.contains("api 1"), qPrintable(wrongApi.refused));
        const auto good = k528::linkplugin::loadFile(QStringLiteral(K528_RTU_PLUGIN));
        QVERIFY2(good.plugin, qPrintable(good.refused));
        QCOMPARE(good.name, QStringLiteral("modbus-rtu"));
    }
};

QTEST_GUILESS_MAIN(TestLinkLine)
#include "test_link_line.moc"
