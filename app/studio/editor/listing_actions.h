// The listing of the editor's current document (listing.h): printed, or
// written as PDF, with its file, machine and diagnostics.
#pragma once

#include <QObject>

namespace k528::studio {

class EditorTab;

class ListingActions : public QObject {
    Q_OBJECT
public:
    explicit ListingActions(EditorTab& tab);

    // The pages written to `path` (0 = failed, a status message why).
    int exportPdf(const QString& path);
    void exportPdfDialog();
    void printDialog();

signals:
    void statusMessage(const QString& text);

private:
    EditorTab& tab_;
};

} // namespace k528::studio
