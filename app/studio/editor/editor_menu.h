// The Editor menu of the menu bar and the tools' buttons of the editor's
// toolbar: refactoring (refactor_actions.h), listing (listing_actions.h),
// setup sheet (setup_sheet_actions.h), teach-in (teach_in.h), the machine
// of the current file, and the programs of a database machine.
#pragma once

#include <QObject>

class QAction;
class QMenu;
class QToolBar;

namespace k528::studio {

class EditorTab;
class ListingActions;
class RefactorActions;
class SetupSheetActions;
class TeachIn;
class ViewedController;

class EditorMenu : public QObject {
    Q_OBJECT
public:
    EditorMenu(EditorTab& tab, QToolBar* toolbar, ViewedController* viewed);

    QMenu* menu() const { return editorMenu_; }
    // The texts in the UI's language, the current file's machine named.
    void retranslate();

private:
    void fillFileMachineMenu();
    EditorTab& tab_;
    ViewedController* viewed_ = nullptr;
    QMenu *editorMenu_ = nullptr, *refactorMenu_ = nullptr, *listingMenu_ = nullptr, *fileMachineMenu_ = nullptr,
          *sheetMenu_ = nullptr, *teachMenu_ = nullptr, *teachRMenu_ = nullptr;
    QAction *sheetPreviewAction_ = nullptr, *sheetPdfAction_ = nullptr, *teachFrameAction_ = nullptr;
    QAction *renumberAction_ = nullptr, *moveAction_ = nullptr, *formatAction_ = nullptr, *printAction_ = nullptr,
            *pdfAction_ = nullptr, *openDbAction_ = nullptr, *fileMachineAction_ = nullptr,
            *refactorAction_ = nullptr, *listingAction_ = nullptr;
};

} // namespace k528::studio
