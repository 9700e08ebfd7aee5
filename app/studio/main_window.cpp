#include "main_window.h"

#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QEvent>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QComboBox>
#include <QListWidget>
#include <QTabWidget>

#include "backplot/backplot_dock.h"
#include "backplot/backplot_widget.h"
#include "controller/controller_dock.h"
#include "controller/simulated_controller.h"
#include "constants/constants_dock.h"
#include "engine/self_test.h"
#include "k923/k923_widget.h"
#include "language.h"
#include "machine/fault_texts.h"
#include "machine/machine_panel.h"
#include "machine/status_views.h"
#include "profile/builtin.h"
#include "rparams/rparams_dock.h"
#include "monitor/program_monitor.h"
#include "scope/scope_dock.h"
#include "history/history_dock.h"
#include "proveout/proveout_pane.h"
#include "editor/editor_tab.h"
#include "session/program_loader.h"
#include "session/simulation_session.h"
#include "util/version.h"
#include "editor/debug_panel.h"
#include "workspace/elided_label.h"
#include "workspace/panel_scaler.h"
#include "workspace/screen_fit.h"
#include "workspace/standard_workspaces.h"
#include "workspace/workspaces.h"

#include <QCloseEvent>
#include <QScrollArea>
#include <QSettings>
#include <QTimer>
#include <QWindow>

namespace k528::studio {

MainWindow::MainWindow(QWidget* parent)
    : MainWindow(MachineChoice{profile::builtin(profile::kDefaultProfile), QString(), QString()},
                 parent) {}

MainWindow::MainWindow(const MachineChoice& machine, QWidget* parent)
    : QMainWindow(parent), machine_(machine) {
    setObjectName("mainWindow");
    setWindowIcon(QIcon(":/icons/k528studio.svg"));
    workArea_ = new QTabWidget(this);
    workArea_->setObjectName("workArea");
    workArea_->setDocumentMode(true);
    setCentralWidget(workArea_);
    setDockOptions(AnimatedDocks | AllowTabbedDocks | AllowNestedDocks);
    session_ = new SimulationSession(machine_.profile, this);
    session_->watchInput(); // an input wakes the idle machine's frames (simulation_session.h)
    simController_ = new SimulatedController(*session_, this);
    viewed_ = simController_;
    programMonitor_ = new ProgramMonitor(*viewed_, workArea_);
    workArea_->addTab(programMonitor_, QString());
    programEditor_ = new EditorTab(session_, workArea_);
    workArea_->addTab(programEditor_, QString());
    connect(programEditor_, &EditorTab::statusMessage, this, [this](const QString& m) { statusBar()->showMessage(m, 10000); });
    createDocks();
    // The files of the last session, or the machine's sample on a first start.
    programEditor_->openStartDocuments(QString::fromStdString(machine_.profile.name));
    createWorkspaces();
    createMenus();
    // The status bar's permanent texts are cut rather than widen the window
    // (a database path can be long).
    machineLabel_ = new ElidedLabel(this, Qt::ElideMiddle);
    machineLabel_->setObjectName("status.machine");
    statusBar()->addPermanentWidget(machineLabel_, 1);
    machineLabel_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    timeLabel_ = new ElidedLabel(this);
    timeLabel_->setObjectName("status.machineTime");
    statusBar()->addPermanentWidget(timeLabel_);
    connect(session_, &SimulationSession::advanced, this, [this] {
        const std::int64_t s = session_->timeMs() / 1000;
        const QString t = tr("Machine time %1:%2:%3")
                              .arg(s / 3600, 2, 10, QChar('0'))
                              .arg(s / 60 % 60, 2, 10, QChar('0'))
                              .arg(s % 60, 2, 10, QChar('0'));
        if (timeLabel_->text() != t)
            timeLabel_->setText(t);
    });
    retranslate();
    assignFileShortcuts();
    connect(workArea_, &QTabWidget::currentChanged, this, &MainWindow::assignFileShortcuts);
    resize(availableArea(this).size().boundedTo(QSize(1280, 800)));
}

void MainWindow::createWorkspaces() {
    // Where each dock was added: its home when a workspace does not place it.
    for (QDockWidget* d : findChildren<QDockWidget*>(QString(), Qt::FindDirectChildrenOnly))
        d->setProperty("k528.homeArea", static_cast<int>(dockWidgetArea(d)));
    workspaces_ = new Workspaces(this, workArea_);
    for (WorkspaceSpec& s : standardWorkspaces(availableArea(this).size()))
        workspaces_->add(std::move(s));
    connect(workspaces_, &Workspaces::activated, this, &MainWindow::assignFileShortcuts);
    menuBar()->setCornerWidget(workspaces_->switcher(), Qt::TopRightCorner);
    // Until placeOnScreen() chooses: the one that fits the screen.
    const QString saved = QSettings().value("workspaces/current").toString();
    workspaces_->activate(workspaces_->spec(saved) ? saved : Workspaces::firstChoice(availableArea(this).size()));
}

void MainWindow::assignFileShortcuts() {
    if (!workspaces_ || !keepAction_)
        return;
    const bool editorShown = !workArea_->isHidden() && workArea_->currentWidget() == programEditor_;
    programEditor_->openAction()->setShortcut(editorShown ? QKeySequence(QKeySequence::Open) : QKeySequence());
    programEditor_->saveAction()->setShortcut(editorShown ? QKeySequence(QKeySequence::Save) : QKeySequence());
    loadProgramsAction_->setShortcut(editorShown ? QKeySequence() : QKeySequence(QKeySequence::Open));
    keepAction_->setShortcut(editorShown ? QKeySequence() : QKeySequence(QKeySequence::Save));
}

void MainWindow::placeOnScreen() {
    const QRect area = availableArea(this);
    QSettings s;
    const QByteArray kept = s.value("window/geometry").toByteArray();
    if (kept.isEmpty() || !restoreGeometry(kept))
        setGeometry(area);
    if (kept.isEmpty())
        setWindowState(windowState() | Qt::WindowMaximized);
    keepOnScreen();
    workspaces_->reload(); // the shares are of the window's size now
    if (QWindow* w = windowHandle())
        connect(w, &QWindow::screenChanged, this, &MainWindow::keepOnScreen, Qt::UniqueConnection);
}

void MainWindow::keepOnScreen() { keepInside(this, availableArea(this)); }

void MainWindow::closeEvent(QCloseEvent* event) {
    // What the user arranged, for the next start (also when the close is
    // refused: it costs nothing).
    workspaces_->save();
    QSettings().setValue("window/geometry", saveGeometry());
    QMainWindow::closeEvent(event);
}

QDockWidget* MainWindow::addDock(const char* objectName, Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(this);
    dock->setObjectName(objectName);
    dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable |
                      QDockWidget::DockWidgetClosable);
    auto* hint = new QLabel(dock);
    hint->setObjectName(QString(objectName) + ".hint");
    hint->setAlignment(Qt::AlignCenter);
    hint->setWordWrap(true);
    hint->setMargin(12);
    dock->setWidget(hint);
    addDockWidget(area, dock);
    return dock;
}

void MainWindow::createDocks() {
    k923Dock_ = addDock("dock.k923", Qt::RightDockWidgetArea);
    // The K923 panel: the session's panel model draws it and takes its keys.
    delete k923Dock_->widget();
    k923_ = new K923Widget(k923Dock_);
    k923_->setDisplay(viewed_->state().display);
    k923Dock_->setWidget(k923_);
    connect(k923_, &K923Widget::keyPressed, this, [this](panel::KeyPress k) {
        if (viewed_->acceptsKeys())
            viewed_->pressKey(k); // updated() redraws the panel
        else
            statusBar()->showMessage(tr("The controller on the link takes no keys: press them on its own K923"), 5000);
    });
    connect(viewed_, &Controller::updated, k923_, [this] { k923_->setDisplay(viewed_->state().display); });
    machineDock_ = addDock("dock.machine", Qt::RightDockWidgetArea);
    delete machineDock_->widget();
    auto* scroll = new QScrollArea(machineDock_);
    scroll->setObjectName("machinePanelScroll");
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    machinePanel_ = new MachinePanelWidget(*session_, scroll);
    scroll->setWidget(machinePanel_);
    machineDock_->setWidget(scroll);
    // The panel scales to its dock (it scrolls only below 60 %).
    new PanelScaler(scroll, [this](QSize room) { machinePanel_->fitTo(room); });
    // The machine's panel beside the K923, as on the shop floor.
    splitDockWidget(k923Dock_, machineDock_, Qt::Horizontal);
    messagesDock_ = addDock("dock.messages", Qt::BottomDockWidgetArea);
    delete messagesDock_->widget();
    messagesView_ = new MessagesView(*viewed_, messagesDock_);
    messagesDock_->setWidget(messagesView_);
    axesDock_ = addDock("dock.axes", Qt::BottomDockWidgetArea);
    delete axesDock_->widget();
    axesView_ = new AxesView(*viewed_, axesDock_);
    axesDock_->setWidget(axesView_);
    tabifyDockWidget(messagesDock_, axesDock_);
    messagesDock_->raise();
    QDockWidget* backplotDock = backplot::addBackplotDock(this, *session_); // backplot/backplot_dock.cpp
    if (auto* bp = backplotDock->findChild<backplot::BackplotWidget*>()) {
        // A picked segment: the editor goes to its line (else the Program tab
        // to its frame); the editor's line highlights its segments.
        connect(bp, &backplot::BackplotWidget::lineActivated, this, [this](int program, int line) {
            if (programEditor_->showLine(program, line)) {
                workArea_->setCurrentWidget(programEditor_);
                return;
            }
            if (programMonitor_->shownProgram() != program) { // pin it (it follows the controller otherwise)
                const int choice = programMonitor_->programChoice()->findData(program);
                if (choice < 0)
                    return;
                programMonitor_->programChoice()->setCurrentIndex(choice);
                programMonitor_->refresh();
            }
            if (const program::Program* p = session_->controller().programs().find(program))
                for (std::size_t i = 0; i < p->frames.size(); ++i)
                    if (p->frames[i].span.line == line)
                        programMonitor_->frames()->setCurrentRow(static_cast<int>(i));
            workArea_->setCurrentWidget(programMonitor_);
        });
        connect(programEditor_, &EditorTab::cursorLineChanged, bp, &backplot::BackplotWidget::selectLine);
    }
    addScopeDock(this, *session_);
    addControllerDock(this); // controller/controller_dock.cpp: the Controller menu and dock
    addConstantsDock(this, *session_); // constants/constants_dock.cpp
    addRParamsDock(this, *session_);   // rparams/rparams_dock.cpp
    addHistoryDock(this, *session_); // history/history_dock.cpp
    addProveoutDock(this, programEditor_, workArea_); // proveout/proveout_pane.cpp
    // The debugger of the editor in a dock of its own (the technologist
    // shows it on demand).
    debuggerDock_ = addDock("dock.debugger", Qt::RightDockWidgetArea);
    if (DebugPanel* debug = programEditor_->debugPanel()) {
        delete debuggerDock_->widget();
        debuggerDock_->setWidget(debug); // out of the editor's splitter
    }
    // A content that cannot shrink scrolls inside its dock rather than
    // widen the window (the K923 and the machine's panel scale instead).
    for (QDockWidget* d : findChildren<QDockWidget*>(QString(), Qt::FindDirectChildrenOnly))
        if (d != k923Dock_ && d != machineDock_ && d != messagesDock_)
            scrollInside(d);
}

void MainWindow::setViewedController(Controller* controller) {
    Controller* c = controller ? controller : simController_;
    if (c == viewed_)
        return;
    disconnect(viewed_, &Controller::updated, k923_, nullptr);
    viewed_ = c;
    connect(viewed_, &Controller::updated, k923_, [this] { k923_->setDisplay(viewed_->state().display); });
    k923_->setDisplay(viewed_->state().display);
    programMonitor_->setController(*viewed_);
    messagesView_->setController(*viewed_);
    axesView_->setController(*viewed_);
    if (controller)
        connect(controller, &QObject::destroyed, this, [this, controller] {
            if (viewed_ == controller)
                setViewedController(nullptr);
        });
}

void MainWindow::createMenus() {
    fileMenu_ = menuBar()->addMenu(QString());
    loadProgramsAction_ =
        fileMenu_->addAction(QString(), QKeySequence::Open, this, &MainWindow::loadPrograms);
    loadProgramsAction_->setObjectName("action.loadPrograms");
    keepAction_ = fileMenu_->addAction(QString(), QKeySequence::Save, this, [this] { keepInDatabase(); });
    keepAction_->setObjectName("action.keepInDatabase");
    machineMenu_ = fileMenu_->addMenu(QString());
    machineMenu_->setObjectName("menu.machine");
    connect(machineMenu_, &QMenu::aboutToShow, this, &MainWindow::fillMachineMenu);
    fillMachineMenu();
    fileMenu_->addSeparator();
    quitAction_ = fileMenu_->addAction(QString(), QKeySequence::Quit, qApp, &QApplication::quit);
    quitAction_->setObjectName("action.quit");

    menuBar()->addMenu(programEditor_->editorMenu()); // the Editor tab's tools (editor_tab_tools.cpp)
    viewMenu_ = menuBar()->addMenu(QString());
    viewMenu_->addMenu(workspaces_->menu());
    viewMenu_->addSeparator();
    for (QDockWidget* d : {k923Dock_, machineDock_, messagesDock_, axesDock_})
        viewMenu_->addAction(d->toggleViewAction());
    if (auto* d = findChild<QDockWidget*>("dock.backplot"))
        viewMenu_->addAction(d->toggleViewAction());
    if (auto* scope = findChild<QDockWidget*>("dock.scope"))
        viewMenu_->addAction(scope->toggleViewAction());
    for (const char* name : {"dock.constants", "dock.rparams"})
        if (auto* d = findChild<QDockWidget*>(name))
            viewMenu_->addAction(d->toggleViewAction());
    if (auto* history = findChild<QDockWidget*>("dock.history"))
        viewMenu_->addAction(history->toggleViewAction());
    viewMenu_->addAction(debuggerDock_->toggleViewAction());
    if (auto* d = findChild<QDockWidget*>("dock.proveout"))
        viewMenu_->addAction(d->toggleViewAction());

    languageMenu_ = menuBar()->addMenu(QString());
    auto* group = new QActionGroup(this);
    russianAction_ = languageMenu_->addAction(QStringLiteral("Русский"));
    englishAction_ = languageMenu_->addAction(QStringLiteral("English"));
    for (QAction* a : {russianAction_, englishAction_}) {
        a->setCheckable(true);
        group->addAction(a);
    }
    russianAction_->setObjectName("action.language.ru");
    englishAction_->setObjectName("action.language.en");
    (currentLanguage() == "ru" ? russianAction_ : englishAction_)->setChecked(true);
    connect(russianAction_, &QAction::triggered, this, [] { setLanguage("ru"); });
    connect(englishAction_, &QAction::triggered, this, [] { setLanguage("en"); });

    createSimulationMenu();
    if (auto* c = findChild<ControllerDock*>("dock.controller")) {
        menuBar()->addMenu(c->menu());
        viewMenu_->addAction(c->toggleViewAction());
    }

    helpMenu_ = menuBar()->addMenu(QString());
    aboutAction_ = helpMenu_->addAction(QString(), this, [this] {
        QMessageBox::about(this, tr("About K528 Studio"),
                           tr("<h3>K528 Studio %1</h3><p>Workstation for the Konstar K528-05 "
                              "two-axis positioning controller and its K923 operator panel.</p>"
                              "<p>Licence: GNU GPL version 3 or later.</p>")
                               .arg(QString::fromLatin1(k528::version_string)));
    });
}

void MainWindow::loadPrograms() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Load programs"), QString(), tr("K528 programs (*.k528 *.txt);;All files (*)"));
    if (!path.isEmpty())
        loadProgramsFrom(path);
}

bool MainWindow::loadProgramsFrom(const QString& path) {
    const ProgramLoad r = loadProgramFile(*session_, path);
    QStringList names;
    for (int n : r.programs)
        names << QStringLiteral("L%1").arg(n);
    const QString file = QFileInfo(path).fileName();
    if (r.loaded && r.findings.isEmpty()) {
        statusBar()->showMessage(tr("Loaded %1 from %2").arg(names.join(", "), file), 10000);
        return true;
    }
    QMessageBox box(r.loaded ? QMessageBox::Information : QMessageBox::Warning, tr("Load programs"),
                    r.loaded ? tr("Loaded %1 from %2, with warnings.").arg(names.join(", "), file)
                             : r.problem,
                    QMessageBox::Ok, this);
    box.setObjectName("programLoadReport");
    box.setDetailedText(r.findings.join('\n'));
    if (!r.findings.isEmpty())
        box.setInformativeText(r.findings.mid(0, 5).join('\n'));
    box.exec();
    return r.loaded;
}

int MainWindow::keepInDatabase() {
    const engine::Controller& c = session_->controller();
    const profile::MachineProfile p =
        engine::memoryProfile(session_->simulation().profile(), c.c(), c.rValues(), c.programs());
    const MachineSave s = saveMachine(p);
    const QString name = QString::fromStdString(p.name);
    if (s.revision == 0) {
        QMessageBox::warning(this, tr("Keep in the database"),
                             tr("The memory of %1 was not kept: %2").arg(name, s.error));
        return 0;
    }
    statusBar()->showMessage(
        s.changes == 0 ? tr("%1: the database already holds this memory (revision %2)").arg(name).arg(s.revision)
                       : tr("%1 kept in the database as revision %2 (%3 changes)")
                             .arg(name)
                             .arg(s.revision)
                             .arg(s.changes),
        10000);
    return s.revision;
}

void MainWindow::fillMachineMenu() {
    machineMenu_->clear();
    QString warning;
    const QStringList names = machineNames(&warning);
    for (const QString& n : names) {
        QAction* a = machineMenu_->addAction(n);
        a->setObjectName("action.machine." + n);
        a->setCheckable(true);
        a->setChecked(QString::fromStdString(machine_.profile.name) == n);
        connect(a, &QAction::triggered, this, [this, n] { switchMachine(n); });
    }
    if (!warning.isEmpty()) {
        machineMenu_->addSeparator();
        machineMenu_->addAction(warning)->setEnabled(false);
    }
}

MainWindow* MainWindow::switchMachine(const QString& name) {
    MachineChoice choice;
    try {
        choice = loadMachine(name);
    } catch (const std::exception& e) {
        QMessageBox::warning(this, tr("Machine"),
                             tr("The machine %1 cannot be loaded: %2").arg(name, QString::fromUtf8(e.what())));
        return nullptr;
    }
    rememberMachine(name);
    workspaces_->save(); // the new window opens in this workspace, as it is
    programEditor_->rememberOpenFiles(); // and with these files
    auto* w = new MainWindow(choice);
    w->setAttribute(Qt::WA_DeleteOnClose);
    w->setGeometry(geometry());
    w->keepOnScreen();
    w->show();
    session_->setRunning(false);
    close();
    return w;
}

void MainWindow::createSimulationMenu() {
    simulationMenu_ = menuBar()->addMenu(QString());
    simulationMenu_->setObjectName("menu.simulation");
    pauseAction_ = simulationMenu_->addAction(QString());
    pauseAction_->setObjectName("action.simulation.pause");
    pauseAction_->setCheckable(true);
    pauseAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Pause));
    connect(pauseAction_, &QAction::toggled, session_,
            [this](bool paused) { session_->setRunning(!paused); });
    speedMenu_ = simulationMenu_->addMenu(QString());
    auto* speeds = new QActionGroup(this);
    for (double f : {1.0, 2.0, 5.0, 10.0}) {
        QAction* a = speedMenu_->addAction(QStringLiteral("%1×").arg(f));
        a->setObjectName(QStringLiteral("action.simulation.speed%1").arg(f));
        a->setCheckable(true);
        a->setChecked(f == 1.0);
        a->setData(f);
        speeds->addAction(a);
        speedActions_ << a;
        connect(a, &QAction::triggered, session_, [this, f] { session_->setSpeed(f); });
    }
    // Faults for training: the faults this machine can show, on and off.
    faultsMenu_ = simulationMenu_->addMenu(QString());
    faultsMenu_->setObjectName("menu.simulation.faults");
    for (const machine::FaultSpec& f : session_->simulation().availableFaults()) {
        QAction* a = faultsMenu_->addAction(QString());
        a->setCheckable(true);
        a->setObjectName(QStringLiteral("action.fault.%1.%2.%3.%4")
                             .arg(QString::fromLatin1(machine::faultName(f.kind).data(),
                                                      static_cast<qsizetype>(machine::faultName(f.kind).size())))
                             .arg(f.axis == engine::AxisId::X ? "x" : "z")
                             .arg(f.detail)
                             .arg(QString::fromStdString(f.equipment)));
        faultActions_ << a;
        const machine::FaultSpec spec = f;
        connect(a, &QAction::toggled, this, [this, spec](bool on) {
            if (on)
                session_->simulation().inject(spec);
            else
                session_->simulation().clear(spec);
            session_->advance(0); // the views (the K923 too) show it at once
        });
    }
    faultsMenu_->addSeparator();
    clearFaultsAction_ = faultsMenu_->addAction(QString(), this, [this] {
        session_->simulation().clearFaults();
        session_->advance(0);
        updateFaultActions();
    });
}

void MainWindow::updateFaultActions() {
    const auto faults = session_->simulation().availableFaults();
    for (int i = 0; i < faultActions_.size(); ++i) {
        const QSignalBlocker block(faultActions_[i]);
        faultActions_[i]->setChecked(session_->simulation().faultActive(faults[static_cast<std::size_t>(i)]));
    }
}

void MainWindow::retranslate() {
    setWindowTitle(tr("K528 Studio"));
    fileMenu_->setTitle(tr("&File"));
    loadProgramsAction_->setText(tr("&Load programs..."));
    keepAction_->setText(tr("&Keep the controller's memory in the database"));
    machineMenu_->setTitle(tr("&Machine"));
    {
        const QString name = QString::fromStdString(machine_.profile.name);
        machineLabel_->setText(machine_.source.isEmpty()
                                   ? tr("Machine: %1").arg(name)
                                   : tr("Machine: %1 (%2)").arg(name, machine_.source));
        machineLabel_->setToolTip(machine_.warning);
    }
    quitAction_->setText(tr("&Quit"));
    viewMenu_->setTitle(tr("&View"));
    languageMenu_->setTitle(tr("&Language"));
    helpMenu_->setTitle(tr("&Help"));
    aboutAction_->setText(tr("&About K528 Studio"));

    workArea_->setTabText(workArea_->indexOf(programMonitor_), tr("Program"));
    workArea_->setTabText(workArea_->indexOf(programEditor_), tr("Editor"));
    k923Dock_->setWindowTitle(tr("K923 operator panel"));
    machineDock_->setWindowTitle(tr("Machine control panel"));
    messagesDock_->setWindowTitle(tr("Messages"));
    axesDock_->setWindowTitle(tr("Axes and signals"));
    debuggerDock_->setWindowTitle(tr("Debugger"));
    simulationMenu_->setTitle(tr("&Simulation"));
    pauseAction_->setText(tr("&Pause the machine"));
    speedMenu_->setTitle(tr("&Speed"));
    faultsMenu_->setTitle(tr("&Faults for training"));
    clearFaultsAction_->setText(tr("&Clear all faults"));
    const auto faults = session_->simulation().availableFaults();
    for (int i = 0; i < faultActions_.size(); ++i)
        faultActions_[i]->setText(faultTitle(faults[static_cast<std::size_t>(i)]));
    statusBar()->showMessage(machine_.warning.isEmpty() ? tr("Ready") : machine_.warning);
}

void MainWindow::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QMainWindow::changeEvent(event);
}

} // namespace k528::studio
