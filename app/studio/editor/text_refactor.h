// The editor's refactorings over a whole file's text: renumber a
// program's frames (start, step) with every IF/GOTO target following its
// frame, move or copy a program to another number with the L calls that
// name it following, and format the file. Each one reads the text with
// core's parser, changes the store with core/program/refactor and writes it
// back through core's one formatter (program::format), as `k528 format`
// does. A text with syntax errors is refused: formatting would lose what
// could not be read.
#pragma once

#include <QString>

namespace k528::studio {

struct TextRefactor {
    bool ok = false;
    QString text;  // the new text of the whole file (when ok)
    QString error; // why nothing was changed (in the UI's language)
};

// program 0: every program of the file.
TextRefactor renumberText(const QString& text, int program, int start, int step);
TextRefactor moveProgramText(const QString& text, int from, int to, bool copy);
TextRefactor formatText(const QString& text);

} // namespace k528::studio
