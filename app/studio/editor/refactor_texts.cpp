#include "editor/refactor_texts.h"

#include "program/refactor.h"
#include "util/text_pattern.h"

#include <QCoreApplication>

#include <string>

namespace k528::studio {

namespace {

struct Entry {
    const char* id;
    const char* text; // English, as core's catalog says it; translated in context RefactorTexts
};

// core/program/refactor.cpp's catalog, each text marked for the translators.
const Entry kRefactorTexts[] = {
    {"refactor.no-program", QT_TRANSLATE_NOOP("k528::studio::RefactorTexts", "there is no program L%1")},
    {"refactor.program-number", QT_TRANSLATE_NOOP("k528::studio::RefactorTexts", "a program number is 1..99, not %1")},
    {"refactor.program-exists", QT_TRANSLATE_NOOP("k528::studio::RefactorTexts", "program L%1 exists already")},
    {"refactor.start-step",
     QT_TRANSLATE_NOOP("k528::studio::RefactorTexts", "the start and step of numbering must be at least 1")},
    {"refactor.past-999",
     QT_TRANSLATE_NOOP("k528::studio::RefactorTexts", "the last frame number would exceed 999 (%1 frames)")},
};

const Entry* entryOf(std::string_view id) {
    for (const Entry& e : kRefactorTexts)
        if (id == e.id)
            return &e;
    return nullptr;
}

} // namespace

bool hasRefactorText(std::string_view id) { return entryOf(id) != nullptr; }

QString refactorText(const program::RefactorResult& r) {
    const Entry* e = entryOf(r.textId);
    if (!e) // an id without a translation: core's English
        return QString::fromStdString(r.text(false));
    const QString pattern = QCoreApplication::translate("k528::studio::RefactorTexts", e->text);
    return QString::fromStdString(util::fillPattern(pattern.toStdString(), r.args));
}

} // namespace k528::studio
