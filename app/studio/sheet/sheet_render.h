// The setup sheet (core's proveout/setup_sheet.h) laid out for paper: HTML
// for a QTextDocument, printed on any paged device (a QPrinter, a QPdfWriter).
// Shared by the studio (Editor > Setup sheet) and k528-sheet, the renderer of
// `k528 setup-sheet`, so both give the same page.
#pragma once

#include "proveout/setup_sheet.h"

#include <QString>

class QPagedPaintDevice;

namespace k528::studio {

QString setupSheetHtml(const proveout::SetupSheet& sheet, bool russian);
// Prints the sheet on `device` (A4 portrait, 12 mm margins set by the caller
// or here for a QPdfWriter); returns the pages printed.
int printSetupSheet(const proveout::SetupSheet& sheet, bool russian, QPagedPaintDevice& device);
// Writes the sheet to `path` as PDF; "" when done, else why not.
QString writeSetupSheetPdf(const proveout::SetupSheet& sheet, bool russian, const QString& path);

} // namespace k528::studio
