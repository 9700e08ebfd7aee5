// The prove-out pane of the technologist (dock "dock.proveout", docs/proveout.md):
// the current editor's file proved on the machine it is checked for, as
// `k528 check --profile` does (core/proveout: a rapid into the material, the
// tool or the turret into the chuck, a feed with the spindle or the wheel
// stopped, a cut deeper than the tool takes) — each finding with its frame;
// activating one puts the editor's cursor on its line. The findings go to
// the editor too (EditorTab::setProveoutFindings: its Problems list, the red
// box on their lines and their hover text). Below, the machine's
// tools by turret station with their offsets from the R presets (the setup
// sheet's table, handbook 14.3). The proof runs on a worker thread after each
// validation of the file (the editor's), so typing never waits for it.
#pragma once

#include "proveout/proveout.h"

#include <QPointer>
#include <QWidget>

#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

class QCheckBox;
class QDockWidget;
class QLabel;
class QLineEdit;
class QMainWindow;
class QPushButton;
class QTabWidget;
class QTableWidget;

namespace k528::studio {

class EditorTab;
class ProgramEditor;

class ProveoutPane : public QWidget {
    Q_OBJECT
public:
    // Data of a finding's first cell: its rule id ("rapid-into-material").
    static constexpr int kRuleRole = Qt::UserRole + 10;
    // The editor's indicator on the lines of the findings (a red box; the
    // editor's own squiggles are 8 and 9).
    static constexpr int kIndicator = 10; // ProgramEditor::kProveoutIndicator

    explicit ProveoutPane(EditorTab* editor, QWidget* parent = nullptr);
    ~ProveoutPane() override;

    // Proves the current editor's file now, on this thread (tests).
    void proveNow();
    // The findings shown (the last proof of the current file).
    const std::vector<proveout::Finding>& findings() const { return findings_; }
    QTableWidget* findingsTable() const { return table_; }
    QTableWidget* toolsTable() const { return tools_; }
    QLabel* summary() const { return summary_; }
    QLineEdit* blankEdit() const { return blank_; }
    // How many proofs were shown (tests wait for the worker's).
    int proofs() const { return proofs_; }

    // What a proof reads and what it gives (proveout_pane.cpp).
    struct Input;
    struct Output;

signals:
    void proved();
    // A finding was activated and the editor shows its line.
    void lineShown(int program, int line);

protected:
    void changeEvent(QEvent* e) override;

private:
    // What to prove, or why nothing can be (a text for the summary).
    bool input(Input& in, QString& why) const;
    void schedule();
    void show(const Output& out);
    void showNothing(const QString& why); // nothing can be proved: why
    void fillFindings();
    void markEditor();
    void showTools(const Input* in);
    void retranslate();
    void refreshSummary();
    void activate(int row);

    EditorTab* editor_ = nullptr;
    QPointer<ProgramEditor> marked_; // the editor whose lines are marked
    QLabel *blankLabel_ = nullptr, *summary_ = nullptr, *toolsTitle_ = nullptr;
    QLineEdit* blank_ = nullptr;
    QPushButton* proveButton_ = nullptr;
    QCheckBox* auto_ = nullptr;
    QTableWidget *table_ = nullptr, *tools_ = nullptr;
    std::vector<proveout::Finding> findings_;
    // The summary's state: why nothing was proved ("" = proved), what ran.
    QString why_;
    bool materialRan_ = false, chuckRan_ = false, blankFromFile_ = false;
    std::uint64_t generation_ = 0;
    bool busy_ = false, again_ = false;
    int proofs_ = 0;
    std::shared_ptr<bool> alive_;
};

// The dock "dock.proveout" with the pane, in window `w`; activating a finding
// shows its line in the editor (the work area turns to it).
QDockWidget* addProveoutDock(QMainWindow* w, EditorTab* editor, QTabWidget* workArea);

// What is wrong with a UCG line (core's stock::ucgTexts() id, parseUcg's
// errorId) in the window's language, said as stock::ucgErrorText says it:
// «UCG: отверстие длиннее заготовки».
QString ucgErrorText(std::string_view id);
// The id has a text here (studio.ui_language: every id of core's catalog has).
bool hasUcgText(std::string_view id);

} // namespace k528::studio
