// The listing of a program file: printed (Qt Print Support) or
// exported to PDF. Every page has a header — the file, the machine it is
// checked for, the date, the count of problems and «page n of m» — then the
// file's lines with their numbers, each diagnostic in a line of its own
// under the line it is about («^ error [M33] text», the caret under its
// column), as the editor's Problems list gives them.
#pragma once

#include "program/diagnostic.h"

#include <QDateTime>
#include <QString>
#include <QStringList>
#include <vector>

class QPagedPaintDevice;

namespace k528::studio {

struct ListingInfo {
    QString file;    // the file's name (or «untitled 1»)
    QString machine; // the machine the file is checked for ("" = the language only)
    QDateTime date;
};

struct ListingRow {
    int line = 0;       // 1-based line of the file; 0 for a diagnostic's row
    QString text;       // the line's text, or «^ error [Mnn] text»
    bool error = false; // a diagnostic row: error (else warning)
};

// The rows of the listing: every line of `text`, each followed by the
// diagnostics about it (in the UI's language).
std::vector<ListingRow> listingRows(const QString& text, const std::vector<program::Diagnostic>& diagnostics);

// The header lines of page `page` (1-based) of `pages`.
QStringList listingHeader(const ListingInfo& info, const std::vector<program::Diagnostic>& diagnostics, int page,
                          int pages);

// Paints the listing onto `device` (a QPrinter or QPdfWriter), a new page
// whenever one is full. Returns the number of pages, 0 if nothing could be
// painted (the device did not open).
int printListing(const QString& text, const std::vector<program::Diagnostic>& diagnostics, const ListingInfo& info,
                 QPagedPaintDevice& device);

// The listing as a PDF file at `path` (A4). Returns the pages, 0 and `error`
// why not.
int exportListingPdf(const QString& text, const std::vector<program::Diagnostic>& diagnostics,
                     const ListingInfo& info, const QString& path, QString* error = nullptr);

} // namespace k528::studio
