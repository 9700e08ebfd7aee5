// A bus scan in real time: `k528 link scan --addresses 1-247` at
// 115 200 bit/s with the default timeout, on an RS485 bus of ptys that gives
// each byte its wire time (tests/link/rs485_bus.py --pace), a `k528 serve` at
// address 7 on it. The figure is the wall time of the whole scan; the scan
// must find the station and only it.
// Usage: bench_link_scan K528 RS485_BUS_PY
#include "report.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <cstdio>

using namespace k528;

namespace {

bool waitFor(QProcess& p, const QByteArray& text, int ms) {
    if (!p.waitForStarted(ms))
        return false;
    QByteArray said;
    QElapsedTimer clock;
    clock.start();
    while (!said.contains(text) && p.state() == QProcess::Running && clock.elapsed() < ms) {
        p.waitForReadyRead(100);
        said += p.readAllStandardError();
    }
    return said.contains(text);
}

void stop(QProcess& p) {
    if (p.state() == QProcess::Running) {
        p.terminate();
        p.waitForFinished(5000);
    }
}

} // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    if (argc != 3) {
        std::fprintf(stderr, "usage: bench_link_scan K528 RS485_BUS_PY\n");
        return 2;
    }
    const QString k528 = QString::fromLocal8Bit(argv[1]), busScript = QString::fromLocal8Bit(argv[2]);
    QTemporaryDir dir;
    const QString tag = QString::number(QCoreApplication::applicationPid());
    const QString client = dir.filePath("scan-c" + tag), station = dir.filePath("scan-s" + tag);
    QProcess bus, serve;
    bus.start("/usr/bin/python3", {busScript, "--pace", "1", client, station});
    if (!waitFor(bus, "bus: ready", 10000)) {
        std::fprintf(stderr, "the pty bus did not start\n");
        return 2;
    }
    serve.start(k528, {"serve", "--port", station, "--address", "7"});
    if (!waitFor(serve, "k528 serve:", 10000)) {
        std::fprintf(stderr, "k528 serve did not start\n");
        stop(bus);
        return 2;
    }
    QProcess scan;
    QElapsedTimer clock;
    clock.start();
    // In English: the station's line is matched below (k528 link speaks
    // Russian unless told otherwise).
    scan.start(k528, {"link", "--lang", "en", "--port", client, "scan", "--addresses", "1-247"});
    scan.waitForFinished(300000);
    const double seconds = static_cast<double>(clock.elapsed()) / 1000.0;
    const QString out = QString::fromUtf8(scan.readAllStandardOutput());
    const QString err = QString::fromUtf8(scan.readAllStandardError());
    stop(serve);
    stop(bus);
    for (const QString& p : {client, station})
        QFile::remove("/run/lock/LCK.." + p.section('/', -1));
    const QStringList lines = out.split('\n', Qt::SkipEmptyParts);
    if (scan.exitCode() != 0 || lines.size() != 1 || !lines[0].startsWith("115200 bit/s, address 7: echo ok")) {
        std::fprintf(stderr, "the scan did not find exactly station 7 (exit %d):\n%s%s", scan.exitCode(),
                     qPrintable(out), qPrintable(err));
        return 2;
    }
    std::printf("scan: %s\n%s", qPrintable(lines[0]), qPrintable(err));
    bench::Report report;
    report.figure("link scan of 247 addresses at 115200 bit/s (default timeout)", seconds, "s", 60,
                  bench::Better::Lower);
    return report.exitCode();
}
