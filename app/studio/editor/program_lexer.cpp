#include "editor/program_lexer.h"

#include "program/tokens.h"

#include <Qsci/qsciscintilla.h>
#include <QFontDatabase>
#include <algorithm>

namespace k528::studio {

using program::TokenKind;

ProgramLexer::ProgramLexer(QObject* parent) : QsciLexerCustom(parent) {}

QString ProgramLexer::description(int style) const {
    if (style < 0 || style >= program::kTokenKindCount)
        return {};
    return QString::fromLatin1(program::tokenKindName(static_cast<TokenKind>(style)));
}

QColor ProgramLexer::defaultColor(int style) const {
    switch (static_cast<TokenKind>(style)) {
    case TokenKind::Comment: return QColor(0x6a, 0x8a, 0x35);
    case TokenKind::Header: return QColor(0x80, 0x00, 0x80);
    case TokenKind::Title: return QColor(0x80, 0x40, 0x80);
    case TokenKind::Skip: return QColor(0xc0, 0x40, 0x00);
    case TokenKind::FrameNumber: return QColor(0x80, 0x80, 0x80);
    case TokenKind::GWord: return QColor(0x00, 0x30, 0xc0);
    case TokenKind::MWord: return QColor(0xa0, 0x00, 0x00);
    case TokenKind::MessageRef: return QColor(0x00, 0x80, 0x80);
    case TokenKind::Call: return QColor(0xa0, 0x50, 0x00);
    case TokenKind::AxisValue: return QColor(0x00, 0x00, 0x00);
    case TokenKind::Feed: return QColor(0x00, 0x70, 0x40);
    case TokenKind::RParam: return QColor(0x90, 0x20, 0x90);
    case TokenKind::Literal: return QColor(0x30, 0x30, 0x30);
    case TokenKind::Keyword: return QColor(0x00, 0x30, 0xc0);
    case TokenKind::JumpTarget: return QColor(0xa0, 0x50, 0x00);
    case TokenKind::Operator: return QColor(0x50, 0x50, 0x50);
    case TokenKind::MessageNumber: return QColor(0x00, 0x80, 0x80);
    case TokenKind::MessageText: return QColor(0x20, 0x20, 0x20);
    default: return QColor(0x40, 0x40, 0x40);
    }
}

QFont ProgramLexer::defaultFont(int style) const {
    QFont f = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    const auto k = static_cast<TokenKind>(style);
    if (k == TokenKind::Header || k == TokenKind::GWord || k == TokenKind::Keyword || k == TokenKind::MWord)
        f.setBold(true);
    if (k == TokenKind::Comment || k == TokenKind::Title)
        f.setItalic(true);
    return f;
}

void ProgramLexer::styleText(int start, int end) {
    QsciScintilla* ed = editor();
    if (!ed || end <= start)
        return;
    const int firstLine = static_cast<int>(ed->SendScintilla(QsciScintilla::SCI_LINEFROMPOSITION, start));
    const int lastLine = static_cast<int>(ed->SendScintilla(QsciScintilla::SCI_LINEFROMPOSITION, end - 1));
    const int from = static_cast<int>(ed->SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, firstLine));
    startStyling(from);
    int realFirst = firstLine;
    if (lastLine - firstLine > 2 * kLookBehindLines) {
        realFirst = lastLine - kLookBehindLines;
        const int realFrom = static_cast<int>(ed->SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, realFirst));
        setStyling(realFrom - from, static_cast<int>(TokenKind::Default));
        for (int line = firstLine; line < realFirst; ++line)
            ed->SendScintilla(QsciScintilla::SCI_SETFOLDLEVEL, line, QsciScintilla::SC_FOLDLEVELBASE + 1);
        placeholderFrom_ = placeholderFrom_ < 0 ? firstLine : std::min(placeholderFrom_, firstLine);
        placeholderTo_ = std::max(placeholderTo_, realFirst);
    }
    for (int line = realFirst; line <= lastLine; ++line) {
        const int lineStart = static_cast<int>(ed->SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, line));
        const int lineEnd = static_cast<int>(ed->SendScintilla(QsciScintilla::SCI_GETLINEENDPOSITION, line));
        const int next = line + 1 < ed->lines()
                             ? static_cast<int>(ed->SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, line + 1))
                             : lineEnd;
        QByteArray bytes(lineEnd - lineStart, '\0');
        if (!bytes.isEmpty())
            ed->SendScintilla(QsciScintilla::SCI_GETTEXTRANGE, lineStart, lineEnd, bytes.data());
        // A line is tokenized on its own: the parser reads lines independently;
        // a "#k=text" line is read as a line of the %MESSAGES section.
        std::string text(bytes.constData(), static_cast<std::size_t>(bytes.size()));
        std::size_t first = text.find_first_not_of(" \t");
        std::string prefix;
        if (first != std::string::npos && text[first] == '#' && text.find('=') != std::string::npos)
            prefix = "%MESSAGES\n";
        const std::string whole = prefix + text + "\n";
        const program::TokenizeResult t = program::tokenize(whole);
        int at = 0; // bytes styled on this line
        for (const program::Token& tok : t.tokens) {
            if (tok.begin < prefix.size())
                continue;
            const int b = static_cast<int>(tok.begin - prefix.size());
            const int e = static_cast<int>(tok.end - prefix.size());
            if (b > at)
                setStyling(b - at, static_cast<int>(TokenKind::Default));
            setStyling(e - b, static_cast<int>(tok.kind));
            at = e;
        }
        if (next - lineStart > at)
            setStyling(next - lineStart - at, static_cast<int>(TokenKind::Default));
        // Folding: %L and %MESSAGES open a section.
        const bool header = first != std::string::npos && text[first] == '%';
        const int level = header ? (QsciScintilla::SC_FOLDLEVELBASE | QsciScintilla::SC_FOLDLEVELHEADERFLAG)
                                 : QsciScintilla::SC_FOLDLEVELBASE + 1;
        ed->SendScintilla(QsciScintilla::SCI_SETFOLDLEVEL, line, level);
    }
}

void ProgramLexer::styleVisible(int firstLine, int lastLine) {
    QsciScintilla* ed = editor();
    if (!ed || placeholderFrom_ < 0 || lastLine < placeholderFrom_ || firstLine >= placeholderTo_)
        return;
    const int a = std::max(firstLine, placeholderFrom_);
    const int b = std::min(lastLine + 1, placeholderTo_);
    // Shrink the placeholder interval by the part coloured now (at its ends).
    if (a <= placeholderFrom_)
        placeholderFrom_ = b;
    else if (b >= placeholderTo_)
        placeholderTo_ = a;
    if (placeholderFrom_ >= placeholderTo_)
        placeholderFrom_ = placeholderTo_ = -1;
    const int start = static_cast<int>(ed->SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, a));
    const int end = static_cast<int>(ed->SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, b));
    styleText(start, std::max(start + 1, end));
}

} // namespace k528::studio
