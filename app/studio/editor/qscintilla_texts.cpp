// QScintilla's own texts (the editor's context menu: QsciScintilla::
// createStandardContextMenu) for our translators: Debian's QScintilla ships
// no Russian file, so our .ts carries them in QScintilla's context.
#include <QtGlobal>

namespace k528::studio {

namespace {
[[maybe_unused]] const char* const kQScintillaTexts[] = {
    QT_TRANSLATE_NOOP("QsciScintilla", "&Undo"),  QT_TRANSLATE_NOOP("QsciScintilla", "&Redo"),
    QT_TRANSLATE_NOOP("QsciScintilla", "Cu&t"),   QT_TRANSLATE_NOOP("QsciScintilla", "&Copy"),
    QT_TRANSLATE_NOOP("QsciScintilla", "&Paste"), QT_TRANSLATE_NOOP("QsciScintilla", "Delete"),
    QT_TRANSLATE_NOOP("QsciScintilla", "Select All"),
};
} // namespace

} // namespace k528::studio
