#include <QtTest>

#include <QTemporaryDir>

#include <sys/stat.h>

#include "cli_runner.h"
#include "util/version.h"

class TestCliBasics : public QObject {
    Q_OBJECT
private slots:
    void version() {
        const auto r = runK528({"--version"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out, QString("k528 %1 (K528 Studio)\n").arg(k528::version_string));
    }
    void help() {
        const auto r = runK528({"--help"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.startsWith("Usage: k528 COMMAND"));
        QVERIFY(r.out.contains("Exit codes: 0 success"));
    }
    void noArgumentsIsUsageError() {
        const auto r = runK528({});
        QCOMPARE(r.exitCode, 2);
    }
    // The command line's own usage errors in Russian, as every command's
    // --lang by default, and in English with --lang en: never an English
    // sentence in a Russian run (three English words in a row).
    void unknownCommandIsUsageError() {
        static const QRegularExpression english(QStringLiteral("(?:[A-Za-z]+ ){2,}[A-Za-z]+"));
        struct Case {
            QStringList args;
            QString ru, en;
        };
        const QList<Case> cases = {
            {{"frobnicate"}, QStringLiteral("k528: неизвестная команда «frobnicate»\nСправка: k528 --help.\n"),
             "k528: unknown command 'frobnicate'\nTry 'k528 --help'.\n"},
            {{"--frobnicate"}, QStringLiteral("k528: неизвестный параметр --frobnicate\nСправка: k528 --help.\n"),
             "k528: unknown option --frobnicate\nTry 'k528 --help'.\n"},
            {{"check", "--frobnicate", "x.k528"}, QStringLiteral("k528: неизвестный параметр --frobnicate\nСправка: k528 --help.\n"),
             "k528: unknown option --frobnicate\nTry 'k528 --help'.\n"},
            {{"run", "--max-seconds"}, QStringLiteral("k528: параметру --max-seconds нужно значение\nСправка: k528 --help.\n"),
             "k528: option --max-seconds needs a value\nTry 'k528 --help'.\n"},
            {{"check", "--json=yes", "x.k528"}, QStringLiteral("k528: параметр --json не принимает значения\nСправка: k528 --help.\n"),
             "k528: option --json takes no value\nTry 'k528 --help'.\n"},
        };
        for (const Case& c : cases) {
            auto r = runK528(c.args);
            QCOMPARE(r.exitCode, 2);
            QCOMPARE(r.err, c.ru);
            QVERIFY2(!r.err.contains(english), qPrintable(r.err));
            // --lang en right after the command (an option before it would take it as its value).
            QStringList en = c.args;
            en.insert(1, "--lang");
            en.insert(2, "en");
            r = runK528(en);
            QCOMPARE(r.exitCode, 2);
            QCOMPARE(r.err, c.en);
            en.remove(1, 2);
            en.insert(1, "--lang=en");
            QCOMPARE(runK528(en).err, c.en);
        }
    }
    // An extra word after --version / --help is a usage error.
    void versionAndHelpTakeNoArguments() {
        auto v = runK528({"--version", "extra"});
        QCOMPARE(v.exitCode, 2);
        QCOMPARE(v.out, QString());
        QVERIFY2(v.err.contains(QStringLiteral("--version не принимает аргументов, а здесь «extra»")), qPrintable(v.err));
        v = runK528({"--version", "extra", "--lang", "en"});
        QCOMPARE(v.exitCode, 2);
        QVERIFY2(v.err.contains("--version takes no arguments, not 'extra'"), qPrintable(v.err));
        QCOMPARE(runK528({"--help", "extra"}).exitCode, 2);
        QCOMPARE(runK528({"help", "check", "extra"}).exitCode, 2);
        QCOMPARE(runK528({"help", "check"}).exitCode, 0);
    }

    // Output lost to a full disk is an I/O error (exit 2), never
    // success — for every command that prints.
    void lostStandardOutputIsAnError_data() {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("format") << QStringList{"format", "@FILE"};
        QTest::newRow("check --json") << QStringList{"check", "--json", "@FILE"};
        QTest::newRow("check") << QStringList{"check", "@BAD"};
        QTest::newRow("run --json") << QStringList{"run", "--json", "@FILE"};
        QTest::newRow("panel") << QStringList{"panel", "--keys", "F1"};
        QTest::newRow("--version") << QStringList{"--version"};
        QTest::newRow("--help") << QStringList{"--help"};
    }
    void lostStandardOutputIsAnError() {
        QFETCH(QStringList, args);
        QTemporaryDir dir;
        const QString file = dir.filePath("ok.k528");
        const QString bad = dir.filePath("bad.k528");
        QFile f(file);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("%L1\nG1 X5 F100\nM30\n");
        f.close();
        QFile b(bad);
        QVERIFY(b.open(QIODevice::WriteOnly));
        b.write("G1 X5..3\n");
        b.close();
        args.replaceInStrings("@FILE", file);
        args.replaceInStrings("@BAD", bad);
        QVERIFY(QFileInfo::exists("/dev/full"));
        const auto r = runK528ToFile(args, "/dev/full");
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("k528: не удаётся записать стандартный вывод: на устройстве не осталось места")),
                 qPrintable(r.err));
        // The same command to a real file succeeds (or reports its errors: 1).
        const auto ok = runK528ToFile(args, dir.filePath("out.txt"));
        QVERIFY2(ok.exitCode == 0 || ok.exitCode == 1, qPrintable(ok.err));
        QVERIFY(QFileInfo(dir.filePath("out.txt")).size() > 0);
    }

    // A device, a FIFO, a directory or a file far beyond what a
    // controller holds is refused with exit 2 and the reason, by every
    // command that reads a file (one reader, util/input_file.h).
    void inputsHaveALimit_data() {
        QTest::addColumn<QString>("command");
        QTest::newRow("check") << "check";
        QTest::newRow("format") << "format";
        QTest::newRow("run") << "run";
        QTest::newRow("panel --profile") << "panel";
        QTest::newRow("db import") << "db";
    }
    void inputsHaveALimit() {
        QFETCH(QString, command);
        QTemporaryDir dir;
        const auto call = [&](const QString& path) {
            if (command == "panel")
                return runK528({"panel", "--profile", path, "--db", dir.filePath("none.db")});
            if (command == "db")
                return runK528({"db", "import", path, "--db", dir.filePath("x.db")});
            return runK528({command, path});
        };
        auto r = call("/dev/zero");
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("/dev/zero") && r.err.contains(QStringLiteral("это символьное устройство, а не обычный файл")),
                 qPrintable(r.err));
        const QString fifo = dir.filePath("fifo");
        QCOMPARE(::mkfifo(fifo.toLocal8Bit().constData(), 0600), 0);
        r = call(fifo);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("это FIFO (именованный канал), а не обычный файл")), qPrintable(r.err));
        // 17 MiB (sparse): beyond the 16 MiB limit, refused before it is read.
        const QString big = dir.filePath("big.k528");
        QFile f(big);
        QVERIFY(f.open(QIODevice::WriteOnly));
        QVERIFY(f.resize(17 << 20));
        f.close();
        r = call(big);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("он больше 16 МиБ")) && r.err.contains(QStringLiteral("99 программ по 999 кадров")),
                 qPrintable(r.err));
        if (command != "panel") {
            QCOMPARE(call(dir.path()).exitCode, 2);
        }
    }
    void standardInputHasTheLimitToo() {
        QByteArray huge(17 << 20, 'M');
        const auto r = runK528({"check", "-"}, huge);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("не удаётся прочитать стандартный ввод: он больше 16 МиБ")), qPrintable(r.err));
    }

    // Running out of memory ends in a message and exit 2, not an
    // abort on an uncaught std::bad_alloc (address space capped by prlimit).
    void outOfMemoryIsAMessage() {
        if (!QFileInfo::exists("/usr/bin/prlimit"))
            QSKIP("prlimit (util-linux) is not installed");
#if defined(__SANITIZE_ADDRESS__)
        QSKIP("AddressSanitizer reserves more address space than the cap");
#endif
        // k528 starts in about 32 MiB of address space; 48 MiB leave less
        // than two bytes of room per byte of this 12.8 MB text.
        QTemporaryDir dir;
        const QString file = dir.filePath("large.k528");
        QFile f(file);
        QVERIFY(f.open(QIODevice::WriteOnly));
        QByteArray frames;
        for (int i = 0; i < 400000; ++i)
            frames += "G1 X1.5 FX100 Z-2.25 FZ200 ; c\n";
        f.write(frames);
        f.close();
        const auto r = runK528ToFile({"check", file}, dir.filePath("out.txt"), QStringLiteral(K528_CLI),
                                     {"/usr/bin/prlimit", "--as=" + QString::number(48 << 20)});
        QVERIFY2(r.exitCode == 2, qPrintable(QString("exit %1: %2").arg(r.exitCode).arg(r.err)));
        QVERIFY2(r.err.contains(QStringLiteral("k528: не хватило памяти, чтобы выполнить команду")), qPrintable(r.err));
        const auto en = runK528ToFile({"check", "--lang", "en", file}, dir.filePath("out.txt"), QStringLiteral(K528_CLI),
                                      {"/usr/bin/prlimit", "--as=" + QString::number(48 << 20)});
        QVERIFY2(en.exitCode == 2, qPrintable(QString("exit %1: %2").arg(en.exitCode).arg(en.err)));
        QVERIFY2(en.err.contains("not enough memory"), qPrintable(en.err));
    }
};

QTEST_GUILESS_MAIN(TestCliBasics)
#include "test_cli_basics.moc"
