#include <QtTest>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>

#include "cli_runner.h"
#include "test_util.h"

namespace {

using testutil::writeBytes;

} // namespace

class TestCliCheck : public QObject {
    Q_OBJECT
private slots:
    void cleanFileExitsZeroSilently() {
        QTemporaryDir dir;
        const QString f = writeBytes(dir, "ok.k528", "%L1\nN1 G1 X5 FX100\nN2 M30\n");
        const auto r = runK528({"check", f});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out, QString());
        QCOMPARE(r.err, QString());
    }
    // A file with nothing in it is not silently clean: a warning, exit 0.
    void fileWithoutProgramsIsSaidSo() {
        QTemporaryDir dir;
        for (const char* text : {"", "; a comment only\n\n", "(remark)\n"}) {
            const QString f = writeBytes(dir, "none.k528", text);
            const auto r = runK528({"check", "--lang", "en", f});
            QCOMPARE(r.exitCode, 0);
            QVERIFY2(r.out.contains(":1:1: warning: the file holds no program"), qPrintable(r.out));
        }
        // Near miss: a message table alone is something.
        const QString m = writeBytes(dir, "msg.k528", "%MESSAGES\n#1=ПРОБА\n");
        QVERIFY(!runK528({"check", "--lang", "en", m}).out.contains("holds no program"));
    }
    void plainLinesInRussianByDefault() {
        QTemporaryDir dir;
        const QString f = writeBytes(dir, "bad.k528", "%L1\nN1 GOTO 5\nG1 X1\nN2 M30\n");
        const auto r = runK528({"check", f});
        QCOMPARE(r.exitCode, 1);
        const QStringList lines = r.out.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 2);
        QCOMPARE(lines[0], f + ":2:9: error: [M53] Ошибка перехода: кадра N5 нет в программе L1");
        QVERIFY(lines[1].startsWith(f + ":3:1: warning: Кадры в строках 3–4 никогда не выполняются"));
        QVERIFY(!lines[1].contains("[M")); // no manual number: no bracket
    }
    void plainLinesInEnglish() {
        QTemporaryDir dir;
        const QString f = writeBytes(dir, "bad.k528", "G2 X1\nM30\n");
        const auto r = runK528({"check", "--lang", "en", f});
        QCOMPARE(r.exitCode, 1);
        QCOMPARE(r.out, f + ":1:1: error: [M47] G?: G02 is not a G function of table 5\n");
    }
    void warningsOnlyExitZero() {
        QTemporaryDir dir;
        const QString f = writeBytes(dir, "w.k528", "G04\nM30\n");
        const auto r = runK528({"check", f});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains(": warning: G04 без X"));
    }
    void jsonHasExactlyTheKeysOfTheSpec() {
        QTemporaryDir dir;
        const QString a = writeBytes(dir, "a.k528", "%L3\nN1 L7 X5\nM30\n%L1\nG04\nM30\n");
        const QString b = writeBytes(dir, "b.k528", "G1 X5\nM30\n");
        const auto r = runK528({"check", "--json", a, b});
        QCOMPARE(r.exitCode, 1);
        QJsonParseError pe;
        const QJsonDocument doc = QJsonDocument::fromJson(r.out.toUtf8(), &pe);
        QCOMPARE(pe.error, QJsonParseError::NoError);
        const QJsonObject root = doc.object();
        QCOMPARE(root.keys(), QStringList{"files"});
        const QJsonArray files = root["files"].toArray();
        QCOMPARE(files.size(), 2);
        const QJsonObject fa = files[0].toObject();
        QCOMPARE(fa.keys(), (QStringList{"diagnostics", "file", "programs"}));
        QCOMPARE(fa["file"].toString(), a);
        QCOMPARE(fa["programs"].toArray(), (QJsonArray{1, 3}));
        const QJsonArray d = fa["diagnostics"].toArray();
        QCOMPARE(d.size(), 3); // 34 X/L and 45 L missing on line 2, G04 without X on line 5
        for (const auto& v : d)
            QCOMPARE(v.toObject().keys(), (QStringList{"column", "end_column", "line", "manual_number", "message_en",
                                                      "message_ru", "rule", "severity"}));
        const QJsonObject first = d[0].toObject();
        QCOMPARE(first["line"].toInt(), 2);
        QCOMPARE(first["column"].toInt(), 4);
        QCOMPARE(first["end_column"].toInt(), 6);
        QCOMPARE(first["severity"].toString(), QString("error"));
        QCOMPARE(first["manual_number"].toInt(), 45);
        QVERIFY(first["message_ru"].toString().startsWith("L отсутствует"));
        QVERIFY(first["message_en"].toString().startsWith("L missing"));
        const QJsonObject warn = d[2].toObject();
        QCOMPARE(warn["severity"].toString(), QString("warning"));
        QVERIFY(warn["manual_number"].isNull());
        const QJsonObject fb = files[1].toObject();
        QCOMPARE(fb["programs"].toArray(), QJsonArray{1});
        QCOMPARE(fb["diagnostics"].toArray().size(), 0);
    }
    void numberOptionNamesTheHeaderlessProgram() {
        QTemporaryDir dir;
        const QString f = writeBytes(dir, "p.k528", "G1 X5\nM30\n");
        const auto r = runK528({"check", "--json", "--number", "42", f});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject root = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(root["files"].toArray()[0].toObject()["programs"].toArray(), QJsonArray{42});
        // A call of itself is a cycle in program 42.
        const QString g = writeBytes(dir, "q.k528", "L42\nM30\n");
        QCOMPARE(runK528({"check", "--number", "42", g}).exitCode, 0);
        QVERIFY(runK528({"check", "--number", "42", g}).out.contains("[M48]"));
        QCOMPARE(runK528({"check", g}).exitCode, 1); // as program 1, L42 does not exist
    }
    void standardInput() {
        const auto r = runK528({"check", "--lang", "en", "-"}, "N1 GOTO 2\n");
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.out.startsWith("<stdin>:1:9: error: [M53]"));
    }
    void jsonIsValidUtf8WhateverTheInput() {
        // A stray byte in a frame, an unknown header of one Cyrillic letter,
        // bad bytes after a header and after a jump frame.
        const QByteArray input = "%L1\nG1 X5\xFF\n%\xD0\x96\nM30\n%L2 \xD0\x96\xFE\nN1 GOTO 1 \xC0\xAF\nM30\n";
        QProcess p;
        p.start(QStringLiteral(K528_CLI), {"check", "--json", "-"});
        QVERIFY(p.waitForStarted());
        p.write(input);
        p.closeWriteChannel();
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 1);
        const QByteArray out = p.readAllStandardOutput();
        QVERIFY2(QString::fromUtf8(out).toUtf8() == out, out.constData()); // valid UTF-8
        QVERIFY(!QString::fromUtf8(out).contains(QChar::ReplacementCharacter)); // escaped, not replaced
        QJsonParseError pe;
        const QJsonDocument doc = QJsonDocument::fromJson(out, &pe);
        QCOMPARE(pe.error, QJsonParseError::NoError);
        const QJsonArray d = doc.object()["files"].toArray()[0].toObject()["diagnostics"].toArray();
        QStringList lines;
        for (const auto& v : d) {
            const QJsonObject o = v.toObject();
            lines << QString("%1:%2 %3").arg(o["line"].toInt()).arg(o["column"].toInt()).arg(o["message_en"].toString());
        }
        const QString all = lines.join('\n');
        // The stray byte once, shown escaped.
        QVERIFY2(lines.filter(QRegularExpression("^2:")).size() == 1, qPrintable(all));
        QVERIFY2(all.contains("2:6 invalid byte sequence \\xFF"), qPrintable(all));
        QVERIFY2(all.contains("3:1 unknown header '%Ж'"), qPrintable(all));
        QVERIFY2(all.contains("5:5 unexpected text after the program header: 'Ж\\xFE'"), qPrintable(all));
        QVERIFY2(all.contains("6:11 unexpected text in an unconditional jump frame: '\\xC0\\xAF'"), qPrintable(all));
    }
    void usageAndIoErrors() {
        QTemporaryDir dir;
        const QString ok = writeBytes(dir, "ok.k528", "M30\n");
        QCOMPARE(runK528({"check"}).exitCode, 2);
        QCOMPARE(runK528({"check", "--frobnicate", ok}).exitCode, 2);
        QCOMPARE(runK528({"check", "--number", "0", ok}).exitCode, 2);
        QCOMPARE(runK528({"check", "--number", "100", ok}).exitCode, 2);
        QCOMPARE(runK528({"check", "--number", "x", ok}).exitCode, 2);
        QCOMPARE(runK528({"check", "--lang", "de", ok}).exitCode, 2);
        const auto missing = runK528({"check", dir.filePath("nope.k528")});
        QCOMPARE(missing.exitCode, 2);
        QVERIFY(missing.err.startsWith(QStringLiteral("k528: не удаётся открыть")));
        QVERIFY(missing.err.contains("nope.k528"));
        QCOMPARE(runK528({"check", dir.path()}).exitCode, 2);
        // The readable files are still checked.
        const QString bad = writeBytes(dir, "bad.k528", "G2\n");
        const auto mixed = runK528({"check", bad, dir.filePath("nope.k528")});
        QCOMPARE(mixed.exitCode, 2);
        QVERIFY(mixed.out.contains("[M47]"));
        const auto help = runK528({"check", "--help"});
        QCOMPARE(help.exitCode, 0);
        QVERIFY(help.out.contains("--profile"));
    }
    void profileChecksTheMachinesConstants() {
        QTemporaryDir dir;
        // A machine file made from the training lathe with known constants:
        // X -4..272 mm (diameter), Z 5..415 mm with a zero offset R229 of 120 mm,
        // F УСК.АВТ. 5000 / 6000 mm/min, discretes 0.001 mm.
        QFile src(QStringLiteral(K528_SOURCE_DIR) + "/resources/profiles/training-lathe.k528m");
        QVERIFY(src.open(QIODevice::ReadOnly));
        QString machine = QString::fromUtf8(src.readAll());
        const std::pair<const char*, const char*> values[] = {
            {"C007", "1"}, {"C010", "1"}, {"C042", "500000"}, {"C046", "-4000"}, {"C047", "272000"},
            {"C059", "0"}, {"C062", "1"}, {"C094", "600000"}, {"C098", "5000"}, {"C099", "415000"}};
        for (const auto& [c, v] : values) {
            const QRegularExpression line(QString("^%1=[^ \\n]*").arg(c), QRegularExpression::MultilineOption);
            QVERIFY2(machine.contains(line), c);
            machine.replace(line, QString("%1=%2").arg(c, v));
        }
        machine.replace(QRegularExpression("^R229=.*\\n", QRegularExpression::MultilineOption), "");
        QVERIFY(machine.contains("\n[r]\n"));
        machine.replace("\n[r]\n", "\n[r]\nR229=120000\n");
        const QString profile = writeBytes(dir, "lathe.k528m", machine.toUtf8());
        const QString f = writeBytes(dir, "p.k528", "G90 G1 X300 FX100 Z-110\nG1 Z-110 FZ7000\nG53 Z-110\nM30\n");
        const auto r = runK528({"check", "--lang", "en", "--profile", profile, f});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(":1:8: warning: [M12] software limit (X): X300 (diameter) is beyond the + limit 272"),
                 qPrintable(r.out));
        QVERIFY(r.out.contains(":2:10: warning: FZ7000 is above"));
        QVERIFY(r.out.contains(":3:5: warning: [M28] software limit (Z): Z-110 is beyond the - limit 5"));
        QCOMPARE(r.out.count('\n'), 3); // Z-110 is 10 mm with the zero offset: beyond only under G53
        QCOMPARE(runK528({"check", f}).out, QString()); // no profile, no machine warnings
        // A built-in profile by name.
        QCOMPARE(runK528({"check", "--profile", "grinder-205", f}).exitCode, 0);
        QVERIFY(runK528({"check", "--profile", "grinder-205", f}).out.contains("[M12]"));
        const auto bad = runK528({"check", "--profile", "no-such-machine", f});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY(bad.err.startsWith("k528: "));
    }
    void samplesAreCleanOnTheirMachines() {
        const QDir samples(QStringLiteral(K528_SOURCE_DIR) + "/resources/samples");
        int n = 0;
        for (const QString& name : samples.entryList({"*.k528"}, QDir::Files)) {
            const QString profile = name.startsWith("grinder") ? "grinder-205" : "training-lathe";
            const auto r = runK528({"check", "--profile", profile, samples.filePath(name)});
            QVERIFY2(r.exitCode == 0 && r.out.isEmpty(), qPrintable(name + ": " + r.out + r.err));
            ++n;
        }
        QVERIFY(n >= 3);
    }
};

QTEST_GUILESS_MAIN(TestCliCheck)
#include "test_cli_check.moc"
