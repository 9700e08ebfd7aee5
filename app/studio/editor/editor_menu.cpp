#include "editor/editor_menu.h"

#include "controller/controller.h"
#include "editor/editor_tab.h"
#include "editor/listing_actions.h"
#include "editor/refactor_actions.h"
#include "editor/setup_sheet_actions.h"
#include "editor/teach_in.h"
#include "session/machine_source.h"

#include <QMenu>
#include <QToolBar>
#include <QToolButton>

namespace k528::studio {

namespace {
QToolButton* menuButton(QToolBar* bar, QAction* a, QMenu* m) {
    a->setMenu(m);
    auto* b = qobject_cast<QToolButton*>(bar->widgetForAction(a));
    if (b)
        b->setPopupMode(QToolButton::InstantPopup);
    return b;
}
} // namespace

EditorMenu::EditorMenu(EditorTab& tab, QToolBar* toolbar, ViewedController* viewed)
    : QObject(&tab), tab_(tab), viewed_(viewed) {
    RefactorActions* refactor = tab.refactor();
    ListingActions* listing = tab.listing();
    SetupSheetActions* sheet = tab.setupSheets();
    TeachIn* teach = tab.teachIn();
    editorMenu_ = new QMenu(&tab);
    editorMenu_->setObjectName("menu.editor");
    refactorMenu_ = new QMenu(&tab);
    renumberAction_ = refactorMenu_->addAction(QString(), refactor, &RefactorActions::renumberDialog);
    moveAction_ = refactorMenu_->addAction(QString(), refactor, &RefactorActions::moveProgramDialog);
    formatAction_ = refactorMenu_->addAction(QString(), refactor, [refactor] { refactor->formatFile(); });
    formatAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
    listingMenu_ = new QMenu(&tab);
    printAction_ = listingMenu_->addAction(QString(), listing, &ListingActions::printDialog);
    printAction_->setShortcut(QKeySequence::Print);
    pdfAction_ = listingMenu_->addAction(QString(), listing, &ListingActions::exportPdfDialog);
    sheetMenu_ = new QMenu(&tab);
    sheetMenu_->setObjectName("menu.editor.setupSheet");
    sheetPreviewAction_ = sheetMenu_->addAction(QString(), sheet, &SetupSheetActions::preview);
    sheetPdfAction_ = sheetMenu_->addAction(QString(), sheet, &SetupSheetActions::exportPdfDialog);
    teachMenu_ = new QMenu(&tab);
    teachMenu_->setObjectName("menu.editor.teach");
    teachFrameAction_ = teachMenu_->addAction(QString(), teach, [teach] { teach->teachPosition(); });
    teachFrameAction_->setObjectName("editor.teachFrame");
    teachFrameAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_T));
    teachRMenu_ = teachMenu_->addMenu(QString());
    teachRMenu_->setObjectName("menu.editor.teachR");
    connect(teachRMenu_, &QMenu::aboutToShow, teach, [this, teach] { teach->fillTargetsMenu(teachRMenu_); });
    fileMachineMenu_ = new QMenu(&tab);
    fileMachineMenu_->setObjectName("menu.editor.fileMachine");
    connect(fileMachineMenu_, &QMenu::aboutToShow, this, &EditorMenu::fillFileMachineMenu);
    openDbAction_ = new QAction(&tab);
    connect(openDbAction_, &QAction::triggered, &tab, &EditorTab::openDatabaseDialog);

    toolbar->addSeparator();
    refactorAction_ = toolbar->addAction(QString());
    menuButton(toolbar, refactorAction_, refactorMenu_);
    listingAction_ = toolbar->addAction(QString());
    menuButton(toolbar, listingAction_, listingMenu_);
    fileMachineAction_ = toolbar->addAction(QString());
    fileMachineAction_->setObjectName("editor.fileMachine");
    menuButton(toolbar, fileMachineAction_, fileMachineMenu_);
    toolbar->addAction(openDbAction_);

    editorMenu_->addMenu(refactorMenu_);
    editorMenu_->addMenu(listingMenu_);
    editorMenu_->addMenu(sheetMenu_);
    editorMenu_->addMenu(teachMenu_);
    editorMenu_->addMenu(fileMachineMenu_);
    editorMenu_->addAction(openDbAction_);
}

void EditorMenu::retranslate() {
    editorMenu_->setTitle(tr("&Editor"));
    refactorMenu_->setTitle(tr("Refactor"));
    refactorAction_->setText(tr("Refactor"));
    renumberAction_->setText(tr("Renumber frames…"));
    moveAction_->setText(tr("Move or copy a program…"));
    formatAction_->setText(tr("Format the file"));
    listingMenu_->setTitle(tr("Listing"));
    listingAction_->setText(tr("Listing"));
    printAction_->setText(tr("Print…"));
    pdfAction_->setText(tr("Export PDF…"));
    sheetMenu_->setTitle(tr("Setup sheet"));
    sheetPreviewAction_->setText(tr("Print preview…"));
    sheetPreviewAction_->setToolTip(tr("The setup sheet of this file on its machine: the blank, the tools with their "
                                       "offsets, the programs with their cycle times, the R-parameters to preset"));
    sheetPdfAction_->setText(tr("Export PDF…"));
    teachMenu_->setTitle(tr("Teach-in"));
    teachFrameAction_->setText(tr("Insert the controller's position as a frame"));
    teachFrameAction_->setToolTip(tr("The position the viewed controller's axes are at (current coordinates, as "
                                     "its panel shows them) as a frame after the cursor's line"));
    teachRMenu_->setTitle(tr("Position into an R-parameter"));
    tab_.teachIn()->fillTargetsMenu(teachRMenu_);
    fileMachineMenu_->setTitle(tr("Machine of this file"));
    const int i = tab_.currentIndex();
    const QString m = i >= 0 ? tab_.checkedMachineTitle(i) : QString();
    fileMachineAction_->setText(tr("Machine: %1").arg(m.isEmpty() ? tr("none") : m));
    fileMachineAction_->setToolTip(tr("The machine this file is checked for: its limits, feeds and axes"));
    openDbAction_->setText(tr("Open from the database…"));
    openDbAction_->setToolTip(tr("The programs and messages of a machine of the database; saving writes its next revision"));
}

void EditorMenu::fillFileMachineMenu() {
    fileMachineMenu_->clear();
    const int i = tab_.currentIndex();
    if (i < 0) {
        fileMachineMenu_->addAction(tr("No file is open"))->setEnabled(false);
        return;
    }
    const QString current = tab_.fileMachine(i);
    auto add = [&](const QString& text, const QString& choice) {
        QAction* a = fileMachineMenu_->addAction(text);
        a->setCheckable(true);
        a->setChecked(current == choice);
        a->setObjectName("action.fileMachine." + (choice.isEmpty() ? QStringLiteral("workstation") : choice));
        connect(a, &QAction::triggered, &tab_, [this, i, choice] { tab_.setFileMachine(i, choice); });
    };
    add(viewed_ ? tr("The workstation's machine (%1)").arg(machineTitle(viewed_->current().profile()))
                 : tr("The workstation's machine (none)"),
        QString());
    add(tr("None: the language only"), EditorTab::kNoMachine);
    fileMachineMenu_->addSeparator();
    QString warning;
    for (const TitledMachine& m : titledMachines(&warning))
        add(m.title, m.name);
    if (!warning.isEmpty())
        fileMachineMenu_->addAction(warning)->setEnabled(false);
}

} // namespace k528::studio
