// `k528 shop publish` with real parts: a mosquitto broker started on a free
// localhost port, three `k528 serve --tcp` controllers as machines of a test
// database, mosquitto_sub receiving the retained states, an alarm raised and
// cleared (a controller restarted on a machine that overran its limit
// switch, then on the plain one), a state change made on a controller's K923
// while publishing, the publisher's goodbye, and the last will of a
// publisher killed with SIGKILL.
#include "cli_runner.h"
#include "rig/mqtt_broker.h"
#include "rig/shop_machines.h"

#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QtTest>

using namespace k528::testrig;

namespace {

const QString kCli = QStringLiteral(K528_CLI);

// What mosquitto_sub -v prints: "TOPIC PAYLOAD" a line (with -d, among
// its debug lines: only lines of our topics are messages).
struct Message {
    QString topic;
    QJsonObject payload;
};

QList<Message> messages(const QByteArray& out) {
    QList<Message> list;
    for (const QByteArray& line : out.split('\n')) {
        const qsizetype space = line.indexOf(' ');
        if (space <= 0 || !line.startsWith("k528/"))
            continue;
        list.push_back({QString::fromUtf8(line.left(space)), QJsonDocument::fromJson(line.mid(space + 1)).object()});
    }
    return list;
}

} // namespace

class TestShopMqtt : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString overrun_;
    ShopMachines shop_;
    MqttBroker broker_;

    CliResult k528(QStringList args) { return shop_.k528(std::move(args)); }
    // mosquitto_sub on `topic` until `count` messages came or `seconds` passed.
    void subscribe(QProcess& sub, const QString& topic, int count, int seconds) {
        broker_.subscribe(sub, topic, count, seconds);
        QVERIFY(sub.waitForStarted());
    }
    QByteArray readUntil(QProcess& p, const std::function<bool(const QByteArray&)>& done, int ms, QByteArray out = {}) {
        QElapsedTimer t;
        t.start();
        while (!done(out) && t.elapsed() < ms) {
            p.waitForReadyRead(50);
            out += p.readAllStandardOutput();
            if (p.state() != QProcess::Running) {
                out += p.readAllStandardOutput();
                break;
            }
        }
        return out;
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        // Three machines: a1 in F7, a2 in F2 with keys from its standard input, a3 in F7; a port for the broker.
        const QString failed =
            shop_.start(kCli, QDir(dir_.path()), {"a1", "a2", "a3"},
                        [](int i) { return i == 1 ? QStringList{"--stdin-keys"} : QStringList{"--keys", kWorkWithPcKeys}; }, 1);
        QVERIFY2(failed.isEmpty(), qPrintable(failed));
        QVERIFY(broker_.start(shop_.ports[3]));
        const QString file = shop_.machineFile;
        // A lathe whose X slide stands beyond its limit switch: an alarm at power-on.
        overrun_ = dir_.filePath("overrun.k528m");
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QString text = QString::fromUtf8(f.readAll());
        text.replace("\nname=training-lathe\n", "\nname=overrun-lathe\n");
        text += "x.limit_plus_mm=80\nx.start_mm=85\n";
        QFile o(overrun_);
        QVERIFY(o.open(QIODevice::WriteOnly));
        o.write(text.toUtf8());
    }
    void cleanupTestCase() {
        shop_.stop();
        broker_.stop();
    }

    void publishesStatesAlarmsAndGoodbye() {
        QProcess pub;
        pub.start(kCli, {"shop", "publish", "--mqtt", broker_.url(), "--interval-ms", "100", "--client-id", "shop-test",
                         "--db", shop_.db});
        QVERIFY(pub.waitForStarted());
        QByteArray said;
        // Its banner in the command's language (Russian by default).
        QTRY_VERIFY_WITH_TIMEOUT(
            (said += pub.readAllStandardError()).contains(QStringLiteral("k528 shop publish: станков: 3, каждые 100 мс").toUtf8()),
            10000);
        // The retained states: a subscriber that comes later gets every machine's.
        QTest::qWait(500);
        QProcess states;
        subscribe(states, "k528/+/state", 3, 10);
        QVERIFY(states.waitForFinished(15000));
        const QList<Message> got = messages(states.readAllStandardOutput());
        QCOMPARE(got.size(), 3);
        for (const Message& m : got) {
            const QString name = m.topic.section('/', 1, 1);
            QCOMPARE(m.topic, "k528/" + name + "/state");
            QCOMPARE(m.payload["machine"].toString(), name);
            QVERIFY(m.payload["online"].toBool());
            QCOMPARE(m.payload["mode"].toInt(), name == "a2" ? 2 : 7);
            QCOMPARE(m.payload["state"].toString(), QStringLiteral("idle"));
        }
        // The publisher itself, retained.
        QProcess who;
        subscribe(who, "k528/_publisher/shop-test", 1, 5);
        QVERIFY(who.waitForFinished(8000));
        QList<Message> w = messages(who.readAllStandardOutput());
        QCOMPARE(w.size(), 1);
        QVERIFY(w[0].payload["online"].toBool());
        QCOMPARE(w[0].payload["machines"].toArray().size(), 3);

        // A state change on a controller's K923 (a2: F1) reaches its topic.
        QProcess change;
        QByteArray out;
        // The retained one, then the change.
        QVERIFY2(broker_.subscribeAcknowledged(change, "k528/a2/state", 2, 10, out), out.constData());
        shop_.serves[1]->process().write("F1\n");
        QVERIFY(shop_.serves[1]->process().waitForBytesWritten(3000));
        out = readUntil(change, [](const QByteArray& o) { return messages(o).size() >= 2; }, 10000, out);
        QList<Message> c = messages(out);
        QCOMPARE(c.size(), 2);
        QCOMPARE(c[1].payload["mode"].toInt(), 1);

        // An alarm: a3 comes back on a machine beyond its limit switch (raised), then as it was (cleared).
        QProcess alarms;
        out.clear();
        QVERIFY2(broker_.subscribeAcknowledged(alarms, "k528/a3/alarms", 2, 30, out), out.constData());
        shop_.serves[2]->kill();
        QVERIFY2(shop_.serves[2]->start({"--keys", kWorkWithPcKeys, "--profile", overrun_, "--db", shop_.db}, &said), said.constData());
        out = readUntil(alarms, [](const QByteArray& o) { return messages(o).size() >= 1; }, 10000, out);
        shop_.serves[2]->kill();
        QVERIFY2(shop_.serves[2]->start({"--keys", kWorkWithPcKeys}, &said), said.constData());
        out = readUntil(alarms, [](const QByteArray& o) { return messages(o).size() >= 2; }, 10000, out);
        const QList<Message> a = messages(out);
        QCOMPARE(a.size(), 2);
        QCOMPARE(a[0].payload["event"].toString(), QStringLiteral("raised"));
        QCOMPARE(a[1].payload["event"].toString(), QStringLiteral("cleared"));
        QCOMPARE(a[0].payload["number"].toInt(), a[1].payload["number"].toInt());
        QVERIFY2(a[0].payload["text_ru"].toString().contains("Конечник"), qPrintable(a[0].payload["text_ru"].toString()));
        QVERIFY(!a[0].payload["at"].toString().isEmpty());

        // Stopped: the publisher says so (retained) and exits 0.
        pub.terminate();
        QVERIFY(pub.waitForFinished(10000));
        QCOMPARE(pub.exitCode(), 0);
        subscribe(who, "k528/_publisher/shop-test", 1, 5);
        QVERIFY(who.waitForFinished(8000));
        w = messages(who.readAllStandardOutput());
        QCOMPARE(w.size(), 1);
        QCOMPARE(w[0].payload["online"].toBool(), false);
        QCOMPARE(w[0].payload["why"].toString(), QStringLiteral("stopped"));
    }

    void aKilledPublisherLeavesItsLastWill() {
        QProcess pub;
        pub.start(kCli, {"shop", "publish", "--mqtt", broker_.url(), "--interval-ms", "200", "--client-id", "victim", "--db",
                         shop_.db});
        QVERIFY(pub.waitForStarted());
        QByteArray said;
        QTRY_VERIFY_WITH_TIMEOUT((said += pub.readAllStandardError()).contains("k528 shop publish:"), 10000);
        QProcess will;
        QByteArray out;
        // Online (retained), then the will.
        QVERIFY2(broker_.subscribeAcknowledged(will, "k528/_publisher/victim", 2, 10, out), out.constData());
        pub.kill();
        pub.waitForFinished(3000);
        QVERIFY(will.waitForFinished(15000));
        const QList<Message> w = messages(out + will.readAllStandardOutput());
        QCOMPARE(w.size(), 2);
        QVERIFY(w[0].payload["online"].toBool());
        QCOMPARE(w[1].payload["online"].toBool(), false);
        QVERIFY2(w[1].payload["why"].toString().contains("last will"), qPrintable(w[1].payload["why"].toString()));
    }

    void badBrokersAreClear() {
        CliResult r = k528({"shop", "publish", "--mqtt", "http://127.0.0.1:1883"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("» — не mqtt://ХОСТ[:ПОРТ]")), qPrintable(r.err));
        r = k528({"shop", "publish", "--lang", "en"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("needs --mqtt"), qPrintable(r.err));
        // Nobody listens there (the port of a2's controller is not MQTT's; a closed one refuses).
        const std::vector<quint16> closed = freePorts(1);
        r = k528({"shop", "publish", "--mqtt", "mqtt://127.0.0.1:" + QString::number(closed[0]), "--lang", "en"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("cannot connect to mqtt://127.0.0.1:") && r.err.contains("refused"), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestShopMqtt)
#include "test_shop_mqtt.moc"
