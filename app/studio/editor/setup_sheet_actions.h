// The setup sheet (карта наладки) of the editor's current document on the
// machine it is checked for: its content (core's proveout::setupSheet, with
// the cycle times), written as PDF, or shown in a print preview.
#pragma once

#include <QObject>

namespace k528::proveout {
struct SetupSheet;
}

namespace k528::studio {

class EditorTab;

class SetupSheetActions : public QObject {
    Q_OBJECT
public:
    explicit SetupSheetActions(EditorTab& tab);

    // The sheet of the current document; false and `why` when none can be made.
    bool setupSheet(proveout::SetupSheet& sheet, QString& why);
    // "" when written, else why not.
    QString exportPdf(const QString& path);
    void exportPdfDialog();
    void preview();

signals:
    void statusMessage(const QString& text);

private:
    EditorTab& tab_;
};

} // namespace k528::studio
