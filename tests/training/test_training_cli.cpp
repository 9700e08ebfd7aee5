// `k528 exercise list|show` and `k528 grade` (shared/spec/cli.md): the
// course listed, the reference handed out and graded, a class of 30 files
// graded by one command (each file its own grade, the wrong ones losing
// points at their frames), and bad input refused with a clear message.
#include "cli_runner.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

namespace {

QJsonArray jsonArray(const CliResult& r) {
    QJsonParseError e{};
    const QJsonDocument d = QJsonDocument::fromJson(r.out.toUtf8(), &e);
    if (e.error != QJsonParseError::NoError || !d.isArray())
        qWarning("not a JSON array: %s\n%s", qPrintable(r.out.left(400)), qPrintable(r.err));
    return d.array();
}

bool write(const QString& path, const QString& text) {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return false;
    return f.write(text.toUtf8()) == text.toUtf8().size();
}

} // namespace

class TestTrainingCli : public QObject {
    Q_OBJECT

private slots:
    void theCourseIsListed() {
        const CliResult r = runK528({"exercise", "list", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray a = jsonArray(r);
        QVERIFY(a.size() >= 12);
        QSet<QString> ids;
        for (const QJsonValue& v : a) {
            const QJsonObject o = v.toObject();
            QVERIFY(!o.value("id").toString().isEmpty());
            QVERIFY(!o.value("title").toString().isEmpty());
            QVERIFY(o.value("machine").toString() == "training-lathe" ||
                    o.value("machine").toString() == "grinder-205");
            ids.insert(o.value("id").toString());
        }
        QVERIFY(ids.contains("lathe-03-step"));
        QVERIFY(ids.contains("grinder-04-dressing"));
        const CliResult en = runK528({"exercise", "list", "--lang", "en"});
        QCOMPARE(en.exitCode, 0);
        QVERIFY2(en.out.contains("A turned step"), qPrintable(en.out));
        const CliResult ru = runK528({"exercise", "list"});
        QVERIFY2(ru.out.contains(QStringLiteral("Обточка ступени")), qPrintable(ru.out));
    }

    void anExerciseIsShownAndItsReferenceScores100() {
        const CliResult task = runK528({"exercise", "show", "lathe-03-step", "--lang", "en"});
        QCOMPARE(task.exitCode, 0);
        QVERIFY2(task.out.contains("Cycle time at most 120 s"), qPrintable(task.out));
        // The unit is the window's too: a Russian page said «не более 120 s».
        const CliResult taskRu = runK528({"exercise", "show", "lathe-03-step", "--lang", "ru"});
        QCOMPARE(taskRu.exitCode, 0);
        QVERIFY2(taskRu.out.contains(QStringLiteral("Время цикла не более 120 с\n")), qPrintable(taskRu.out));
        QVERIFY(task.out.contains("Z-40"));
        const CliResult ref = runK528({"exercise", "show", "lathe-03-step", "--reference"});
        QCOMPARE(ref.exitCode, 0);
        QVERIFY(ref.out.contains("%L1"));
        // The reference as a student hands it in, on stdin.
        const CliResult g = runK528({"grade", "lathe-03-step", "-", "--json"}, ref.out.toUtf8());
        QCOMPARE(g.exitCode, 0);
        const QJsonArray a = jsonArray(g);
        QCOMPARE(a.size(), 1);
        QCOMPARE(a[0].toObject().value("score").toInt(), 100);
        QCOMPARE(a[0].toObject().value("passed").toBool(), true);
        QCOMPARE(a[0].toObject().value("deductions").toArray().size(), 0);
    }

    // 30 students' files: every third cuts the finishing pass 0.5 mm too deep.
    void aClassOf30IsGradedByOneCommand() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const CliResult ref = runK528({"exercise", "show", "lathe-03-step", "--reference"});
        QCOMPARE(ref.exitCode, 0);
        QVERIFY(ref.out.contains("N14 #4 X30\n"));
        QStringList args{"grade", "lathe-03-step", "--json", "--jobs", "2"};
        for (int i = 1; i <= 30; ++i) {
            const QString file = dir.filePath(QStringLiteral("student%1.k528").arg(i, 2, 10, QChar('0')));
            QString text = ref.out;
            if (i % 3 == 0)
                text.replace("N14 #4 X30\n", "N14 #4 X29\n");
            QVERIFY(write(file, text));
            args << file;
        }
        const CliResult r = runK528(args);
        QCOMPARE(r.exitCode, 1); // not everyone passed
        const QJsonArray a = jsonArray(r);
        QCOMPARE(a.size(), 30);
        for (int i = 1; i <= 30; ++i) {
            const QJsonObject o = a[i - 1].toObject();
            QVERIFY(o.value("file").toString().endsWith(QStringLiteral("student%1.k528").arg(i, 2, 10, QChar('0'))));
            QCOMPARE(o.value("student").toString(), QStringLiteral("student%1").arg(i, 2, 10, QChar('0')));
            const QJsonArray ded = o.value("deductions").toArray();
            if (i % 3 != 0) {
                QCOMPARE(o.value("score").toInt(), 100);
                QVERIFY(ded.isEmpty());
                continue;
            }
            QVERIFY2(o.value("score").toInt() < 100, qPrintable(QString::number(i)));
            QVERIFY(!ded.isEmpty());
            const QJsonObject d = ded[0].toObject();
            QCOMPARE(d.value("frame").toInt(), 15);
            QVERIFY(d.value("line").toInt() > 0);
            QVERIFY(d.value("points").toDouble() > 0);
            QVERIFY(d.value("text_ru").toString().contains("L1 N15"));
            QVERIFY(d.value("text_en").toString().contains("over-cut"));
        }
        // The table and the trainer's CSV are other renderings of the same
        // grades: shown on the first six of the class (four passed, two not),
        // so the sanitizer build does not simulate the class three times.
        args.removeAll("--json");
        args = args.mid(0, 4 + 6); // grade, the exercise, --jobs 2, six files
        const CliResult t = runK528(args + QStringList{"--lang", "en"});
        QCOMPARE(t.exitCode, 1);
        QVERIFY2(t.out.contains("Passed: 4/6"), qPrintable(t.out));
        QVERIFY(t.out.contains("student06"));
        QVERIFY(!t.out.contains("student07"));
        // The trainer's record: one CSV line a student.
        QStringList csvArgs = args;
        csvArgs << "--csv" << "--lang" << "en";
        const CliResult c = runK528(csvArgs);
        QCOMPARE(c.exitCode, 1);
        const QStringList lines = c.out.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 7);
        QCOMPARE(lines[0], QStringLiteral("student,file,exercise,score,passed,status,cycle_time_s,deductions"));
        QVERIFY2(lines[1].startsWith("student01,") &&
                     lines[1].contains("student01.k528,lathe-03-step,100,yes,completed,"),
                 qPrintable(lines[1]));
        QVERIFY2(lines[3].startsWith("student03,") && lines[3].contains("student03.k528,lathe-03-step,"),
                 qPrintable(lines[3]));
        QVERIFY(lines[3].contains("over-cut"));
        QVERIFY(lines[3].contains("L1 N15"));
        QCOMPARE(runK528(args + QStringList{"--csv", "--json"}).exitCode, 2);
    }

    void oneFileGivesAReportWithTheStudentsName() {
        QTemporaryDir dir;
        const CliResult ref = runK528({"exercise", "show", "lathe-03-step", "--reference"});
        const QString file = dir.filePath("ivanov.k528");
        QVERIFY(write(file, QString(ref.out).replace("N14 #4 X30\n", "N14 #4 X29\n")));
        const CliResult r = runK528({"grade", "lathe-03-step", file, "--student", QStringLiteral("Иванов")});
        QVERIFY2(r.out.contains(QStringLiteral("(Иванов)")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("Перерез")), qPrintable(r.out));
        QVERIFY(r.out.contains("L1 N15"));
    }

    void badInputIsRefusedClearly() {
        CliResult r = runK528({"grade", "no-such", "x.k528", "--lang", "en"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("no exercise 'no-such'"), qPrintable(r.err));
        // Russian by default: no English sentence.
        for (const QStringList& args : {QStringList{"grade", "no-such", "x.k528"}, QStringList{"exercise", "show", "no-such"},
                                        QStringList{"exercise", "attempts", "no-such"}}) {
            r = runK528(args);
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.contains(QStringLiteral("нет упражнения «no-such» (k528 exercise list)")) &&
                         r.err.contains(QStringLiteral("Справка: k528 --help.")) && !r.err.contains("Try"),
                     qPrintable(r.err));
        }
        r = runK528({"grade", "lathe-03-step", "/nonexistent/x.k528"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("/nonexistent/x.k528"), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
        r = runK528({"grade", "lathe-03-step"});
        QCOMPARE(r.exitCode, 2);
        r = runK528({"exercise", "show", "lathe-99"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains("lathe-99"));
        r = runK528({"grade", "lathe-03-step", "a.k528", "b.k528", "--student", "X"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains("--student"));
    }
};

QTEST_GUILESS_MAIN(TestTrainingCli)
#include "test_training_cli.moc"
