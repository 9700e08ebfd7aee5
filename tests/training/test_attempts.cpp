// Graded attempts kept in the database (schema version 4), across
// processes: `k528 grade --db` (one process) records each file's attempt —
// the student, the exercise, the program text, the score and the grade —
// this test's own connection (another process) reads them back, and
// `k528 exercise attempts` (a third) lists them. On SQLite, and on a
// throwaway PostgreSQL cluster (training.attempts.postgresql).
#include "cli_runner.h"
#include "db/db_test_util.h"
#include "db/sha256.h"
#include "training/record.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using namespace k528;
using namespace k528::testing;

namespace {

db::AttemptFilter filter(std::string student, std::string exercise, int limit = 0) {
    db::AttemptFilter f;
    f.student = std::move(student);
    f.exercise = std::move(exercise);
    f.limit = limit;
    return f;
}

QJsonArray jsonArray(const CliResult& r) {
    const QJsonDocument d = QJsonDocument::fromJson(r.out.toUtf8());
    if (!d.isArray())
        qWarning("not a JSON array: %s\n%s", qPrintable(r.out.left(400)), qPrintable(r.err));
    return d.array();
}

bool write(const QString& path, const QString& text) {
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(text.toUtf8()) == text.toUtf8().size();
}

} // namespace

class TestAttempts : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString db_, reference_, deep_;

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        db_ = QString::fromStdString(testLocation(dir_, "class.db").text());
        const CliResult init = runK528({"db", "init", "--db", db_});
        QVERIFY2(init.exitCode == 0, qPrintable(init.err));
        const CliResult ref = runK528({"exercise", "show", "lathe-03-step", "--reference"});
        QCOMPARE(ref.exitCode, 0);
        reference_ = ref.out;
        deep_ = reference_;
        QVERIFY(deep_.contains("N14 #4 X30\n"));
        deep_.replace("N14 #4 X30\n", "N14 #4 X29\n"); // the finishing pass 0.5 mm too deep
    }

    // k528 grade --db records every file; another connection reads each
    // attempt as graded: its student, program, score and deductions.
    void aClassGradedByOneProcessIsReadByAnother() {
        const QString ivanov = dir_.filePath("ivanov.k528"), petrov = dir_.filePath("petrov.k528");
        QVERIFY(write(ivanov, reference_));
        QVERIFY(write(petrov, deep_));
        const CliResult g = runK528({"grade", "lathe-03-step", ivanov, petrov, "--json", "--db", db_});
        QCOMPARE(g.exitCode, 1); // petrov did not pass
        const QJsonArray graded = jsonArray(g);
        QCOMPARE(graded.size(), 2);

        db::Database d = db::Database::open(db::Location::parse(db_.toStdString()));
        QVERIFY(d.schemaVersion() >= 4);
        const auto rows = d.attempts(filter("", "lathe-03-step"));
        QCOMPARE(rows.size(), std::size_t(2));
        // Newest first: petrov's, then ivanov's.
        const db::AttemptEntry& p = rows[0];
        const db::AttemptEntry& i = rows[1];
        QVERIFY(p.id > i.id);
        QCOMPARE(i.student, std::string("ivanov"));
        QCOMPARE(p.student, std::string("petrov"));
        QCOMPARE(i.program, reference_.toStdString());
        QCOMPARE(p.program, deep_.toStdString());
        QCOMPARE(p.sha256, db::sha256Hex(deep_.toStdString()));
        QCOMPARE(i.score, 100);
        QVERIFY(i.passed);
        QCOMPARE(i.status, std::string("completed"));
        QVERIFY(i.cycleTimeMs > 0);
        QCOMPARE(p.score, graded[1].toObject().value("score").toInt());
        QVERIFY(p.score < 100);
        QCOMPARE(p.passed, graded[1].toObject().value("passed").toBool());
        QVERIFY(!p.at.empty());
        QVERIFY(!p.recordedBy.empty());
        // The findings as the grade gave them: the over-cut at frame N15, its line.
        const QJsonArray want = graded[1].toObject().value("deductions").toArray();
        const auto found = training::storedDeductions(p);
        QCOMPARE(found.size(), std::size_t(want.size()));
        QVERIFY(!found.empty());
        QCOMPARE(found[0].n, 15);
        QCOMPARE(found[0].line, want[0].toObject().value("line").toInt());
        QCOMPARE(found[0].points, want[0].toObject().value("points").toDouble());
        QCOMPARE(QString::fromStdString(training::render(found[0].text, training::Language::Ru)),
                 want[0].toObject().value("text_ru").toString());
        QVERIFY(training::storedDeductions(i).empty());
    }

    // k528 exercise attempts (a third process) lists them, filtered, as JSON and CSV.
    void theAttemptsAreListed() {
        const CliResult all = runK528({"exercise", "attempts", "--db", db_, "--json"});
        QVERIFY2(all.exitCode == 0, qPrintable(all.err));
        const QJsonArray a = jsonArray(all);
        QCOMPARE(a.size(), 2);
        QCOMPARE(a[0].toObject().value("student").toString(), QStringLiteral("petrov"));
        QCOMPARE(a[0].toObject().value("grade").toObject().value("score").toInt(),
                 a[0].toObject().value("score").toInt());
        const CliResult one = runK528({"exercise", "attempts", "--db", db_, "--student", "ivanov", "--json"});
        QCOMPARE(jsonArray(one).size(), 1);
        const CliResult none = runK528({"exercise", "attempts", "lathe-02-facing", "--db", db_, "--json"});
        QCOMPARE(jsonArray(none).size(), 0);
        const CliResult csv = runK528({"exercise", "attempts", "--db", db_, "--csv", "--lang", "en"});
        QCOMPARE(csv.exitCode, 0);
        const QStringList lines = csv.out.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 3);
        QCOMPARE(lines[0], QStringLiteral("id,at,student,exercise,file,score,passed,status,cycle_time_s,deductions"));
        QVERIFY2(lines[1].contains(",petrov,lathe-03-step,") && lines[1].contains(QStringLiteral("petrov.k528,%1,no,").arg(a[0].toObject().value("score").toInt())) &&
                     lines[1].contains("over-cut") &&
                     lines[1].contains("L1 N15"),
                 qPrintable(lines[1]));
        QVERIFY2(lines[2].contains(",ivanov,lathe-03-step,") && lines[2].contains("ivanov.k528,100,yes,completed,"),
                 qPrintable(lines[2]));
        const CliResult table = runK528({"exercise", "attempts", "--db", db_, "--lang", "en"});
        QVERIFY2(table.out.contains("Attempts: 2"), qPrintable(table.out));
    }

    // Grading the same program again records a second attempt with the
    // same grade (deterministic), under the name given.
    void theSameProgramAgainIsTheSameGrade() {
        const QString file = dir_.filePath("again.k528");
        QVERIFY(write(file, deep_));
        const CliResult g = runK528({"grade", "lathe-03-step", file, "--student", QStringLiteral("Петров П."),
                                     "--record", "--db", db_});
        QCOMPARE(g.exitCode, 1);
        db::Database d = db::Database::open(db::Location::parse(db_.toStdString()));
        const auto rows = d.attempts();
        QCOMPARE(rows.size(), std::size_t(3));
        QCOMPARE(rows[0].student, std::string("Петров П."));
        QCOMPARE(rows[0].sha256, rows[1].sha256);
        QCOMPARE(rows[0].score, rows[1].score);
        // The grade's JSON is the same but for the student and the file.
        const auto without = [](const std::string& grade) {
            QJsonObject o = QJsonDocument::fromJson(QByteArray::fromStdString(grade)).object();
            o.remove("student");
            o.remove("file");
            return o;
        };
        QCOMPARE(without(rows[0].grade), without(rows[1].grade));
        QCOMPARE(d.attempts(filter("Петров П.", "")).size(), std::size_t(1));
        QCOMPARE(d.attempts(filter("", "", 1)).size(), std::size_t(1));
    }

    // Bad input: a clear message and nothing lost or written.
    void badInputIsRefused() {
        db::Database d = db::Database::open(db::Location::parse(db_.toStdString()));
        const std::size_t before = d.attempts().size();
        db::AttemptEntry bad;
        bad.student = "x";
        bad.exercise = "lathe-03-step";
        bad.score = 101;
        try {
            d.recordAttempt(bad);
            QFAIL("a score of 101 was recorded");
        } catch (const db::Error& e) {
            QCOMPARE(e.kind(), db::ErrorKind::Invalid);
            QVERIFY2(QString::fromUtf8(e.what()).contains("0..100"), e.what());
        }
        bad.score = 50;
        bad.student.clear();
        QVERIFY_THROWS_EXCEPTION(db::Error, d.recordAttempt(bad));
        QCOMPARE(d.attempts().size(), before);
        // A database that is not there is not created by a grade: said, nothing graded into it.
        if (!onPostgres()) {
            const QString missing = dir_.filePath("no-such/class.db");
            const CliResult g = runK528({"grade", "lathe-03-step", dir_.filePath("ivanov.k528"), "--db", missing});
            QCOMPARE(g.exitCode, 2);
            QVERIFY2(!g.err.isEmpty(), qPrintable(g.out));
            QVERIFY(!QFile::exists(missing));
        }
    }

    // An attempt stored before the collision rules were the prove-out's
    // carries the old ids ("collision.rapid_into_material", "kind":
    // "tool_into_chuck"): read back, they are today's rule and text ids, its
    // deductions render as texts (not as ids) in both languages, and
    // `k528 exercise attempts` shows them so.
    void anOldAttemptReadsWithTodaysIds() {
        const QString location = QString::fromStdString(testLocation(dir_, "old.db").text());
        QCOMPARE(runK528({"db", "init", "--db", location}).exitCode, 0);
        db::AttemptEntry old;
        old.student = "sidorov";
        old.exercise = "lathe-03-step";
        old.file = "sidorov.k528";
        old.program = "%L1\nN1 G00 X10\n";
        old.score = 20;
        old.passed = false;
        old.status = "completed";
        old.cycleTimeMs = 12000;
        old.grade = R"({"file":"sidorov.k528","student":"sidorov","exercise":"lathe-03-step","score":20,)"
                    R"("passed":false,"status":"completed","deductions":[)"
                    R"({"category":"collision","points":30,"fails":true,"program":1,"frame":1,"line":2,)"
                    R"("text_ru":"x","text_en":"x","id":"collision.rapid_into_material",)"
                    R"("args":["10","-1","2.5",{"ru":"L1 N1","en":"L1 N1"},"2"]},)"
                    R"({"category":"collision","points":50,"fails":true,"program":1,"frame":2,"line":3,)"
                    R"("text_ru":"x","text_en":"x","id":"collision.tool_into_chuck",)"
                    R"("args":["40","-118","0",{"ru":"L1 N2","en":"L1 N2"},"3"]},)"
                    R"({"category":"collision","points":20,"fails":true,"program":0,"frame":0,"line":0,)"
                    R"("text_ru":"x","text_en":"x","id":"collision.tool_into_chuck.manual","args":["40","-118","0"]},)"
                    R"({"category":"collision","points":30,"fails":true,"program":1,"frame":3,"line":4,)"
                    R"("text_ru":"x","text_en":"x","id":"collision.cut_without_spindle",)"
                    R"("args":["40","-5","0",{"ru":"L1 N3","en":"L1 N3"},"4"]}],)"
                    R"("collisions":[{"program":1,"frame":1,"line":2,"kind":"rapid_into_material",)"
                    R"("at":{"z":-1,"d":10},"depth_mm":2.5},)"
                    R"({"program":1,"frame":2,"line":3,"kind":"tool_into_chuck","at":{"z":-118,"d":40},"depth_mm":0},)"
                    R"({"program":1,"frame":3,"line":4,"kind":"rapid_into_ring","at":{"z":5,"d":40},"depth_mm":0.1}]})";
        {
            db::Database d = db::Database::open(db::Location::parse(location.toStdString()));
            d.recordAttempt(old);
        }
        db::Database d = db::Database::open(db::Location::parse(location.toStdString()));
        const auto rows = d.attempts();
        QCOMPARE(rows.size(), std::size_t(1));
        const auto ded = training::storedDeductions(rows[0]);
        QCOMPARE(ded.size(), std::size_t(4));
        QCOMPARE(ded[0].text.id, std::string("collision.rapid-into-material"));
        QCOMPARE(ded[1].text.id, std::string("collision.tool-into-chuck"));
        QCOMPARE(ded[2].text.id, std::string("collision.tool-into-chuck.manual"));
        QCOMPARE(ded[3].text.id, std::string("collision.feed-spindle-stopped"));
        for (const training::Deduction& x : ded)
            for (const training::Language l : {training::Language::Ru, training::Language::En}) {
                const std::string text = training::render(x.text, l);
                QVERIFY2(text.find("collision") == std::string::npos, text.c_str());
            }
        QCOMPARE(training::render(ded[0].text, training::Language::En),
                 std::string("a rapid (G00) into the metal at X10 Z-1, 2.5 mm into the blank — frame L1 N1, line 2: "
                             "the tool is broken"));
        QCOMPARE(training::render(ded[1].text, training::Language::Ru),
                 std::string("Инструмент в патрон или кулачки на X40 Z-118 — кадр L1 N2, строка 3"));

        const CliResult listed = runK528({"exercise", "attempts", "--db", location, "--json"});
        QVERIFY2(listed.exitCode == 0, qPrintable(listed.err));
        const QJsonArray a = jsonArray(listed);
        QCOMPARE(a.size(), 1);
        const QJsonObject grade = a[0].toObject().value("grade").toObject();
        const QJsonArray col = grade.value("collisions").toArray();
        QCOMPARE(col.size(), 3);
        QCOMPARE(col[0].toObject().value("rule").toString(), QStringLiteral("rapid-into-material"));
        QCOMPARE(col[1].toObject().value("rule").toString(), QStringLiteral("tool-into-chuck"));
        QCOMPARE(col[2].toObject().value("rule").toString(), QStringLiteral("rapid-into-material"));
        QCOMPARE(col[2].toObject().value("text").toString(), QStringLiteral("rapid-into-material.ring"));
        QVERIFY(!col[0].toObject().contains("kind"));
        QCOMPARE(col[0].toObject().value("depth_mm").toDouble(), 2.5);
        QCOMPARE(grade.value("deductions").toArray()[3].toObject().value("id").toString(),
                 QStringLiteral("collision.feed-spindle-stopped"));
        const CliResult csv = runK528({"exercise", "attempts", "--db", location, "--csv", "--lang", "en"});
        QCOMPARE(csv.exitCode, 0);
        QVERIFY2(csv.out.contains("the tool into the chuck or its jaws at X40 Z-118") && !csv.out.contains("collision."),
                 qPrintable(csv.out));
    }
};

QTEST_GUILESS_MAIN(TestAttempts)
#include "test_attempts.moc"
