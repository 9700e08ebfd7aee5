// The window's language where core gives both at once. A text of the
// desktop itself is tr(); a core text with an id is core_texts.h's (and
// catalog_texts.h's for the names and messages of core's catalogs).
#pragma once

#include <QString>

#include <string_view>
#include <utility>

namespace k528::studio {

// Whether the window speaks Russian: only for what is about the language
// itself rather than a choice between two texts (which translator is
// loaded, the locale of a date or a number, the language of a PDF).
bool russianWindow();

// The one place that picks between what core gives in both languages: the
// Russian's in a Russian window, else the English's. Two texts (coreText
// below), the language core is told to speak (`inWindowLanguage(db::Lang::Ru,
// db::Lang::En)`), or a text's arguments in each language.
template <class T>
T inWindowLanguage(T ru, T en) {
    return russianWindow() ? std::move(ru) : std::move(en);
}

// A text core holds as data in both languages, too many or too much made
// of values for the translators' files: a C-parameter's description, hint
// and unit, an R-parameter's meaning, a check's finding with its values,
// a message recorded in the history, a machine file's text and its English.
QString coreText(std::string_view ru, std::string_view en);

} // namespace k528::studio
