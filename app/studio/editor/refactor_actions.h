// The editor's refactorings of the current document: renumber its frames,
// move or copy a program, format the file (each one undo step, over
// text_refactor.h), and the dialogs that ask for them.
#pragma once

#include <QObject>

namespace k528::studio {

class EditorTab;
class ProgramEditor;
struct TextRefactor;

class RefactorActions : public QObject {
    Q_OBJECT
public:
    explicit RefactorActions(EditorTab& tab);

    // False and a status message why not. program 0 = every program.
    bool renumber(int program, int start, int step);
    bool moveProgram(int from, int to, bool copy);
    bool formatFile();
    void renumberDialog();
    void moveProgramDialog();

signals:
    void statusMessage(const QString& text);

private:
    bool apply(ProgramEditor* ed, const TextRefactor& r, const QString& done);
    // The whole text replaced as one undo step, the cursor and view kept.
    static void replaceText(ProgramEditor* ed, const QString& text);
    EditorTab& tab_;
};

} // namespace k528::studio
