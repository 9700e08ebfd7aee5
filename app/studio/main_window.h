// The K528 Studio main window: a central work area (the program being run,
// the editor) and docks (the K923 panel, the machine's control panel,
// messages, axes, backplot, oscilloscope, debugger, controller, constants,
// R-parameters, history), arranged by workspaces for the operator, the
// technologist and the trainee (workspace/workspaces.h; the switch is in the
// menu bar's corner). It never grows past the screen: the docks' contents
// scroll or scale, long status texts are elided (workspace/screen_fit.h).
// At start-up it builds one simulated machine (SimulationSession) that
// advances with real time; every view shows it until the Controller dock
// connects a real controller and the views follow that one (ViewedController);
// the Simulation menu pauses the simulated machine, sets its speed and
// injects faults for training.
#pragma once

#include "session/machine_source.h"

#include <QMainWindow>

class QDockWidget;
class QLabel;
class QTabWidget;
class QActionGroup;

namespace k528::studio {

class K923Widget;
class SimulationSession;
class MachinePanelWidget;
class MessagesView;
class AxesView;
class ProgramMonitor;
class EditorTab;
class Controller;
class SimulatedController;
class ViewedController;
class ViewNotice;
class Workspaces;
class ShopView;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // The workstation on the built-in default profile (tests).
    explicit MainWindow(QWidget* parent = nullptr);
    // The workstation on `machine` (loadMachine()).
    explicit MainWindow(const MachineChoice& machine, QWidget* parent = nullptr);
    // Closes a real controller's line first, while every view still lives.
    ~MainWindow() override;

    // The docks, by role (object names "dock.k923", "dock.machine",
    // "dock.messages", "dock.axes").
    QDockWidget* k923Dock() const { return k923Dock_; }
    // The K923 panel in the dock "dock.k923".
    K923Widget* k923() const { return k923_; }
    QDockWidget* machineDock() const { return machineDock_; }
    QDockWidget* messagesDock() const { return messagesDock_; }
    QDockWidget* axesDock() const { return axesDock_; }
    QTabWidget* workArea() const { return workArea_; }
    // The simulated machine the docks show (the K923 panel model goes over
    // session()->controller()).
    SimulationSession* session() const { return session_; }
    MachinePanelWidget* machinePanel() const { return machinePanel_; }
    MessagesView* messagesView() const { return messagesView_; }
    AxesView* axesView() const { return axesView_; }
    // The tab "Program" of the work area: the program the controller runs.
    ProgramMonitor* programMonitor() const { return programMonitor_; }
    // The controller every view shows (controller/controller.h): the
    // simulated one of this window, or a real one on the link (the
    // Controller dock switches). Views that only the simulated machine has
    // (its control panel, the debugger) are greyed with the reason then.
    Controller* viewedController() const;
    ViewedController* viewed() const { return viewed_; }
    SimulatedController* simulatedController() const { return simController_; }
    void setViewedController(Controller* controller); // nullptr: the simulated one
    EditorTab* programEditor() const { return programEditor_; }
    // The Shop workspace's page: every machine of the database on its line.
    ShopView* shopView() const { return shopView_; }
    // The machine this window simulates, and where it came from.
    const MachineChoice& machine() const { return machine_; }
    // File > Machine: the machines to choose from (rebuilt as it opens).
    QMenu* machineMenu() const { return machineMenu_; }
    // The workspaces (operator, technologist, training) and their switch.
    Workspaces* workspaces() const { return workspaces_; }
    // The debugger's dock ("dock.debugger": the editor's DebugPanel).
    QDockWidget* debuggerDock() const { return debuggerDock_; }
    // Puts the window on its screen: where it was last time (inside the
    // screen's available area), else filling that area; then the workspace
    // it was left in, else the one that fits the screen. Call before show().
    void placeOnScreen();

public slots:
    // Replaces this window by one on machine `name` (database, built-in or
    // file), keeping its geometry; a machine that cannot be loaded is said
    // in a message box and this window stays. Returns the new window.
    MainWindow* switchMachine(const QString& name);
    // File > Load programs: asks for a program file and loads it
    // (session/program_loader.h), telling what it found.
    void loadPrograms();
    // The same for a given file, without asking; returns whether it loaded.
    bool loadProgramsFrom(const QString& path);
    // File > Keep in the database: the memory of the controller shown (C, R,
    // programs, messages; read over the link for a real one) as a new
    // revision of this machine. Returns the revision when the controller
    // answered at once (the simulation), 0 when it could not be kept (said in
    // a box) or is read over the line (memoryKept() tells the end).
    int keepInDatabase();

signals:
    void memoryKept(int revision, const QString& message);
    // Load programs ended (the controller on the link answers later).
    void programsLoaded(bool ok, const QString& message);

protected:
    void changeEvent(QEvent* event) override;
    void closeEvent(QCloseEvent* event) override;

private:
    void createDocks();
    void viewedChanged();
    void createMenus();
    void fillMachineMenu();
    void updateMachineLabel();
    // After File > Database…: the machine's label names the new database
    // (or says the machine is not in it).
    void followDatabase();
    void createSimulationMenu();
    void updateFaultActions();
    void retranslate();
    void createWorkspaces();
    // Ctrl+O and Ctrl+S: the editor's while it is the page shown, else File's.
    void assignFileShortcuts();
    void keepOnScreen();
    QDockWidget* addDock(const char* objectName, Qt::DockWidgetArea area);

    QTabWidget* workArea_ = nullptr;
    QDockWidget* k923Dock_ = nullptr;
    K923Widget* k923_ = nullptr;
    QDockWidget* machineDock_ = nullptr;
    QDockWidget* messagesDock_ = nullptr;
    QDockWidget* axesDock_ = nullptr;
    MachineChoice machine_;
    QMenu* fileMenu_ = nullptr;
    QMenu* machineMenu_ = nullptr;
    QLabel* machineLabel_ = nullptr;
    QMenu* viewMenu_ = nullptr;
    QMenu* languageMenu_ = nullptr;
    QMenu* helpMenu_ = nullptr;
    QMenu* simulationMenu_ = nullptr;
    QMenu* faultsMenu_ = nullptr;
    QMenu* speedMenu_ = nullptr;
    QAction* pauseAction_ = nullptr;
    QAction* clearFaultsAction_ = nullptr;
    QList<QAction*> speedActions_;
    QList<QAction*> faultActions_;
    QLabel* timeLabel_ = nullptr;
    SimulationSession* session_ = nullptr;
    SimulatedController* simController_ = nullptr;
    ViewedController* viewed_ = nullptr;
    ViewNotice* machineNotice_ = nullptr;
    ViewNotice* debuggerNotice_ = nullptr;
    QMetaObject::Connection k923Updates_;
    QMetaObject::Connection staleWatch_;
    bool shownStale_ = false;
    MachinePanelWidget* machinePanel_ = nullptr;
    MessagesView* messagesView_ = nullptr;
    AxesView* axesView_ = nullptr;
    ProgramMonitor* programMonitor_ = nullptr;
    EditorTab* programEditor_ = nullptr;
    ShopView* shopView_ = nullptr;
    QDockWidget* debuggerDock_ = nullptr;
    Workspaces* workspaces_ = nullptr;
    QMenu* workspaceMenu_ = nullptr;
    QAction* quitAction_ = nullptr;
    QAction* loadProgramsAction_ = nullptr;
    QAction* keepAction_ = nullptr;
    QAction* aboutAction_ = nullptr;
    QAction* russianAction_ = nullptr;
    QAction* englishAction_ = nullptr;
};

} // namespace k528::studio
