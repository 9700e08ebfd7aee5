// The masters of the program editor (manual 2.2.1 «мастера»): a
// dialog that builds one frame — ISO motion, dwell, subprogram call,
// oscillation, move until signal, computational frame, conditional and
// unconditional jump — or a technological message, through core's frame
// builders (program/builders.h): the canonical text is previewed and its
// problems shown as the fields are typed; OK is enabled when it has none.
// Opened on an existing frame, the fields hold that frame.
#pragma once

#include "program/builders.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;
class QStackedWidget;
class QDialogButtonBox;

namespace k528::studio {

class FrameMaster : public QDialog {
    Q_OBJECT
public:
    enum Kind { Iso, Dwell, Call, Oscillation, UntilSignal, Compute, IfGoto, Goto, Message, KindCount };

    explicit FrameMaster(QWidget* parent = nullptr);

    void setKind(Kind k);
    Kind kind() const;
    // Fills the fields from a frame's or a "#k=text" line's text; false if
    // the line is neither (the fields stay as they are).
    bool setFromLine(const QString& line);
    // Says at the top what OK does (replaces line N, inserts after it).
    void setPlacement(const QString& text);
    QString placement() const;

    // The canonical text built from the fields, and whether it may be inserted.
    QString text() const { return text_; }
    bool valid() const { return valid_; }
    QString problemsText() const;

    // The field editors, by name (tests type into them).
    QLineEdit* field(const QString& name) const;

private:
    void rebuild();
    program::FrameHead head() const;
    QLineEdit* addField(QWidget* page, const QString& name);

    QComboBox* kindBox_ = nullptr;
    QCheckBox* skip_ = nullptr;
    QLineEdit* n_ = nullptr;
    QStackedWidget* pages_ = nullptr;
    QComboBox* axis_ = nullptr;
    QComboBox* op_ = nullptr;
    QLabel* placement_ = nullptr;
    QLabel* preview_ = nullptr;
    QLabel* problems_ = nullptr;
    QDialogButtonBox* buttons_ = nullptr;
    QString text_;
    bool valid_ = false;
    std::vector<program::Diagnostic> last_;
};

} // namespace k528::studio
