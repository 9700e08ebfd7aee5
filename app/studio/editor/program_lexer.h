// The colouring of K528 program text in the editor: a QsciLexerCustom whose
// styles are core's token kinds (program/tokens.h). Each line Scintilla asks
// for is tokenized by core (the parser's own spans), so colours never
// disagree with the parser; header lines (%L, %MESSAGES) are fold points.
#pragma once

#include <Qsci/qscilexercustom.h>

namespace k528::studio {

class ProgramLexer : public QsciLexerCustom {
    Q_OBJECT
public:
    explicit ProgramLexer(QObject* parent = nullptr);

    const char* language() const override { return "K528"; }
    QString description(int style) const override;
    QColor defaultColor(int style) const override;
    QFont defaultFont(int style) const override;
    void styleText(int start, int end) override;

    // Scintilla asks for every line from the last styled one down to the
    // screen: after a jump deep into a big file that would be thousands of
    // lines at once. Lines more than kLookBehindLines above the requested
    // end get the default style at once and are remembered as placeholders;
    // styleVisible() colours the placeholders that come into view.
    static constexpr int kLookBehindLines = 300;
    void styleVisible(int firstLine, int lastLine);

private:
    int placeholderFrom_ = -1; // lines [from, to) hold placeholder styles
    int placeholderTo_ = -1;
};

} // namespace k528::studio
