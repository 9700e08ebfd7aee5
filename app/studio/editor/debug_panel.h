// The debugger's pane of the editor tab: run the file's program
// on the simulated machine (sent through the check-then-load path first),
// hold, continue («Пуск»), stop, reset; single frame; run to cursor; the
// speed of the simulation (real time, ×2…×100, fastest); the call stack
// (R158 level, program, frame, line) and a watch list of R-parameters with
// live values, edited through the controller (Controller::setR: refused
// while a frame executes, allowed while the program is held).
// The logic is DebugSession's; this is the widgets over it.
#pragma once

#include <QList>
#include <QWidget>

class QAction;
class QDialog;
class QComboBox;
class QLabel;
class QLineEdit;
class QToolBar;
class QTreeWidget;
class QTreeWidgetItem;

namespace k528::studio {

class DebugSession;
class EditorTab;
class SimulationSession;

class DebugPanel : public QWidget {
    Q_OBJECT
public:
    DebugPanel(EditorTab* tab, SimulationSession* session, QWidget* parent = nullptr);

    DebugSession* debugger() const { return debug_; }
    QTreeWidget* callStack() const { return stack_; }
    QTreeWidget* watch() const { return watch_; }
    QLabel* status() const { return status_; }
    QComboBox* speed() const { return speed_; }
    QList<int> watched() const { return watched_; }

public slots:
    // Run: continues a held program, else sends the current file and runs
    // its first program from the top. False when it could not.
    bool run();
    void hold();
    void resume();
    void stop();
    void reset();
    void setSingleFrame(bool on);
    // Run to the frame at (or after) the cursor's line of the current editor.
    bool runToCursor();
    // Start here: the state before the frame at (or after) the cursor's
    // line rebuilt by the preview (engine::findStartPoint) and listed in a
    // dialog; its Start sends the file and starts the first program before
    // that frame, the axes brought there by the safe path. False (said in
    // the status) when the frame cannot be a start frame.
    bool startHere();
    // The dialog of Start here while it is open.
    QDialog* startDialog() const { return startDialog_; }
    // Watch list: R0..R299; false (said in the status) for another number.
    bool addWatch(int number);
    void removeWatch(int number);
    // Writes R`number` as the operator would; false (said) when refused.
    bool setWatchValue(int number, qint64 value);

signals:
    void statusMessage(const QString& text);

protected:
    void changeEvent(QEvent* e) override;

private:
    void refresh();
    void refreshStack();
    void refreshWatch();
    void retranslate();
    void watchEdited(QTreeWidgetItem* item, int column);

    EditorTab* tab_ = nullptr;
    SimulationSession* session_ = nullptr;
    DebugSession* debug_ = nullptr;
    QToolBar* toolbar_ = nullptr;
    QAction* startHereAction_ = nullptr;
    QDialog* startDialog_ = nullptr;
    QAction *runAction_ = nullptr, *holdAction_ = nullptr, *resumeAction_ = nullptr, *stepAction_ = nullptr,
            *cursorAction_ = nullptr, *stopAction_ = nullptr, *resetAction_ = nullptr;
    QComboBox* speed_ = nullptr;
    QLabel* speedLabel_ = nullptr;
    QLabel* status_ = nullptr;
    QLabel* stackLabel_ = nullptr;
    QLabel* watchLabel_ = nullptr;
    QTreeWidget* stack_ = nullptr;
    QTreeWidget* watch_ = nullptr;
    QLineEdit* watchAdd_ = nullptr;
    QList<int> watched_;
    bool refreshing_ = false;
};

} // namespace k528::studio
