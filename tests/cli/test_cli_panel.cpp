// `k528 panel` (shared/spec/cli.md): the K923 of a freshly powered-on
// controller, keys in order, the four lines (or JSON) out.
#include "cli_runner.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

namespace {
QString lines(std::initializer_list<const char*> l) {
    QString out;
    for (const char* s : l)
        out += QString::fromUtf8(s).leftJustified(20) + "\n";
    return out;
}
} // namespace

class TestCliPanel : public QObject {
    Q_OBJECT
private slots:
    void powerOn() {
        const auto r = runK528({"panel"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out, lines({"РУЧ            100%", "", " X    0.000    0.000",
                               " Z    0.000    0.000"}));
        QVERIFY(r.err.isEmpty());
    }

    void keys_data() {
        QTest::addColumn<QString>("keys");
        QTest::addColumn<QString>("out");
        QTest::newRow("auto 2") << "F1 MODE"
                                << lines({"АВТ            100%", "", " X    0.000 F=  0.00",
                                          " Z    0.000 F=  0.00"});
        QTest::newRow("presets") << "F4 SHIFT+DOWN"
                                 << lines({"УСТ ПРЕДУСТАНОВКИ", " 2-ИСХОДНОЕ", " 3-ПОДНАЛАДКА",
                                           ">4-ПРАВКА"});
        QTest::newRow("cparams") << "F5 1 1 1 1 ENTER PAR 4 0 ENTER"
                                 << lines({"ПАРАМЕТРЫ СТАНКА", "F ОБЫЧНАЯ", "N040>X=150000",
                                           "N092 Z=200000"});
        QTest::newRow("editor") << "F6 1 1 1 1 ENTER UP ENTER"
                                << lines({" N1  G90 G0  G   #1", " M3  M8  M       L",
                                          "X42.000    F=", "Z2.000     F="});
        QTest::newRow("help") << "help 4"
                              << lines({"ABS_X 0.000", "ERR_X 0.000", "DAC_X 0", "PLS_X 0"});
        QTest::newRow("wait") << "F2 WAIT:0.5 MODE"
                              << lines({"РУЧ            100%", "", " X    0.000 F=  0.00",
                                        " Z    0.000 F=  0.00"});
    }
    void keys() {
        QFETCH(QString, keys);
        QFETCH(QString, out);
        const auto r = runK528({"panel", "--keys", keys});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out, out);
    }

    void otherProfile() {
        // grinder-205 (appendix Ж): C140 = 4 -> L2 is 10 %.
        const auto r = runK528({"panel", "--profile", "grinder-205", "--keys", "F1 L2"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.startsWith("АВТ             10%"), qPrintable(r.out));
    }

    void json() {
        const auto r = runK528({"panel", "--json", "--keys", "F4 2 1"});
        QCOMPARE(r.exitCode, 0);
        QJsonParseError e;
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8(), &e).object();
        QCOMPARE(e.error, QJsonParseError::NoError);
        const QJsonArray l = o["lines"].toArray();
        QCOMPARE(l.size(), 4);
        QCOMPARE(l[0].toString(), QString("УСТ2 ИСХОДНОЕ     X "));
        QCOMPARE(l[2].toString(), QString(">R220=1             "));
        const QJsonObject leds = o["leds"].toObject();
        QCOMPARE(leds["green"].toArray().size(), 0);
        QCOMPARE(leds["red"].toArray().size(), 0);
        QCOMPARE(leds["override"].toArray(), QJsonArray({4}));
        QCOMPARE(leds["shift"].toBool(), false);
        const QJsonObject blink = o["blink"].toObject();
        QCOMPARE(blink["row"].toInt(), 2);
        QCOMPARE(blink["column"].toInt(), 7);
        QCOMPARE(blink["length"].toInt(), 1);
        const auto n = runK528({"panel", "--json"});
        QVERIFY(QJsonDocument::fromJson(n.out.toUtf8()).object()["blink"].isNull());
    }

    // --machine: the simulated machine of the profile, with its PLC — the K
    // keys run the lathe's spindle and the PLC lights their LEDs (Z1906);
    // the pendant's buttons switch the drives on and start the
    // reference-point cycle; the E-stop mushroom gives message 9.
    void onTheSimulatedMachine() {
        const auto spindle = runK528(
            {"panel", "--machine", "--json", "--keys", "PUSH:DRIVES_ON WAIT:1 F2 K1 WAIT:5"});
        QCOMPARE(spindle.exitCode, 0);
        const QJsonObject leds = QJsonDocument::fromJson(spindle.out.toUtf8()).object()["leds"].toObject();
        QVERIFY2(leds["green"].toArray().contains(1), qPrintable(spindle.out)); // K1: spindle runs
        // Without the drives the PLC refuses the spindle: K1 stays dark.
        const auto refused = runK528({"panel", "--machine", "--json", "--keys", "F2 K1 WAIT:5"});
        QVERIFY(!QJsonDocument::fromJson(refused.out.toUtf8())
                     .object()["leds"].toObject()["green"].toArray().contains(1));
        // The ideal machine's PLC does not read the K keys.
        const auto ideal = runK528({"panel", "--json", "--keys", "F2 K1 WAIT:5"});
        QVERIFY(QJsonDocument::fromJson(ideal.out.toUtf8()).object()["leds"].toObject()["green"]
                    .toArray().isEmpty());
        // Homing from the pendant: ПБТ, X+ then Z+, the homed flags on line 1.
        const auto homed = runK528({"panel", "--machine", "--keys",
                                    "PUSH:DRIVES_ON WAIT:1 F3 PUSH:X+ WAIT:60 PUSH:Z+ WAIT:60"});
        QCOMPARE(homed.exitCode, 0);
        QVERIFY2(homed.out.startsWith("ПБТ X Z"), qPrintable(homed.out));
        // The E-stop: message 9 in the faults list (HELP 2), «!» on line 1.
        const auto estop = runK528({"panel", "--machine", "--keys",
                                    "PUSH:DRIVES_ON WAIT:1 PUSH:ESTOP WAIT:0.1 HELP 2"});
        QCOMPARE(estop.exitCode, 0);
        QVERIFY2(estop.out.contains("9."), qPrintable(estop.out));
        const auto pulled = runK528({"panel", "--machine", "--keys",
                                     "PUSH:DRIVES_ON WAIT:1 PUSH:ESTOP WAIT:0.1 PULL:ESTOP "
                                     "PUSH:RESET WAIT:0.5 ESC"});
        QVERIFY2(!pulled.out.section('\n', 0, 0).contains("!"), qPrintable(pulled.out));
    }

    // --machine FAULT:/CLEAR: — the K923's health faults of table М.1 and
    // the PLC's debug stop, as a trainer scripts them; PLCMODE:N — the PLC
    // imposes a mode (Z1000.8-10), the F keys are refused.
    void healthFaultsAndImposedMode() {
        const auto noPlc = runK528({"panel", "--machine", "--keys", "FAULT:PLC_LINK"});
        QCOMPARE(noPlc.exitCode, 0);
        QCOMPARE(noPlc.out.section('\n', 1, 1), QString("НЕТ СВЯЗИ С ПЛК").leftJustified(20));
        const auto noBp = runK528({"panel", "--machine", "--keys", "FAULT:BP_LINK"});
        QCOMPARE(noBp.out, lines({"НЕТ СВЯЗИ С БП", "", "", ""}));
        const auto ram = runK528({"panel", "--machine", "--keys", "fault:ram F2"});
        QCOMPARE(ram.out, lines({"НЕИСПРАВНО ОЗУ", "", "", ""}));
        const auto resident = runK528({"panel", "--machine", "--keys", "FAULT:RESIDENT"});
        QCOMPARE(resident.out, lines({"НАРУШЕН РЕЗИДЕНТ", "", "", ""}));
        const auto stop = runK528({"panel", "--machine", "--keys", "FAULT:PLC_STOP WAIT:0.5"});
        QCOMPARE(stop.out.section('\n', 1, 1), QString("Режим ПЛК СТОП !").leftJustified(20));
        // Mended: the message goes.
        const auto mended = runK528(
            {"panel", "--machine", "--keys", "FAULT:PLC_LINK WAIT:0.5 CLEAR:PLC_LINK WAIT:0.5"});
        QVERIFY2(!mended.out.contains("НЕТ СВЯЗИ"), qPrintable(mended.out));

        const auto imposed = runK528({"panel", "--machine", "--keys", "PLCMODE:1 WAIT:0.1 F2"});
        QCOMPARE(imposed.exitCode, 0);
        QVERIFY2(imposed.out.startsWith("АВТ"), qPrintable(imposed.out));
        QCOMPARE(imposed.out.section('\n', 1, 1), QString("РЕЖИМ ЗАДАН ПЛК").leftJustified(20));
        const auto released =
            runK528({"panel", "--machine", "--keys", "PLCMODE:1 WAIT:0.1 PLCMODE:0 F2"});
        QVERIFY2(released.out.startsWith("РУЧ"), qPrintable(released.out));
        // F5 imposed: the password is asked at once.
        const auto data = runK528({"panel", "--machine", "--keys", "PLCMODE:5 WAIT:0.1"});
        QVERIFY2(data.out.startsWith("ПАРОЛЬ?"), qPrintable(data.out));
        // The ideal machine's PLC imposes a mode too.
        const auto ideal = runK528({"panel", "--keys", "PLCMODE:1 F2"});
        QVERIFY2(ideal.out.startsWith("АВТ"), qPrintable(ideal.out));
    }

    // --lang: the messages on stderr in Russian (the default) or English,
    // as the other commands; here a hand-made machine description that
    // cannot be used, for `k528 panel` and `k528 serve` alike.
    void language() {
        QTemporaryDir dir;
        const auto write = [&](const QString& name, const QByteArray& text) {
            QFile f(dir.filePath(name));
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(text);
        };
        write("when.json", R"({"format": 1, "name": "b", "alarms": [{"k": 1, "when": "nosuch"}]})");
        QFile lathe(QStringLiteral(K528_SOURCE_DIR "/resources/profiles/training-lathe.k528m"));
        QVERIFY(lathe.open(QIODevice::ReadOnly));
        QByteArray machine = lathe.readAll();
        const QByteArray builtIn = "\nmachine=training-lathe\n";
        QVERIFY(machine.contains(builtIn));
        machine.replace(builtIn, "\nmachine=" + dir.filePath("when.json").toUtf8() + "\n");
        write("broken.k528m", machine);
        const QString profile = dir.filePath("broken.k528m");
        for (const QStringList& command : {QStringList{"panel", "--machine"},
                                          QStringList{"serve", "--tcp", "127.0.0.1:1502"}}) {
            const auto ru = runK528(command + QStringList{"--profile", profile});
            QCOMPARE(ru.exitCode, 2);
            QVERIFY2(ru.err.startsWith(QStringLiteral("k528: описание станка ")) &&
                         ru.err.contains(QStringLiteral("неизвестный сигнал «nosuch»")),
                     qPrintable(ru.err));
            const auto en = runK528(command + QStringList{"--profile", profile, "--lang", "en"});
            QCOMPARE(en.exitCode, 2);
            QVERIFY2(en.err.startsWith(QStringLiteral("k528: machine description ")) &&
                         en.err.contains(QStringLiteral("unknown signal 'nosuch'")),
                     qPrintable(en.err));
            // A profile that is none: core's problem in the language asked for.
            const auto noneRu = runK528(command + QStringList{"--profile", "no-such-machine"});
            QCOMPARE(noneRu.exitCode, 2);
            QVERIFY2(noneRu.err.contains(QStringLiteral("no-such-machine: это не встроенный профиль")),
                     qPrintable(noneRu.err));
            const auto noneEn = runK528(command + QStringList{"--profile", "no-such-machine", "--lang", "en"});
            QVERIFY2(noneEn.err.contains(QStringLiteral("no-such-machine: neither a built-in profile")),
                     qPrintable(noneEn.err));
            const auto bad = runK528(command + QStringList{"--lang", "de"});
            QCOMPARE(bad.exitCode, 2);
            // Not English: said in Russian, the default.
            QVERIFY2(bad.err.contains(QStringLiteral("--lang — ru или en, а не «de»")), qPrintable(bad.err));
        }
    }

    void errors_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("unknown key")
            << QStringList{"panel", "--keys", "F1 FOO ENTER"} << "unknown key 'FOO'";
        QTest::newRow("F9") << QStringList{"panel", "--keys", "F9"} << "unknown key 'F9'";
        QTest::newRow("bad shift")
            << QStringList{"panel", "--keys", "SHIFT+X"} << "unknown key 'SHIFT+X'";
        QTest::newRow("bad wait") << QStringList{"panel", "--keys", "WAIT:abc"} << "WAIT:abc";
        QTest::newRow("negative wait") << QStringList{"panel", "--keys", "WAIT:-1"} << "WAIT:-1";
        QTest::newRow("unknown profile")
            << QStringList{"panel", "--profile", "no-such-machine"} << "no-such-machine";
        QTest::newRow("file argument") << QStringList{"panel", "x.k528"} << "takes no file";
        QTest::newRow("unknown option") << QStringList{"panel", "--frob"} << "--frob";
        QTest::newRow("button without --machine")
            << QStringList{"panel", "--keys", "PUSH:START"} << "give --machine";
        QTest::newRow("unknown button")
            << QStringList{"panel", "--machine", "--keys", "PUSH:FOO"} << "unknown machine button";
        QTest::newRow("hold without time")
            << QStringList{"panel", "--machine", "--keys", "HOLD:X+"} << "HOLD:BUTTON:S";
        QTest::newRow("pull a button")
            << QStringList{"panel", "--machine", "--keys", "PULL:START"} << "PULL:ESTOP";
        QTest::newRow("fault without --machine")
            << QStringList{"panel", "--keys", "FAULT:RAM"} << "give --machine";
        QTest::newRow("unknown fault")
            << QStringList{"panel", "--machine", "--keys", "FAULT:FOO"} << "faults: PLC_LINK";
        QTest::newRow("bad mode")
            << QStringList{"panel", "--machine", "--keys", "PLCMODE:8"} << "PLCMODE:0 lets go";
    }
    void errors() {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const auto r = runK528(args + QStringList{"--lang", "en"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.out.isEmpty());
        QVERIFY2(r.err.startsWith("k528: ") && r.err.contains(message), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliPanel)
#include "test_cli_panel.moc"
