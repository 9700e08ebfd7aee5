// The training course's dock (app/studio/training): the editor's program
// graded on a worker thread, the score and the deductions shown, a
// deduction clicked naming its line (the editor goes there), the attempt in
// the class's table and its CSV; the main window places the dock in the
// Training workspace and its View menu toggles it.
#include "editor/editor_tab.h"
#include "rig/widgets.h"
#include "editor/program_editor.h"
#include "language.h"
#include "main_window.h"
#include "training/exercise.h"
#include "training/training_pane.h"
#include "cli_runner.h"
#include "workspace/workspaces.h"

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QScreen>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QProcess>
#include <QRegularExpression>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

using namespace k528;
using namespace k528::studio;

namespace {

QString deepStep() {
    QString text = QString::fromStdString(training::findExercise("lathe-03-step")->reference);
    text.replace(QStringLiteral("N14 #4 X30\n"), QStringLiteral("N14 #4 X29\n"));
    return text;
}

int lineOf(const QString& text, const QString& what) {
    return static_cast<int>(text.left(static_cast<int>(text.indexOf(what))).count(QLatin1Char('\n'))) + 1;
}

// The text of a PDF as pdftotext -layout reads it (poppler-utils).
QString pdfText(const QString& pdf) {
    QProcess p;
    p.start(QStringLiteral("pdftotext"), {QStringLiteral("-layout"), pdf, QStringLiteral("-")});
    if (!p.waitForFinished(30000) || p.exitCode() != 0)
        return QStringLiteral("pdftotext failed: ") + QString::fromUtf8(p.readAllStandardError());
    return QString::fromUtf8(p.readAllStandardOutput());
}

// A line of the report that names the student and, after the name, the score.
bool rowOf(const QString& report, const QString& student, int score) {
    const QRegularExpression re(QStringLiteral("%1\\s.*\\s%2\\s").arg(QRegularExpression::escape(student)).arg(score));
    for (const QString& line : report.split(QLatin1Char('\n')))
        if (re.match(line + QLatin1Char(' ')).hasMatch())
            return true;
    return false;
}

} // namespace

class TestTrainingPane : public QObject {
    Q_OBJECT

    // The attempts go to a database of this run's own (K528_DB, inherited
    // by the k528 processes the tests start).
    QTemporaryDir dbDir_;

private slots:
    void initTestCase() {
        QVERIFY(dbDir_.isValid());
        qputenv("K528_DB", dbDir_.filePath(QStringLiteral("class.db")).toUtf8());
        setLanguage(QStringLiteral("en"));
    }

    void theEditorsProgramIsGradedAndADeductionNamesItsLine() {
        const QString text = deepStep();
        TrainingPane pane([&] { return std::pair<QString, QString>(text, QStringLiteral("petrov.k528")); });
        pane.resize(600, 700);
        QVERIFY(pane.selectExercise(QStringLiteral("lathe-03-step")));
        QVERIFY(!pane.selectExercise(QStringLiteral("no-such")));
        QVERIFY(pane.exerciseChoice()->currentText().contains(QStringLiteral("A turned step")));
        pane.studentName()->setText(QStringLiteral("Petrov"));
        QSignalSpy graded(&pane, &TrainingPane::graded);
        pane.gradeEditorButton()->click();
        QVERIFY(pane.grading());
        QVERIFY(!pane.gradeEditorButton()->isEnabled()); // one grading at a time
        QVERIFY(graded.wait(60000));
        QVERIFY(!pane.grading());
        const int score = graded.front().at(0).toInt();
        QVERIFY(score < 100 && score > 0);
        QVERIFY2(pane.scoreLabel()->text().startsWith(QStringLiteral("Petrov: %1/100").arg(score)),
                 qPrintable(pane.scoreLabel()->text()));
        QVERIFY(pane.deductions()->count() >= 1);
        QListWidgetItem* over = nullptr;
        for (int i = 0; i < pane.deductions()->count(); ++i)
            if (pane.deductions()->item(i)->text().contains(QStringLiteral("over-cut")))
                over = pane.deductions()->item(i);
        QVERIFY(over);
        QVERIFY(over->text().contains(QStringLiteral("L1 N15")));
        QSignalSpy line(&pane, &TrainingPane::lineActivated);
        emit pane.deductions()->itemActivated(over);
        QCOMPARE(line.size(), 1);
        QCOMPARE(line.front().at(0).toInt(), 1);
        QCOMPARE(line.front().at(1).toInt(), lineOf(text, QStringLiteral("N15 ")));
        // The class: the attempt kept with the student's name; its CSV.
        QCOMPARE(pane.attemptsTable()->rowCount(), 1);
        QCOMPARE(pane.attemptsTable()->item(0, 0)->text(), QStringLiteral("Petrov"));
        QCOMPARE(pane.attemptsTable()->item(0, 2)->text(), QString::number(score));
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("class.csv"));
        QCOMPARE(pane.exportCsv(csv), QString());
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QStringList rows = QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(rows.size(), 2);
        QVERIFY(rows[0].startsWith(QStringLiteral("student,exercise,file,time,score,passed")));
        QVERIFY2(rows[1].startsWith(QStringLiteral("Petrov,lathe-03-step,petrov.k528,")), qPrintable(rows[1]));
        QVERIFY(rows[1].contains(QStringLiteral(",%1,").arg(score)));
        QVERIFY(rows[1].contains(QStringLiteral("L1 N15")));
        // The class report as PDF, read back: each student's row with the score.
        const QString pdf = dir.filePath(QStringLiteral("class.pdf"));
        QCOMPARE(pane.exportPdf(pdf), QString());
        const QString report = pdfText(pdf);
        QVERIFY2(report.contains(QStringLiteral("class report")), qPrintable(report));
        QVERIFY(!pane.classAttempts().empty());
        for (const db::AttemptEntry& a : pane.classAttempts())
            QVERIFY2(rowOf(report, QString::fromStdString(a.student), a.score), qPrintable(report));
        QVERIFY2(report.contains(QStringLiteral("L1 N15")), qPrintable(report));
        QVERIFY(!pane.exportPdf(QStringLiteral("/nonexistent/dir/class.pdf")).isEmpty());
        QVERIFY(!QFile::exists(QStringLiteral("/nonexistent/dir/class.pdf")));
        // Another exercise chosen: the grade of this one is not shown over its drawing.
        QVERIFY(pane.selectExercise(QStringLiteral("lathe-02-facing")));
        QCOMPARE(pane.deductions()->count(), 0);
        // A CSV that cannot be written says why and keeps nothing half-written.
        QVERIFY(!pane.exportCsv(QStringLiteral("/nonexistent/dir/class.csv")).isEmpty());
    }

    void anEmptyEditorIsToldNotGraded() {
        TrainingPane pane([] { return std::pair<QString, QString>(); });
        QSignalSpy graded(&pane, &TrainingPane::graded);
        pane.gradeEditorButton()->click();
        QVERIFY(!pane.grading());
        QCOMPARE(graded.size(), 0);
        QVERIFY(pane.scoreLabel()->text().contains(QStringLiteral("no program")));
    }

    // The class is the database's: an attempt `k528 grade --record` kept (another
    // process) is listed, one graded here is read by `k528 exercise attempts`.
    void theClassIsTheDatabasesAcrossProcesses() {
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("sidorov.k528"));
        {
            QFile f(file);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(QByteArray::fromStdString(training::findExercise("lathe-03-step")->reference));
        }
        const QString text = deepStep();
        TrainingPane pane([&] { return std::pair<QString, QString>(text, QStringLiteral("kuznetsov.k528")); });
        QVERIFY(pane.selectExercise(QStringLiteral("lathe-03-step")));
        pane.reloadClass(); // the desktop's connection (the database made on its first use)
        QVERIFY(pane.classNote()->isHidden());
        const CliResult g = runK528({"grade", "lathe-03-step", file, "--record"});
        QVERIFY2(g.exitCode == 0, qPrintable(g.err));
        pane.tabs()->setCurrentIndex(2); // the Class tab reads the database again
        const auto& rows = pane.classAttempts();
        QVERIFY(!rows.empty());
        QCOMPARE(rows.front().student, std::string("sidorov"));
        QCOMPARE(rows.front().score, 100);
        QCOMPARE(pane.attemptsTable()->item(0, 0)->text(), QStringLiteral("sidorov"));
        QCOMPARE(pane.attemptsTable()->item(0, 2)->text(), QStringLiteral("100"));
        QVERIFY(pane.classNote()->isHidden());
        pane.studentName()->setText(QStringLiteral("Kuznetsov"));
        QSignalSpy graded(&pane, &TrainingPane::graded);
        pane.gradeEditorButton()->click();
        QVERIFY(graded.wait(60000));
        const int score = graded.front().at(0).toInt();
        QVERIFY(pane.attempts().back().recordedId > 0);
        QCOMPARE(pane.classAttempts().front().student, std::string("Kuznetsov"));
        const CliResult listed = runK528({"exercise", "attempts", "lathe-03-step", "--student", "Kuznetsov", "--json"});
        QVERIFY2(listed.exitCode == 0, qPrintable(listed.err));
        const QJsonArray a = QJsonDocument::fromJson(listed.out.toUtf8()).array();
        QCOMPARE(a.size(), 1);
        QCOMPARE(a[0].toObject().value("score").toInt(), score);
        QCOMPARE(a[0].toObject().value("file").toString(), QStringLiteral("kuznetsov.k528"));
        QCOMPARE(a[0].toObject().value("id").toInteger(), pane.attempts().back().recordedId);
    }

    // A database that cannot take the attempt: the grade stands, the pane says
    // why it was not kept, and the class lists it as this session's.
    void anAttemptTheDatabaseRefusesIsKeptInTheSession() {
        QTemporaryDir dir;
        const QString bad = dir.filePath(QStringLiteral("not-a-database.db"));
        {
            QFile f(bad);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("this is not an SQLite file, and it stays as it is\n");
        }
        const QByteArray before = qgetenv("K528_DB");
        qputenv("K528_DB", bad.toUtf8());
        const QString text = deepStep();
        TrainingPane pane([&] { return std::pair<QString, QString>(text, QStringLiteral("orlov.k528")); });
        QVERIFY(pane.selectExercise(QStringLiteral("lathe-03-step")));
        pane.studentName()->setText(QStringLiteral("Orlov"));
        QSignalSpy graded(&pane, &TrainingPane::graded);
        pane.gradeEditorButton()->click();
        QVERIFY(graded.wait(60000));
        qputenv("K528_DB", before);
        QCOMPARE(pane.attempts().back().recordedId, 0);
        QVERIFY2(pane.scoreLabel()->text().contains(QStringLiteral("Not kept in the database")),
                 qPrintable(pane.scoreLabel()->text()));
        QCOMPARE(pane.classAttempts().size(), std::size_t(1));
        QCOMPARE(pane.classAttempts().front().student, std::string("Orlov"));
        QVERIFY(!pane.classNote()->isHidden());
        QFile f(bad);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("this is not an SQLite file, and it stays as it is\n"));
    }

    void theMainWindowPlacesTheDockInTheTrainingWorkspace() {
        MainWindow w;
        w.placeOnScreen();
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* dock = w.findChild<QDockWidget*>(QStringLiteral("dock.training"));
        QVERIFY(dock);
        QVERIFY(w.workspaces()->activate(QStringLiteral("training")));
        QTRY_VERIFY(dock->isVisible() || !w.tabifiedDockWidgets(dock).isEmpty());
        QVERIFY(!w.tabifiedDockWidgets(dock).isEmpty());
        dock->raise();
        QTRY_VERIFY(dock->isVisible());
        QVERIFY(w.workspaces()->activate(QStringLiteral("operator")));
        QTRY_VERIFY(!dock->isVisible());
        // The editor's program graded from the dock; a deduction puts the editor on its line.
        QVERIFY(w.workspaces()->activate(QStringLiteral("technologist")));
        w.programEditor()->newFile();
        const QString text = deepStep();
        w.programEditor()->currentEditor()->setText(text);
        auto* pane = dock->findChild<TrainingPane*>(); // inside the dock's scroll area
        QVERIFY(pane);
        QVERIFY(pane->selectExercise(QStringLiteral("lathe-03-step")));
        QSignalSpy graded(pane, &TrainingPane::graded);
        pane->gradeEditorButton()->click();
        QVERIFY(graded.wait(60000));
        QListWidgetItem* over = nullptr;
        for (int i = 0; i < pane->deductions()->count(); ++i)
            if (pane->deductions()->item(i)->text().contains(QStringLiteral("L1 N15")))
                over = pane->deductions()->item(i);
        QVERIFY(over);
        emit pane->deductions()->itemActivated(over);
        int lineNo = -1, index = -1;
        w.programEditor()->currentEditor()->getCursorPosition(&lineNo, &index);
        QCOMPARE(lineNo + 1, lineOf(text, QStringLiteral("N15 ")));
    }

    // The pane in the whole window, in the Training workspace, in each
    // language, at the test's screen (1366x768, 1920x1080): every control
    // inside the window, the attempt graded; a screenshot of each for a look
    // (build/…/tests/screenshots/training-pane-<lang>-<screen>.png).
    void theWholeWindowInEachLanguage() {
        for (const QString& lang : {QStringLiteral("ru"), QStringLiteral("en")}) {
            QVERIFY(setLanguage(lang));
            MainWindow w;
            w.placeOnScreen();
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QVERIFY(w.workspaces()->activate(QStringLiteral("training")));
            auto* dock = w.findChild<QDockWidget*>(QStringLiteral("dock.training"));
            dock->raise();
            QTRY_VERIFY(dock->isVisible());
            auto* pane = dock->findChild<TrainingPane*>();
            QVERIFY(pane->selectExercise(QStringLiteral("lathe-03-step")));
            const QString text = deepStep();
            w.programEditor()->newFile();
            w.programEditor()->currentEditor()->setText(text);
            pane->studentName()->setText(lang == QLatin1String("ru") ? QStringLiteral("Петров") : QStringLiteral("Petrov"));
            QSignalSpy graded(pane, &TrainingPane::graded);
            pane->gradeEditorButton()->click();
            QVERIFY(graded.wait(60000));
            QApplication::processEvents();
            const QRect inside = w.rect();
            for (QWidget* c : {static_cast<QWidget*>(pane->exerciseChoice()), static_cast<QWidget*>(pane->studentName()),
                               static_cast<QWidget*>(pane->gradeEditorButton()), static_cast<QWidget*>(pane->scoreLabel()),
                               static_cast<QWidget*>(pane->deductions())}) {
                QVERIFY(c->isVisible());
                const QRect r(c->mapTo(&w, QPoint(0, 0)), c->size());
                QVERIFY2(inside.contains(r), qPrintable(c->objectName()));
                QVERIFY2(c->width() > 40 && c->height() > 10, qPrintable(c->objectName()));
            }
            const QString dir = QStringLiteral(K528_BINARY_DIR "/tests/screenshots");
            QDir().mkpath(dir);
            const QSize screen = w.screen()->size();
            K528_VERIFY_SHOT(w.grab(), QStringLiteral("training-pane-%1-%2x%3-attempt.png")
                                             .arg(lang).arg(screen.width()).arg(screen.height()));
            pane->tabs()->setCurrentIndex(2);
            QApplication::processEvents();
            QVERIFY(pane->attemptsTable()->rowCount() >= 1);
            // The class's buttons and the trainer's lock, inside the window.
            QVERIFY(pane->lockButton()->isEnabled()); // the window named its machine
            for (QWidget* c : {static_cast<QWidget*>(pane->lockButton()), static_cast<QWidget*>(pane->pdfButton()),
                               static_cast<QWidget*>(pane->refreshButton())}) {
                QVERIFY(c->isVisible());
                const QRect r(c->mapTo(&w, QPoint(0, 0)), c->size());
                QVERIFY2(inside.contains(r), qPrintable(c->objectName()));
            }
            K528_VERIFY_SHOT(w.grab(), QStringLiteral("training-pane-%1-%2x%3-class.png")
                                             .arg(lang).arg(screen.width()).arg(screen.height()));
            // The class report as PDF in the window's language, kept beside the screenshots.
            const QString report = dir + QStringLiteral("/training-class-report-%1-%2x%3.pdf")
                                             .arg(lang).arg(screen.width()).arg(screen.height());
            QCOMPARE(pane->exportPdf(report), QString());
            const QString reportText = pdfText(report);
            for (const db::AttemptEntry& a : pane->classAttempts())
                if (!a.student.empty() && a.student != "the editor's program") // a student's, not the editor's
                    QVERIFY2(rowOf(reportText, QString::fromStdString(a.student), a.score), qPrintable(reportText));
            QVERIFY2(reportText.contains(lang == QLatin1String("ru") ? QStringLiteral("отчёт по группе")
                                                                     : QStringLiteral("class report")),
                     qPrintable(reportText));
            // Locked for a class: the note names it; the K923 refuses F5 with the lock's words.
            QCOMPARE(pane->lockConstants(lang == QLatin1String("ru") ? QStringLiteral("ТМ-21") : QStringLiteral("TM-21")),
                     QString());
            QApplication::processEvents();
            QVERIFY(pane->lockNote()->text().contains(QStringLiteral("-21")));
            K528_VERIFY_SHOT(w.grab(), QStringLiteral("training-pane-%1-%2x%3-locked.png")
                                             .arg(lang).arg(screen.width()).arg(screen.height()));
            QCOMPARE(pane->unlockConstants(), QString());
            pane->tabs()->setCurrentIndex(0);
            QApplication::processEvents();
            K528_VERIFY_SHOT(w.grab(), QStringLiteral("training-pane-%1-%2x%3-task.png")
                                             .arg(lang).arg(screen.width()).arg(screen.height()));
        }
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
};

QTEST_MAIN(TestTrainingPane)
#include "test_training_pane.moc"
