// The technologist's program editor as a tab of the main window (issue 11):
// several files in tabs (ProgramEditor each), new/open/save/save as, recent
// files, an unsaved-changes guard, reload when a file changes on disk, the
// outline of the file's programs, the Problems list (severity, program,
// line, [Mnn], text) that jumps to the place, the count of problems, the
// machine the file is checked for, and «send to the controller» through the
// check-then-load path (session/program_loader).
#pragma once

#include <QFileSystemWatcher>
#include <QWidget>
#include <functional>

class QLabel;
class QTabWidget;
class QTreeWidget;
class QToolBar;
class QMenu;

namespace k528::studio {

class DebugPanel;
class ProgramEditor;
class SimulationSession;

class EditorTab : public QWidget {
    Q_OBJECT
public:
    enum class CloseChoice { Save, Discard, Cancel };

    explicit EditorTab(SimulationSession* session, QWidget* parent = nullptr);

    ProgramEditor* currentEditor() const;
    int documentCount() const;
    ProgramEditor* editorAt(int index) const;
    QString pathOf(int index) const;
    QTreeWidget* problems() const { return problems_; }
    QTreeWidget* outline() const { return outline_; }
    QLabel* problemCount() const { return count_; }
    // The debugger's pane (editor/debug_panel.h); null without a session.
    DebugPanel* debugPanel() const { return debug_; }

    // Check the files against the session's machine (File > Machine).
    void setCheckAgainstMachine(bool on);

    // The question asked before a modified document is closed; tests replace it.
    void setCloseQuestion(std::function<CloseChoice(const QString& name)> ask) { ask_ = std::move(ask); }

public slots:
    void newFile();
    bool openFile(const QString& path);
    void openDialog();
    bool save();
    bool saveAs();
    bool saveTo(int index, const QString& path);
    bool closeDocument(int index);
    // Closes every document (asking for the modified ones); false = cancelled.
    bool closeAll();
    // Sends the current file to the simulated controller (check, then load).
    bool sendToController();
    // Opens the frame master on the cursor's line (editing it when it holds
    // a frame or a message, else inserting a new frame after it).
    void openMaster();
    // The master's text into the current editor: replaces the cursor's line
    // or inserts a line after it.
    void insertFromMaster(const QString& text, bool replaceLine);
    // The backplot's pick: puts the cursor on 1-based `line` of the document
    // (the current one first) that holds program `program` there; false if none.
    bool showLine(int program, int line);

signals:
    void problemCountChanged(int errors, int warnings);
    void statusMessage(const QString& text);
    // The current editor's cursor moved to another line: the program there
    // and the 1-based line (the backplot highlights its segments).
    void cursorLineChanged(int program, int line);

protected:
    void changeEvent(QEvent* e) override;
    bool eventFilter(QObject* watched, QEvent* e) override;

private:
    int addDocument(const QString& path, const QString& text);
    void refreshProblems();
    void refreshOutline();
    void refreshTitles();
    void fileChangedOnDisk(const QString& path);
    void addRecent(const QString& path);
    void fillRecentMenu();
    void retranslate();

    SimulationSession* session_ = nullptr;
    QToolBar* toolbar_ = nullptr;
    QTabWidget* tabs_ = nullptr;
    QTreeWidget* problems_ = nullptr;
    QTreeWidget* outline_ = nullptr;
    QLabel* count_ = nullptr;
    DebugPanel* debug_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QFileSystemWatcher watcher_;
    bool checkMachine_ = true;
    int untitled_ = 0;
    std::function<CloseChoice(const QString&)> ask_;
    QAction *newAction_ = nullptr, *openAction_ = nullptr, *saveAction_ = nullptr, *saveAsAction_ = nullptr,
            *sendAction_ = nullptr, *masterAction_ = nullptr, *machineAction_ = nullptr, *recentAction_ = nullptr;
};

} // namespace k528::studio
