// The Controller menu and dock (dock "dock.controller"): the operator's PC
// beside a real K528-05 (or `k528 serve`). Connect through a link plugin
// (port from the system's serial ports, baud, parity, station address), the
// line's state (answers, no answer — a frame with a bad CRC is dropped and
// ends there —, bad replies, exceptions, retries, round-trip time, how busy
// the line is), pull the controller's memory into a new database revision of
// this window's machine, push a machine file or a database machine after a
// preview of what changes (core's profile diff against the memory just
// read), with progress and cancel, and a live monitor: mode, program and
// frame, coordinates and following errors, alarms with their texts, the K
// LEDs and the machine messages (Z1301/Z1302, Z1900..Z1903); the line's
// counters as a Modbus user reads them (answers, timeouts, CRC errors,
// exceptions by code, retries, round trip median and p95) and its frame log
// saved to a file. While connected, every view of the window shows the real
// controller (the seam of controller/controller.h).
#pragma once

#include "controller/controller.h"
#include "profile/profile.h"
#include "workspace/pane_dock.h"

#include <QDockWidget>
#include <QStringList>
#include <memory>

class QCheckBox;
class QComboBox;
class QDialog;
class QLabel;
class QMenu;
class QAction;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QGroupBox;

namespace k528::linkplugin {
class LinkPlugin;
}

namespace k528::studio {

class MainWindow;
class LinkController;

class ControllerDock : public PaneDock {
    Q_OBJECT
public:
    explicit ControllerDock(MainWindow* window);
    ~ControllerDock() override;

    QMenu* menu() const { return menu_; }
    LinkController* link() const { return link_.get(); }
    QComboBox* portBox() const { return port_; }
    QComboBox* baudBox() const { return baud_; }
    QComboBox* parityBox() const { return parity_; }
    QSpinBox* addressBox() const { return address_; }
    QComboBox* pluginBox() const { return plugin_; }
    // The machines of the database that know their line (their stored line
    // fills the form when one is chosen).
    QComboBox* machineBox() const { return machine_; }
    // The database's machine the line was connected for ("" the form's line).
    QString connectedMachine() const { return connectedMachine_; }
    QLabel* lineLabel() const { return lineState_; }
    QLabel* monitorLabel() const { return monitor_; }
    QProgressBar* progressBar() const { return progress_; }
    QPushButton* cancelButton() const { return cancel_; }
    QDialog* preview() const { return preview_; } // the open push preview, if any
    QString lastMessage() const { return lastMessage_; }
    int lastRevision() const { return lastRevision_; }

public slots:
    void connectLine(); // from the form; connectedChanged() tells
    // Controller > Connect: the dock shown, its port field focused (the line
    // is the user's to choose).
    void askForLine();
    // Connects to the line the database's machine `name` keeps (closing the
    // one open, unless a transfer is under way); false when it has none or
    // the line cannot be changed now.
    bool connectMachine(const QString& name);
    // The database's machines with a line, read again.
    void refreshMachines();
    void disconnectLine();
    // The window closes: the views go back to the simulated controller and
    // the line is closed whatever is under way (a transfer is aborted as on
    // a cancel: nothing half-committed), while every view is still alive.
    void closeLine();
    void pullIntoDatabase();
    void pushFile(const QString& path = QString()); // asks for the file when empty
    void pushMachine(const QString& name);           // a database / built-in machine
    void cancelTransfer();
    void refreshPorts();
    // Clears the C or R area of the controller the window shows (after a
    // question unless `ask` is false); memoryCleared() tells the end.
    void clearMemory(k528::studio::MemoryArea area, bool ask = true);
    // The line's frame log to a file (asks for it when empty).
    void saveFrameLog(const QString& path = QString());

signals:
    void connectedChanged(bool connected);
    // A pull or push ended (ok or not); the message is also in the status bar.
    void transferFinished(bool ok, const QString& message);
    void previewShown();
    void frameLogSaved(bool ok, const QString& path);
    void memoryCleared(bool ok, const QString& message);

private:
    void build();
    void retranslate() override;
    void updateEnabled();
    void updateMonitor();
    void updateLine();
    bool tcpChosen() const;
    void pluginChosen();
    void machineChosen();
    void say(const QString& text);
    void startPush(const profile::MachineProfile& file, const QString& what);
    void showPreview(const profile::MachineProfile& memory);

    MainWindow* window_;
    std::vector<linkplugin::LinkPlugin*> plugins_;
    QStringList pluginNames_;
    QString pluginProblem_;
    std::unique_ptr<LinkController> link_;
    QMenu* menu_ = nullptr;
    QAction* connectAction_ = nullptr;
    QAction* disconnectAction_ = nullptr;
    QAction* pullAction_ = nullptr;
    QAction* pushFileAction_ = nullptr;
    QMenu* pushMachineMenu_ = nullptr;
    QAction* clearCAction_ = nullptr;
    QAction* clearRAction_ = nullptr;
    QGroupBox* lineBox_ = nullptr;
    QGroupBox* monitorBox_ = nullptr;
    QComboBox* plugin_ = nullptr;
    QComboBox* machine_ = nullptr;
    QMenu* connectMachineMenu_ = nullptr;
    QStringList pluginIds_; // "modbus-rtu", "modbus-tcp" (the metadata's names)
    QString connectedMachine_;
    QComboBox* port_ = nullptr;
    QComboBox* baud_ = nullptr;
    QComboBox* parity_ = nullptr;
    QSpinBox* address_ = nullptr;
    QPushButton* connect_ = nullptr;
    QPushButton* refreshPorts_ = nullptr;
    QPushButton* pull_ = nullptr;
    QPushButton* push_ = nullptr;
    QPushButton* cancel_ = nullptr;
    QPushButton* frames_ = nullptr;
    QCheckBox* showOnViews_ = nullptr;
    QLabel* lineState_ = nullptr;
    QLabel* monitor_ = nullptr;
    QLabel* transfer_ = nullptr;
    QLabel* captions_[6] = {};
    QProgressBar* progress_ = nullptr;
    QDialog* preview_ = nullptr;
    bool connecting_ = false;
    std::unique_ptr<profile::MachineProfile> pending_; // the push waiting for its preview
    QString pendingWhat_;
    QString pendingMachine_; // the database's machine pushed ("" a file)
    QStringList pendingLeftOut_; // its programs the push leaves out, and why
    QString notOnRecord_;    // why the last transfer is not on record
    QString lastMessage_, lastMonitor_, lostWhy_;
    int lastRevision_ = 0;
};

// Builds the dock on `window` (right dock area, tabbed with the machine's panel).
ControllerDock* addControllerDock(MainWindow* window);

} // namespace k528::studio
