// The shop's machines on their lines, with real parts: sixteen `k528 serve
// --tcp` on free localhost ports registered as machines of a test database
// (their `line` set with `k528 db set`), `k528 shop status` polling them,
// mbpoll -m tcp reading their registers, a server killed and restarted
// during `shop status --watch`, a gateway that adds 20–50 ms each way (a
// delaying proxy).
#include "cli_runner.h"
#include "rig/shop_machines.h"

#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include "db/state_times.h"
#include "shop/state_time.h"

#include <QDateTime>
#include <map>

using namespace k528::testrig;

namespace {

const QString kCli = QStringLiteral(K528_CLI);
constexpr int kMachines = 16;

} // namespace

class TestShopStatus : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    ShopMachines shop_;

    CliResult k528(QStringList args, int timeoutMs = 60000) { return shop_.k528(std::move(args), timeoutMs); }
    // Machines with an even index in F7 «РАБОТА С ПЭВМ», the others in F2 (after power-on).
    QStringList keysOf(int i) const { return i % 2 == 0 ? QStringList{"--keys", kWorkWithPcKeys} : QStringList{}; }
    static QJsonArray jsonList(const QString& text) { return QJsonDocument::fromJson(text.toUtf8()).array(); }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        // The database: sixteen machines made from the built-in lathe, each
        // with its line; the sixteen controllers, started together; two spare ports.
        const QString failed = shop_.start(kCli, QDir(dir_.path()), shopMachineNames(kMachines),
                                           [this](int i) { return keysOf(i); }, 2);
        QVERIFY2(failed.isEmpty(), qPrintable(failed));
    }
    void cleanupTestCase() { shop_.stop(); }

    void statusListsSixteenWithTheirModes() {
        const CliResult r = k528({"shop", "status", "--json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonArray list = jsonList(r.out);
        QCOMPARE(list.size(), kMachines);
        for (int i = 0; i < kMachines; ++i) {
            const QJsonObject m = list[i].toObject();
            QCOMPARE(m["machine"].toString(), shopMachineName(i));
            QVERIFY2(m["online"].toBool(), qPrintable(QJsonDocument(m).toJson()));
            QCOMPARE(m["mode"].toInt(), i % 2 == 0 ? 7 : 2);
            QCOMPARE(m["pc_ready"].toBool(), i % 2 == 0);
            QCOMPARE(m["state"].toString(), QStringLiteral("idle"));
            QCOMPARE(m["alarms"].toArray().size(), 0);
            QCOMPARE(m["line"].toString(), "tcp://127.0.0.1:" + QString::number(shop_.ports[i]) + "/1");
        }
        // Plain: a line each; named machines only.
        const CliResult some = k528({"shop", "status", "m03", "m04"});
        QVERIFY2(some.exitCode == 0, qPrintable(some.err));
        const QStringList lines = some.out.trimmed().split('\n');
        QCOMPARE(lines.size(), 2);
        // In the command's language: Russian by default, English with --lang en.
        QVERIFY2(lines[0].startsWith("m03") && lines[0].contains(QStringLiteral("на связи")) &&
                     lines[0].contains(QStringLiteral("F7 (РАБОТА С ПЭВМ), программа ")),
                 qPrintable(some.out));
        QVERIFY2(lines[1].startsWith("m04") && lines[1].contains(" F2,"), qPrintable(some.out));
        const CliResult english = k528({"shop", "status", "m03", "--lang", "en"});
        QVERIFY2(english.out.startsWith("m03") && english.out.contains("online") &&
                     english.out.contains("F7 (РАБОТА С ПЭВМ), program ") && english.out.contains("; since "),
                 qPrintable(english.out));
    }

    void mbpollReadsTheirRegisters() {
        for (int i = 0; i < kMachines; ++i) {
            const CliResult r = runProgram("mbpoll",
                                           {"-m", "tcp", "-p", QString::number(shop_.ports[i]), "-a", "1", "-0", "-1", "-o",
                                            "1", "-r", "6000", "-c", "1", "-t", "4", "127.0.0.1"},
                                           10000);
            QVERIFY2(r.out.contains(i % 2 == 0 ? "[6000]: \t7" : "[6000]: \t2"), qPrintable(r.out + r.err));
        }
    }

    void aKilledServerIsOfflineWithinASecondAndBack() {
        QProcess watch;
        watch.start(kCli, {"shop", "status", "--watch", "--json", "--interval-ms", "100", "--seconds", "20", "--db", shop_.db});
        QVERIFY(watch.waitForStarted());
        QByteArray out;
        // The first poll of every machine: sixteen objects.
        QTRY_VERIFY_WITH_TIMEOUT((out += watch.readAllStandardOutput()).count("\"online\":true") >= kMachines, 10000);
        const int k = 4; // m05
        const QByteArray lost = "{\"machine\":\"" + shopMachineName(k).toUtf8() + "\",\"line\":";
        QElapsedTimer t;
        t.start();
        shop_.serves[k]->kill();
        const qsizetype before = out.size();
        QTRY_VERIFY_WITH_TIMEOUT((out += watch.readAllStandardOutput()).mid(before).contains("\"online\":false"), 3000);
        const qint64 offlineMs = t.elapsed();
        const QByteArray after = out.mid(before);
        QVERIFY2(after.contains(lost) && after.contains("\"state\":\"offline\""), after.constData());
        QVERIFY2(offlineMs < 1000, qPrintable(QString("offline after %1 ms").arg(offlineMs)));
        // Only m05 went offline.
        QCOMPARE(after.count("\"online\":false"), 1);
        // Restarted (now in F7): online again, the others untouched.
        QByteArray said;
        QVERIFY2(shop_.serves[k]->start({"--keys", kWorkWithPcKeys}, &said), said.constData());
        const qsizetype mark = out.size();
        QTRY_VERIFY_WITH_TIMEOUT((out += watch.readAllStandardOutput()).mid(mark).contains(lost), 5000);
        const QByteArray back = out.mid(mark);
        QVERIFY2(back.contains("\"online\":true") && back.contains("\"mode\":7"), back.constData());
        watch.terminate();
        QVERIFY(watch.waitForFinished(10000));
        QCOMPARE(watch.exitCode(), 0);
        // The time in each state went into the database (written when a state
        // changed and at the end): every machine's, m05's offline time too.
        k528::db::Database d = k528::db::Database::open(k528::db::Location::parse(shop_.db.toStdString()));
        const auto rows = k528::db::stateTimes(d, k528::shop::localDay(QDateTime::currentMSecsSinceEpoch()));
        std::map<std::string, std::int64_t> total;
        std::int64_t offline = 0;
        for (const k528::db::StateTime& r : rows) {
            QVERIFY2(r.source.rfind("shop@", 0) == 0, r.source.c_str());
            total[r.machine] += r.ms;
            if (r.machine == shopMachineName(k).toStdString() && r.state == "offline")
                offline += r.ms;
        }
        QCOMPARE(static_cast<int>(total.size()), kMachines);
        for (const auto& [machine, ms] : total)
            QVERIFY2(ms > 0, (machine + ": " + std::to_string(ms) + " ms").c_str());
        QVERIFY2(offline > 0, std::to_string(offline).c_str());
    }

    void linesAreCheckedAndNamed() {
        // A value that is not a line is refused when it is set; nothing changes.
        CliResult r = k528({"db", "set", "m01", "line=tcp://127.0.0.1/1", "--lang", "en"});
        QVERIFY(r.exitCode != 0);
        QVERIFY2(r.err.contains("no HOST:PORT after tcp://"), qPrintable(r.err));
        r = k528({"db", "set", "m01", "line=serial:/dev/ttyUSB0?baud=fast", "--lang", "en"});
        QVERIFY(r.exitCode != 0);
        QVERIFY2(r.err.contains("baud is a rate in bit/s"), qPrintable(r.err));
        // In Russian by default, as every report of k528 db.
        r = k528({"db", "set", "m01", "line=tcp://127.0.0.1/1"});
        QVERIFY(r.exitCode != 0);
        QVERIFY2(r.err.contains("после tcp:// нет ХОСТ:ПОРТ"), qPrintable(r.err));
        r = k528({"shop", "status", "--json", "m01"});
        QVERIFY2(r.exitCode == 0 && jsonList(r.out).size() == 1, qPrintable(r.out + r.err));
        QCOMPARE(jsonList(r.out)[0].toObject()["line"].toString(), "tcp://127.0.0.1:" + QString::number(shop_.ports[0]) + "/1");
        // A machine without a line, named: said so; an unknown one too.
        r = k528({"shop", "status", "training-lathe", "--lang", "en"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("machine 'training-lathe' has no line: k528 db set training-lathe line="),
                 qPrintable(r.err));
        r = k528({"shop", "status", "nosuch", "--lang", "en"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("no machine 'nosuch'"), qPrintable(r.err));
        // A line nobody listens on: offline with the reason, the others as they are.
        r = k528({"db", "set", "training-lathe", "line=tcp://127.0.0.1:" + QString::number(shop_.ports[kMachines]) + "/1"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = k528({"shop", "status", "--json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonArray list = jsonList(r.out);
        QCOMPARE(list.size(), kMachines + 1);
        bool sawOffline = false;
        for (const QJsonValue& v : list) {
            const QJsonObject m = v.toObject();
            if (m["machine"].toString() == "training-lathe") {
                sawOffline = true;
                QCOMPARE(m["online"].toBool(), false);
                QVERIFY2(m["why"].toString().contains("refused"), qPrintable(m["why"].toString()));
                QVERIFY(m["last_seen"].isNull());
            } else {
                QVERIFY(m["online"].toBool());
            }
        }
        QVERIFY(sawOffline);
        r = k528({"db", "set", "training-lathe", "line="});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    }

    void aSlowGatewayKeepsUp() {
        // m01 behind a proxy that holds every chunk 20–50 ms each way.
        const quint16 proxyPort = shop_.ports[kMachines + 1];
        QProcess proxy;
        proxy.start("/usr/bin/python3", {QStringLiteral(K528_SOURCE_DIR "/tests/shop/delay_proxy.py"),
                                         QString::number(proxyPort), QString::number(shop_.ports[0]), "20", "50"});
        QVERIFY(proxy.waitForStarted());
        QByteArray said;
        QTRY_VERIFY2_WITH_TIMEOUT((said += proxy.readAllStandardOutput() + proxy.readAllStandardError()).contains("listening"),
                                  said.constData(), 10000);
        CliResult r = k528({"db", "set", "m01", "line=tcp://127.0.0.1:" + QString::number(proxyPort) + "/1"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        // Polled every 100 ms for 3 s: online from the first poll, never offline.
        r = k528({"shop", "status", "--watch", "--json", "--interval-ms", "100", "--seconds", "3", "m01"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains("\"online\":true") && !r.out.contains("\"online\":false"), qPrintable(r.out));
        // A round trip through it takes 40–100 ms and still fits a 100 ms period.
        r = runProgram(kCli, {"link", "--lang", "en", "--tcp", "127.0.0.1:" + QString::number(proxyPort), "watch", "--seconds", "2",
                              "--interval-ms", "100", "--json"},
                       20000);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const int polls = static_cast<int>(r.out.count("\"online\":true"));
        QVERIFY2(polls >= 15, qPrintable(QString("%1 polls in 2 s; %2").arg(polls).arg(r.err)));
        QVERIFY2(!r.out.contains("\"online\":false"), qPrintable(r.out));
        proxy.kill();
        proxy.waitForFinished(3000);
        r = k528({"db", "set", "m01", "line=tcp://127.0.0.1:" + QString::number(shop_.ports[0]) + "/1"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestShopStatus)
#include "test_shop_status.moc"
