#include "editor/completion_texts.h"

#include "editing/completion.h"
#include "session/translated_texts.h"
#include "window_language.h"

#include <QCoreApplication>

#include <optional>

namespace k528::studio {

namespace {

// core/editing/completion.cpp's catalog, each text marked for the translators.
const TranslatedText kCompletions[] = {
    {"completion.on-axis", QT_TRANSLATE_NOOP("k528::studio::CompletionTexts", "%1 (axis %2)")},
    {"completion.m-stop", QT_TRANSLATE_NOOP("k528::studio::CompletionTexts", "stop until CYCLE START")},
    {"completion.m-end-program", QT_TRANSLATE_NOOP("k528::studio::CompletionTexts", "end of program")},
    {"completion.m-end-subprogram", QT_TRANSLATE_NOOP("k528::studio::CompletionTexts", "end of subprogram")},
    {"completion.r-user", QT_TRANSLATE_NOOP("k528::studio::CompletionTexts", "user parameter")},
    {"completion.r-reserved", QT_TRANSLATE_NOOP("k528::studio::CompletionTexts", "reserved")},
    {"completion.r-reserved-read-only", QT_TRANSLATE_NOOP("k528::studio::CompletionTexts", "reserved (read only)")},
    {"completion.r-read-only", QT_TRANSLATE_NOOP("k528::studio::CompletionTexts", "%1 (read only)")},
    {"completion.program", QT_TRANSLATE_NOOP("k528::studio::CompletionTexts", "program %1")},
};

const TranslatedTexts kCompletionTexts("k528::studio::CompletionTexts", kCompletions);

} // namespace

bool hasCompletionText(std::string_view id) { return kCompletionTexts.has(id); }

QString completionDetail(const editing::CompletionItem& item) {
    // The meanings of table 5 and appendix Л are data of two languages: shown
    // in the window's.
    if (!item.detailId.empty())
        if (const std::optional<QString> text =
                kCompletionTexts.text(item.detailId, inWindowLanguage(item.detailArgsIn(true), item.detailArgsIn(false))))
            return *text;
    return coreText(item.detail(true), item.detail(false)); // a text as it is (or an id without a translation)
}

} // namespace k528::studio
