// The shop's poller: 32 K528-05 over Modbus TCP (`k528 serve
// --tcp` on free localhost ports, machines of a database of its own: the
// test rig's ShopMachines), `k528 shop publish` polling every 100 ms into a
// mosquitto broker (the rig's MqttBroker). Figures: the CPU of the poller process (user + system time from
// /proc over 10 s of wall time, % of one core) and the time from a state
// change in a controller (a key pressed on its K923 through `serve
// --stdin-keys`: the mode changes) to the moment the new state arrives on its
// MQTT topic at a subscriber (mosquitto_sub, timed when this program reads
// its line: an upper bound).
// Usage: bench_shop_poll K528 MACHINES SECONDS CHANGES
#include "report.h"
#include "rig/mqtt_broker.h"
#include "rig/shop_machines.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <algorithm>
#include <cstdio>
#include <unistd.h>

using namespace k528;

namespace {

// User + system seconds of a process so far.
double cpuSeconds(qint64 pid) {
    QFile f(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!f.open(QIODevice::ReadOnly))
        return -1;
    const QByteArray s = f.readAll();
    const QList<QByteArray> fields = s.mid(s.lastIndexOf(')') + 2).split(' ');
    // After the name: state(0) ... utime(11) stime(12).
    return (fields.value(11).toDouble() + fields.value(12).toDouble()) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

} // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    if (argc != 5) {
        std::fprintf(stderr, "usage: bench_shop_poll K528 MACHINES SECONDS CHANGES\n");
        return 2;
    }
    const QString k528 = QString::fromLocal8Bit(argv[1]);
    const int machines = std::atoi(argv[2]);
    const double seconds = std::atof(argv[3]);
    const int changes = std::atoi(argv[4]);
    QTemporaryDir dir;
    // The machines m01… of a database of their own, each served by a
    // controller that reads its K923's keys from its standard input; a port
    // more for the broker.
    testrig::ShopMachines shop;
    const QString failed =
        shop.start(k528, QDir(dir.path()), testrig::shopMachineNames(machines),
                   [&shop](int) { return QStringList{"--stdin-keys", "--db", shop.db}; }, 1);
    if (!failed.isEmpty()) {
        std::fprintf(stderr, "the machines did not start: %s\n", qPrintable(failed));
        return 2;
    }
    const auto name = [](int i) { return testrig::shopMachineName(i); };
    testrig::MqttBroker broker;
    if (!broker.start(shop.ports[static_cast<std::size_t>(machines)])) {
        std::fprintf(stderr, "mosquitto did not start\n");
        return 2;
    }
    const quint16 brokerPort = broker.port();
    QProcess sub;
    sub.start("mosquitto_sub", {"-h", "127.0.0.1", "-p", QString::number(brokerPort), "-t", "k528/+/state", "-v"});
    sub.waitForStarted();
    QProcess pub;
    pub.start(k528, {"shop", "publish", "--mqtt", broker.url(), "--interval-ms", "100", "--db", shop.db});
    // Each machine's state as last received, and when.
    QMap<QString, QJsonObject> last;
    QByteArray pending;
    const auto receive = [&](int ms) -> std::vector<std::pair<double, QJsonObject>> {
        std::vector<std::pair<double, QJsonObject>> got;
        sub.waitForReadyRead(ms);
        pending += sub.readAllStandardOutput();
        const double now = bench::nowSeconds();
        for (qsizetype eol; (eol = pending.indexOf('\n')) >= 0;) {
            const QByteArray line = pending.left(eol);
            pending.remove(0, eol + 1);
            const QJsonObject o = QJsonDocument::fromJson(line.mid(line.indexOf(' ') + 1)).object();
            last[o["machine"].toString()] = o;
            got.emplace_back(now, o);
        }
        return got;
    };
    QElapsedTimer wait;
    wait.start();
    while (last.size() < machines && wait.elapsed() < 30000)
        receive(100);
    int online = 0;
    for (const QJsonObject& o : last)
        online += o["online"].toBool() ? 1 : 0;
    if (online != machines) {
        std::fprintf(stderr, "%d of %d machines online on their topics: %s\n", online, machines,
                     pub.readAllStandardError().constData());
        return 2;
    }
    // The poller's CPU over `seconds` of steady polling.
    const qint64 pid = pub.processId();
    const double cpu0 = cpuSeconds(pid), wall0 = bench::nowSeconds();
    while (bench::nowSeconds() - wall0 < seconds)
        receive(100);
    const double cpuPercent = (cpuSeconds(pid) - cpu0) / (bench::nowSeconds() - wall0) * 100.0;
    // State changes: a key on one controller's K923, its new mode on its topic.
    std::vector<double> latencies;
    for (int c = 0; c < changes; ++c) {
        const int i = (c * 7) % machines;
        const int mode = last[name(i)]["mode"].toInt() == 1 ? 2 : 1;
        const double pause = bench::nowSeconds() + (150 + (c * 37) % 100) / 1000.0; // not in step with the poll
        while (bench::nowSeconds() < pause)
            receive(10);
        const double t0 = bench::nowSeconds();
        QProcess& serve = shop.serves[static_cast<std::size_t>(i)]->process();
        serve.write(mode == 1 ? "F1\n" : "F2\n");
        serve.waitForBytesWritten(1000);
        double arrived = -1;
        while (arrived < 0 && bench::nowSeconds() - t0 < 5) {
            for (const auto& [t, o] : receive(20))
                if (o["machine"].toString() == name(i) && o["mode"].toInt() == mode)
                    arrived = t;
        }
        if (arrived < 0) {
            std::fprintf(stderr, "the change of %s to F%d never arrived\n", qPrintable(name(i)), mode);
            return 2;
        }
        latencies.push_back((arrived - t0) * 1000.0);
    }
    pub.terminate();
    pub.waitForFinished(10000);
    sub.terminate();
    sub.waitForFinished(3000);
    shop.stop();
    broker.stop();
    std::sort(latencies.begin(), latencies.end());
    bench::Report rep;
    rep.figure("shop.poller_cpu_32_lines_100ms", cpuPercent, "%", 10, bench::Better::Lower);
    rep.figure("shop.change_to_topic_median", latencies[latencies.size() / 2], "ms", 250, bench::Better::Lower);
    rep.figure("shop.change_to_topic_max", latencies.back(), "ms", 250, bench::Better::Lower);
    return rep.exitCode();
}
