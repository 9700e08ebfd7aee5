#include <QtTest>

#include <QTemporaryDir>

#include <unistd.h>

#include "cli_runner.h"
#include "test_util.h"

namespace {

using testutil::writeBytes;

QByteArray read(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

const char* kMessy = "; shaft\n\n\n%l1 (main)\nn1 g01 x5.3420 f=50.00 z-1234.678 f=1000.00 ; c\n"
                     "n2 r75 = 2 * r99\nn3 if r1 > 0 goto 1\nm30\n%messages\n#2=Б\n#1=А\n";
const char* kCanonical = "; shaft\n\n%L1 (main)\nN1 G1 X5.342 FX50 Z-1234.678 FZ1000 ; c\n"
                         "N2 R75=2*R99\nN3 IF R1>0 GOTO 1\nM30\n\n%MESSAGES\n#1=А\n#2=Б\n";

} // namespace

class TestCliFormat : public QObject {
    Q_OBJECT
private slots:
    void printsTheCanonicalText() {
        QTemporaryDir dir;
        const QString f = writeBytes(dir, "m.k528", kMessy);
        const auto r = runK528({"format", f});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out, QString::fromUtf8(kCanonical));
        QCOMPARE(r.err, QString());
        // format of format's output is identical to it.
        const QString g = writeBytes(dir, "c.k528", r.out.toUtf8());
        QCOMPARE(runK528({"format", g}).out, r.out);
        QCOMPARE(runK528({"format", "-"}, r.out.toUtf8()).out, r.out);
    }
    void semanticErrorsDoNotStopFormatting() {
        QTemporaryDir dir;
        const QString f = writeBytes(dir, "e.k528", "goto 99\ng2 x1\n");
        const auto r = runK528({"format", f});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out, QString("GOTO 99\nG2 X1\n"));
    }
    void renumberRewritesEveryJump() {
        QTemporaryDir dir;
        const QString f = writeBytes(dir, "r.k528", "%L1\nN5 G1 X1\nIF R1>0 GOTO 7\nN7 GOTO 5\nM30\n");
        auto r = runK528({"format", "--renumber", f});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out, QString("%L1\nN1 G1 X1\nN2 IF R1>0 GOTO 3\nN3 GOTO 1\nN4 M30\n"));
        r = runK528({"format", "--renumber", "--start", "10", "--step", "5", f});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out, QString("%L1\nN10 G1 X1\nN15 IF R1>0 GOTO 20\nN20 GOTO 10\nN25 M30\n"));
        r = runK528({"format", "--renumber", "--start", "998", "--step", "5", "--lang", "en", f});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains("999"));
        QCOMPARE(runK528({"format", "--step", "5", f}).exitCode, 2);
        QCOMPARE(runK528({"format", "--renumber", "--step", "0", f}).exitCode, 2);
        QCOMPARE(runK528({"format", "--renumber", "--in-place", f}).exitCode, 0);
        QCOMPARE(read(f), QByteArray("%L1\nN1 G1 X1\nN2 IF R1>0 GOTO 3\nN3 GOTO 1\nN4 M30\n"));
    }
    void syntaxErrorsStopFormatting() {
        QTemporaryDir dir;
        const QString f = writeBytes(dir, "s.k528", "G1 X5..3\nG1 Q5\n");
        const auto r = runK528({"format", "--lang", "en", f});
        QCOMPARE(r.exitCode, 1);
        QCOMPARE(r.out, QString());
        QVERIFY(r.err.contains(f + ":1:4: error: [M33] X value: '5..3' is not a number"));
        QVERIFY(r.err.contains(f + ":2:4: error: unknown address 'Q'"));
        QVERIFY(r.err.contains("not formatted"));
        QCOMPARE(read(f), QByteArray("G1 X5..3\nG1 Q5\n"));
        QVERIFY(runK528({"format", f}).err.contains("не отформатирован"));
    }
    void checkOption() {
        QTemporaryDir dir;
        const QString messy = writeBytes(dir, "m.k528", kMessy);
        const QString canon = writeBytes(dir, "c.k528", kCanonical);
        QCOMPARE(runK528({"format", "--check", canon}).exitCode, 0);
        const auto r = runK528({"format", "--check", messy});
        QCOMPARE(r.exitCode, 1);
        QCOMPARE(r.out, QString());
        QVERIFY(r.err.contains("не в каноническом виде"));
        QCOMPARE(read(messy), QByteArray(kMessy));
    }
    void inPlace() {
        QTemporaryDir dir;
        const QString f = writeBytes(dir, "m.k528", kMessy);
        const auto r = runK528({"format", "--in-place", f});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out, QString());
        QCOMPARE(read(f), QByteArray(kCanonical));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{"m.k528"}); // no temporary left
        QCOMPARE(runK528({"format", "--in-place", f}).exitCode, 0);
        QCOMPARE(read(f), QByteArray(kCanonical));
    }
    // --in-place keeps the file's permissions and replaces the file a
    // symbolic link points to, not the link.
    void inPlaceKeepsPermissionsAndLinks() {
        QTemporaryDir dir;
        const QString f = writeBytes(dir, "m.k528", kMessy);
        QVERIFY(QFile::setPermissions(f, QFile::ReadOwner | QFile::WriteOwner | QFile::ReadGroup));
        const QString link = dir.filePath("link.k528");
        QVERIFY(QFile::link(f, link));
        const auto r = runK528({"format", "--in-place", link});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(QFileInfo(link).isSymLink());
        QCOMPARE(read(f), QByteArray(kCanonical));
        QCOMPARE(QFile::permissions(f),
                 QFile::ReadOwner | QFile::WriteOwner | QFile::ReadGroup | QFile::ReadUser |
                     QFile::WriteUser);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::System).size(), 2); // no temporary left
    }
    // `run` starts the first program of a file; formatting keeps
    // the programs in the order written, so the formatted file runs the same.
    void formattingKeepsWhatRunStarts() {
        QTemporaryDir dir;
        const QString f = writeBytes(dir, "two.k528", "%L2\nG1 X5 F100\nM30\n%L1\nG1 X7 F100\nM30\n");
        const auto before = runK528({"run", f});
        QVERIFY2(before.exitCode == 0, qPrintable(before.err));
        const auto formatted = runK528({"format", f});
        QCOMPARE(formatted.exitCode, 0);
        QVERIFY(formatted.out.indexOf("%L2") < formatted.out.indexOf("%L1"));
        const QString g = writeBytes(dir, "formatted.k528", formatted.out.toUtf8());
        const auto after = runK528({"run", g});
        QCOMPARE(after.exitCode, 0);
        QCOMPARE(after.out, before.out);
        QVERIFY2(before.out.contains("stopped at L2"), qPrintable(before.out));
    }
    // --in-place in a read-only folder names the file and the
    // reason, not a temporary file.
    void inPlaceInAReadOnlyFolderSaysWhy() {
        // Root writes into a read-only folder: then k528 runs as nobody.
        const bool root = ::geteuid() == 0;
        if (root && !QFileInfo::exists("/usr/bin/setpriv"))
            QSKIP("running as root without setpriv");
        QTemporaryDir dir;
        QVERIFY(QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner |
                                                      QFile::ReadOther | QFile::ExeOther));
        const QString sub = dir.filePath("ro");
        QVERIFY(QDir().mkdir(sub));
        const QString f = sub + "/m.k528";
        QFile out(f);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(kMessy);
        out.close();
        QVERIFY(QFile::setPermissions(f, QFile::ReadOwner | QFile::WriteOwner | QFile::ReadOther));
        QVERIFY(QFile::setPermissions(sub, QFile::ReadOwner | QFile::ExeOwner | QFile::ReadOther |
                                               QFile::ExeOther));
        const QStringList prefix =
            root ? QStringList{"/usr/bin/setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"}
                 : QStringList{};
        const auto r = runK528ToFile({"format", "--in-place", f}, "/dev/null", QStringLiteral(K528_CLI), prefix);
        QFile::setPermissions(sub, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("не удаётся записать ") + f + QStringLiteral(": в его папке ") + sub +
                                QStringLiteral(" нельзя создать файл: доступ запрещён")),
                 qPrintable(r.err));
        QVERIFY(!r.err.contains(".tmp") && !r.err.contains("k528-"));
        QCOMPARE(read(f), QByteArray(kMessy));
    }
    void headerlessFilesStayHeaderless() {
        QTemporaryDir dir;
        const QString f = writeBytes(dir, "h.k528", "g1 x5\nm30\n");
        QCOMPARE(runK528({"format", "--number", "12", f}).out, QString("G1 X5\nM30\n"));
    }
    void usageAndIoErrors() {
        QTemporaryDir dir;
        const QString f = writeBytes(dir, "m.k528", "M30\n");
        QCOMPARE(runK528({"format"}).exitCode, 2);
        QCOMPARE(runK528({"format", f, f}).exitCode, 2);
        QCOMPARE(runK528({"format", "--check", "--in-place", f}).exitCode, 2);
        QCOMPARE(runK528({"format", "--in-place", "-"}, "M30\n").exitCode, 2);
        QCOMPARE(runK528({"format", "--number", "0", f}).exitCode, 2);
        const auto missing = runK528({"format", dir.filePath("nope.k528")});
        QCOMPARE(missing.exitCode, 2);
        QVERIFY(missing.err.startsWith(QStringLiteral("k528: не удаётся открыть")));
    }
};

QTEST_GUILESS_MAIN(TestCliFormat)
#include "test_cli_format.moc"
