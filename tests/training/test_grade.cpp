// core/training: the shipped course, and the grade of real attempts run on
// the simulated machine — each exercise's reference scores 100; a step cut
// 0.5 mm too deep, a rapid through the blank, a finishing pass left out, an
// injected limit switch not recovered from each lose points and name the
// frame; the same file graded twice gives the same JSON; broken exercise
// files are refused with the key named.
#include "training/exercise.h"
#include "training/exercise_texts.h"
#include "training/grade.h"
#include "training/procedure.h"
#include "util/json.h"

#include <QtTest>

#include <string>

using namespace k528;

namespace {

const training::Exercise& exercise(const char* id) {
    const training::Exercise* e = training::findExercise(id);
    if (!e)
        qFatal("no shipped exercise %s", id);
    return *e;
}

// `text` with the first occurrence of `from` replaced by `to` (the test
// fails loudly when the reference no longer has `from`).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    if (at == std::string::npos)
        qFatal("'%s' is not in the program", from.c_str());
    text.replace(at, from.size(), to);
    return text;
}

// The line (1-based) of the file on which `what` first stands.
int lineOf(const std::string& text, const std::string& what) {
    const auto at = text.find(what);
    if (at == std::string::npos)
        qFatal("'%s' is not in the program", what.c_str());
    int line = 1;
    for (std::size_t i = 0; i < at; ++i)
        line += text[i] == '\n';
    return line;
}

QString describe(const training::Grade& g) {
    QString s = QStringLiteral("%1: score %2, %3\n").arg(QString::fromStdString(g.file)).arg(g.score).arg(QString::fromStdString(g.status));
    for (const training::Deduction& d : g.deductions)
        s += QStringLiteral("  -%1 [%2] %3\n")
                 .arg(d.points)
                 .arg(QString::fromStdString(d.category),
                      QString::fromStdString(training::render(d.text, training::Language::En)));
    return s;
}

const training::Deduction* find(const training::Grade& g, const std::string& category) {
    for (const training::Deduction& d : g.deductions)
        if (d.category == category)
            return &d;
    return nullptr;
}

} // namespace

class TestTrainingGrade : public QObject {
    Q_OBJECT

private slots:
    void theStarterCourseHasEightLatheAndFourGrinderExercises() {
        const auto& all = training::shippedExercises();
        int lathe = 0, grinder = 0;
        for (const training::Exercise& e : all) {
            QVERIFY2(!e.title.ru.empty() && !e.title.en.empty(), e.id.c_str());
            QVERIFY2(!e.task.ru.empty() && !e.task.en.empty(), e.id.c_str());
            QVERIFY2(!e.reference.empty(), e.id.c_str());
            lathe += e.machine == "training-lathe";
            grinder += e.machine == "grinder-205";
        }
        QVERIFY(lathe >= 8);
        QVERIFY(grinder >= 4);
        QCOMPARE(training::starterCourse().exercises.size(), all.size());
        QVERIFY(training::findExercise("no-such-exercise") == nullptr);
    }

    void eachReferenceScores100_data() {
        QTest::addColumn<QString>("id");
        for (const training::Exercise& e : training::shippedExercises())
            QTest::newRow(e.id.c_str()) << QString::fromStdString(e.id);
    }
    void eachReferenceScores100() {
        QFETCH(QString, id);
        const training::Exercise& e = exercise(id.toStdString().c_str());
        const training::Grader grader(e);
        const training::Grade g = grader.grade(e.reference, "reference.k528");
        QVERIFY2(g.score == 100 && g.passed && g.deductions.empty(), qPrintable(describe(g)));
        if (e.drawing.kind != training::Drawing::Kind::None) {
            QCOMPARE(g.status, std::string("completed"));
            QVERIFY(!g.finished.empty());
        }
        for (const training::StepResult& s : g.steps)
            QVERIFY2(s.done, training::stepName(s.step.kind).data());
    }

    // 0.5 mm too deep (per side) on the finishing pass of the step: an
    // over-cut of the Ø30 -0.1 cylinder, 450 µm beyond its least material,
    // put on the frame that cut it and no other.
    void aStepCutTooDeepLosesPointsAndNamesItsFrame() {
        const training::Exercise& e = exercise("lathe-03-step");
        const std::string text = replaced(e.reference, "N14 #4 X30", "N14 #4 X29");
        const training::Grade g = training::Grader(e).grade(text, "deep.k528", "Петров");
        QVERIFY2(g.score < 100, qPrintable(describe(g)));
        QCOMPARE(g.status, std::string("completed"));
        QCOMPARE(g.overcut.size(), std::size_t(1));
        const training::Deviation& d = g.overcut.front();
        QCOMPARE(d.n, 15);
        QCOMPARE(d.line, lineOf(text, "N15 "));
        QVERIFY2(std::abs(d.depthUm - 450) < 5, qPrintable(QString::number(d.depthUm)));
        // The over-cut runs the step's length: 40 mm x 0.45 mm.
        QVERIFY2(std::abs(d.areaMm2 - 40 * 0.45) < 0.5, qPrintable(QString::number(d.areaMm2)));
        const training::Deduction* o = find(g, "overcut");
        QVERIFY(o);
        QCOMPARE(o->n, 15);
        QVERIFY(o->points >= e.scoring.overcutBase);
        const std::string ru = training::render(o->text, training::Language::Ru);
        const std::string en = training::render(o->text, training::Language::En);
        QVERIFY2(ru.find("L1 N15") != std::string::npos, ru.c_str());
        QVERIFY2(en.find("L1 N15") != std::string::npos && en.find(" µm beyond") != std::string::npos,
                 en.c_str());
        QVERIFY2(en.find("line " + std::to_string(d.line)) != std::string::npos, en.c_str());
        for (const training::Deduction& x : g.deductions)
            QVERIFY2(x.category == "overcut", qPrintable(describe(g)));
        // The student's name and the file are kept on the grade.
        QCOMPARE(g.student, std::string("Петров"));
        QCOMPARE(g.file, std::string("deep.k528"));
    }

    // The finishing pass left out: Ø30.5 stays where the drawing allows at
    // most Ø30 (+0): an under-cut of 250 µm put on the nearest pass.
    void aMissingFinishingPassIsAnUndercutAtTheNearestPass() {
        const training::Exercise& e = exercise("lathe-03-step");
        std::string text = replaced(e.reference, "N14 #4 X30\n", "");
        text = replaced(text, "N15 G1 Z-40 FZ100\n", "");
        text = replaced(text, "N16 X42 FX100\n", "");
        const training::Grade g = training::Grader(e).grade(text, "rough.k528");
        QVERIFY2(g.score < 100, qPrintable(describe(g)));
        QVERIFY(g.overcut.empty());
        QVERIFY(!g.undercut.empty());
        bool cylinder = false;
        for (const training::Deviation& d : g.undercut)
            if (std::abs(d.depthUm - 250) < 5 && d.located && d.n == 11)
                cylinder = true;
        QVERIFY2(cylinder, qPrintable(describe(g)));
        QVERIFY(find(g, "undercut"));
    }

    // A rapid (G00) straight from above the blank into it: the tool is
    // broken, the attempt fails, the frame and the line are named.
    void aRapidThroughTheBlankIsFoundAndNamed() {
        const training::Exercise& e = exercise("lathe-03-step");
        const std::string text = replaced(e.reference, "N2 #3 X36", "N2 G0 X36 Z-20");
        const training::Grade g = training::Grader(e).grade(text, "crash.k528");
        QVERIFY2(!g.passed, qPrintable(describe(g)));
        QVERIFY(!g.collisions.empty());
        const training::Collision& c = g.collisions.front();
        // The prove-out's rule (core/proveout/rules.h), the id `k528 check --profile` reports.
        QCOMPARE(c.rule, proveout::Rule::RapidIntoMaterial);
        QCOMPARE(proveout::ruleId(c.rule), std::string_view("rapid-into-material"));
        QCOMPARE(c.n, 2);
        QCOMPARE(c.line, lineOf(text, "N2 G0"));
        // It entered the blank (Ø40, face at Z0) from above: at its surface
        // (the slides' actual path, not the programmed line).
        QVERIFY2(std::abs(c.at.r - 20) < 0.1, qPrintable(QString::number(c.at.r)));
        QVERIFY(c.at.z < 0 && c.at.z > -20);
        const training::Deduction* d = find(g, "collision");
        QVERIFY(d && d->fails && d->n == 2);
        const std::string en = training::render(d->text, training::Language::En);
        QVERIFY2(en.find("rapid (G00)") != std::string::npos && en.find("L1 N2") != std::string::npos,
                 en.c_str());
    }

    // The grooving tool sits in the turret unlike the turning tool (its
    // offsets R102/R103): the reference copies them into the correction
    // R226/R227 after M62 and passes; without the copy the slide goes where
    // it went for tool 1, the groove lands off by the offsets and the
    // attempt fails on the grooving frame — as the part would on the machine.
    void aToolChangeWithoutItsOffsetsMisplacesTheCut() {
        const training::Exercise& e = exercise("lathe-05-groove");
        QVERIFY(e.reference.find("R226=R102") != std::string::npos);
        const std::string forgot = replaced(e.reference, "N11 R226=R102\nN12 R227=R103\n", "");
        QVERIFY(forgot != e.reference);
        const training::Grade g = training::Grader(e).grade(forgot, "forgot.k528");
        QVERIFY2(!g.passed && g.score < 100, qPrintable(describe(g)));
        // Cut 3.5 mm off towards +Z and 0.6 mm deeper: on the plunge (N15) or
        // its dwell (N16: the slide still closes its lag there).
        const training::Deduction* over = find(g, "overcut");
        QVERIFY2(over && (over->line == lineOf(forgot, "N15 G1 X30") || over->line == lineOf(forgot, "N16 G4")),
                 qPrintable(describe(g)));
        QVERIFY2(find(g, "undercut"), qPrintable(describe(g)));
    }

    // The program handed out in lathe-08 finishes at rapid (N15 G0 Z-40):
    // graded as handed out it fails on that frame; the reference passes.
    void theHandedOutProgramWithAnErrorFailsAtItsFrame() {
        const training::Exercise& e = exercise("lathe-08-find-error");
        QVERIFY(!e.given.empty());
        const training::Grade g = training::Grader(e).grade(e.given, "given.k528");
        QVERIFY2(!g.passed, qPrintable(describe(g)));
        const training::Deduction* d = find(g, "collision");
        QVERIFY2(d, qPrintable(describe(g)));
        QCOMPARE(d->n, 15);
        QCOMPARE(d->line, lineOf(e.given, "N15 G0"));
    }

    // The limit switch of X+ is hit during the retract (frame N10): the
    // reference recovers (off the switch, ESC, «Пуск») and passes; the same
    // program without the recovery leaves the message standing and fails.
    void anInjectedFaultPassesOnlyWhenTheProcedureRecovers() {
        const training::Exercise& e = exercise("lathe-07-limit-switch");
        const training::Grader grader(e);
        const training::Grade ok = grader.grade(e.reference, "recovered.k528");
        QVERIFY2(ok.passed && ok.score == 100, qPrintable(describe(ok)));
        QCOMPARE(ok.faults.size(), std::size_t(1));
        QVERIFY(ok.faults.front().injectedMs >= 0);
        QVERIFY(ok.faults.front().clearedMs > ok.faults.front().injectedMs);
        QCOMPARE(ok.faults.front().n, 10);
        QVERIFY(!ok.messages.empty());

        const std::string stuck =
            replaced(e.reference, "; OPERATOR: F2 HOLD:X-:1 ESC PROGRAM:1 PUSH:START RUN\n", "");
        const training::Grade bad = grader.grade(stuck, "stuck.k528");
        QVERIFY2(!bad.passed, qPrintable(describe(bad)));
        QVERIFY(bad.score < 100);
        QVERIFY(bad.status != "completed");
        QVERIFY(find(bad, "not_completed") || find(bad, "step"));
        bool ackMissing = false;
        for (const training::StepResult& s : bad.steps)
            if (s.step.kind == training::OperatorStep::Kind::Acknowledge)
                ackMissing = !s.done;
        QVERIFY(ackMissing);

        // Acknowledging without moving off the switch does not recover either.
        const std::string noMove = replaced(e.reference, "F2 HOLD:X-:1 ESC", "F2 ESC");
        const training::Grade half = grader.grade(noMove, "half.k528");
        QVERIFY2(!half.passed, qPrintable(describe(half)));
    }

    void gradingTheSameFileTwiceGivesTheSameJson() {
        const training::Exercise& e = exercise("lathe-04-steps-subprogram");
        const training::Grader grader(e);
        const std::string text = e.reference;
        const std::string a = json::dump(training::gradeJson(grader.grade(text, "a.k528"), true));
        const std::string b = json::dump(training::gradeJson(grader.grade(text, "a.k528"), true));
        QCOMPARE(a, b);
        // And a different program gives a different one (the JSON is about the program).
        const training::Exercise& s = exercise("lathe-03-step");
        const std::string c = json::dump(training::gradeJson(
            training::Grader(s).grade(replaced(s.reference, "N14 #4 X30", "N14 #4 X29"), "a.k528")));
        QVERIFY(c != a);
    }

    // A file the machine does not take scores 0 and names the first error.
    void aProgramWithErrorsScoresZeroWithItsLine() {
        const training::Exercise& e = exercise("lathe-03-step");
        const std::string text = replaced(e.reference, "N3 G1 Z-40 FZ200", "N3 G1 Z-40 FZ200 Q7");
        const training::Grade g = training::Grader(e).grade(text, "typo.k528");
        QCOMPARE(g.score, 0);
        QVERIFY(!g.passed);
        QCOMPARE(g.status, std::string("errors"));
        QVERIFY(!g.diagnostics.empty());
        QCOMPARE(g.diagnostics.front().line, lineOf(text, "N3 G1"));
        QCOMPARE(g.deductions.size(), std::size_t(1));
        QCOMPARE(g.deductions.front().line, lineOf(text, "N3 G1"));
    }

    // A bad operator step is refused with its line and why; the grade fails.
    void aBadOperatorStepIsNamed() {
        std::vector<training::ProcedureError> errors;
        const training::Procedure p = training::readProcedure(
            "; OPERATOR: PULL:ESTOP PUSH:DRIVES_ON\n; OPERATOR: HOME PUSH:TURBO WAIT:x RUN\n", 1,
            errors);
        QCOMPARE(errors.size(), std::size_t(2));
        QCOMPARE(errors[0].line, 2);
        QCOMPARE(errors[0].token, std::string("PUSH:TURBO"));
        QCOMPARE(errors[1].token, std::string("WAIT:x"));
        QVERIFY(!p.standard);
        QCOMPARE(p.steps.size(), std::size_t(4)); // the good ones are kept
        QCOMPARE(training::formatProcedure(p), std::string("PULL:ESTOP PUSH:DRIVES_ON HOME RUN"));
    }

    void aBrokenExerciseFileNamesTheKey_data() {
        QTest::addColumn<QString>("change");
        QTest::addColumn<QString>("to");
        QTest::addColumn<QString>("message");
        QTest::addColumn<QString>("russian");
        QTest::newRow("diameter") << QStringLiteral("\"d\": 30,") << QStringLiteral("\"d\": \"30\",")
                                  << QStringLiteral("drawing.contour[1].d: expected a number")
                                  << QStringLiteral("drawing.contour[1].d: ожидается число");
        QTest::newRow("machine") << QStringLiteral("\"training-lathe\"") << QStringLiteral("\"lathe-x\"")
                                 << QStringLiteral("machine: not a built-in machine: 'lathe-x'")
                                 << QStringLiteral("machine: не встроенный станок: «lathe-x»");
        QTest::newRow("unknown key") << QStringLiteral("\"limits\": {")
                                     << QStringLiteral("\"limits\": {\"cycle_tme_s\": 1, ")
                                     << QStringLiteral("limits.cycle_tme_s: unknown key")
                                     << QStringLiteral("limits.cycle_tme_s: неизвестный ключ");
        QTest::newRow("step") << QStringLiteral("\"step\": \"home\"") << QStringLiteral("\"step\": \"jump\"")
                              << QStringLiteral("operator[0].step: expected home")
                              << QStringLiteral("operator[0].step: ожидается home, preset");
        QTest::newRow("blank") << QStringLiteral("\"ucg\": \"UCG") << QStringLiteral("\"ucg\": \"UCX")
                               << QStringLiteral("blank.ucg: UCG: expected UCG")
                               << QStringLiteral("blank.ucg: UCG: ожидалось UCG");
        QTest::newRow("format") << QStringLiteral("\"format\": 1") << QStringLiteral("\"format\": 2")
                                << QStringLiteral("format: this reader knows format 1")
                                << QStringLiteral("format: эта программа читает формат 1");
    }
    void aBrokenExerciseFileNamesTheKey() {
        QFETCH(QString, change);
        QFETCH(QString, to);
        QFETCH(QString, message);
        QFETCH(QString, russian);
        QFile f(QStringLiteral(K528_SOURCE_DIR "/resources/exercises/lathe-03-step.json"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QString text = QString::fromUtf8(f.readAll());
        QVERIFY(text.contains(change));
        text.replace(text.indexOf(change), change.size(), to);
        try {
            (void)training::readExercise(text.toStdString(), "lathe-03-step", "lathe-03-step.json");
            QFAIL("a broken exercise was read");
        } catch (const training::ExerciseError& err) {
            const QString what = QString::fromUtf8(err.what());
            QVERIFY2(what.startsWith(QStringLiteral("lathe-03-step.json: ")), qPrintable(what));
            QVERIFY2(what.contains(message), qPrintable(what));
            QCOMPARE(QString::fromStdString(err.text(false)), what);
            // In Russian: the same key, said in Russian, no English words
            // but the file's own (keys, values).
            const QString ru = QString::fromStdString(err.text(true));
            QVERIFY2(ru.startsWith(QStringLiteral("lathe-03-step.json: ")), qPrintable(ru));
            QVERIFY2(ru.contains(russian), qPrintable(ru));
            QVERIFY2(!ru.contains(QRegularExpression(QStringLiteral("\\b(expected|unknown|not|the|is)\\b"))), qPrintable(ru));
        }
    }

    // Every text of the exercise reader has its Russian and English, and
    // the Russian says it in Russian.
    void everyExerciseTextIsBilingual() {
        for (const util::CatalogText& t : training::exerciseTexts().texts()) {
            QVERIFY2(!t.ru.empty() && !t.en.empty() && t.ru != t.en, t.id.data());
            QVERIFY2(QString::fromUtf8(t.ru.data(), qsizetype(t.ru.size())).contains(QRegularExpression(QStringLiteral("[а-яё]"))), t.id.data());
        }
        // A file the reader cannot find: named, in either language.
        const training::ExerciseError e("course.json", std::nullopt, "not-embedded");
        QCOMPARE(QString::fromUtf8(e.what()), QStringLiteral("course.json: not among the embedded resources"));
        QCOMPARE(QString::fromStdString(e.text(true)), QStringLiteral("course.json: нет среди встроенных ресурсов"));
        const training::ExerciseError f("x.json", "", "expected-object");
        QCOMPARE(QString::fromStdString(e.text(true)).isEmpty(), false);
        QCOMPARE(QString::fromStdString(f.text(true)), QStringLiteral("x.json: файл: ожидается объект"));
        QCOMPARE(QString::fromUtf8(f.what()), QStringLiteral("x.json: the file: expected an object"));
    }

    void theShippedFileReadsAsIs() {
        QFile f(QStringLiteral(K528_SOURCE_DIR "/resources/exercises/lathe-03-step.json"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        const training::Exercise e =
            training::readExercise(f.readAll().toStdString(), "lathe-03-step", "lathe-03-step.json");
        QCOMPARE(e.drawing.contour, exercise("lathe-03-step").drawing.contour);
        QCOMPARE(e.reference, exercise("lathe-03-step").reference);
    }
};

QTEST_GUILESS_MAIN(TestTrainingGrade)
#include "test_grade.moc"
