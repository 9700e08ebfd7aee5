#include "editor/refactor_texts.h"

#include "program/refactor.h"
#include "session/translated_texts.h"

#include <QCoreApplication>

#include <optional>
#include <string>

namespace k528::studio {

namespace {

// core/program/refactor.cpp's catalog, each text marked for the translators.
const TranslatedText kRefactors[] = {
    {"refactor.no-program", QT_TRANSLATE_NOOP("k528::studio::RefactorTexts", "there is no program L%1")},
    {"refactor.program-number", QT_TRANSLATE_NOOP("k528::studio::RefactorTexts", "a program number is 1..99, not %1")},
    {"refactor.program-exists", QT_TRANSLATE_NOOP("k528::studio::RefactorTexts", "program L%1 exists already")},
    {"refactor.start-step",
     QT_TRANSLATE_NOOP("k528::studio::RefactorTexts", "the start and step of numbering must be at least 1")},
    {"refactor.past-999",
     QT_TRANSLATE_NOOP("k528::studio::RefactorTexts", "the last frame number would exceed 999 (%1 frames)")},
};

const TranslatedTexts kRefactorTexts("k528::studio::RefactorTexts", kRefactors);

} // namespace

bool hasRefactorText(std::string_view id) { return kRefactorTexts.has(id); }

QString refactorText(const program::RefactorResult& r) {
    if (const std::optional<QString> text = kRefactorTexts.text(r.textId, r.args))
        return *text;
    return QString::fromStdString(r.text(false)); // an id without a translation: core's English
}

} // namespace k528::studio
