#include "main_window.h"

#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QEvent>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QTabWidget>

#include "k923/k923_widget.h"
#include "language.h"
#include "util/version.h"

namespace k528::studio {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setObjectName("mainWindow");
    setWindowIcon(QIcon(":/icons/k528studio.svg"));
    workArea_ = new QTabWidget(this);
    workArea_->setObjectName("workArea");
    workArea_->setDocumentMode(true);
    setCentralWidget(workArea_);
    setDockOptions(AnimatedDocks | AllowTabbedDocks | AllowNestedDocks);
    createDocks();
    createMenus();
    statusBar();
    retranslate();
    resize(1280, 800);
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
    // The K923 panel. Until the panel model drives it, it shows what a
    // switched-on panel without data shows: the lit, empty LCD, LEDs off.
    delete k923Dock_->widget();
    k923_ = new K923Widget(k923Dock_);
    k923_->setDisplay(K923Widget::blankDisplay());
    k923Dock_->setWidget(k923_);
    machineDock_ = addDock("dock.machine", Qt::RightDockWidgetArea);
    messagesDock_ = addDock("dock.messages", Qt::BottomDockWidgetArea);
    axesDock_ = addDock("dock.axes", Qt::BottomDockWidgetArea);
    tabifyDockWidget(messagesDock_, axesDock_);
    messagesDock_->raise();
}

void MainWindow::createMenus() {
    fileMenu_ = menuBar()->addMenu(QString());
    quitAction_ = fileMenu_->addAction(QString(), QKeySequence::Quit, qApp, &QApplication::quit);
    quitAction_->setObjectName("action.quit");

    viewMenu_ = menuBar()->addMenu(QString());
    for (QDockWidget* d : {k923Dock_, machineDock_, messagesDock_, axesDock_})
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

    helpMenu_ = menuBar()->addMenu(QString());
    aboutAction_ = helpMenu_->addAction(QString(), this, [this] {
        QMessageBox::about(this, tr("About K528 Studio"),
                           tr("<h3>K528 Studio %1</h3><p>Workstation for the Konstar K528-05 "
                              "two-axis positioning controller and its K923 operator panel.</p>"
                              "<p>Licence: GNU GPL version 3 or later.</p>")
                               .arg(QString::fromLatin1(k528::version_string)));
    });
}

void MainWindow::retranslate() {
    setWindowTitle(tr("K528 Studio"));
    fileMenu_->setTitle(tr("&File"));
    quitAction_->setText(tr("&Quit"));
    viewMenu_->setTitle(tr("&View"));
    languageMenu_->setTitle(tr("&Language"));
    helpMenu_->setTitle(tr("&Help"));
    aboutAction_->setText(tr("&About K528 Studio"));

    k923Dock_->setWindowTitle(tr("K923 operator panel"));
    machineDock_->setWindowTitle(tr("Machine control panel"));
    messagesDock_->setWindowTitle(tr("Messages"));
    axesDock_->setWindowTitle(tr("Axes and signals"));
    const auto hint = [](QDockWidget* d, const QString& text) {
        if (auto* l = qobject_cast<QLabel*>(d->widget()))
            l->setText(text);
    };
    hint(machineDock_, tr("The machine's push-buttons, handwheel, override and lamps."));
    hint(messagesDock_, tr("Alarms and messages of the controller and the machine."));
    hint(axesDock_, tr("Axis positions, following error, DAC and interface signals."));
    statusBar()->showMessage(tr("Ready"));
}

void MainWindow::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QMainWindow::changeEvent(event);
}

} // namespace k528::studio
