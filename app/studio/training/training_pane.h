// The dock «Training» (dock.training; docs/training-course.md): an exercise
// of the course chosen, its task and its drawing; the student's program —
// the editor's current document or a file — run on a simulated machine of
// its own and graded on a worker thread (core/training); the finished part
// drawn over the drawing with the over-cut and the under-cut coloured
// (PartView), the score and the deductions (a click puts the editor on the
// frame's line, and the pane's listing of the graded program); the
// session's attempts (student, exercise, score, time) as a class's table,
// exported as CSV.
#pragma once

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
    training::Grade grade;
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

    // The exercise shown, by id (false: none such).
    bool selectExercise(const QString& id);
    // Grades `text` (a program file's) on a worker thread; graded() tells
    // the end. False if a grading is under way.
    bool grade(const QString& text, const QString& file);
    bool grading() const { return watcher_ != nullptr; }
    // The attempts as CSV (UTF-8, a header line); "" or the error.
    QString exportCsv(const QString& path) const;

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
    void addAttemptRow(const Attempt& a);
    void gradeEditor();
    void gradeFile();
    void exportDialog();
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
    QFutureWatcherBase* watcher_ = nullptr;
    QString status_; // what the score label says between grades
};

// Adds the dock to `window` (right area, hidden: the Training workspace
// places it); `editorText` gives the editor's current document.
QDockWidget* addTrainingDock(QMainWindow* window, std::function<std::pair<QString, QString>()> editorText);

} // namespace k528::studio
