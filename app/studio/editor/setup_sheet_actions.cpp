#include "editor/setup_sheet_actions.h"

#include "editor/editor_tab.h"
#include "editor/program_editor.h"
#include "window_language.h"
#include "proveout/setup_sheet.h"
#include "session/core_texts.h"
#include "sheet/sheet_render.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QGuiApplication>
#include <QMessageBox>
#include <QPrintPreviewDialog>
#include <QPrinter>
#include <QScreen>

namespace k528::studio {

SetupSheetActions::SetupSheetActions(EditorTab& tab) : QObject(&tab), tab_(tab) {}

bool SetupSheetActions::setupSheet(proveout::SetupSheet& sheet, QString& why) {
    ProgramEditor* ed = tab_.currentEditor();
    if (!ed) {
        why = tr("Open a program file in the editor: its setup sheet is made on the machine it is checked for.");
        return false;
    }
    ed->validateNow();
    if (!ed->machine()) {
        why = tr("The file is checked for no machine: choose one (Editor menu) for its setup sheet.");
        return false;
    }
    if (program::hasErrors(ed->diagnostics())) {
        why = tr("The file has errors (Problems): its setup sheet is made once they are fixed.");
        return false;
    }
    const int i = tab_.currentIndex();
    const QString name = tab_.pathOf(i).isEmpty() ? tab_.documentName(i) : QFileInfo(tab_.pathOf(i)).fileName();
    QGuiApplication::setOverrideCursor(Qt::WaitCursor);
    try {
        sheet = proveout::setupSheet(*ed->machine(), ed->store(), ed->text().toStdString(), name.toStdString());
    } catch (const std::exception& e) {
        QGuiApplication::restoreOverrideCursor();
        why = tr("The setup sheet cannot be made: %1").arg(coreErrorText(e));
        return false;
    }
    QGuiApplication::restoreOverrideCursor();
    return true;
}

QString SetupSheetActions::exportPdf(const QString& path) {
    proveout::SetupSheet sheet;
    QString why;
    if (!setupSheet(sheet, why)) {
        emit statusMessage(why);
        return why;
    }
    const QString error = writeSetupSheetPdf(sheet, russianWindow(), path);
    emit statusMessage(error.isEmpty() ? tr("Setup sheet written to %1").arg(path)
                                       : tr("Cannot write %1: %2").arg(path, error));
    return error;
}

void SetupSheetActions::exportPdfDialog() {
    const int i = tab_.currentIndex();
    if (i < 0)
        return;
    QString suggestion = tab_.pathOf(i);
    if (!suggestion.isEmpty())
        suggestion = QFileInfo(suggestion).path() + "/" + QFileInfo(suggestion).completeBaseName() + "-setup.pdf";
    const QString p =
        QFileDialog::getSaveFileName(&tab_, tr("Export the setup sheet"), suggestion, tr("PDF (*.pdf)"));
    if (!p.isEmpty())
        exportPdf(p);
}

void SetupSheetActions::preview() {
    proveout::SetupSheet sheet;
    QString why;
    if (!setupSheet(sheet, why)) {
        emit statusMessage(why);
        QMessageBox::information(&tab_, tr("Setup sheet"), why);
        return;
    }
    const bool russian = russianWindow();
    QPrinter printer(QPrinter::HighResolution);
    printer.setPageSize(QPageSize(QPageSize::A4));
    printer.setPageMargins(QMarginsF(12, 12, 12, 12), QPageLayout::Millimeter);
    printer.setDocName(tr("Setup sheet") + QStringLiteral(": ") + QString::fromStdString(sheet.file));
    QPrintPreviewDialog dialog(&printer, &tab_);
    dialog.setObjectName("dialog.setupSheet");
    dialog.setWindowTitle(tr("Setup sheet: %1").arg(QString::fromStdString(sheet.file)));
    if (const QScreen* screen = tab_.window()->screen()) // the page large enough to read
        dialog.resize(screen->availableGeometry().size() * 0.85);
    connect(&dialog, &QPrintPreviewDialog::paintRequested, this,
            [&sheet, russian](QPrinter* p) { printSetupSheet(sheet, russian, *p); });
    dialog.exec();
}

} // namespace k528::studio
