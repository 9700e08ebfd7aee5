// The link with real parts: a socat pty pair for the RS485 line, `k528
// serve` on one end; mbpoll (a Modbus master we did not write) and `k528
// link` on the other; SIGKILL of a push mid-transfer; the plugin loader
// refusing foreign plugins.
#include "cli_runner.h"
#include "link_plugins.h"
#include "pty_line.h"

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
    ptytest::PtyPair line_;
    ptytest::Serve serve_;

    void startServe(const QString& keys, const QStringList& more = {}) {
        stopServe();
        QVERIFY2(serve_.start(line_.a(), QStringList{"--keys", keys} + more), serve_.said().constData());
    }
    void stopServe() {
        serve_.stop();
        line_.removeLocks();
    }
    Run link(QStringList args) {
        args.prepend(line_.b());
        args.prepend("--port");
        args = QStringList{"link", "--lang", "en"} + args;
        return run(kCli, args);
    }
    static QString readAll(const QString& path) {
        QFile f(path);
        return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
    }
    static void writeFile(const QString& path, const QString& text) {
        QFile f(path);
        if (f.open(QIODevice::WriteOnly | QIODevice::Truncate))
            f.write(text.toUtf8());
    }
    Run mbpoll(QStringList args) {
        QStringList all = {"-m", "rtu", "-b", "115200", "-P", "none", "-a", "1", "-0", "-1", "-o", "0.5"};
        all += args;
        return run("mbpoll", all, 10000);
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        QVERIFY(line_.start(dir_.path(), "k528"));
    }
    void cleanupTestCase() {
        stopServe();
        line_.stop();
    }

    void mbpollReadsAndWrites() {
        startServe("F7 1 1 1 1 ENTER DOWN DOWN ENTER");
        // C40 F ОБЫЧНАЯ X of training-lathe at Z4124/Z4125 (32-bit, low word first).
        Run r = mbpoll({"-r", "4124", "-c", "1", "-t", "4:int", line_.b()});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains("[4124]: \t150000"), qPrintable(r.out));
        // Live state: mode 7.
        r = mbpoll({"-r", "6000", "-c", "1", "-t", "4", line_.b()});
        QVERIFY2(r.out.contains("[6000]: \t7"), qPrintable(r.out));
        // Write R5 = 1234 (5010) and read it back with k528 link pull.
        r = mbpoll({"-r", "5010", "-t", "4", line_.b(), "1234"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        r = mbpoll({"-r", "5010", "-c", "1", "-t", "4", line_.b()});
        QVERIFY2(r.out.contains("[5010]: \t1234"), qPrintable(r.out));
        // 02 outside the writable map, 03 a value outside its range.
        r = mbpoll({"-r", "5316", "-t", "4", line_.b(), "7"}); // R158, the positioner's own
        QVERIFY2(r.err.contains("Illegal data address") || r.out.contains("Illegal data address"), qPrintable(r.out + r.err));
        r = mbpoll({"-r", "4101", "-t", "4", line_.b(), "9"});
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
        r = mbpoll({"-r", "5010", "-t", "4", line_.b(), "5"});
        QVERIFY2((r.out + r.err).contains("busy"), qPrintable(r.out + r.err));
    }

    void noAnswerIsExit2() {
        stopServe();
        Run r = run(kCli, {"link", "--lang", "en", "--port", line_.b(), "--timeout-ms", "50", "ping"});
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
            push.start(kCli, {"link", "--lang", "en", "--port", line_.b(), "push", bigFile});
            QVERIFY(push.waitForStarted());
            QTest::qWait(delayMs);
            if (push.state() == QProcess::Running) {
                ::kill(static_cast<pid_t>(push.processId()), SIGKILL);
                ++killedMidway;
            }
            push.waitForFinished(5000);
            line_.removeLocks();
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
        py.start("/usr/bin/python3", {QStringLiteral(K528_SOURCE_DIR "/tests/link/foreign_controller.py"), line_.a()});
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
        line_.removeLocks();
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(f.readAll());
        QVERIFY2(text.contains("C040=123456"), qPrintable(text.left(400)));
        QVERIFY(text.contains("C017=2"));
        QVERIFY(text.contains("C001=1"));
        QVERIFY(text.contains("C007=1"));
        QVERIFY(text.contains("R5=-7"));
        // The setup R-parameters of the extended map, low word first; the positioner's own are no presets.
        QVERIFY(text.contains("R150=1"));
        QVERIFY(text.contains("R200=20000"));
        QVERIFY(text.contains("R231=-123456"));
        QVERIFY2(!text.contains("R158=") && !text.contains("R222="), qPrintable(text));
    }

    void lostOutputAndUnreadableFilesAreExit2() {
        startServe("F7 1 1 1 1 ENTER DOWN DOWN ENTER");
        const QString file = dir_.filePath("pulled.k528m");
        QVERIFY(QFile::exists(file));
        const QList<QStringList> commands = {{"status", "--json"},
                                             {"ping"},
                                             {"watch", "--seconds", "0.3"},
                                             {"pull", "--out", dir_.filePath("full.k528m")},
                                             {"push", file},
                                             {"diag"}};
        for (const QStringList& c : commands) {
            QProcess p;
            p.setStandardOutputFile("/dev/full");
            p.start(kCli, QStringList{"link", "--lang", "en", "--port", line_.b()} + c);
            QVERIFY(p.waitForFinished(60000));
            const QString err = QString::fromUtf8(p.readAllStandardError());
            QVERIFY2(p.exitCode() == 2, qPrintable(c.join(' ') + ": " + err));
            QVERIFY2(err.contains("cannot write standard output: No space left on device"), qPrintable(c.join(' ') + ": " + err));
        }
        QProcess list;
        list.setStandardOutputFile("/dev/full");
        list.start(kCli, {"link", "--lang", "en", "--list"});
        QVERIFY(list.waitForFinished(30000));
        QCOMPARE(list.exitCode(), 2);
        Run r = link({"push", "/nonexistent"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("cannot open /nonexistent"), qPrintable(r.err));
        r = link({"push", dir_.path()});
        QCOMPARE(r.exitCode, 2);
        // A machine file with a bad line is the input's error (1), not an I/O error.
        const QString bad = dir_.filePath("broken.k528m");
        {
            QFile f(bad);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("[machine]\nformat=1\nname=x\n[c]\nC999=1\n");
        }
        r = link({"push", bad});
        QCOMPARE(r.exitCode, 1);
    }

    void pushProgramFilesSetupRAndClear() {
        startServe("F7 1 1 1 1 ENTER DOWN DOWN ENTER", {"--profile", "grinder-205"});
        const QString file = dir_.filePath("grinder.k528m");
        Run r = link({"pull", "--out", file});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QString text = readAll(file);
        QVERIFY2(text.contains("\nR204="), qPrintable(text.left(2000))); // the grinder's own setup data
        // R200..R231 set in the file: every one the PC may write goes in.
        QString changed = text;
        changed.replace(QRegularExpression("\nR2[0-3]\\d=[^\n]*"), "");
        QString setup;
        for (int n = 200; n <= 231; ++n)
            setup += QStringLiteral("R%1=%2\n").arg(n).arg(n == 222 || n == 223 ? 0 : 100000 + n);
        changed.replace("\n[r]\n", "\n[r]\n" + setup);
        const QString changedFile = dir_.filePath("setup.k528m");
        writeFile(changedFile, changed);
        r = link({"push", changedFile});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains("written and verified: C-parameters, R-parameters (R0..R157, R159..R221, R224..R231)"),
                 qPrintable(r.out));
        r = link({"pull", "--out", dir_.filePath("again.k528m")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString again = readAll(dir_.filePath("again.k528m"));
        for (int n = 200; n <= 231; ++n)
            if (n != 222 && n != 223)
                QVERIFY2(again.contains(QStringLiteral("\nR%1=%2").arg(n).arg(100000 + n)), qPrintable(QString::number(n)));

        // A program file (a technologist's .k528): its programs, the called one first, and its messages.
        const QString prog = dir_.filePath("part.k528");
        writeFile(prog, "%L60 (part)\nN1 G1 X10 FX100\nN2 L61\n%L61 (sub)\nN1 G1 X5 FX100\nN2 M17\n"
                        "%MESSAGES\n#5=ПРОВЕРКА РАЗМЕРА\n");
        r = link({"push", prog});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains("written and verified: messages, program 61, program 60"), qPrintable(r.out));
        r = link({"pull", "--out", dir_.filePath("third.k528m")});
        const QString third = readAll(dir_.filePath("third.k528m"));
        QVERIFY(third.contains("[program 60]") && third.contains("N2 L61") && third.contains("#5=ПРОВЕРКА РАЗМЕРА"));
        // One the controller would refuse is refused before anything is sent.
        writeFile(prog, "%L62\nN1 L77\n");
        r = link({"push", prog});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("part.k528:2:") && r.err.contains("nothing was sent"), qPrintable(r.err));

        // Clear R, then C (manual 2.6.8).
        r = link({"clear", "r"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(r.out.contains("cleared the R area"));
        r = link({"pull", "--out", dir_.filePath("noR.k528m")});
        QVERIFY2(!readAll(dir_.filePath("noR.k528m")).contains("\nR204="), "R204 survived clear r");
        r = link({"clear", "c"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = link({"pull", "--out", dir_.filePath("noC.k528m")});
        QVERIFY(readAll(dir_.filePath("noC.k528m")).contains("\nC017=0"));
    }

    void refusedOffTheScreenOfThePc() {
        writeFile(dir_.filePath("small.k528"), "%L63\nN1 G1 X1 FX100\n");
        startServe("");
        for (const QStringList& c : {QStringList{"push", dir_.filePath("small.k528")}, QStringList{"clear", "c"},
                                     QStringList{"clear", "r"}}) {
            const Run r = link(c);
            QCOMPARE(r.exitCode, 1);
            QVERIFY2(r.err.contains("not in F7 «РАБОТА С ПЭВМ» (mode F2 now)"), qPrintable(r.err));
        }
        startServe("F7 1 1 1 1 ENTER"); // УПРАВЛЕНИЕ ДАННЫМИ, its menu
        for (const QStringList& c : {QStringList{"push", dir_.filePath("small.k528")}, QStringList{"clear", "c"}}) {
            const Run r = link(c);
            QCOMPARE(r.exitCode, 1);
            QVERIFY2(r.err.contains("in F7 УПРАВЛЕНИЕ ДАННЫМИ but not on «РАБОТА С ПЭВМ»"), qPrintable(r.err));
        }
        // A foreign master writing the setup R outside the PC's screen: 06; on it, R231 yes, R232 no.
        Run m = mbpoll({"-r", "5462", "-t", "4", line_.b(), "5"});
        QVERIFY2((m.out + m.err).contains("busy"), qPrintable(m.out + m.err));
        startServe("F7 1 1 1 1 ENTER DOWN DOWN ENTER");
        m = mbpoll({"-r", "5462", "-t", "4", line_.b(), "5"});
        QVERIFY2(m.exitCode == 0, qPrintable(m.out + m.err));
        m = mbpoll({"-r", "5464", "-t", "4", line_.b(), "5"});
        QVERIFY2((m.out + m.err).contains("Illegal data address"), qPrintable(m.out + m.err));
    }

    void busCountersAndFrameLog() {
        startServe("");
        const QString frames = dir_.filePath("frames.txt");
        Run r = link({"--frames", frames, "diag", "--json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains("\"bus messages\":") && r.out.contains("\"bus CRC errors\":0"), qPrintable(r.out));
        const QString log = readAll(frames);
        QVERIFY2(log.contains("  TX  station   1  01 08 00 0B 00 00") && log.contains("CRC ok"), qPrintable(log));
        r = link({"diag", "--clear"});
        QVERIFY2(r.exitCode == 0 && r.out.contains("counters cleared"), qPrintable(r.out + r.err));
        r = link({"diag", "--json"});
        QVERIFY2(r.out.contains("\"bus messages\":1,"), qPrintable(r.out)); // only the request that reads it
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
