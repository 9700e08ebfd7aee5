// The dock «Training» (dock.training; docs/training-course.md): an exercise
// of the course chosen, its task and its drawing; the student's program —
// the editor's current document or a file — run on a simulated machine of
// its own and graded on a worker thread (core/training); the finished part
// drawn over the drawing with the over-cut and the under-cut coloured
// (PartView), the score and the deductions (a click puts the editor on the
// frame's line, and the pane's listing of the graded program); every
// attempt kept in the shop's database (db::Database::recordAttempt, the
// process's one connection: ShopDatabase) and the class's attempts on record
// — graded here, by `k528 grade --record` or on another PC — listed (student,
// exercise, score, time) and exported as CSV.
#pragma once

#include "db/database.h"
#include "profile/profile.h"
#include "training/grade.h"

#include <QWidget>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

class QComboBox;
class QDockWidget;
class QFutureWatcherBase;
class QLabel;
class QLineEdit;
class QListWidget;
class QMainWindow;
class QPlainTextEdit;
class QPushButton;
class QTableWidget;
class QTabWidget;
class QTextBrowser;

namespace k528::studio {

class ConstantsLock;

// The half profile (z along, diameter up) of a graded part: the blank, the
// drawing's nominal contour and its tolerance limits, the finished part,
// the over-cut (red) and under-cut (amber) regions.
class PartView : public QWidget {
    Q_OBJECT
public:
    explicit PartView(QWidget* parent = nullptr);
    // Only the drawing (before an attempt), or a grade's part over it.
    void setDrawing(const training::DrawingShapes& d, std::vector<training::Shape> blank);
    void setGrade(const training::Grade* g); // null: the drawing alone
    QSize sizeHint() const override { return {360, 180}; }
    QSize minimumSizeHint() const override { return {160, 90}; }

protected:
    void paintEvent(QPaintEvent* e) override;

private:
    training::DrawingShapes drawing_;
    std::vector<training::Shape> blank_, finished_;
    std::vector<training::Shape> over_, under_;
};

// One graded attempt of the session.
struct Attempt {
    QString student, exercise, file;
    QString when; // local time, yyyy-MM-dd HH:mm:ss
    std::string program; // the text graded
    training::Grade grade;
    std::int64_t recordedId = 0; // its row in the database, 0: not recorded
};

class TrainingPane : public QWidget {
    Q_OBJECT
public:
    // `editorText`: the editor's current document and its name ("" none).
    TrainingPane(std::function<std::pair<QString, QString>()> editorText, QWidget* parent = nullptr);
    ~TrainingPane() override;

    QComboBox* exerciseChoice() const { return exercise_; }
    QLineEdit* studentName() const { return student_; }
    QListWidget* deductions() const { return deductions_; }
    QLabel* scoreLabel() const { return score_; }
    QTableWidget* attemptsTable() const { return attempts_; }
    PartView* partView() const { return part_; }
    QTabWidget* tabs() const { return tabs_; }
    QPushButton* gradeEditorButton() const { return gradeEditor_; }
    const std::vector<Attempt>& attempts() const { return attemptList_; }
    // The class as the Class tab lists it: the database's attempts, newest
    // first (with this session's that the database did not take).
    const std::vector<db::AttemptEntry>& classAttempts() const { return classRows_; }
    QPushButton* refreshButton() const { return refresh_; }
    QPushButton* pdfButton() const { return pdf_; }

    // The machine whose constants the trainer locks for a class (the
    // window's; ConstantsLock): the Class tab's Lock/Unlock button.
    void setMachine(const profile::MachineProfile& machine);
    QPushButton* lockButton() const { return lockButton_; }
    QLabel* lockNote() const { return lockNote_; }
    // The trainer's action (the button asks the class's name): "" or the error.
    QString lockConstants(const QString& forClass);
    QString unlockConstants();
    QLabel* classNote() const { return classNote_; }
    // Reads the class's attempts from the database again.
    void reloadClass();

    // The exercise shown, by id (false: none such).
    bool selectExercise(const QString& id);
    // Grades `text` (a program file's) on a worker thread; graded() tells
    // the end. False if a grading is under way.
    bool grade(const QString& text, const QString& file);
    bool grading() const { return watcher_ != nullptr; }
    // The attempts as CSV (UTF-8, a header line); "" or the error.
    QString exportCsv(const QString& path) const;
    // The class report as PDF (A4 landscape, in the window's language): each
    // attempt a row — student, exercise, file, time, score, result, cycle
    // time, deductions; "" or the error (nothing half-written is left).
    QString exportPdf(const QString& path) const;

signals:
    void graded(int score, bool passed);
    // A deduction clicked: its frame's program and 1-based line.
    void lineActivated(int program, int line);

protected:
    void changeEvent(QEvent* e) override;

private:
    void retranslate();
    void showExercise();
    void showGrade();
    void showClass();
    void record(Attempt& a);
    void gradeEditor();
    void gradeFile();
    void exportDialog();
    void exportPdfDialog();
    void lockClicked();
    void showLock();
    const training::Exercise* current() const;
    std::shared_ptr<const training::Grader> graderFor(const training::Exercise& e);

    std::function<std::pair<QString, QString>()> editorText_;
    QComboBox* exercise_ = nullptr;
    QLabel* exerciseLabel_ = nullptr;
    QLabel* studentLabel_ = nullptr;
    QLineEdit* student_ = nullptr;
    QPushButton* gradeEditor_ = nullptr;
    QPushButton* gradeFile_ = nullptr;
    QPushButton* csv_ = nullptr;
    QPushButton* pdf_ = nullptr;
    QPushButton* lockButton_ = nullptr;
    QLabel* lockNote_ = nullptr;
    ConstantsLock* lock_ = nullptr;
    QPushButton* refresh_ = nullptr;
    QLabel* classNote_ = nullptr;
    QTabWidget* tabs_ = nullptr;
    QTextBrowser* task_ = nullptr;
    PartView* part_ = nullptr;
    QLabel* score_ = nullptr;
    QListWidget* deductions_ = nullptr;
    QPlainTextEdit* listing_ = nullptr;
    QTableWidget* attempts_ = nullptr;
    std::map<std::string, std::shared_ptr<const training::Grader>> graders_;
    std::optional<Attempt> last_;
    std::vector<Attempt> attemptList_;
    std::vector<db::AttemptEntry> classRows_;
    QString classError_;  // why the class is not the database's ("" it is)
    QString recordError_; // why the last attempt was not recorded
    QFutureWatcherBase* watcher_ = nullptr;
    QString status_; // what the score label says between grades
};

// Adds the dock to `window` (right area, hidden: the Training workspace
// places it); `editorText` gives the editor's current document.
QDockWidget* addTrainingDock(QMainWindow* window, std::function<std::pair<QString, QString>()> editorText);

} // namespace k528::studio
