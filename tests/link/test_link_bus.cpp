// The link on an RS485 bus of ptys (rs485_bus.py: every station hears every
// other; a station at another baud rate hears garbage): `k528 link scan`
// finds a `k528 serve` at address 7 at 19200 and at 115200 bit/s and names
// it, two controllers on one bus at once; `k528 link watch` says since when
// the line is lost, keeps the last values as stale and carries on by itself
// when the controller, or the port itself, comes back.
#include "cli_runner.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const QString kCli = QStringLiteral(K528_CLI);
const QString kBus = QStringLiteral(K528_SOURCE_DIR "/tests/link/rs485_bus.py");

} // namespace

class TestLinkBus : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QProcess bus_;
    std::vector<std::unique_ptr<QProcess>> serves_;
    QString client_, s1_, s2_;

    void removeLocks() {
        for (const QString& p : {client_, s1_, s2_})
            QFile::remove("/run/lock/LCK.." + QFileInfo(p).fileName());
    }
    void startBus() {
        stopBus();
        bus_.start("/usr/bin/python3", {kBus, "24", client_, s1_, s2_});
        QVERIFY(bus_.waitForStarted());
        QByteArray said;
        QTRY_VERIFY_WITH_TIMEOUT((said += bus_.readAllStandardError()).contains("bus: ready") ||
                                     bus_.state() != QProcess::Running,
                                 10000);
        QVERIFY2(bus_.state() == QProcess::Running, said.constData());
    }
    void stopBus() {
        if (bus_.state() == QProcess::Running) {
            bus_.terminate();
            bus_.waitForFinished(5000);
        }
    }
    // A `k528 serve` on `port`, or nullptr when it did not start serving.
    QProcess* serve(const QString& port, const QStringList& more) {
        auto p = std::make_unique<QProcess>();
        QStringList args = {"serve", "--port", port};
        args += more;
        p->start(kCli, args);
        if (!p->waitForStarted())
            return nullptr;
        QByteArray said;
        QElapsedTimer clock;
        clock.start();
        while (!said.contains("k528 serve:") && p->state() == QProcess::Running && clock.elapsed() < 10000) {
            p->waitForReadyRead(100);
            said += p->readAllStandardError();
        }
        if (!said.contains("k528 serve:")) {
            qWarning("serve did not start: %s", said.constData());
            return nullptr;
        }
        serves_.push_back(std::move(p));
        return serves_.back().get();
    }
    void stopServes() {
        for (auto& p : serves_) {
            if (p->state() == QProcess::Running) {
                p->terminate();
                p->waitForFinished(5000);
            }
        }
        serves_.clear();
        removeLocks();
    }
    CliResult link(QStringList args, int timeoutMs = 60000) {
        args.prepend(client_);
        args.prepend("--port");
        args = QStringList{"link", "--lang", "en"} + args;
        return runProgram(kCli, args, timeoutMs);
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        const QString tag = QString::number(QCoreApplication::applicationPid());
        client_ = dir_.filePath("bc" + tag);
        s1_ = dir_.filePath("b1" + tag);
        s2_ = dir_.filePath("b2" + tag);
        startBus();
    }
    void cleanup() { stopServes(); }
    void cleanupTestCase() {
        stopServes();
        stopBus();
        removeLocks();
    }

    void scanFindsAddress7At19200() {
        QVERIFY(serve(s1_, {"--address", "7", "--baud", "19200"}));
        const CliResult r = link({"scan", "--bauds", "115200,19200", "--addresses", "1-10"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList lines = r.out.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 1);
        QVERIFY2(lines[0].startsWith("19200 bit/s, address 7: echo ok; server id 0x28, running "
                                     "«K528-05 simulated by k528 serve: training-lathe»; K528-05 map: mode F2"),
                 qPrintable(lines[0]));
        QVERIFY2(r.err.contains("scan: 1 station answered"), qPrintable(r.err));
        // At 115200 the station heard garbage and kept silent: ten timeouts.
        QVERIFY2(r.err.contains("line: 0 answers, 10 timeouts"), qPrintable(r.err));
    }

    void scanFindsAddress7At115200AsJson() {
        QVERIFY(serve(s1_, {"--address", "7"}));
        const CliResult r = link({"scan", "--addresses", "6-8", "--json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList lines = r.out.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 1);
        QVERIFY2(lines[0].contains("\"address\":7") && lines[0].contains("\"baud\":115200") &&
                     lines[0].contains("\"identity\":\"K528-05 simulated by k528 serve: training-lathe\"") &&
                     lines[0].contains("\"mode\":2"),
                 qPrintable(lines[0]));
    }

    void twoControllersOnOneBus() {
        QVERIFY(serve(s1_, {"--address", "3", "--profile", "grinder-205"}));
        QVERIFY(serve(s2_, {"--address", "7", "--keys", "F7 1 1 1 1 ENTER DOWN DOWN ENTER"}));
        const CliResult r = link({"scan", "--addresses", "1-8"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains("address 3: echo ok; server id 0x28, running «K528-05 simulated by k528 serve: grinder-205»"),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains("address 7: echo ok") && r.out.contains("«РАБОТА С ПЭВМ»"), qPrintable(r.out));
        QCOMPARE(r.out.split('\n', Qt::SkipEmptyParts).size(), 2);
        // Each answers its own address; the counters of FC 8 show the bus each one heard.
        const CliResult d = link({"--address", "7", "diag", "--json"});
        QVERIFY2(d.exitCode == 0, qPrintable(d.err));
        const QRegularExpression bus("\"bus messages\":(\\d+)");
        const auto m = bus.match(d.out);
        QVERIFY2(m.hasMatch(), qPrintable(d.out));
        QVERIFY2(m.captured(1).toInt() >= 8, qPrintable(d.out)); // also the requests to other stations
        const QRegularExpression own("\"messages to this station\":(\\d+)");
        QVERIFY(own.match(d.out).captured(1).toInt() < m.captured(1).toInt());
    }

    void watchSaysSinceWhenAndComesBack() {
        QProcess* s = serve(s1_, {"--address", "1"});
        QVERIFY(s);
        QProcess watch;
        watch.start(kCli, {"link", "--lang", "en", "--port", client_, "--timeout-ms", "50", "watch", "--seconds", "9"});
        QVERIFY(watch.waitForStarted());
        QByteArray out;
        QTRY_VERIFY_WITH_TIMEOUT((out += watch.readAllStandardOutput()).contains("mode F2"), 5000);
        // The controller goes away: the line is lost, since a time, with the last values stale.
        s->terminate();
        s->waitForFinished(5000);
        QTRY_VERIFY_WITH_TIMEOUT((out += watch.readAllStandardOutput()).contains("line lost at"), 5000);
        QVERIFY2(out.contains("last values, stale: mode F2"), out.constData());
        // It comes back (F7 now): the watch goes on by itself.
        QVERIFY(serve(s1_, {"--address", "1", "--keys", "F7 1 1 1 1 ENTER"}));
        QTRY_VERIFY_WITH_TIMEOUT((out += watch.readAllStandardOutput()).contains("line back at"), 6000);
        QTRY_VERIFY_WITH_TIMEOUT((out += watch.readAllStandardOutput()).contains("mode F7"), 3000);
        QVERIFY(watch.waitForFinished(15000));
        out += watch.readAllStandardOutput();
        QCOMPARE(watch.exitCode(), 0);
        QVERIFY(QRegularExpression("line lost at \\d\\d:\\d\\d:\\d\\d").match(QString::fromUtf8(out)).hasMatch());
    }

    void watchReopensAPortThatWentAway() {
        // The port itself disappears (a USB adapter pulled: here the bus and its ptys end) and comes back.
        QVERIFY(serve(s1_, {"--address", "1"}));
        QProcess watch;
        watch.start(kCli, {"link", "--lang", "en", "--port", client_, "--timeout-ms", "50", "watch", "--json", "--seconds", "10"});
        QVERIFY(watch.waitForStarted());
        QByteArray out;
        QTRY_VERIFY_WITH_TIMEOUT((out += watch.readAllStandardOutput()).contains("\"online\":true"), 5000);
        stopServes();
        stopBus();
        QTRY_VERIFY_WITH_TIMEOUT((out += watch.readAllStandardOutput()).contains("\"online\":false"), 5000);
        QVERIFY2(out.contains("\"lost_since\":\"") && out.contains("\"stale\":{\"online\":true"), out.constData());
        startBus();
        QVERIFY(serve(s1_, {"--address", "1"}));
        const int before = out.size();
        QTRY_VERIFY_WITH_TIMEOUT((out += watch.readAllStandardOutput()).mid(before).contains("\"online\":true"), 8000);
        QVERIFY(watch.waitForFinished(15000));
        QCOMPARE(watch.exitCode(), 0);
        const QString err = QString::fromUtf8(watch.readAllStandardError());
        QVERIFY2(err.contains("timeouts"), qPrintable(err));
    }
};

QTEST_GUILESS_MAIN(TestLinkBus)
#include "test_link_bus.moc"
