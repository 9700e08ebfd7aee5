#include "editor/listing_actions.h"

#include "editor/editor_tab.h"
#include "editor/listing.h"
#include "editor/program_editor.h"

#include <QDateTime>
#include <QFileDialog>
#include <QFileInfo>
#include <QPrintDialog>
#include <QPrinter>

namespace k528::studio {

ListingActions::ListingActions(EditorTab& tab) : QObject(&tab), tab_(tab) {}

int ListingActions::exportPdf(const QString& path) {
    ProgramEditor* ed = tab_.currentEditor();
    if (!ed)
        return 0;
    ed->validateNow();
    const int i = tab_.currentIndex();
    const ListingInfo info{tab_.pathOf(i).isEmpty() ? tab_.documentName(i) : tab_.pathOf(i),
                           tab_.checkedMachineTitle(i), QDateTime::currentDateTime()};
    QString error;
    const int pages = exportListingPdf(ed->text(), ed->diagnostics(), info, path, &error);
    emit statusMessage(pages > 0 ? tr("Listing of %1 pages written to %2").arg(pages).arg(path) : error);
    return pages;
}

void ListingActions::exportPdfDialog() {
    const int i = tab_.currentIndex();
    if (i < 0)
        return;
    QString suggestion = tab_.pathOf(i);
    if (!suggestion.isEmpty())
        suggestion = QFileInfo(suggestion).path() + "/" + QFileInfo(suggestion).completeBaseName() + ".pdf";
    const QString p = QFileDialog::getSaveFileName(&tab_, tr("Export the listing"), suggestion, tr("PDF (*.pdf)"));
    if (!p.isEmpty())
        exportPdf(p);
}

void ListingActions::printDialog() {
    ProgramEditor* ed = tab_.currentEditor();
    if (!ed)
        return;
    ed->validateNow();
    QPrinter printer(QPrinter::HighResolution);
    QPrintDialog dialog(&printer, &tab_);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const int i = tab_.currentIndex();
    const ListingInfo info{tab_.pathOf(i).isEmpty() ? tab_.documentName(i) : tab_.pathOf(i),
                           tab_.checkedMachineTitle(i), QDateTime::currentDateTime()};
    const int pages = printListing(ed->text(), ed->diagnostics(), info, printer);
    emit statusMessage(pages > 0 ? tr("Printed %1 pages").arg(pages) : tr("The listing could not be printed"));
}

} // namespace k528::studio
