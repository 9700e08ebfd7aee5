// The technologist's program editor as a tab of the main window:
// several files in tabs (ProgramEditor each), new/open/save/save as, recent
// files, an unsaved-changes guard, reload when a file changes on disk, the
// outline of the file's programs, the Problems list (severity, program,
// line, [Mnn], text) that jumps to the place, the count of problems, the
// machine the file is checked for, and «send to the controller» / «open from
// the controller» on the controller the window shows (controller/controller.h:
// the simulated one, or a real one on the link), a send after the same
// preview of what changes as the Controller dock's push; the machine each
// file is checked for, and the programs of a database machine opened and
// saved as its next revision (database_programs.h), with their release
// states beside them (program_releases.h). Its tools are classes of their
// own over the current document, in the Editor menu (editor_menu.h):
// RefactorActions (renumber / move / copy a program, format the file),
// ListingActions (print and PDF listings), SetupSheetActions (the setup
// sheet) and TeachIn (the controller's position into the text).
#pragma once

#include <QFileSystemWatcher>
#include <QWidget>
#include <functional>
#include <vector>

class QLabel;
class QTabWidget;
class QTreeWidget;
class QTreeView;
class QToolBar;
class QMenu;
class QDialog;

namespace k528::proveout {
struct Finding;
}

namespace k528::studio {

class CycleTimeLabel;
class DebugPanel;
class EditorMenu;
class ListingActions;
class RefactorActions;
class SetupSheetActions;
class TeachIn;
class ProgramEditor;
class ProgramReleases;
class ViewedController;

class EditorTab : public QWidget {
    Q_OBJECT
public:
    enum class CloseChoice { Save, Discard, Cancel };

    // Over the controllers of the window (`viewed`: the one shown, whose
    // machine "the workstation's machine" is; its simulated one carries the
    // debugger); nullptr: an editor alone.
    explicit EditorTab(ViewedController* viewed, QWidget* parent = nullptr);

    ProgramEditor* currentEditor() const;
    int documentCount() const;
    ProgramEditor* editorAt(int index) const;
    // The index of the document shown (-1: none).
    int currentIndex() const;
    QString pathOf(int index) const;
    // The name of document `index` as its tab shows it (without « *»): the
    // file's, the sample's, «untitled N» or the database machine's and revision.
    QString documentName(int index) const;
    // The Problems list: a view over ProblemsModel (problems_model.h).
    QTreeView* problems() const { return problems_; }
    QTreeWidget* outline() const { return outline_; }
    QLabel* problemCount() const { return count_; }
    // The cycle time of the current file's first program (cycle_time_label.h).
    CycleTimeLabel* cycleTime() const { return cycle_; }
    // The release states of the current document's database machine
    // (editor/program_releases.h; hidden for a file).
    ProgramReleases* releases() const { return releases_; }
    // The debugger's pane (editor/debug_panel.h); null without a session.
    DebugPanel* debugPanel() const { return debug_; }
    // The toolbar's New, Open and Save (the main window gives Open and Save
    // Ctrl+O and Ctrl+S while the editor is the page shown).
    QAction* newAction() const { return newAction_; }
    QAction* openAction() const { return openAction_; }
    QAction* saveAction() const { return saveAction_; }

    // The prove-out's findings of document `ed` (proveout_pane.h): boxed on
    // its lines, and in the Problems list after its diagnostics while it is
    // the current one (counted in problemCount(); problemCountChanged()
    // stays the validation's).
    void setProveoutFindings(ProgramEditor* ed, const std::vector<proveout::Finding>& findings);

    // Check the files against the session's machine (File > Machine).
    void setCheckAgainstMachine(bool on);

    // The question asked before a modified document is closed; tests replace it.
    void setCloseQuestion(std::function<CloseChoice(const QString& name)> ask) { ask_ = std::move(ask); }
    // The question asked before a file changed on disk replaces unsaved edits
    // (true = reload); tests replace it.
    void setReloadQuestion(std::function<bool(const QString& path)> ask) { askReload_ = std::move(ask); }

    // The machine document `index` is checked for: "" = the workstation's
    // (File > Machine), kNoMachine = the language only, else a machine's
    // name (database, built-in or file, as File > Machine offers them).
    static inline const QString kNoMachine = QStringLiteral("-");
    bool setFileMachine(int index, const QString& choice);
    QString fileMachine(int index) const;
    // The name of the machine the document is checked for now ("" = none).
    QString checkedMachineName(int index) const;
    // Its title in the window's language (machineTitle()), "" = none.
    QString checkedMachineTitle(int index) const;
    // The Editor menu (refactoring, listing, setup sheet, teach-in, database,
    // machine) for the menu bar.
    QMenu* editorMenu() const;
    // The tools over the current document.
    RefactorActions* refactor() const { return refactor_; }
    ListingActions* listing() const { return listing_; }
    SetupSheetActions* setupSheets() const { return setupSheets_; }
    TeachIn* teachIn() const { return teachIn_; }
    // The database machine of document `index` ("" = a file) and its revision.
    QString databaseMachine(int index) const;
    int databaseRevision(int index) const;

    // What a window's start shows: the files open when a window last closed
    // (those still there), else — on a first start, or when they are gone —
    // the sample program of the machine `machineName` (sampleFor()), so the
    // editor is never an empty pane the first time. Nothing when the user
    // last closed every file. The window's close keeps the list.
    void openStartDocuments(const QString& machineName);
    // The shipped sample (resources/samples/) for a machine: the first whose
    // name shares a word with the machine's ("training-lathe" → lathe-…),
    // else the first of all; "" if none is shipped.
    static QString sampleFor(const QString& machineName);
    // Keeps the paths of the files open now for the next start.
    void rememberOpenFiles();

public slots:
    void newFile();
    bool openFile(const QString& path);
    // A shipped sample program (resources/samples/<name>) as a document that
    // is not yet a file: named «<name> (sample)», saving asks where.
    bool openSample(const QString& name);
    void openDialog();
    bool save();
    bool saveAs();
    bool saveTo(int index, const QString& path);
    bool closeDocument(int index);
    // Closes every document (asking for the modified ones); false = cancelled.
    bool closeAll();
    // Sends the current file's programs and messages to the controller shown:
    // its memory is read, the preview of what changes shown (sendPreview()),
    // then the controller checks and takes it (Controller::loadPrograms).
    // Without the preview (setPreviewBeforeSending(false)) it is sent at
    // once. Returns false when it cannot start, or a controller that answered
    // at once refused; sent() tells the end.
    bool sendToController();
    void setPreviewBeforeSending(bool on) { previewBeforeSending_ = on; }
    QDialog* sendPreview() const { return sendPreview_; }
    // The programs and messages of the controller shown as a new document
    // (read over the link for a real one); openedFromController() tells the end.
    bool openFromController();
    // Opens the frame master on the cursor's line (editing it when it holds
    // a frame or a message, else inserting a new frame after it).
    void openMaster();
    // The master's text into the current editor: replaces the cursor's line
    // or inserts a line after it.
    void insertFromMaster(const QString& text, bool replaceLine);

public:
    // `text` at the current document's cursor as one undo step: replacing
    // the cursor's line (its comments kept after it), filling it when it is
    // empty, else as a new line after it. `line`: the line it is on (-1: no
    // document); `keptComment`: a comment of the replaced line stayed.
    struct PlacedLine {
        int line = -1;
        bool keptComment = false;
    };
    PlacedLine placeLine(const QString& text, bool replaceLine);

public slots:
    // The backplot's pick: puts the cursor on 1-based `line` of the document
    // (the current one first) that holds program `program` there; false if none.
    bool showLine(int program, int line);

    // The programs and messages of a database machine as a document; saving
    // it writes the machine's next revision.
    bool openFromDatabase(const QString& machine);
    void openDatabaseDialog();
    bool saveToDatabase(int index);

signals:
    void problemCountChanged(int errors, int warnings);
    void statusMessage(const QString& text);
    void sendPreviewShown();
    void sent(bool ok, const QString& message);
    void openedFromController(bool ok, const QString& message);
    // The current editor's cursor moved to another line: the program there
    // and the 1-based line (the backplot highlights its segments).
    void cursorLineChanged(int program, int line);
    // A finding of the prove-out was activated in the Problems list: its
    // place (the tool's tip, Z and X as the path has them; the backplot marks it).
    void proveoutFindingActivated(int program, int line, double z, double x);

protected:
    void changeEvent(QEvent* e) override;
    bool eventFilter(QObject* watched, QEvent* e) override;

private:
    int addDocument(const QString& path, const QString& text);
    void refreshProblems();
    void refreshCount();
    void fitCodeColumn();
    void refreshOutline();
    void refreshTitles();
    void fileChangedOnDisk(const QString& path);
    void addRecent(const QString& path);
    void fillRecentMenu();
    void retranslate();
    void applyMachine(ProgramEditor* ed);
    void reapplyWorkstationMachine();
    // The comments of a frame's line as written ("(…)" then "; …"), "" if none.
    static QString commentsOfLine(const QString& line);

    void send(const QString& text, const QString& name);
    ViewedController* viewed_ = nullptr;
    bool previewBeforeSending_ = true;
    class QDialog* sendPreview_ = nullptr;
    QToolBar* toolbar_ = nullptr;
    QTabWidget* tabs_ = nullptr;
    QTreeView* problems_ = nullptr;
    class ProblemsModel* problemsModel_ = nullptr;
    ProgramReleases* releases_ = nullptr;
    QTreeWidget* outline_ = nullptr;
    QLabel* count_ = nullptr;
    CycleTimeLabel* cycle_ = nullptr;
    DebugPanel* debug_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QFileSystemWatcher watcher_;
    bool checkMachine_ = true;
    int untitled_ = 0;
    std::function<CloseChoice(const QString&)> ask_;
    std::function<bool(const QString&)> askReload_;
    RefactorActions* refactor_ = nullptr;
    ListingActions* listing_ = nullptr;
    SetupSheetActions* setupSheets_ = nullptr;
    TeachIn* teachIn_ = nullptr;
    EditorMenu* menu_ = nullptr;
    QAction *newAction_ = nullptr, *openAction_ = nullptr, *saveAction_ = nullptr, *saveAsAction_ = nullptr,
            *sendAction_ = nullptr, *masterAction_ = nullptr, *machineAction_ = nullptr, *recentAction_ = nullptr,
            *openControllerAction_ = nullptr;
};

} // namespace k528::studio
