// The shop's poller: 32 K528-05 over Modbus TCP (`k528 serve
// --tcp` on free localhost ports, machines of a database of its own),
// `k528 shop publish` polling every 100 ms into a mosquitto broker started
// here. Figures: the CPU of the poller process (user + system time from
// /proc over 10 s of wall time, % of one core) and the time from a state
// change in a controller (a key pressed on its K923 through `serve
// --stdin-keys`: the mode changes) to the moment the new state arrives on its
// MQTT topic at a subscriber (mosquitto_sub, timed when this program reads
// its line: an upper bound).
// Usage: bench_shop_poll K528 MACHINES SECONDS CHANGES
#include "report.h"
#include "rig/tcp_serve.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTcpSocket>
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

bool run(const QString& program, const QStringList& args) {
    QProcess p;
    p.start(program, args);
    if (!p.waitForFinished(120000) || p.exitCode() != 0) {
        std::fprintf(stderr, "%s %s failed: %s\n", qPrintable(program), qPrintable(args.join(' ')),
                     p.readAllStandardError().constData());
        return false;
    }
    return true;
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
    const QString db = dir.filePath("shop.db");
    const std::vector<quint16> ports = testrig::freePorts(machines + 1);
    if (static_cast<int>(ports.size()) != machines + 1) {
        std::fprintf(stderr, "no free ports\n");
        return 2;
    }
    const quint16 brokerPort = ports[static_cast<std::size_t>(machines)];
    QProcess broker;
    broker.start("mosquitto", {"-p", QString::number(brokerPort)});
    QElapsedTimer wait;
    wait.start();
    for (bool up = false; !up && wait.elapsed() < 10000;) {
        QTcpSocket s;
        s.connectToHost("127.0.0.1", brokerPort);
        up = s.waitForConnected(200);
    }
    const auto name = [](int i) { return QStringLiteral("m%1").arg(i + 1, 2, 10, QLatin1Char('0')); };
    const QString file = dir.filePath("lathe.k528m");
    if (!run(k528, {"db", "init", "--db", db}) ||
        !run(k528, {"db", "export", "training-lathe", "--out", file, "--db", db}))
        return 2;
    for (int i = 0; i < machines; ++i)
        if (!run(k528, {"db", "import", file, "--as", name(i), "--db", db}) ||
            !run(k528, {"db", "set", name(i), "line=tcp://127.0.0.1:" + QString::number(ports[i]) + "/1", "--db", db}))
            return 2;
    // The controllers, started together (the database of their profile is this one).
    std::vector<std::unique_ptr<testrig::Serve>> serves;
    for (int i = 0; i < machines; ++i) {
        serves.push_back(std::make_unique<testrig::Serve>(k528, ports[static_cast<std::size_t>(i)]));
        serves.back()->process().start(k528, {"serve", "--tcp", serves.back()->address(), "--stdin-keys", "--db", db});
    }
    for (auto& s : serves) {
        s->process().waitForStarted(10000);
        QByteArray said;
        QElapsedTimer t;
        t.start();
        while (!said.contains("k528 serve:") && t.elapsed() < 60000 && s->process().state() == QProcess::Running) {
            s->process().waitForReadyRead(100);
            said += s->process().readAllStandardError();
        }
        said += s->process().readAllStandardError();
        if (!said.contains("k528 serve:")) {
            std::fprintf(stderr, "k528 serve did not start: %s\n", said.constData());
            return 2;
        }
    }
    QProcess sub;
    sub.start("mosquitto_sub", {"-h", "127.0.0.1", "-p", QString::number(brokerPort), "-t", "k528/+/state", "-v"});
    sub.waitForStarted();
    QProcess pub;
    pub.start(k528, {"shop", "publish", "--mqtt", "mqtt://127.0.0.1:" + QString::number(brokerPort), "--interval-ms",
                     "100", "--db", db});
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
    wait.restart();
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
        QProcess& serve = serves[static_cast<std::size_t>(i)]->process();
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
    serves.clear();
    broker.terminate();
    broker.waitForFinished(5000);
    std::sort(latencies.begin(), latencies.end());
    bench::Report rep;
    rep.figure("shop.poller_cpu_32_lines_100ms", cpuPercent, "%", 10, bench::Better::Lower);
    rep.figure("shop.change_to_topic_median", latencies[latencies.size() / 2], "ms", 250, bench::Better::Lower);
    rep.figure("shop.change_to_topic_max", latencies.back(), "ms", 250, bench::Better::Lower);
    return rep.exitCode();
}
