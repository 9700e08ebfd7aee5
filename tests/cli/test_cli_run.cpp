// `k528 run` (shared/spec/cli.md): the JSON end state, options, exit codes,
// determinism.
#include "cli_runner.h"
#include "util/json.h"

#include <QTemporaryDir>
#include <QtTest>
#include <tuple>

using namespace k528;

namespace {

QString samples() {
    return QStringLiteral(K528_SOURCE_DIR "/resources/samples/");
}

struct Files {
    QTemporaryDir dir;
    QString write(const QString& name, const QByteArray& text) {
        const QString path = dir.filePath(name);
        QFile f(path);
        f.open(QIODevice::WriteOnly);
        f.write(text);
        return path;
    }
};

Json parseJson(const CliResult& r) {
    return json::parse(r.out.toStdString());
}

} // namespace

class TestCliRun : public QObject {
    Q_OBJECT
private slots:
    void jsonShape() {
        const auto r = runK528({"run", "--json", samples() + "lathe-shaft.k528"});
        QCOMPARE(r.exitCode, 0);
        const Json v = parseJson(r);
        QCOMPARE(QString::fromStdString(v.at("status").get<std::string>()), QString("completed"));
        QVERIFY(v.at("alarms").is_array());
        QCOMPARE(v.at("alarms").size(), std::size_t(0));
        QVERIFY(v.at("time_s").get<double>() > 100);
        QVERIFY(v.at("home_time_s").get<double>() > 1);
        QVERIFY(v.at("frames").get<std::int64_t>() > 20);
        const Json& axes = v.at("axes");
        QVERIFY(axes.is_object());
        for (const char* axis : {"X", "Z"})
            for (const char* key : {"current", "machine", "max_following_error"})
                QVERIFY2(axes.at(axis).at(key).is_number(), key);
        // The values, every field: golden case sample-lathe-shaft (tests/programs).
        const Json& rv = v.at("r");
        QCOMPARE(rv.size(), std::size_t(300));
        QCOMPARE(rv.begin().key(), std::string("0"));
        QCOMPARE(std::prev(rv.end()).key(), std::string("299"));
        // The key order of cli.md, with our extension "blocked_by" after
        // "alarms" (docs/engine.md): empty when the run started.
        std::vector<std::string> keys;
        for (const auto& item : v.items())
            keys.push_back(item.key());
        QCOMPARE(keys, (std::vector<std::string>{"status", "alarms", "blocked_by", "time_s",
                                                 "home_time_s", "frames", "axes", "r"}));
        QVERIFY(v.at("blocked_by").empty());
    }
    void deterministic() {
        const QStringList args{"run", "--json", "--profile", "grinder-205",
                               samples() + "grinder-bore-205.k528"};
        const auto a = runK528(args);
        const auto b = runK528(args);
        QCOMPARE(a.exitCode, 0);
        QCOMPARE(a.out, b.out);
        QVERIFY(!a.out.isEmpty());
    }
    // An alarm: status "alarm", exit 1, the message with program and line.
    void alarmExit() {
        Files f;
        const QString p = f.write("ovf.k528", "%L3\nN1 R1=2147483647\nN2 R1=R1+1\n");
        const auto r = runK528({"run", "--json", p});
        QCOMPARE(r.exitCode, 1);
        const Json v = parseJson(r);
        QCOMPARE(QString::fromStdString(v.at("status").get<std::string>()), QString("alarm"));
        const Json& a = v.at("alarms").at(0);
        QCOMPARE(a.at("number").get<std::int64_t>(), 46);
        QCOMPARE(QString::fromStdString(a.at("text_ru").get<std::string>()),
                 QString("Переполнение"));
        QCOMPARE(a.at("program").get<std::int64_t>(), 3);
        QCOMPARE(a.at("line").get<std::int64_t>(), 3);
        // --no-home on a machine that needs it (42): golden case sample-lathe-grooves-no-home.
    }
    // The wheel outside R205..R206: the positioner blocks the program with
    // 44 «D круга < Dmin» / 43 «D круга > Dmax» (appendix М), never a
    // silent timeout after 0 frames.
    void wheelDiameterBlocksTheProgram() {
        for (const auto& [r207, number, text] :
             {std::tuple{"207=13000", 44, "D круга < Dmin"}, std::tuple{"207=21000", 43, "D круга > Dmax"}}) {
            const auto r = runK528({"run", "--json", "--profile", "grinder-205", "--r", r207,
                                    samples() + "grinder-bore-205.k528"});
            QCOMPARE(r.exitCode, 1);
            const Json v = parseJson(r);
            QCOMPARE(QString::fromStdString(v.at("status").get<std::string>()), QString("alarm"));
            QCOMPARE(v.at("frames").get<std::int64_t>(), 0);
            const Json& a = v.at("alarms").at(0);
            QCOMPARE(a.at("number").get<std::int64_t>(), number);
            QCOMPARE(QString::fromStdString(a.at("text_ru").get<std::string>()),
                     QString::fromUtf8(text));
        }
    }
    void timeout() {
        Files f;
        const QString p = f.write("loop.k528", "%L1\nN1 G1 Z-1 FZ600\nN2 G1 Z0\nN3 GOTO 1\n");
        const auto r = runK528({"run", "--json", "--max-seconds", "5", p});
        QCOMPARE(r.exitCode, 1);
        const Json v = parseJson(r);
        QCOMPARE(QString::fromStdString(v.at("status").get<std::string>()), QString("timeout"));
        QVERIFY(std::fabs(v.at("time_s").get<double>() - 5.0) < 0.01);
        // --override is the program's: the homing runs at 100 % and the
        // program at 0 % stands still until the limit.
        const auto z = runK528({"run", "--json", "--override", "0", "--max-seconds", "2", p});
        QCOMPARE(z.exitCode, 1);
        const Json w = parseJson(z);
        QCOMPARE(QString::fromStdString(w.at("status").get<std::string>()), QString("timeout"));
        QCOMPARE(w.at("home_time_s").get<double>(), v.at("home_time_s").get<double>());
        QVERIFY(std::fabs(w.at("time_s").get<double>() - 2.0) < 0.01);
    }
    void presetsAndOverrides() {
        Files f;
        const QString p = f.write("r.k528", "%L1\nN1 R11=R10+1\nN2 G0 Z-60\n");
        const auto a = runK528({"run", "--json", "--r", "10=123", p});
        QCOMPARE(a.exitCode, 0);
        const Json v = parseJson(a);
        QCOMPARE(v.at("r").at("11").get<std::int64_t>(), 124);
        // C94 (F УСК.АВТ. of Z) halved: the rapid takes longer.
        const auto b = runK528({"run", "--json", "--param", "94=300000", p});
        QCOMPARE(b.exitCode, 0);
        QVERIFY(parseJson(b).at("time_s").get<double>() > v.at("time_s").get<double>() + 0.4);
        // 50 % override.
        const auto c = runK528({"run", "--json", "--override", "50", p});
        QVERIFY(parseJson(c).at("time_s").get<double>() > v.at("time_s").get<double>() + 0.4);
        // --program picks one of the file.
        const QString two = f.write("two.k528", "%L4\nN1 R1=4\n%L2\nN1 R1=2\n");
        QCOMPARE(parseJson(runK528({"run", "--json", two})).at("r").at("1").get<std::int64_t>(), 4);
        QCOMPARE(parseJson(runK528({"run", "--json", "--program", "2", two}))
                     .at("r")
                     .at("1")
                     .get<std::int64_t>(),
                 2);
    }
    // --profile NAME takes the machine from the database first (the shop's
    // constants as `k528 db set` left them), --db names it; without a
    // database file the built-in profile runs.
    void profileFromTheDatabase() {
        Files f;
        const QString p = f.write("rapid.k528", "%L1\nN1 G0 Z-60\n");
        const QString db = f.dir.filePath("shop.db");
        const auto builtin = runK528({"run", "--json", "--db", db, p});
        QCOMPARE(builtin.exitCode, 0);
        QVERIFY(!QFile::exists(db)); // looking for a machine creates nothing
        QCOMPARE(runK528({"db", "init", "--db", db}).exitCode, 0);
        const auto same = runK528({"run", "--json", "--db", db, p});
        QCOMPARE(same.out, builtin.out); // the seeded machine is the built-in one
        // C94 (F УСК.АВТ. of Z) halved in the database: the rapid takes longer.
        const auto set = runK528({"db", "set", "training-lathe", "C094=300000", "--db", db});
        QVERIFY2(set.exitCode == 0, qPrintable(set.err));
        const auto slower = runK528({"run", "--json", "--db", db, p});
        QCOMPARE(slower.exitCode, 0);
        QVERIFY(parseJson(slower).at("time_s").get<double>() >
                parseJson(builtin).at("time_s").get<double>() + 0.4);
        // A machine only the database knows, under its own name.
        const QString file = f.dir.filePath("lathe2.k528m");
        QCOMPARE(runK528({"db", "export", "training-lathe", "--out", file, "--db", db}).exitCode, 0);
        QCOMPARE(runK528({"db", "import", file, "--as", "lathe-2", "--db", db}).exitCode, 0);
        const auto other = runK528({"run", "--json", "--profile", "lathe-2", "--db", db, p});
        QVERIFY2(other.exitCode == 0, qPrintable(other.err));
        QCOMPARE(other.out, slower.out);
        // k528 check and k528 panel take the same machine.
        const QString far = f.write("far.k528", "%L1\nN1 G0 Z-200\n");
        QVERIFY(runK528({"check", "--profile", "lathe-2", "--db", db, far}).out.contains("[M"));
        QCOMPARE(runK528({"panel", "--profile", "lathe-2", "--db", db}).exitCode, 0);
        const auto unknown = runK528({"run", "--profile", "lathe-3", "--db", db, p});
        QCOMPARE(unknown.exitCode, 2);
        QVERIFY(unknown.err.contains("lathe-3"));
        // A damaged database is an error, not a silent fall-back.
        const QString bad = f.write("bad.db", QByteArray(4096, 'x'));
        const auto damaged = runK528({"run", "--db", bad, p});
        QCOMPARE(damaged.exitCode, 2);
        QVERIFY(!damaged.err.isEmpty());
    }
    void usageErrors() {
        const QString s = samples() + "lathe-shaft.k528";
        const QList<QStringList> bad = {
            {"run"},
            {"run", "--param", "29=5000", s},
            {"run", "--param", "200=1", s},
            {"run", "--param", "x", s},
            {"run", "--r", "240=1", s},
            {"run", "--r", "5=3000000000", s},
            {"run", "--override", "33", s},
            {"run", "--max-seconds", "-1", s},
            // NaN and inf are not numbers of seconds.
            {"run", "--max-seconds", "nan", s},
            {"run", "--max-seconds", "inf", s},
            {"run", "--m0-wait", "nan", s},
            {"run", "--m0-wait", "-nan", s},
            {"run", "--m0-wait", "inf", s},
            {"run", "--profile", "no-such-machine", s},
            {"run", "--program", "7", s},
            {"run", "--frobnicate", s},
            {"run", "/no/such/file.k528"},
        };
        for (const QStringList& args : bad) {
            const auto r = runK528(args);
            QVERIFY2(r.exitCode == 2, qPrintable(args.join(' ')));
            QVERIFY2(r.err.startsWith("k528: "), qPrintable(args.join(' ') + ": " + r.err));
        }
        QVERIFY(runK528({"run", "--param", "29=5000", s}).err.contains("29"));
    }
    // A file with errors is not run: diagnostics as `check` prints them, exit 1.
    void fileErrors() {
        Files f;
        const QString p = f.write("bad.k528", "%L1\nN1 G1 X=\nN2 GOTO 9\n");
        const auto r = runK528({"run", p});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.out.contains("bad.k528:2:"));
        QVERIFY(r.out.contains("error"));
        const QString q = f.write("jump.k528", "%L1\nN1 GOTO 9\n");
        const auto j = runK528({"run", "--json", q});
        QCOMPARE(j.exitCode, 1);
        QVERIFY(j.out.isEmpty());
        QVERIFY(j.err.contains("[M53]"));
    }
    // A hand-made machine description that cannot be used: the file, the
    // place in it and what is wrong, in the language asked for (exit 2).
    void brokenDescription() {
        Files f;
        const QString json = f.write("when.json", R"({"format": 1, "name": "b", "flags": ["f"],
            "alarms": [{"k": 1, "when": "f & nosuch"}]})");
        QFile lathe(QStringLiteral(K528_SOURCE_DIR "/resources/profiles/training-lathe.k528m"));
        QVERIFY(lathe.open(QIODevice::ReadOnly));
        QByteArray machine = lathe.readAll();
        const QByteArray builtIn = "\nmachine=training-lathe\n";
        QVERIFY(machine.contains(builtIn));
        machine.replace(builtIn, "\nmachine=" + json.toUtf8() + "\n");
        const QString profile = f.write("broken.k528m", machine);
        const QString p = f.write("p.k528", "%L1\nN1 G90 G01 X10 FX100\nN2 M30\n");
        const auto ru = runK528({"run", "--profile", profile, "--lang", "ru", p});
        QCOMPARE(ru.exitCode, 2);
        QCOMPARE(ru.err.trimmed(), QStringLiteral("k528: описание станка %1: alarms[0].when: столбец 5: неизвестный "
                                                  "сигнал «nosuch» в \"f & nosuch\"").arg(json));
        const auto en = runK528({"run", "--profile", profile, "--lang", "en", p});
        QCOMPARE(en.exitCode, 2);
        QCOMPARE(en.err.trimmed(), QStringLiteral("k528: machine description %1: alarms[0].when: column 5: unknown "
                                                  "signal 'nosuch' in \"f & nosuch\"").arg(json));
    }
    void plainOutput() {
        const auto r =
            runK528({"run", "--profile", "grinder-205", samples() + "grinder-bore-205.k528"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.startsWith("status     completed\n"));
        QVERIFY(r.out.contains("(diameter)"));
        QVERIFY(r.out.contains("M to PLC"));
    }

    // An alarm line is the panel's text (engine::alarmText): «37. Ошибка N
    // ДОС» with the blank table М.1 prints, «46.Переполнение» without.
    void plainAlarmLines() {
        Files f;
        const QString p = f.write("ovf.k528", "%L3\nN1 R1=2147483647\nN2 R1=R1+1\n");
        const auto o = runK528({"run", p});
        QCOMPARE(o.exitCode, 1);
        QVERIFY2(o.out.contains(QString("\nalarm      46.Переполнение  (L3, line 3)\n")),
                 qPrintable(o.out));
        // Both encoders on one channel (C69 = C17 = 1): 37 at power-on.
        const auto e = runK528({"run", "--param", "17=1", "--param", "69=1", p});
        QCOMPARE(e.exitCode, 1);
        QVERIFY2(e.out.contains(QString("\nalarm      37. Ошибка N ДОС\n")), qPrintable(e.out));
        const auto en = runK528({"run", "--lang", "en", "--param", "17=1", "--param", "69=1", p});
        QVERIFY2(en.out.contains(QString("\nalarm      37. N encoder error\n")),
                 qPrintable(en.out));
    }

    // --trace FILE.csv (docs/engine.md): one row per tick with the columns of
    // cli.md; its largest |following error| per axis is the engine's maximum
    // (the JSON's max_following_error) within one discrete (0.001 mm).
    void traceOfAKnownMove() {
        Files f;
        const QString p = f.write("move.k528", "%L1\nN1 G1 Z-20 FZ6000\nN2 G0 X40\n");
        const QString csv = f.dir.filePath("trace.csv");
        // АВТ.БЕЗ ПБТ (C8, C60) = 1: the program runs without the reference cycles.
        const auto r = runK528({"run", "--json", "--no-home", "--param", "8=1", "--param", "60=1",
                                "--trace", csv, p});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const Json v = parseJson(r);
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = file.readAll().split('\n');
        QCOMPARE(lines.front(),
                 QByteArray("t_ms,X_setpoint_mm,X_position_mm,X_velocity_mm_min,"
                            "X_following_error_mm,X_dac,Z_setpoint_mm,Z_position_mm,"
                            "Z_velocity_mm_min,Z_following_error_mm,Z_dac"));
        double maxErr[2] = {0, 0};
        double lastPos[2] = {0, 0};
        double maxSpeedZ = 0;
        qint64 lastT = 0;
        int rows = 0;
        for (qsizetype i = 1; i < lines.size(); ++i) {
            if (lines[i].isEmpty())
                continue;
            const QList<QByteArray> c = lines[i].split(',');
            QCOMPARE(c.size(), 11);
            const qint64 t = c[0].toLongLong();
            QCOMPARE(t, lastT + 1); // every 1 ms tick, none left out
            lastT = t;
            for (int a = 0; a < 2; ++a) {
                const double sp = c[1 + 5 * a].toDouble(), pos = c[2 + 5 * a].toDouble();
                const double err = c[4 + 5 * a].toDouble();
                QVERIFY(std::fabs(sp - pos - err) < 2e-5); // error = setpoint - position
                maxErr[a] = std::max(maxErr[a], std::fabs(err));
                lastPos[a] = pos;
            }
            maxSpeedZ = std::max(maxSpeedZ, std::fabs(c[8].toDouble()));
            ++rows;
        }
        QVERIFY(rows > 1000);
        const Json& axes = v.at("axes");
        const char* names[2] = {"X", "Z"};
        for (int a = 0; a < 2; ++a) {
            const double engineMax = axes.at(names[a]).at("max_following_error").get<double>();
            QVERIFY2(engineMax > 0.01, names[a]); // the move really lags
            QVERIFY2(std::fabs(maxErr[a] - engineMax) <= 0.001,
                     qPrintable(QString("%1: trace %2 engine %3")
                                    .arg(names[a]).arg(maxErr[a]).arg(engineMax)));
            QVERIFY(std::fabs(lastPos[a] - axes.at(names[a]).at("current").get<double>()) <= 0.002);
        }
        QVERIFY(maxSpeedZ > 1000.0 && maxSpeedZ < 6000.0 * 1.01); // FZ6000 mm/min at most
        // A trace that cannot be written: exit 2 with the reason.
        const auto bad = runK528({"run", "--no-home", "--trace", f.dir.filePath("no/such/t.csv"), p});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains(QStringLiteral("файл трассы: не удаётся записать ") + f.dir.filePath("no/such/t.csv")) &&
                     bad.err.contains(QStringLiteral("нет такого файла или папки")),
                 qPrintable(bad.err));
    }

    // A trace or an output that is lost says the file and the system's reason,
    // and a trace replaces its file only when whole (written beside it, renamed).
    void lostWritesSayWhy() {
        Files f;
        const QString p = f.write("move.k528", "%L1\nN1 G1 Z-20 FZ6000\nN2 G0 X40\n");
        auto r = runK528({"run", "--no-home", "--trace", "/dev/full", p});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("не удаётся записать /dev/full: на устройстве не осталось места")), qPrintable(r.err));
        const QString csv = f.dir.filePath("t.csv");
        {
            QFile old(csv);
            QVERIFY(old.open(QIODevice::WriteOnly));
            old.write("old trace\n");
        }
        r = runK528({"run", "--no-home", "--param", "8=1", "--param", "60=1", "--trace", csv, p});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile done(csv);
        QVERIFY(done.open(QIODevice::ReadOnly));
        QVERIFY(done.readAll().startsWith("t_ms,"));
        QCOMPARE(QDir(f.dir.path()).entryList({"*.k528-*"}, QDir::Hidden | QDir::Files).size(), 0);
        r = runK528ToFile({"path", "--json", p}, "/dev/full");
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("не удаётся записать стандартный вывод: на устройстве не осталось места")), qPrintable(r.err));
        r = runK528ToFile({"path", p}, "/dev/full");
        QVERIFY2(r.err.contains(QStringLiteral("на устройстве не осталось места")), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliRun)
#include "test_cli_run.moc"
