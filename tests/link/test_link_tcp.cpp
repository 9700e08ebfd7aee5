// The Modbus TCP line with real parts: `k528 serve --tcp` on free localhost
// ports (Qt SerialBus's QModbusTcpServer), mbpoll -m tcp (a Modbus TCP
// master we did not write) and every `k528 link` command over --tcp; two
// controllers on two ports; the unit id; a refused connection; a server
// that goes away and comes back during a watch.
#include "cli_runner.h"
#include "rig/shop_machines.h"
#include "rig/tcp_serve.h"

#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace k528::testrig;

namespace {

const QString kCli = QStringLiteral(K528_CLI);

CliResult run(const QString& program, const QStringList& args, int timeoutMs = 30000) {
    return runProgram(program, args, timeoutMs);
}

QString readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

void writeFile(const QString& path, const QString& text) {
    QFile f(path);
    if (f.open(QIODevice::WriteOnly | QIODevice::Truncate))
        f.write(text.toUtf8());
}

} // namespace

class TestLinkTcp : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    std::vector<quint16> ports_;
    std::unique_ptr<Serve> a_, b_;

    CliResult link(const Serve& s, QStringList args) {
        return run(kCli, QStringList{"link", "--lang", "en", "--tcp", s.address()} + args);
    }
    CliResult mbpoll(quint16 port, QStringList args, int unit = 1) {
        // mbpoll OPTIONS HOST [VALUES]: the values to write come after the host.
        QStringList values;
        while (!args.isEmpty() && !args.last().startsWith('-') && args.size() >= 2 &&
               !args[args.size() - 2].startsWith('-'))
            values.prepend(args.takeLast());
        return run("mbpoll", QStringList{"-m", "tcp", "-p", QString::number(port), "-a", QString::number(unit), "-0",
                                         "-1", "-o", "1"} +
                                 args + QStringList{"127.0.0.1"} + values,
                   10000);
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        ports_ = freePorts(3);
        QCOMPARE(ports_.size(), std::size_t(3));
        a_ = std::make_unique<Serve>(kCli, ports_[0]);
        b_ = std::make_unique<Serve>(kCli, ports_[1]);
        QByteArray said;
        // What it serves, in its --lang (Russian unless told otherwise).
        QVERIFY2(a_->start({"--keys", kWorkWithPcKeys, "--lang", "en"}, &said), said.constData());
        QVERIFY2(said.contains("Modbus TCP " + a_->address().toUtf8() + ", unit 1"), said.constData());
        QVERIFY2(b_->start({"--address", "5"}, &said), said.constData());
        QVERIFY2(said.contains("Modbus TCP " + b_->address().toUtf8() + ", устройство 5"), said.constData());
    }
    void cleanupTestCase() {
        a_.reset();
        b_.reset();
    }

    void mbpollReadsAndWrites() {
        // C40 F ОБЫЧНАЯ X of training-lathe at Z4124/Z4125 (32-bit, low word first).
        CliResult r = mbpoll(ports_[0], {"-r", "4124", "-c", "1", "-t", "4:int"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains("[4124]: \t150000"), qPrintable(r.out));
        r = mbpoll(ports_[0], {"-r", "6000", "-c", "1", "-t", "4"});
        QVERIFY2(r.out.contains("[6000]: \t7"), qPrintable(r.out));
        r = mbpoll(ports_[0], {"-r", "5010", "-t", "4", "4321"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        r = mbpoll(ports_[0], {"-r", "5010", "-c", "1", "-t", "4"});
        QVERIFY2(r.out.contains("[5010]: \t4321"), qPrintable(r.out));
        r = mbpoll(ports_[0], {"-r", "5316", "-t", "4", "7"}); // R158, the positioner's own
        QVERIFY2((r.out + r.err).contains("Illegal data address"), qPrintable(r.out + r.err));
        // The second controller, on its own port, in F2 (not ready for the PC): exception 06.
        r = mbpoll(ports_[1], {"-r", "6000", "-c", "1", "-t", "4"}, 5);
        QVERIFY2(r.out.contains("[6000]: \t2"), qPrintable(r.out + r.err));
        r = mbpoll(ports_[1], {"-r", "5010", "-t", "4", "5"}, 5);
        QVERIFY2((r.out + r.err).contains("busy"), qPrintable(r.out + r.err));
    }

    void everyLinkCommandOverTcp() {
        CliResult r = link(*a_, {"ping"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains("answers on " + a_->address() + " at address 1"), qPrintable(r.out));
        QVERIFY2(r.out.contains("«K528-05 simulated by k528 serve: training-lathe»"), qPrintable(r.out));
        r = link(*a_, {"status", "--json"});
        QVERIFY2(r.exitCode == 0 && r.out.contains("\"mode\":7") && r.out.contains("\"pc_ready\":true"),
                 qPrintable(r.out + r.err));
        QVERIFY2(r.err.isEmpty() || !r.err.contains("bit/s"), qPrintable(r.err));

        const QString pulled = dir_.filePath("pulled.k528m");
        r = link(*a_, {"pull", "--out", pulled});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.err.contains("(Modbus TCP)"), qPrintable(r.err));
        const QString text = readAll(pulled);
        QVERIFY(text.contains("[program 1]"));
        // A file that cannot be written names itself and the system's reason.
        r = link(*a_, {"pull", "--out", "/dev/full"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("cannot write /dev/full: No space left on device"), qPrintable(r.err));
        QVERIFY2(text.contains("\nR5=4321"), qPrintable(text.left(400))); // mbpoll's write of the test before

        QString changed = text;
        changed.replace("[end program]", "N998 G4 X2.5\n[end program]");
        const QString changedFile = dir_.filePath("changed.k528m");
        writeFile(changedFile, changed);
        const QString frames = dir_.filePath("frames.txt");
        r = link(*a_, {"push", changedFile, "--frames", frames});
        QVERIFY2(r.exitCode == 0 && r.out.contains("written and verified"), qPrintable(r.out + r.err));
        // The frame log shows MBAP frames: transaction, protocol 0, length, unit 1, the PDU.
        const QString log = readAll(frames);
        QVERIFY2(QRegularExpression("TX  station   1  00 [0-9A-F]{2} 00 00 00 [0-9A-F]{2} 01 ").match(log).hasMatch(),
                 qPrintable(log.left(600)));
        QVERIFY(log.contains("  MBAP"));
        QVERIFY(!log.contains("CRC ok") && !log.contains("CRC BAD"));
        r = link(*a_, {"pull", "--out", dir_.filePath("again.k528m")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(readAll(dir_.filePath("again.k528m")).contains("N998 G4 X2.5"));

        r = link(*a_, {"clear", "r"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        r = mbpoll(ports_[0], {"-r", "5010", "-c", "1", "-t", "4"});
        QVERIFY2(r.out.contains("[5010]: \t0"), qPrintable(r.out));

        r = link(*a_, {"diag", "--json"});
        QVERIFY2(r.exitCode == 0 && r.out.contains("\"bus messages\""), qPrintable(r.out + r.err));
        r = link(*a_, {"watch", "--json", "--seconds", "0.5", "--interval-ms", "100"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.count("\"online\":true") >= 3, qPrintable(r.out));
    }

    void theUnitIdIsTheAddress() {
        CliResult r = link(*b_, {"--address", "5", "status"});
        QVERIFY2(r.exitCode == 0 && r.out.contains("mode F2"), qPrintable(r.out + r.err));
        // Refused off the screen of the PC, as on RS485.
        r = link(*b_, {"--address", "5", "clear", "r"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("РАБОТА С ПЭВМ"), qPrintable(r.err));
        // Another unit id is another station: it does not answer.
        r = link(*b_, {"--address", "6", "--timeout-ms", "100", "status"});
        QVERIFY2(r.exitCode != 0, qPrintable(r.out + r.err));
    }

    void saidInItsLang() {
        // Russian unless --lang en: the command's lines, core's refusals and
        // the line's failures (from Qt's error code, not its English).
        const auto linkIn = [&](const QString& lang, const Serve& s, const QStringList& args) {
            QStringList a{"link", "--tcp", s.address()};
            if (!lang.isEmpty())
                a << "--lang" << lang;
            return run(kCli, a + args);
        };
        CliResult r = linkIn({}, *a_, {"ping"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains("отвечает на " + a_->address() + ", адрес 1: режим F7 (РАБОТА С ПЭВМ)"), qPrintable(r.out));
        QVERIFY2(r.out.contains("; называет себя «K528-05 simulated by k528 serve: training-lathe»"), qPrintable(r.out));
        r = linkIn("ru", *b_, {"--address", "5", "clear", "r"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("k528 link: контроллер не в F7 «РАБОТА С ПЭВМ» (сейчас режим F2): нажмите F7"),
                 qPrintable(r.err));
        QVERIFY2(r.err.contains("повторите очистку R; ничего не отправлено"), qPrintable(r.err));
        r = linkIn("en", *b_, {"--address", "5", "clear", "r"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("k528 link: the controller is not in F7 «РАБОТА С ПЭВМ» (mode F2 now)") &&
                     r.err.contains("then clear R again; nothing was sent"),
                 qPrintable(r.err));
        r = linkIn({}, *a_, {"diag"});
        QVERIFY2(r.exitCode == 0 && r.out.contains("счётчики шины станции 1 (функция Modbus 08):"), qPrintable(r.out));
        QVERIFY2(r.err.contains("линия: ответов: ") && r.err.contains("повторов: 0"), qPrintable(r.err));
        // A scan says each station in the command's language too.
        r = linkIn({}, *a_, {"scan", "--addresses", "1"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains("адрес 1: эхо в порядке; идентификатор сервера 0x28") &&
                     r.out.contains("; карта K528-05: режим F7 «РАБОТА С ПЭВМ»") && r.out.contains("; время отклика "),
                 qPrintable(r.out));
        QVERIFY2(r.err.contains("поиск: ответивших станций: 1"), qPrintable(r.err));
        r = linkIn("en", *a_, {"scan", "--addresses", "1"});
        QVERIFY2(r.out.contains("address 1: echo ok; server id 0x28") && r.out.contains("; K528-05 map: mode F7"),
                 qPrintable(r.out));
        // --json is the same in both.
        const CliResult jsonRu = linkIn("ru", *a_, {"status", "--json"});
        const CliResult jsonEn = linkIn("en", *a_, {"status", "--json"});
        QVERIFY2(jsonRu.exitCode == 0 && jsonRu.out.contains("\"pc_ready\":true"), qPrintable(jsonRu.out + jsonRu.err));
        QCOMPARE(jsonRu.out, jsonEn.out);
        // Nobody listens: Qt's "Connection refused" said in the command's language.
        r = run(kCli, {"link", "--tcp", address(ports_[2]), "status"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("k528 link: не удаётся открыть 127.0.0.1:") && r.err.contains(": соединение отклонено"),
                 qPrintable(r.err));
        r = run(kCli, {"link", "--tcp", address(ports_[2]), "--lang", "en", "status"});
        QVERIFY2(r.err.contains(": connection refused"), qPrintable(r.err));
        r = run(kCli, {"link", "--tcp", a_->address(), "--lang", "de", "status"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("--lang — ru или en, а не «de»")), qPrintable(r.err));
    }

    void badLinesAreClear() {
        // Nobody listens on the third port: exit 2, and why.
        CliResult r = run(kCli, {"link", "--lang", "en", "--tcp", address(ports_[2]), "status"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("cannot open 127.0.0.1:") && r.err.contains("refused"), qPrintable(r.err));
        r = run(kCli, {"link", "--lang", "en", "--tcp", "127.0.0.1", "status"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--tcp takes HOST:PORT"), qPrintable(r.err));
        r = run(kCli, {"link", "--lang", "en", "--tcp", "127.0.0.1:70000", "status"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--tcp takes HOST:PORT"), qPrintable(r.err));
        r = run(kCli, {"link", "--lang", "en", "--tcp", a_->address(), "--baud", "9600", "status"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--baud is a setting of a serial line"), qPrintable(r.err));
        r = run(kCli, {"link", "--lang", "en", "--tcp", a_->address(), "--port", "/dev/null", "status"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("give one"), qPrintable(r.err));
        // A port another server holds: serve says so.
        Serve twice(kCli, ports_[0]);
        QByteArray said;
        QVERIFY(!twice.start({}, &said));
        twice.process().waitForFinished(5000);
        said += twice.process().readAllStandardError();
        QCOMPARE(twice.process().exitCode(), 2);
        QVERIFY2(said.contains("не удаётся обслуживать линию 127.0.0.1:"), said.constData()); // its --lang: ru
    }

    void watchSeesTheServerGoAndComeBack() {
        QProcess watch;
        watch.start(kCli, {"link", "--lang", "en", "--tcp", b_->address(), "--address", "5", "--timeout-ms", "100", "watch",
                           "--seconds", "8"});
        QVERIFY(watch.waitForStarted());
        QByteArray out;
        QTRY_VERIFY_WITH_TIMEOUT((out += watch.readAllStandardOutput()).contains("mode F2"), 5000);
        b_->kill();
        QTRY_VERIFY_WITH_TIMEOUT((out += watch.readAllStandardOutput()).contains("line lost at"), 3000);
        QByteArray said;
        QVERIFY2(b_->start({"--address", "5", "--keys", kWorkWithPcKeys}, &said), said.constData());
        QTRY_VERIFY_WITH_TIMEOUT((out += watch.readAllStandardOutput()).contains("line back at"), 3000);
        QTRY_VERIFY_WITH_TIMEOUT((out += watch.readAllStandardOutput()).contains("mode F7"), 3000);
        QVERIFY(watch.waitForFinished(15000));
        QCOMPARE(watch.exitCode(), 0);
    }
};

QTEST_GUILESS_MAIN(TestLinkTcp)
#include "test_link_tcp.moc"
