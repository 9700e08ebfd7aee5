#include "main_window.h"
#include "session/core_texts.h"
#include "shop/shop_view.h"

#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QFileDialog>
#include <QFile>
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
#include "controller/view_notice.h"
#include "constants/constants_lock.h"
#include "constants/constants_dock.h"
#include "database/database_ui.h"
#include "engine/self_test.h"
#include "k923/k923_widget.h"
#include "language.h"
#include "window_language.h"
#include "machine/fault_texts.h"
#include "machine/machine_panel.h"
#include "machine/status_views.h"
#include "profile/builtin.h"
#include "rparams/rparams_dock.h"
#include "monitor/program_monitor.h"
#include "scope/scope_dock.h"
#include "history/history_dock.h"
#include "training/training_pane.h"
#include "proveout/proveout_pane.h"
#include "editor/editor_tab.h"
#include "editor/program_editor.h"
#include "program/parser.h"
#include "session/shop_database.h"
#include "session/simulation_session.h"
#include "util/version.h"
#include "editor/debug_panel.h"
#include "workspace/elided_label.h"
#include "workspace/panel_scaler.h"
#include "workspace/screen_fit.h"
#include "workspace/standard_workspaces.h"
#include "workspace/workspaces.h"

#include <QCloseEvent>
#include <QPointer>
#include <memory>
#include <optional>
#include <QScrollArea>
#include <QSettings>
#include <QTimer>
#include <QWindow>

namespace k528::studio {

MainWindow::MainWindow(QWidget* parent)
    : MainWindow(MachineChoice{profile::builtin(profile::kDefaultProfile), {}, QString()},
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
    viewed_ = new ViewedController(*simController_, this);
    programMonitor_ = new ProgramMonitor(*simController_, workArea_);
    workArea_->addTab(programMonitor_, QString());
    programEditor_ = new EditorTab(viewed_, workArea_);
    workArea_->addTab(programEditor_, QString());
    connect(programEditor_, &EditorTab::statusMessage, this, [this](const QString& m) { statusBar()->showMessage(m, 10000); });
    createDocks();
    // The Shop workspace's page (shop/shop_view.cpp): after the Controller
    // dock, which a click on a machine's tile connects.
    shopView_ = new ShopView(this);
    workArea_->addTab(shopView_, QString());
    connect(viewed_, &ViewedController::changed, this, &MainWindow::viewedChanged);
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
    // The machine's label stretches over the bar: while a message is shown
    // (a refused key, the trainer's lock) it steps aside for it.
    connect(statusBar(), &QStatusBar::messageChanged, machineLabel_,
            [this](const QString& m) { machineLabel_->setVisible(m.isEmpty()); });
    installDatabaseUi(this, fileMenu_, machineMenu_->menuAction()); // database/database_ui.cpp
    setProperty("k528.machineName", QString::fromStdString(machine_.profile.name)); // File > Transfers… opens on it
    // File > Database…: the machine's label names the new database (the
    // history dock records into it: history/history_dock.cpp).
    connect(DatabaseWatch::instance(), &DatabaseWatch::switched, this, &MainWindow::followDatabase);
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

MainWindow::~MainWindow() {
    // The children go in the order they were made: the simulated controller
    // and the view switch before the docks. A real controller still viewed
    // would be destroyed among the docks, after them.
    if (auto* c = findChild<ControllerDock*>("dock.controller"))
        c->closeLine();
}

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
    k923_->setDisplay(simController_->state().display);
    k923Dock_->setWidget(k923_);
    connect(k923_, &K923Widget::keyPressed, this, [this](panel::KeyPress k) {
        Controller& c = viewed_->current();
        // The trainer's lock: the simulated K923's C-parameter editing refused, the lock named.
        if (c.simulated())
            if (const QString why = ConstantsLock::of(machine_.profile)->refusesKey(c.state(), k); !why.isEmpty()) {
                statusBar()->showMessage(why, 10000);
                return;
            }
        if (c.acceptsKeys())
            c.pressKey(k); // updated() redraws the panel
        else
            statusBar()->showMessage(tr("The controller on the link takes no keys: press them on its own K923"), 5000);
    });
    connect(simController_, &Controller::updated, k923_, [this] {
        if (viewed_->isSimulated())
            k923_->setDisplay(simController_->state().display);
    });
    machineDock_ = addDock("dock.machine", Qt::RightDockWidgetArea);
    delete machineDock_->widget();
    auto* scroll = new QScrollArea(machineDock_);
    scroll->setObjectName("machinePanelScroll");
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    machinePanel_ = new MachinePanelWidget(*session_, scroll);
    scroll->setWidget(machinePanel_);
    // The panel is the simulated machine's: greyed, with the reason, while a
    // real controller is shown.
    machineNotice_ = new ViewNotice(scroll, machineDock_);
    machineNotice_->follow(*viewed_, [](Controller& c) -> std::pair<ViewNotice::Level, QString> {
        if (c.simulated())
            return {ViewNotice::Level::None, {}};
        return {ViewNotice::Level::Unavailable,
                tr("This control panel is the simulated machine's: the controller on the line is worked from its "
                   "own machine's panel (its state is in the other views).")};
    });
    machineDock_->setWidget(machineNotice_);
    // The panel scales to its dock (it scrolls only below 60 %).
    new PanelScaler(scroll, [this](QSize room) { machinePanel_->fitTo(room); });
    // The machine's panel beside the K923, as on the shop floor.
    splitDockWidget(k923Dock_, machineDock_, Qt::Horizontal);
    messagesDock_ = addDock("dock.messages", Qt::BottomDockWidgetArea);
    delete messagesDock_->widget();
    messagesView_ = new MessagesView(*simController_, messagesDock_);
    messagesDock_->setWidget(messagesView_);
    axesDock_ = addDock("dock.axes", Qt::BottomDockWidgetArea);
    delete axesDock_->widget();
    axesView_ = new AxesView(*simController_, axesDock_);
    axesDock_->setWidget(axesView_);
    tabifyDockWidget(messagesDock_, axesDock_);
    messagesDock_->raise();
    QDockWidget* backplotDock = backplot::addBackplotDock(this, *viewed_); // backplot/backplot_dock.cpp
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
            if (const program::Program* p = viewed_->current().programs().find(program))
                for (std::size_t i = 0; i < p->frames.size(); ++i)
                    if (p->frames[i].span.line == line)
                        programMonitor_->frames()->setCurrentRow(static_cast<int>(i));
            workArea_->setCurrentWidget(programMonitor_);
        });
        connect(programEditor_, &EditorTab::cursorLineChanged, bp, &backplot::BackplotWidget::selectLine);
    }
    addScopeDock(this, *viewed_);
    addControllerDock(this); // controller/controller_dock.cpp: the Controller menu and dock
    addConstantsDock(this, *viewed_, machine_.profile); // constants/constants_dock.cpp
    addRParamsDock(this, *viewed_, machine_.profile);   // rparams/rparams_dock.cpp
    addHistoryDock(this, *viewed_);                     // history/history_dock.cpp
    // The training course (training/training_pane.cpp): grades the editor's
    // program; a deduction clicked puts the editor on its frame's line.
    QDockWidget* training = addTrainingDock(this, [this]() -> std::pair<QString, QString> {
        ProgramEditor* ed = programEditor_->currentEditor();
        if (!ed)
            return {};
        for (int i = 0; i < programEditor_->documentCount(); ++i)
            if (programEditor_->editorAt(i) == ed)
                return {ed->text(), QFileInfo(programEditor_->pathOf(i)).fileName()};
        return {ed->text(), QString()};
    });
    connect(static_cast<TrainingPane*>(training->widget()), &TrainingPane::lineActivated, programEditor_,
            &EditorTab::showLine);
    static_cast<TrainingPane*>(training->widget())->setMachine(machine_.profile); // the trainer's lock of its constants
    tabifyDockWidget(backplotDock, training); // its home: a tab of the backplot, not one more row
    QDockWidget* proveoutDock = addProveoutDock(this, programEditor_, workArea_); // proveout/proveout_pane.cpp
    auto* prover = proveoutDock->findChild<ProveoutPane*>();
    if (auto* bp = backplotDock->findChild<backplot::BackplotWidget*>(); bp && prover) {
        // The findings of the editor's file as red markers at their places
        // on the backplot's path (those of the program it shows), a finding
        // activated in the Problems list ringed.
        const auto markFindings = [bp, prover] {
            std::vector<k528::backplot::BackplotScene::FindingMarker> markers;
            for (const proveout::Finding& f : prover->findings())
                markers.push_back({f.program, f.line, f.at.z, f.at.x});
            bp->setFindings(markers);
        };
        connect(prover, &ProveoutPane::proved, bp, markFindings);
        connect(programEditor_, &EditorTab::proveoutFindingActivated, bp, &backplot::BackplotWidget::highlightFinding);
    }
    // The debugger of the editor in a dock of its own (the technologist
    // shows it on demand).
    debuggerDock_ = addDock("dock.debugger", Qt::RightDockWidgetArea);
    if (DebugPanel* debug = programEditor_->debugPanel()) {
        delete debuggerDock_->widget();
        // Out of the editor's splitter; it steps programs on the simulated
        // machine only, which it says while a real controller is shown.
        debuggerNotice_ = new ViewNotice(debug, debuggerDock_);
        debuggerNotice_->follow(*viewed_, [](Controller& c) -> std::pair<ViewNotice::Level, QString> {
            if (c.simulated())
                return {ViewNotice::Level::None, {}};
            return {ViewNotice::Level::Unavailable,
                    tr("The debugger steps programs on the simulated machine; the controller on the line runs "
                       "them itself. Show the simulation again (Controller dock) to debug.")};
        });
        debuggerDock_->setWidget(debuggerNotice_);
    }
    // A content that cannot shrink scrolls inside its dock rather than
    // widen the window (the K923 and the machine's panel scale instead).
    for (QDockWidget* d : findChildren<QDockWidget*>(QString(), Qt::FindDirectChildrenOnly))
        if (d != k923Dock_ && d != machineDock_ && d != messagesDock_) {
            if (auto* notice = qobject_cast<ViewNotice*>(d->widget()))
                notice->scrollContent(); // the notice stays in view above it
            else
                scrollInside(d);
        }
}

Controller* MainWindow::viewedController() const { return &viewed_->current(); }

void MainWindow::setViewedController(Controller* controller) { viewed_->set(controller); }

void MainWindow::viewedChanged() {
    Controller& c = viewed_->current();
    disconnect(k923Updates_);
    if (&c != simController_)
        k923Updates_ = connect(&c, &Controller::updated, k923_, [this] { k923_->setDisplay(viewed_->current().state().display); });
    k923_->setDisplay(c.state().display);
    programMonitor_->setController(c);
    messagesView_->setController(c);
    axesView_->setController(c);
    // A lost line: the views without a notice of their own say it in their titles.
    disconnect(staleWatch_);
    staleWatch_ = connect(&c, &Controller::updated, this, [this] {
        if (viewed_->current().stale() != shownStale_)
            retranslate();
    });
    retranslate();
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
    for (const char* name : {"dock.constants", "dock.rparams", "dock.training"})
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
    (russianWindow() ? russianAction_ : englishAction_)->setChecked(true);
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
    const QString file = QFileInfo(path).fileName();
    std::string text;
    QString m;
    if (!readTextFile(path, text, m)) { // why in the window's language
        QMessageBox::warning(this, tr("Load programs"), m);
        emit programsLoaded(false, m);
        return false;
    }
    QStringList names;
    for (const program::Program* p : program::parse(text).store.inWrittenOrder())
        names << QStringLiteral("L%1").arg(p->number);
    // Into the controller shown, with its rules (checked first; a real one
    // takes each program whole or not at all).
    auto result = std::make_shared<int>(-1);
    QPointer<MainWindow> self(this);
    viewed_->current().loadPrograms(text, file, [self, result, names, file](bool ok, const QString& message) {
        *result = ok ? 1 : 0;
        if (!self)
            return;
        const QStringList findings = message.isEmpty() ? QStringList() : message.split(QLatin1Char('\n'));
        if (ok && findings.isEmpty()) {
            const QString m = tr("Loaded %1 from %2").arg(names.join(", "), file);
            self->statusBar()->showMessage(m, 10000);
            emit self->programsLoaded(true, m);
            return;
        }
        QMessageBox box(ok ? QMessageBox::Information : QMessageBox::Warning, tr("Load programs"),
                        ok ? tr("Loaded %1 from %2, with warnings.").arg(names.join(", "), file) : findings.value(0),
                        QMessageBox::Ok, self);
        box.setObjectName("programLoadReport");
        const QStringList details = ok ? findings : findings.mid(1);
        box.setDetailedText(details.join('\n'));
        if (!details.isEmpty())
            box.setInformativeText(details.mid(0, 5).join('\n'));
        emit self->programsLoaded(ok, box.text());
        box.exec();
    });
    return *result != 0;
}

int MainWindow::keepInDatabase() {
    auto result = std::make_shared<int>(-1);
    QPointer<MainWindow> self(this);
    viewed_->current().readMemory([self, result](bool ok, const QString& why, const profile::MachineProfile& p) {
        *result = 0;
        if (!self)
            return;
        const QString name = QString::fromStdString(p.name.empty() ? self->machine_.profile.name : p.name);
        if (!ok) {
            const QString m = tr("The memory of %1 was not kept: %2").arg(name, why);
            emit self->memoryKept(0, m);
            QMessageBox::warning(self, tr("Keep in the database"), m);
            return;
        }
        const MachineSave s = saveMachine(p);
        if (s.revision == 0) {
            const QString m = tr("The memory of %1 was not kept: %2").arg(name, s.error);
            emit self->memoryKept(0, m);
            QMessageBox::warning(self, tr("Keep in the database"), m);
            return;
        }
        *result = s.revision;
        const QString m = s.changes == 0
                              ? tr("%1: the database already holds this memory (revision %2)").arg(name).arg(s.revision)
                              : tr("%1 kept in the database as revision %2 (%3 changes)")
                                    .arg(name)
                                    .arg(s.revision)
                                    .arg(s.changes);
        self->statusBar()->showMessage(m, 10000);
        emit self->memoryKept(s.revision, m);
    });
    if (*result < 0)
        statusBar()->showMessage(tr("Reading the controller's memory to keep it in the database..."), 10000);
    return std::max(0, *result);
}

void MainWindow::updateMachineLabel() {
    const QString name = machineTitle(machine_.profile);
    // A machine of the database open (followDatabase): the status line's
    // database label beside it names the database, once; elsewhere from
    // (built-in, a file, not in the database open) is said here.
    const QString source =
        machine_.source.kind == MachineSource::Kind::Database ? QString() : machine_.source.text();
    machineLabel_->setText(source.isEmpty() ? tr("Machine: %1").arg(name) : tr("Machine: %1 (%2)").arg(name, source));
    machineLabel_->setToolTip(machine_.warning.isEmpty() ? machine_.source.text() : machine_.warning);
}

void MainWindow::followDatabase() {
    const std::string name = machine_.profile.name;
    const QString where = ShopDatabase::currentText();
    try {
        const auto found = ShopDatabase::at()->use([&](db::Database& d) -> std::optional<QString> {
            if (!d.hasMachine(name))
                return std::nullopt;
            return QString::fromStdString(d.path().string());
        });
        if (found) {
            // As a start on this database names it (session/machine_source.cpp).
            machine_.source = {MachineSource::Kind::Database, *found};
            machine_.warning.clear();
        } else {
            machine_.source = {MachineSource::Kind::NotInDatabase, where};
            machine_.warning = tr("The database %1 has no machine %2: it runs as it was loaded; File > Machine "
                                  "offers this database's machines")
                                   .arg(where, QString::fromStdString(name));
        }
    } catch (const std::exception& e) {
        machine_.source = {MachineSource::Kind::NotInDatabase, where};
        machine_.warning = databaseErrorText(e);
    }
    updateMachineLabel();
}

void MainWindow::fillMachineMenu() {
    machineMenu_->clear();
    QString warning;
    for (const TitledMachine& m : titledMachines(&warning)) {
        const QString n = m.name;
        QAction* a = machineMenu_->addAction(m.title);
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
                             tr("The machine %1 cannot be loaded: %2").arg(name, coreErrorText(e)));
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
    setWindowTitle(databaseWindowTitle());
    fileMenu_->setTitle(tr("&File"));
    loadProgramsAction_->setText(tr("&Load programs..."));
    keepAction_->setText(tr("&Keep the controller's memory in the database"));
    machineMenu_->setTitle(tr("&Machine"));
    updateMachineLabel();
    quitAction_->setText(tr("&Quit"));
    viewMenu_->setTitle(tr("&View"));
    languageMenu_->setTitle(tr("&Language"));
    helpMenu_->setTitle(tr("&Help"));
    aboutAction_->setText(tr("&About K528 Studio"));

    shownStale_ = viewed_->current().stale();
    const QString stale = shownStale_ ? tr(" — stale since %1").arg(viewed_->current().lostSince().toString("HH:mm:ss"))
                                      : QString();
    workArea_->setTabText(workArea_->indexOf(programMonitor_), tr("Program") + stale);
    workArea_->setTabText(workArea_->indexOf(programEditor_), tr("Editor"));
    workArea_->setTabText(workArea_->indexOf(shopView_), tr("Shop"));
    k923Dock_->setWindowTitle((viewed_->isSimulated() ? tr("K923 operator panel")
                                                      : tr("K923: LEDs only (no LCD text or keys over the link)")) +
                              stale);
    k923_->setToolTip(viewed_->isSimulated() ? QString()
                                             : tr("The controller on the line: its K LEDs and override as it shows "
                                                  "them; its LCD text and keys are not on the link — use its own K923"));
    machineDock_->setWindowTitle(tr("Machine control panel"));
    messagesDock_->setWindowTitle(tr("Messages") + stale);
    axesDock_->setWindowTitle(tr("Axes and signals") + stale);
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
