// The dock «Machine constants» (dock.constants): the table of the 152
// C-parameters (ConstantsModel) with search and an axis filter, editing
// checked as it is typed (ConstantsEditor::check), undo/redo, the note for
// the next revision, the history of one constant, the diff of two
// revisions, import/export of machine files and CSV and the C-constant
// calculator. Imports, exports and diffs run on a worker thread with a
// progress bar; the window goes on meanwhile. It shows the controller the
// window views: a real one's constants are read over the link and written
// with its rules (F7 «РАБОТА С ПЭВМ»), which the dock's notice tells.
#pragma once

#include "parameters/parameter_table_pane.h"
#include "profile/profile.h"

#include <QFuture>
#include <QString>
#include <functional>

class QComboBox;
class QCheckBox;
class QDockWidget;
class QMainWindow;
class QProgressBar;
class QToolButton;

namespace k528::studio {

class ConstantsEditor;
class ConstantsFilter;
class ConstantsModel;

// What a long operation gives back to the window.
struct LongResult {
    QString error;   // "" when it succeeded
    QString message; // for the status line
    QString text;    // a diff's text
    int revision = 0;
    bool haveConstants = false;
    std::vector<std::int64_t> constants; // an import: the 153 values to apply
};

class ConstantsPane : public ParameterTablePane {
    Q_OBJECT
public:
    // The constants of the controller `viewed` shows, kept as revisions of `machine`.
    ConstantsPane(ViewedController& viewed, const profile::MachineProfile& machine, QWidget* parent = nullptr);

    ConstantsEditor& editor() const { return *editor_; }
    ConstantsModel* model() const { return model_; }
    ConstantsFilter* filter() const { return filter_; }

    // Long operations (started by the buttons after a file dialog; tests call
    // them directly). Each returns at once; busy() until finished().
    void importFile(const QString& path);
    void exportFile(const QString& path); // .csv: the constants; else a machine file
    // The text of the diff between two revisions (0: the controller's memory now).
    QFuture<LongResult> diffRevisions(int a, int b);
    bool busy() const { return busy_; }

public slots:
    void showHistory();    // of the selected constant
    void showDiff();
    void showCalculator();
    void showCuttingData();
    void chooseImport();
    void chooseExport();
    void selectConstant(int number);

signals:
    void finished(const LongResult& r);

private:
    void retranslatePane() override;
    void runLong(const QString& what, std::function<LongResult(std::function<void(int, int)>)> work,
                 std::function<void(const LongResult&)> done);

    ConstantsEditor* editor_;
    ConstantsModel* model_;
    ConstantsFilter* filter_;
    QComboBox* axis_;
    QCheckBox* hideReserved_;
    QToolButton* undoButton_;
    QToolButton* redoButton_;
    QToolButton* historyButton_;
    QToolButton* diffButton_;
    QToolButton* importButton_;
    QToolButton* exportButton_;
    QToolButton* calcButton_;
    QToolButton* cuttingButton_;
    QProgressBar* progress_;
    bool busy_ = false;
};

// Adds the dock (right area, tabbed with nothing, hidden until chosen from
// the View menu; its place remembered).
QDockWidget* addConstantsDock(QMainWindow* window, ViewedController& viewed, const profile::MachineProfile& machine);

} // namespace k528::studio
