// The dialogs of the constants dock: the history of one constant, the diff
// of two revisions (computed on a worker thread), and the C-constant
// calculator (profile/calculator.h) that explains its formulas and the
// factor of 2 between formula 1 and formulas 2/3 (docs/machine-constants.md).
#pragma once

#include <QDialog>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;
class QTextBrowser;

namespace k528::studio {

class ConstantsEditor;
class ConstantsPane;
class MachineStore;

class HistoryDialog : public QDialog {
    Q_OBJECT
public:
    HistoryDialog(const MachineStore& store, int number, QWidget* parent = nullptr);
    QTableWidget* table() const { return table_; }

private:
    QTableWidget* table_;
};

class DiffDialog : public QDialog {
    Q_OBJECT
public:
    DiffDialog(ConstantsPane& pane, QWidget* parent = nullptr);
    void compare();
    // Compares revision `a` with `b` at once (0: the controller now).
    void compareRevisions(int a, int b);
    QPlainTextEdit* result() const { return text_; }

private:
    ConstantsPane& pane_;
    QSpinBox* a_;
    QSpinBox* b_;
    QPushButton* go_;
    QProgressBar* progress_;
    QLabel* summary_;
    QPlainTextEdit* text_;
};

class CalculatorDialog : public QDialog {
    Q_OBJECT
public:
    CalculatorDialog(ConstantsEditor& editor, QWidget* parent = nullptr);
    // The value the calculation gives for УСКОРЕНИЕ 1 (consistent unit).
    qint64 consistentValue() const { return consistent_; }
    void setInputs(int formula, double a, double b); // tests
    void recalculate();
    bool applyToAccel1();

private:
    ConstantsEditor& editor_;
    QComboBox* axis_;
    QComboBox* formula_;
    QDoubleSpinBox* v_;
    QDoubleSpinBox* t_;
    QDoubleSpinBox* s_;
    QDoubleSpinBox* a_;
    QLabel* vLabel_;
    QLabel* tLabel_;
    QLabel* sLabel_;
    QLabel* aLabel_;
    QTextBrowser* explain_;
    QPushButton* apply_;
    qint64 consistent_ = 0;
};

} // namespace k528::studio
