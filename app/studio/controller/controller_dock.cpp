#include "controller/controller_dock.h"
#include "session/file_problem.h"
#include "session/core_texts.h"

#include "controller/link_controller.h"
#include "controller/push_preview.h"
#include "controller/controller.h"
#include "session/catalog_texts.h"
#include "link_plugins.h"
#include "main_window.h"
#include "profile/diff.h"
#include "profile/text_format.h"
#include "program/formatter.h"
#include "program/parser.h"
#include "session/machine_source.h"
#include "shop/shop_machines.h"
#include "units/units.h"
#include "widgets.h"
#include "workspace/flow_layout.h"

#include <utility>
#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPointer>
#include <QPushButton>
#include <QSaveFile>
#include <QScrollArea>
#include <QTimer>
#include <QSpinBox>
#include <QStatusBar>
#include <QVBoxLayout>

namespace k528::studio {

namespace {

QString fromStd(const std::string& s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }

// A port as a label shows it: a long path (/dev/serial/by-id/usb-FTDI_…-port0)
// may break after its separators (a zero-width space there), so a message
// naming it wraps in a narrow dock instead of being cut at its edge.
QString breakablePort(const QString& port) {
    QString out;
    out.reserve(port.size() + 16);
    for (const QChar c : port) {
        out += c;
        if (c == QLatin1Char('/') || c == QLatin1Char('_') || c == QLatin1Char('-') || c == QLatin1Char('.'))
            out += QChar(0x200B);
    }
    return out;
}

QString dot(bool on, const char* color) {
    return QStringLiteral("<span style='color:%1'>●</span>").arg(on ? QString::fromLatin1(color) : QStringLiteral("#b9bdc1"));
}

QString mm(std::int64_t disc, const units::AxisScale& s) { return fromStd(units::formatDisc(disc, s)); }

} // namespace

ControllerDock* addControllerDock(MainWindow* window) {
    auto* dock = new ControllerDock(window);
    window->addDockWidget(Qt::RightDockWidgetArea, dock);
    if (QDockWidget* machine = window->machineDock())
        window->tabifyDockWidget(machine, dock);
    if (QDockWidget* machine = window->machineDock())
        machine->raise();
    return dock;
}

ControllerDock::ControllerDock(MainWindow* window) : PaneDock(window, "controller"), window_(window) {
    for (const linkplugin::Found& f : linkplugin::discover()) {
        if (f.plugin) {
            plugins_.push_back(f.plugin);
            // The plugin's name and version: its own words (its transport's
            // description is English metadata, not a text of this window).
            pluginNames_ << QStringLiteral("%1 %2").arg(f.name, f.version);
            pluginIds_ << f.name;
        } else {
            pluginProblem_ += QStringLiteral("%1: %2\n").arg(f.file, f.refused);
        }
    }
    build();
    refreshMachines();
    retranslate();
    refreshPorts();
    updateEnabled();
}

ControllerDock::~ControllerDock() = default;

void ControllerDock::build() {
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    // The texts wrap to the dock's width; a dock made narrower than its form
    // scrolls sideways rather than cutting the buttons at its edge.
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    auto* body = new QWidget(scroll);
    auto* lay = new QVBoxLayout(body);
    lay->setContentsMargins(6, 6, 6, 6);

    lineBox_ = new QGroupBox(body);
    auto* form = new QFormLayout(lineBox_);
    plugin_ = new QComboBox(lineBox_);
    plugin_->setObjectName("controller.plugin");
    plugin_->addItems(pluginNames_);
    machine_ = new QComboBox(lineBox_);
    machine_->setObjectName("controller.machine");
    machine_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    machine_->setMinimumContentsLength(14);
    connect(machine_, &QComboBox::activated, this, [this] { machineChosen(); });
    connect(plugin_, &QComboBox::currentIndexChanged, this, [this] { pluginChosen(); });
    port_ = new QComboBox(lineBox_);
    port_->setObjectName("controller.port");
    port_->setEditable(true); // a pty or a port the system does not list
    for (QComboBox* c : {plugin_, port_}) {
        c->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        c->setMinimumContentsLength(14);
    }
    refreshPorts_ = new QPushButton(lineBox_);
    refreshPorts_->setObjectName("controller.refreshPorts");
    auto* portRow = new QHBoxLayout;
    portRow->addWidget(port_, 1);
    portRow->addWidget(refreshPorts_);
    baud_ = new QComboBox(lineBox_);
    baud_->setObjectName("controller.baud");
    for (int b : {9600, 19200, 38400, 57600, 115200})
        baud_->addItem(QString::number(b), b);
    baud_->setCurrentIndex(baud_->count() - 1); // the manual's 115 200 (section 3.2)
    parity_ = new QComboBox(lineBox_);
    parity_->setObjectName("controller.parity");
    parity_->addItem(QString(), QChar('N'));
    parity_->addItem(QString(), QChar('E'));
    parity_->addItem(QString(), QChar('O'));
    address_ = new QSpinBox(lineBox_);
    address_->setObjectName("controller.address");
    address_->setRange(1, 247);
    address_->setValue(1);
    connect_ = new QPushButton(lineBox_);
    connect_->setObjectName("controller.connect");
    connect(connect_, &QPushButton::clicked, this, [this] {
        if (link_)
            disconnectLine();
        else
            connectLine();
    });
    connect(refreshPorts_, &QPushButton::clicked, this, &ControllerDock::refreshPorts);
    for (int i = 0; i < 6; ++i)
        captions_[i] = new QLabel(lineBox_);
    form->addRow(captions_[5], machine_);
    form->addRow(captions_[0], plugin_);
    form->addRow(captions_[1], portRow);
    form->addRow(captions_[2], baud_);
    form->addRow(captions_[3], parity_);
    form->addRow(captions_[4], address_);
    form->addRow(connect_);
    lineState_ = new QLabel(lineBox_);
    lineState_->setObjectName("controller.lineState");
    lineState_->setWordWrap(true);
    form->addRow(lineState_);
    lay->addWidget(lineBox_);

    // The transfer buttons wrap onto a second row in a narrow dock (a shop
    // PC's 1366 px): each stays whole and reachable, none is cut at the edge.
    auto* buttonRow = new QWidget(body);
    buttonRow->setObjectName("controller.buttons");
    auto* buttons = new FlowLayout(buttonRow, 6, 4);
    pull_ = new QPushButton(body);
    pull_->setObjectName("controller.pull");
    push_ = new QPushButton(body);
    push_->setObjectName("controller.push");
    connect(pull_, &QPushButton::clicked, this, &ControllerDock::pullIntoDatabase);
    connect(push_, &QPushButton::clicked, this, [this] { pushFile(); });
    buttons->addWidget(pull_);
    buttons->addWidget(push_);
    frames_ = new QPushButton(body);
    frames_->setObjectName("controller.saveFrames");
    connect(frames_, &QPushButton::clicked, this, [this] { saveFrameLog(); });
    buttons->addWidget(frames_);
    lay->addWidget(buttonRow);
    auto* prog = new QHBoxLayout;
    progress_ = new QProgressBar(body);
    progress_->setObjectName("controller.progress");
    progress_->setRange(0, 1);
    progress_->setValue(0);
    progress_->setTextVisible(true);
    progress_->setFormat(QString());
    cancel_ = new QPushButton(body);
    cancel_->setObjectName("controller.cancel");
    connect(cancel_, &QPushButton::clicked, this, &ControllerDock::cancelTransfer);
    prog->addWidget(progress_, 1);
    prog->addWidget(cancel_);
    lay->addLayout(prog);
    transfer_ = new QLabel(body);
    transfer_->setObjectName("controller.transfer");
    transfer_->setWordWrap(true);
    lay->addWidget(transfer_);
    showOnViews_ = new QCheckBox(body);
    showOnViews_->setObjectName("controller.showOnViews");
    showOnViews_->setChecked(true);
    connect(showOnViews_, &QCheckBox::toggled, this, [this](bool on) {
        window_->setViewedController(on && link_ && link_->isOpen() ? link_.get() : nullptr);
    });
    lay->addWidget(showOnViews_);

    monitorBox_ = new QGroupBox(body);
    auto* mlay = new QVBoxLayout(monitorBox_);
    monitor_ = new QLabel(monitorBox_);
    monitor_->setObjectName("controller.monitor");
    monitor_->setTextFormat(Qt::RichText);
    monitor_->setWordWrap(true);
    monitor_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    monitor_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    mlay->addWidget(monitor_);
    lay->addWidget(monitorBox_, 1);
    lay->addStretch();
    scroll->setWidget(body);
    setWidget(scroll);

    menu_ = new QMenu(this);
    menu_->setObjectName("menu.controller");
    // The menu asks for the line (the dock's form), it does not connect to
    // whatever port the system lists first.
    connectAction_ = menu_->addAction(QString(), this, &ControllerDock::askForLine);
    connectAction_->setObjectName("action.controller.connect");
    // The database's machines with their stored line: one click connects.
    connectMachineMenu_ = menu_->addMenu(QString());
    connectMachineMenu_->setObjectName("menu.controller.connectMachine");
    connect(connectMachineMenu_, &QMenu::aboutToShow, this, [this] {
        connectMachineMenu_->clear();
        const std::vector<ShopMachine> all = shopMachines();
        for (const ShopMachine& m : all)
            connectMachineMenu_
                ->addAction(QStringLiteral("%1 — %2").arg(m.name, QString::fromStdString(m.line)), this,
                            [this, n = m.name] { connectMachine(n); })
                ->setObjectName("action.controller.connect." + m.name);
        if (all.empty())
            connectMachineMenu_->addAction(tr("No machine of the database has a line"))->setEnabled(false);
    });
    disconnectAction_ = menu_->addAction(QString(), this, &ControllerDock::disconnectLine);
    disconnectAction_->setObjectName("action.controller.disconnect");
    menu_->addSeparator();
    pullAction_ = menu_->addAction(QString(), this, &ControllerDock::pullIntoDatabase);
    pullAction_->setObjectName("action.controller.pull");
    pushFileAction_ = menu_->addAction(QString(), this, [this] { pushFile(); });
    pushFileAction_->setObjectName("action.controller.pushFile");
    pushMachineMenu_ = menu_->addMenu(QString());
    pushMachineMenu_->setObjectName("menu.controller.pushMachine");
    connect(pushMachineMenu_, &QMenu::aboutToShow, this, [this] {
        pushMachineMenu_->clear();
        for (const TitledMachine& m : titledMachines()) {
            const QString n = m.name;
            pushMachineMenu_->addAction(m.title, this, [this, n] { pushMachine(n); })->setObjectName("action.controller.push." + n);
        }
    });
    menu_->addSeparator();
    clearCAction_ = menu_->addAction(QString(), this, [this] { clearMemory(MemoryArea::C); });
    clearCAction_->setObjectName("action.controller.clearC");
    clearRAction_ = menu_->addAction(QString(), this, [this] { clearMemory(MemoryArea::R); });
    clearRAction_->setObjectName("action.controller.clearR");
    menu_->addSeparator();
    menu_->addAction(toggleViewAction());
}

void ControllerDock::retranslate() {
    setWindowTitle(tr("Controller"));
    menu_->setTitle(tr("&Controller"));
    connectAction_->setText(tr("&Connect to the controller"));
    connectMachineMenu_->setTitle(tr("Connect to a database &machine"));
    disconnectAction_->setText(tr("&Disconnect"));
    pullAction_->setText(tr("&Pull into the database"));
    pushFileAction_->setText(tr("Push a &file..."));
    pushMachineMenu_->setTitle(tr("Push a database &machine"));
    clearCAction_->setText(tr("Clear the C area (all constants 0)..."));
    clearRAction_->setText(tr("Clear the R area (all R-parameters 0)..."));
    lineBox_->setTitle(tcpChosen() ? tr("Line (Modbus TCP)") : tr("Line (RS485, Modbus RTU)"));
    monitorBox_->setTitle(tr("Live monitor"));
    captions_[0]->setText(tr("Plugin"));
    captions_[1]->setText(tcpChosen() ? tr("Host:port") : tr("Port"));
    captions_[2]->setText(tr("Baud"));
    captions_[3]->setText(tr("Parity"));
    captions_[4]->setText(tcpChosen() ? tr("Unit id") : tr("Address"));
    captions_[5]->setText(tr("Machine"));
    if (machine_->count() > 0)
        machine_->setItemText(0, tr("(the line below)"));
    machine_->setToolTip(tr("The machines of the database that keep their controller's line"));
    setItemTexts(parity_, {tr("none"), tr("even"), tr("odd")});
    refreshPorts_->setText(tr("Ports"));
    refreshPorts_->setToolTip(tr("List the system's serial ports and the database's machines again"));
    pull_->setText(tr("Pull into the database"));
    push_->setText(tr("Push a file..."));
    cancel_->setText(tr("Cancel"));
    frames_->setText(tr("Frame log..."));
    frames_->setToolTip(tr("Save every frame of the line (time, direction, bytes, CRC) to a file"));
    showOnViews_->setText(tr("Show it on every view of the window"));
    lastMonitor_.clear();
    updateEnabled();
    updateLine();
    updateMonitor();
}

bool ControllerDock::tcpChosen() const {
    const int i = plugin_->currentIndex();
    return i >= 0 && i < pluginIds_.size() && pluginIds_[i] == QLatin1String("modbus-tcp");
}

void ControllerDock::pluginChosen() {
    if (!machine_ || !lineBox_)
        return;
    refreshPorts();
    retranslate();
}

void ControllerDock::refreshMachines() {
    const QString current = machine_->currentData().toString();
    machine_->clear();
    machine_->addItem(tr("(the line below)"), QString());
    for (const ShopMachine& m : shopMachines()) {
        machine_->addItem(QStringLiteral("%1 — %2").arg(m.name, QString::fromStdString(m.line)), m.name);
        machine_->setItemData(machine_->count() - 1, QString::fromStdString(m.line), Qt::UserRole + 1);
    }
    const int i = machine_->findData(current);
    machine_->setCurrentIndex(std::max(0, i));
}

void ControllerDock::machineChosen() {
    const QString line = machine_->currentData(Qt::UserRole + 1).toString();
    if (line.isEmpty())
        return;
    std::string error;
    const auto a = profile::parseLine(line.toStdString(), error);
    if (!a)
        return;
    const bool tcp = a->kind == profile::LineAddress::Kind::Tcp;
    const int p = pluginIds_.indexOf(tcp ? QStringLiteral("modbus-tcp") : QStringLiteral("modbus-rtu"));
    if (p >= 0)
        plugin_->setCurrentIndex(p);
    port_->setEditText(QString::fromStdString(profile::lineEndpoint(*a)));
    if (!tcp) {
        baud_->setCurrentIndex(std::max(0, baud_->findData(a->baud)));
        parity_->setCurrentIndex(std::max(0, parity_->findData(QChar(a->parity))));
    }
    address_->setValue(a->address);
}

bool ControllerDock::connectMachine(const QString& name) {
    refreshMachines();
    const int i = machine_->findData(name);
    if (i <= 0)
        return false;
    if (link_) {
        if (link_->busy() || connecting_)
            return false;
        if (connectedMachine_ == name && link_->isOpen()) {
            if (showOnViews_->isChecked())
                window_->setViewedController(link_.get());
            return true;
        }
        closeLine();
    }
    machine_->setCurrentIndex(i);
    machineChosen();
    connectLine();
    return link_ != nullptr;
}

void ControllerDock::refreshPorts() {
    const QString current = port_->currentText();
    port_->clear();
    const int i = plugin_->currentIndex();
    if (i >= 0 && i < static_cast<int>(plugins_.size()))
        port_->addItems(plugins_[static_cast<std::size_t>(i)]->ports());
    if (!current.isEmpty())
        port_->setEditText(current);
}

void ControllerDock::updateEnabled() {
    const bool open = link_ && link_->isOpen();
    const bool busy = open && link_->busy();
    const bool havePlugin = !plugins_.empty();
    connect_->setText(link_ ? tr("Disconnect") : tr("Connect"));
    connect_->setEnabled(havePlugin && !connecting_ && !busy);
    for (QWidget* w : {static_cast<QWidget*>(plugin_), static_cast<QWidget*>(port_), static_cast<QWidget*>(baud_),
                       static_cast<QWidget*>(parity_), static_cast<QWidget*>(address_),
                       static_cast<QWidget*>(machine_)})
        w->setEnabled(havePlugin && !link_);
    // Modbus TCP: the gateway's HOST:PORT and the unit id; no serial settings.
    baud_->setEnabled(baud_->isEnabled() && !tcpChosen());
    parity_->setEnabled(parity_->isEnabled() && !tcpChosen());
    connectAction_->setEnabled(havePlugin && !link_);
    disconnectAction_->setEnabled(link_ && !busy);
    for (QWidget* w : {static_cast<QWidget*>(pull_), static_cast<QWidget*>(push_)})
        w->setEnabled(open && !busy && !preview_);
    pullAction_->setEnabled(open && !busy && !preview_);
    pushFileAction_->setEnabled(open && !busy && !preview_);
    pushMachineMenu_->setEnabled(open && !busy && !preview_);
    cancel_->setEnabled(busy);
    frames_->setEnabled(link_ != nullptr && !connecting_);
    if (!havePlugin)
        lineState_->setText(tr("No controller-link plugin was found (searched: %1). %2")
                                .arg(linkplugin::searchPath().join(", "), pluginProblem_.trimmed()));
}

void ControllerDock::say(const QString& given) {
    // A transfer that could not go on record says so with its own words.
    const QString text = notOnRecord_.isEmpty() ? given : given + QStringLiteral(" — ") + std::exchange(notOnRecord_, {});
    lastMessage_ = text;
    transfer_->setText(text);
    transfer_->setToolTip(text);
    window_->statusBar()->showMessage(text, 15000);
}

void ControllerDock::connectLine() {
    if (link_ || plugins_.empty())
        return;
    const int i = std::max(0, plugin_->currentIndex());
    linkplugin::LineSettings s;
    s.port = port_->currentText().trimmed();
    if (s.port.isEmpty()) {
        say(tcpChosen() ? tr("Enter the gateway's HOST:PORT.")
                        : tr("Choose the serial port the controller is on."));
        return;
    }
    // The database's machine chosen: its line as stored, its texts and names.
    connectedMachine_ = machine_->currentData().toString();
    profile::MachineProfile machine = window_->machine().profile;
    if (!connectedMachine_.isEmpty()) {
        try {
            machine = loadMachine(connectedMachine_).profile;
        } catch (const std::exception&) {
            // the window's machine gives the texts
        }
    }
    s.baud = baud_->currentData().toInt();
    s.parity = parity_->currentData().toChar().toLatin1();
    s.address = address_->value();
    link_ = std::make_unique<LinkController>(*plugins_[static_cast<std::size_t>(i)], s, machine);
    connecting_ = true;
    LinkController* l = link_.get();
    connect(l, &LinkController::opened, this, [this](bool ok, const QString& error) {
        connecting_ = false;
        if (!ok) {
            const QString port = link_->line().port;
            say(tr("No connection on %1: %2").arg(port, error));
            // Not «Connecting…» any more; the whole text wraps (and is the tooltip).
            const QString shown = QString(lastMessage_).replace(port, breakablePort(port));
            lineState_->setText(shown);
            lineState_->setToolTip(lastMessage_);
            transfer_->setText(shown);
            link_.reset();
            connectedMachine_.clear();
            updateEnabled();
            emit connectedChanged(false);
            return;
        }
        say(tr("Connected: %1").arg(link_->description()));
        if (showOnViews_->isChecked())
            window_->setViewedController(link_.get());
        updateEnabled();
        emit connectedChanged(true);
    });
    connect(l, &LinkController::updated, this, &ControllerDock::updateMonitor);
    connect(l, &LinkController::lineChanged, this, &ControllerDock::updateLine);
    connect(l, &LinkController::lost, this, [this](const QString& why) {
        lostWhy_ = why;
        updateMonitor(); // the last values, marked stale
        updateLine();
    });
    connect(l, &LinkController::progress, this, [this](const QString& what, int done, int total) {
        progress_->setRange(0, std::max(1, total));
        progress_->setValue(std::min(done, std::max(1, total)));
        progress_->setFormat(what + QStringLiteral(" (%v/%m)"));
    });
    connect(l, &LinkController::pulled, this, [this](bool ok, const QString& message, const profile::MachineProfile& memory) {
        progress_->setRange(0, 1);
        progress_->setValue(ok ? 1 : 0);
        progress_->setFormat(ok ? tr("memory read") : tr("stopped"));
        if (pending_) { // a push waits for its preview
            if (!ok) {
                pending_.reset();
                say(tr("The push did not start: the controller's memory could not be read (%1); nothing was sent").arg(message));
                emit transferFinished(false, lastMessage_);
            } else {
                showPreview(memory);
            }
            updateEnabled();
            return;
        }
        if (!ok) {
            say(tr("Pull failed: %1").arg(message));
            updateEnabled();
            emit transferFinished(false, lastMessage_);
            return;
        }
        const MachineSave s = saveMachine(memory);
        const QString name = fromStd(memory.name);
        if (s.revision == 0)
            say(tr("Pulled, but not kept in the database: %1").arg(s.error));
        else if (s.changes == 0)
            say(tr("Pulled %1 programs; the database already holds this memory of %2 (revision %3)")
                    .arg(memory.programs.size())
                    .arg(name)
                    .arg(s.revision));
        else
            say(tr("Pulled %1 programs into %2, revision %3 (%4 changes)")
                    .arg(memory.programs.size())
                    .arg(name)
                    .arg(s.revision)
                    .arg(s.changes));
        lastRevision_ = s.revision;
        updateEnabled();
        emit transferFinished(s.revision != 0, lastMessage_);
    });
    connect(l, &LinkController::transferRecorded, this, [this](bool ok, const QString& message) {
        if (!ok) // said with the transfer's own words, which follow at once
            notOnRecord_ = message;
    });
    connect(l, &LinkController::pushed, this, [this](bool ok, const QString& message, const QStringList& written) {
        progress_->setRange(0, 1);
        progress_->setValue(ok ? 1 : 0);
        progress_->setFormat(ok ? tr("pushed") : tr("stopped"));
        const QString done = written.isEmpty() ? tr("nothing") : written.join(", ");
        say(ok ? tr("Pushed %1: written and verified %2").arg(pendingWhat_, done)
               : tr("Push of %1 stopped: %2. Written and verified before: %3").arg(pendingWhat_, message, done));
        updateEnabled();
        emit transferFinished(ok, lastMessage_);
    });
    updateEnabled();
    lineState_->setText(tr("Connecting to %1...").arg(breakablePort(s.port)));
    lineState_->setToolTip(QString());
    l->open();
}

void ControllerDock::askForLine() {
    show();
    raise();
    if (link_)
        return;
    port_->setFocus(Qt::OtherFocusReason);
    if (port_->lineEdit())
        port_->lineEdit()->selectAll();
    refreshMachines();
    lineState_->setText(tr("Choose a machine of the database, or the controller's port (or HOST:PORT for Modbus "
                           "TCP), speed, parity and address, then Connect."));
}

void ControllerDock::disconnectLine() {
    if (!link_ || link_->busy())
        return;
    window_->setViewedController(nullptr);
    link_.reset();
    connecting_ = false;
    connectedMachine_.clear();
    lastMonitor_.clear();
    monitor_->setText(QString());
    say(tr("Disconnected"));
    updateEnabled();
    emit connectedChanged(false);
}

void ControllerDock::closeLine() {
    if (!link_)
        return;
    window_->setViewedController(nullptr);
    link_.reset();
    connecting_ = false;
    connectedMachine_.clear();
}

void ControllerDock::pullIntoDatabase() {
    if (!link_ || !link_->isOpen() || link_->busy() || preview_)
        return;
    pending_.reset();
    say(tr("Pulling the controller's memory..."));
    link_->pull();
    updateEnabled();
}

void ControllerDock::pushFile(const QString& given) {
    if (!link_ || !link_->isOpen() || link_->busy() || preview_)
        return;
    QString path = given;
    if (path.isEmpty())
        path = QFileDialog::getOpenFileName(this, tr("Push a machine file"), QString(),
                                            tr("Machine files (*.k528m *.txt);;All files (*)"));
    if (path.isEmpty())
        return;
    profile::MachineProfile file;
    try {
        file = profile::readMachineFile(path.toStdString());
    } catch (const std::exception& e) {
        say(tr("%1 cannot be pushed: %2; nothing was sent").arg(path, coreErrorText(e)));
        emit transferFinished(false, lastMessage_);
        return;
    }
    pendingMachine_.clear();
    startPush(file, QFileInfo(path).fileName());
    pendingLeftOut_.clear();
}

void ControllerDock::pushMachine(const QString& name) {
    if (!link_ || !link_->isOpen() || link_->busy() || preview_)
        return;
    try {
        pendingMachine_ = name; // on record as the database's machine pushed
        // Released programs only, unless the machine's setting allows drafts
        // (as `k528 link push --machine`); the preview says what is left out.
        const ReleasedPush sent = releasedPush(loadMachine(name).profile, name);
        if (!sent.error.isEmpty())
            throw std::runtime_error(sent.error.toStdString());
        startPush(sent.file, name);
        pendingLeftOut_ = sent.leftOut;
    } catch (const std::exception& e) {
        say(tr("The machine %1 cannot be loaded: %2").arg(name, coreErrorText(e)));
        emit transferFinished(false, lastMessage_);
    }
}

void ControllerDock::startPush(const profile::MachineProfile& file, const QString& what) {
    // First the controller's memory as it is, for the preview of what changes.
    pending_ = std::make_unique<profile::MachineProfile>(file);
    pendingWhat_ = what;
    say(tr("Reading the controller's memory to show what %1 changes...").arg(what));
    link_->pull(false); // a read for the preview, not a pull on record
    updateEnabled();
}

void ControllerDock::showPreview(const profile::MachineProfile& memory) {
    const profile::MachineProfile after = afterPush(memory, *pending_);
    preview_ = showPushPreview(this, tr("Push %1").arg(pendingWhat_), memory, after, tr("Push"), [this](bool send) {
        preview_ = nullptr;
        std::unique_ptr<profile::MachineProfile> file = std::move(pending_);
        if (send && file && link_ && link_->isOpen()) {
            say(tr("Pushing %1...").arg(pendingWhat_));
            link_->push(*file, pendingMachine_);
        } else {
            say(tr("Push of %1 not started; nothing was sent").arg(pendingWhat_));
            emit transferFinished(false, lastMessage_);
        }
        updateEnabled();
    }, pendingLeftOut_);
    say(tr("Check what %1 changes, then push.").arg(pendingWhat_));
    emit previewShown();
}

void ControllerDock::saveFrameLog(const QString& given) {
    if (!link_)
        return;
    QString path = given;
    if (path.isEmpty())
        path = QFileDialog::getSaveFileName(this, tr("Save the frame log"), QStringLiteral("frames.txt"),
                                            tr("Text (*.txt);;All files (*)"));
    if (path.isEmpty())
        return;
    QPointer<ControllerDock> self(this);
    link_->frameLog([self, path](const QString& text) {
        if (!self)
            return;
        SaveFile f(path);
        const QByteArray bytes = text.toUtf8();
        if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size() || !f.commit()) {
            self->say(tr("The frame log was not saved: %1").arg(fileProblem(f)));
            emit self->frameLogSaved(false, path);
            return;
        }
        self->say(tr("The frame log saved to %1 (%2 frames)").arg(path).arg(text.count(QLatin1Char('\n'))));
        emit self->frameLogSaved(true, path);
    });
}

void ControllerDock::clearMemory(MemoryArea area, bool ask) {
    // The controller the window shows, with its rules (manual 2.6.8: F7
    // «ОЧИСТКА С-ПАРАМ» / «ОЧИСТКА Р-ПАРАМ»; over the link «РАБОТА С ПЭВМ»).
    Controller* c = window_->viewedController();
    const QString what = area == MemoryArea::C ? tr("the C area") : tr("the R area");
    if (const QString why = c->whyNotWritable(area); !why.isEmpty()) {
        say(tr("%1 was not cleared: %2").arg(what, why));
        emit memoryCleared(false, lastMessage_);
        return;
    }
    if (ask && QMessageBox::question(this, tr("Clear"),
                                     tr("Clear %1 of %2? Every value becomes 0; the database keeps what it had.")
                                         .arg(what, c->description())) != QMessageBox::Yes)
        return;
    QPointer<ControllerDock> self(this);
    c->clear(area, [self, what](bool ok, const QString& why) {
        if (!self)
            return;
        self->say(ok ? tr("%1 cleared").arg(what) : tr("%1 was not cleared: %2").arg(what, why));
        emit self->memoryCleared(ok, self->lastMessage_);
    });
}

void ControllerDock::cancelTransfer() {
    if (link_ && link_->busy()) {
        link_->cancel();
        say(tr("Cancelling at the next exchange..."));
    }
}

void ControllerDock::updateLine() {
    if (!link_ || !link_->isOpen())
        return;
    const LineInfo& i = link_->lineInfo();
    QStringList exceptions;
    for (const auto& [code, n] : i.stats.exceptionsByCode)
        exceptions << QStringLiteral("%1×%2").arg(code, 2, 10, QChar('0')).arg(n);
    QString text = tr("%1: %2 answers, %3 timeouts, %4 CRC errors, %5 bad replies, %6 exceptions%7, %8 retries; "
                      "round trip median %9 ms, p95 %10 ms; line busy %11 %")
                       .arg(link_->description())
                       .arg(i.stats.exchanges)
                       .arg(i.stats.noAnswer)
                       .arg(i.stats.crcErrors)
                       .arg(i.stats.badReplies)
                       .arg(i.stats.exceptions)
                       .arg(exceptions.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(exceptions.join(QLatin1Char(' '))))
                       .arg(i.stats.retries)
                       .arg(i.stats.roundTrip.median(), 0, 'f', 1)
                       .arg(i.stats.roundTrip.p95(), 0, 'f', 1)
                       .arg(i.busyPercent, 0, 'f', 0);
    if (link_->stale())
        text = staleText(*link_) + QStringLiteral("\n") + text;
    lineState_->setText(text);
}

void ControllerDock::updateMonitor() {
    if (!link_ || !link_->isOpen()) {
        if (!lastMonitor_.isEmpty()) {
            monitor_->clear();
            lastMonitor_.clear();
        }
        return;
    }
    const ControllerState& s = link_->state();
    const link::LiveState& live = link_->live();
    QString h;
    if (link_->stale())
        h = QStringLiteral("<p style='background:#fff1c2; color:#5c4300'>%1<br>%2</p>")
                .arg(staleText(*link_).toHtmlEscaped(), tr("Why: %1").arg(lostWhy_.toHtmlEscaped()));
    h += QStringLiteral("<table cellspacing='2'%1>").arg(link_->stale() ? QStringLiteral(" style='color:#7a7a7a'") : QString());
    const auto row = [&](const QString& k, const QString& v) {
        h += QStringLiteral("<tr><td style='padding-right:8px'><b>%1</b></td><td>%2</td></tr>").arg(k, v);
    };
    QString mode = live.mode >= 1 && live.mode <= 7 ? QStringLiteral("F%1").arg(live.mode) : tr("power-on");
    if (live.pcReady)
        mode += QStringLiteral(" «РАБОТА С ПЭВМ»");
    if (live.running)
        mode += tr(", running");
    row(tr("Mode"), mode);
    row(tr("Program"), live.program > 0 ? tr("L%1, frame N%2").arg(live.program).arg(live.frame) : tr("none"));
    row(tr("Override"), QStringLiteral("%1 %").arg(live.overridePercent));
    for (int i = 0; i < 2; ++i) {
        const engine::AxisView& a = s.axes[static_cast<std::size_t>(i)];
        const std::int32_t err = i == 0 ? live.xError : live.zError;
        row(i == 0 ? QStringLiteral("X") : QStringLiteral("Z"),
            tr("%1 mm (machine %2), following error %3 mm, %4")
                .arg(mm(a.currentDisc, a.scale), mm(a.machineDisc, a.scale), mm(err, a.scale),
                     (i == 0 ? live.homedX : live.homedZ) ? tr("homed") : tr("not homed")));
    }
    QString alarms;
    for (const engine::AlarmView& a : s.alarms)
        alarms += QStringLiteral("<span style='color:#b01c1c'>%1</span><br>")
                      .arg(alarmLine(a).toHtmlEscaped());
    row(tr("Alarms"), alarms.isEmpty() ? tr("none") : alarms);
    QString leds;
    for (int k = 1; k <= 12; ++k) {
        const bool g = s.display.leds.greenOn(k), r = s.display.leds.redOn(k);
        leds += QStringLiteral("K%1").arg(k) + dot(g || r, r && g ? "#e0b000" : r ? "#d23a2a" : "#2fbf4f") +
                (k == 6 ? QStringLiteral("<br>") : QStringLiteral("&nbsp; "));
    }
    row(tr("K LEDs"), leds);
    const engine::InterfaceWords& w = s.words;
    row(QStringLiteral("Z1301 / Z1302"),
        QStringLiteral("%1 / %2").arg(w.word(1301), 4, 16, QChar('0')).arg(w.word(1302), 4, 16, QChar('0')));
    QString msgs = QStringLiteral("Z1900..Z1903: %1 %2 %3 %4")
                       .arg(w.word(1900), 4, 16, QChar('0'))
                       .arg(w.word(1901), 4, 16, QChar('0'))
                       .arg(w.word(1902), 4, 16, QChar('0'))
                       .arg(w.word(1903), 4, 16, QChar('0'));
    const profile::MachineProfile& prof = link_->profile();
    const auto texts = [&](std::uint32_t bits, const std::map<int, std::string>& t, const char* prefix, const char* color) {
        for (int k = 1; k <= 32; ++k)
            if ((bits >> (k - 1)) & 1u) {
                const auto it = t.find(k);
                msgs += QStringLiteral("<br><span style='color:%1'>%2%3 %4</span>")
                            .arg(QString::fromLatin1(color), QString::fromLatin1(prefix))
                            .arg(k, 2, 10, QChar('0'))
                            .arg(it == t.end() ? QString() : fromStd(it->second).toHtmlEscaped());
            }
    };
    texts(s.plcMessages.alarms, prof.plcAlarm, "A", "#b01c1c");
    texts(s.plcMessages.work, prof.plcWork, "W", "#1d4f91");
    row(tr("Machine messages"), msgs);
    if (live.message > 0)
        row(tr("Message"), QStringLiteral("#%1 %2").arg(live.message).arg(fromStd(s.program.messageText).toHtmlEscaped()));
    QStringList progs;
    for (int p : live.programs)
        progs << QStringLiteral("L%1").arg(p);
    row(tr("Programs"), progs.isEmpty() ? tr("none") : progs.join(' '));
    h += QStringLiteral("</table>");
    if (h != lastMonitor_) {
        const bool first = lastMonitor_.isEmpty();
        lastMonitor_ = h;
        monitor_->setText(h);
        // The line has just come up: the live state is what the operator looks
        // at now. In a short dock (1366x768, under the line's form) it lies
        // below the fold; brought into view once, scrolled freely after.
        if (first)
            if (auto* scroll = qobject_cast<QScrollArea*>(widget()))
                QTimer::singleShot(0, scroll, [scroll, box = monitorBox_] { scroll->ensureWidgetVisible(box, 0, 0); });
    }
}

} // namespace k528::studio
