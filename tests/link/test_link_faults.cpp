// The link over a faulty line: `k528 link` — socat pair — fault_proxy.py —
// socat pair — `k528 serve`. The proxy drops, corrupts and holds back bytes
// (seeded). A push retries, reports what the line did, and whatever the
// faults, never leaves a damaged program in the controller: each program is
// afterwards either as it was (absent) or exactly the text sent, read
// through a clean line.
#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>
#include <csignal>

#include "cli_runner.h"
#include "pty_line.h"

namespace {

const QString kCli = QStringLiteral(K528_CLI);
const QString kProxy = QStringLiteral(K528_SOURCE_DIR "/tests/link/fault_proxy.py");

using Run = CliResult;

Run run(const QStringList& args, int timeoutMs = 180000) {
    return runProgram(kCli, args, timeoutMs);
}

QString program(int number, int frames, int salt) {
    QString t = QStringLiteral("[program %1]\n%L%1 (faults)\n").arg(number);
    for (int i = 1; i <= frames; ++i)
        t += QStringLiteral("N%1 G1 X%2 FX100\n").arg(i).arg((i * 7 + salt) % 90);
    return t + "[end program]\n";
}

// The frames of program `number` in a machine file, as lines.
QStringList framesOf(const QString& file, int number) {
    const int at = file.indexOf(QStringLiteral("[program %1]").arg(number));
    if (at < 0)
        return {};
    const int end = file.indexOf("[end program]", at);
    QStringList lines = file.mid(at, end - at).split('\n', Qt::SkipEmptyParts);
    QStringList frames;
    for (const QString& l : lines)
        if (l.startsWith('N'))
            frames << l.trimmed();
    return frames;
}

// The end of a frame log, for a failure's message.
QString lastLines(const QString& path, int n) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    const QStringList lines = QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
    return "\n" + lines.mid(std::max<qsizetype>(0, lines.size() - n)).join('\n');
}

} // namespace

class TestLinkFaults : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    ptytest::PtyPair clientLine_, serverLine_; // the client and the proxy, the proxy and the server
    ptytest::Serve serve_;
    QProcess proxy_;
    QString c_, p1_, p2_, s_; // client end, proxy ends, server end

    void removeLocks() {
        clientLine_.removeLocks();
        serverLine_.removeLocks();
    }
    void startProxy(const QString& drop, const QString& corrupt, const QString& hold, const QString& holdMs,
                    const QString& seed) {
        stopProxy();
        proxy_.start("/usr/bin/python3", {kProxy, p1_, p2_, seed, drop, corrupt, hold, holdMs});
        QVERIFY(proxy_.waitForStarted());
        QByteArray said;
        QTRY_VERIFY_WITH_TIMEOUT((said += proxy_.readAllStandardError()).contains("proxy: ready") ||
                                     proxy_.state() != QProcess::Running,
                                 10000);
        QVERIFY2(proxy_.state() == QProcess::Running, said.constData());
    }
    // A count from the proxy's closing line "proxy: N bytes, D dropped, C corrupted, H held";
    // -1 when the line does not say it.
    static int proxyCount(const QString& said, const char* what) {
        const QRegularExpression re(QStringLiteral("(\\d+) %1").arg(QLatin1String(what)));
        const auto m = re.match(said);
        return m.hasMatch() ? m.captured(1).toInt() : -1;
    }

    QString stopProxy() {
        QString said;
        if (proxy_.state() == QProcess::Running) {
            proxy_.terminate();
            proxy_.waitForFinished(5000);
            said = QString::fromUtf8(proxy_.readAllStandardError());
        }
        return said;
    }
    QString pullClean() {
        startProxy("0", "0", "0", "0", "1");
        const QString file = dir_.filePath("now.k528m");
        QFile::remove(file);
        const Run r = run({"link", "--lang", "en", "--port", c_, "pull", "--out", file});
        stopProxy();
        removeLocks();
        if (r.exitCode != 0) {
            qWarning("clean pull failed: %s", qPrintable(r.err));
            return {};
        }
        QFile f(file);
        return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        QVERIFY(clientLine_.start(dir_.path(), "fc") && serverLine_.start(dir_.path(), "fs"));
        c_ = clientLine_.a();
        p1_ = clientLine_.b();
        p2_ = serverLine_.a();
        s_ = serverLine_.b();
        QVERIFY2(serve_.start(s_, {"--keys", "F7 1 1 1 1 ENTER DOWN DOWN ENTER"}), serve_.said().constData());
    }
    void cleanupTestCase() {
        stopProxy();
        serve_.stop();
        clientLine_.stop();
        serverLine_.stop();
    }

    void pushThroughAFaultyLine() {
        const QString base = pullClean();
        QVERIFY(base.contains("[program 1]"));
        // Two new programs, one long (many windows).
        QString file = base;
        const int at = file.indexOf("[program ");
        file.insert(at, program(51, 400, 3) + program(52, 30, 5));
        const QString path = dir_.filePath("push.k528m");
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(file.toUtf8());
        }
        // A bad line: 0.05 % of the bytes dropped, 0.05 % corrupted (a frame of 253 bytes is
        // damaged one time in four), one chunk in 50 held up to 600 ms — longer than the
        // 300 ms timeout, so a held answer comes after its retry was sent; the timeout itself is
        // well above what a busy machine adds to a round trip, so only the faults cause retries.
        startProxy("0.0005", "0.0005", "0.02", "600", "528");
        const QString frames = dir_.filePath("frames.txt");
        const Run r = run({"link", "--lang", "en", "--port", c_, "--timeout-ms", "300", "--frames", frames, "push", path});
        const QString proxySaid = stopProxy();
        removeLocks();
        qInfo("push over the faulty line: exit %d; %s; %s", r.exitCode,
              qPrintable(r.err.section('\n', -2, -2)), qPrintable(proxySaid.trimmed()));
        // The proxy did damage the line (a count, not the word: "0 corrupted" has the word).
        QVERIFY2(proxyCount(proxySaid, "corrupted") > 0 && proxyCount(proxySaid, "held") > 0,
                 qPrintable(proxySaid));
        // The line's report is there, and the damage was met by retries.
        const QRegularExpression retries("(\\d+) retries");
        const auto m = retries.match(r.err);
        QVERIFY2(m.hasMatch(), qPrintable(r.err));
        QVERIFY2(m.captured(1).toInt() > 0, qPrintable(r.err));
        // The retries carry it through; if not, the frame log's end says what the line did.
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + lastLines(frames, 16)));

        // Through a clean line: each program as it was (absent) or exactly as sent.
        const QString now = pullClean();
        QVERIFY(now.contains("[program 1]"));
        for (int n : {51, 52}) {
            const QStringList got = framesOf(now, n);
            if (got.isEmpty()) {
                QVERIFY2(r.exitCode != 0, "a push that succeeded left a program out");
                continue;
            }
            QCOMPARE(got, framesOf(file, n));
        }
        if (r.exitCode == 0)
            QVERIFY(r.out.contains("program 51") && r.out.contains("program 52"));
    }

    void aLineTooBadStopsCleanly() {
        const QString base = pullClean();
        QString file = base;
        file.insert(file.indexOf("[program "), program(53, 600, 11));
        const QString path = dir_.filePath("push2.k528m");
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(file.toUtf8());
        }
        // 5 % of the bytes corrupted: most frames are damaged, the push gives up.
        startProxy("0.01", "0.05", "0.05", "150", "9");
        const Run r = run({"link", "--lang", "en", "--port", c_, "--timeout-ms", "60", "push", path});
        stopProxy();
        removeLocks();
        qInfo("push over a very bad line: exit %d: %s", r.exitCode, qPrintable(r.err.section('\n', -3).simplified()));
        const QString now = pullClean();
        QVERIFY(now.contains("[program 1]"));
        const QStringList got = framesOf(now, 53);
        if (r.exitCode == 0)
            QCOMPARE(got, framesOf(file, 53));
        else {
            QVERIFY2(r.err.contains("does not answer") || r.err.contains("k528 link:"), qPrintable(r.err));
            QVERIFY(got.isEmpty() || got == framesOf(file, 53)); // never a part
        }
        // And run again on a good line, the push completes.
        startProxy("0", "0", "0", "0", "2");
        const Run again = run({"link", "--lang", "en", "--port", c_, "push", path});
        stopProxy();
        removeLocks();
        QVERIFY2(again.exitCode == 0, qPrintable(again.err));
        QCOMPARE(framesOf(pullClean(), 53), framesOf(file, 53));
    }
    void blocksThroughAFaultyLineAreWholeAndTheReportTellsWhich() {
        // C, R and a program pushed through a bad line, again and again: after
        // each push, read through a clean line, the C block, the R block and
        // the program are each wholly as they were or wholly new, as the
        // push's report says (a part in doubt only when the line broke
        // between its commit and the answer).
        const QString base = pullClean();
        QVERIFY(base.contains("[program 1]"));
        const QRegularExpression c26("\nC026=(\\d+)"), c40("\nC040=(\\d+)");
        const qint64 oldC26 = c26.match(base).captured(1).toLongLong(), oldC40 = c40.match(base).captured(1).toLongLong();
        QString previous = base;
        int stopped = 0, checked = 0;
        for (int round = 1; round <= 6; ++round) {
            QString file = base;
            file.replace(c26, QStringLiteral("\nC026=%1").arg(oldC26 + round));
            file.replace(c40, QStringLiteral("\nC040=%1").arg(oldC40 + round));
            file.replace(QRegularExpression("\nR\\d+=[^\n]*"), "");
            QString setup;
            for (int n = 0; n <= 231; n += 7)
                setup += QStringLiteral("R%1=%2\n").arg(n).arg(round * 1000 + n);
            if (file.contains("\n[r]\n"))
                file.replace("\n[r]\n", "\n[r]\n" + setup);
            else
                file.insert(file.indexOf("\n[program ") + 1, "[r]\n" + setup + "\n");
            file.insert(file.indexOf("[program "), program(54, 120, round));
            const QString path = dir_.filePath("blocks.k528m");
            {
                QFile f(path);
                QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
                f.write(file.toUtf8());
            }
            startProxy("0.002", "0.002", "0.03", "200", QString::number(700 + round));
            const Run r = run({"link", "--lang", "en", "--port", c_, "--timeout-ms", "60", "push", path});
            stopProxy();
            removeLocks();
            const QString now = pullClean();
            QVERIFY(now.contains("[program 1]"));
            // Each part wholly old or wholly new.
            const bool cNew = c26.match(now).captured(1).toLongLong() == oldC26 + round;
            QCOMPARE(c40.match(now).captured(1).toLongLong() == oldC40 + round, cNew);
            QVERIFY(cNew || c26.match(now).captured(1) == c26.match(previous).captured(1));
            int rNew = 0, rSeen = 0;
            for (int n = 0; n <= 231; n += 7) {
                if (n == 158)
                    continue;
                ++rSeen;
                if (now.contains(QRegularExpression(QStringLiteral("\nR%1=%2[ \n]").arg(n).arg(round * 1000 + n))))
                    ++rNew;
            }
            QVERIFY2(rNew == 0 || rNew == rSeen, qPrintable(QStringLiteral("R block half-written: %1 of %2").arg(rNew).arg(rSeen)));
            const QStringList p54 = framesOf(now, 54);
            const bool pNew = p54 == framesOf(file, 54);
            QVERIFY2(pNew || p54 == framesOf(previous, 54), "program 54 half-written");
            // What the push said.
            if (r.exitCode == 0) {
                QVERIFY(cNew && rNew == rSeen && pNew);
            } else {
                ++stopped;
                const QString said = r.out.section("push stopped: ", 1).section('\n', 0, 0);
                qInfo("round %d: %s", round, qPrintable(said));
                const QString newParts = said.section("new: ", 1).section(';', 0, 0);
                const QString oldParts = said.section("as they were: ", 1).section(';', 0, 0);
                auto check = [&](const QString& part, bool isNew) {
                    if (said.startsWith("new: ") && newParts.contains(part))
                        QVERIFY2(isNew, qPrintable(part + " said new: " + said));
                    if (oldParts.contains(part))
                        QVERIFY2(!isNew || previous == base, qPrintable(part + " said as it was: " + said));
                };
                if (!said.isEmpty()) {
                    check("C-parameters", cNew);
                    check("R-parameters", rNew == rSeen);
                    check("program 54", pNew);
                    ++checked;
                }
            }
            previous = now;
        }
        qInfo("%d of 6 pushes stopped by the line; %d reports checked", stopped, checked);
    }

    void clearThroughAFaultyLine() {
        const QString base = pullClean();
        QVERIFY(base.contains("\nR"));
        startProxy("0.003", "0.003", "0.03", "200", "91");
        const Run r = run({"link", "--lang", "en", "--port", c_, "--timeout-ms", "60", "clear", "r"});
        stopProxy();
        removeLocks();
        const QString now = pullClean();
        const bool anyR = now.contains(QRegularExpression("\nR\\d+="));
        if (r.exitCode == 0)
            QVERIFY2(!anyR, "clear r succeeded but R-parameters remain");
        else
            QVERIFY(r.err.contains("k528 link:"));
    }
};

QTEST_GUILESS_MAIN(TestLinkFaults)
#include "test_link_faults.moc"
