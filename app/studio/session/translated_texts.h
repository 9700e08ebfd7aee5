// Core's texts in the window's language: a table of core's ids, each with
// its English (as core's catalog says it) marked for the translators under
// one context, QT_TRANSLATE_NOOP(context, english); said through
// QCoreApplication::translate and filled as core fills its own
// (util::fillPattern: %1..%9 in one pass, %% a per cent sign). The one
// renderer of the desktop's tables of core's texts (core_texts.cpp,
// diagnostic_texts.cpp, database_texts.cpp, controller/link_texts.cpp,
// editor/refactor_texts.cpp, editor/completion_texts.cpp,
// training/training_texts.cpp).
#pragma once

#include <QString>

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace k528::studio {

// One id of core's and its English, QT_TRANSLATE_NOOP(the table's context, …).
struct TranslatedText {
    const char* id;
    const char* english;
};

class TranslatedTexts {
public:
    template <std::size_t N>
    constexpr TranslatedTexts(const char* context, const TranslatedText (&table)[N])
        : context_(context), table_(table) {}

    // The table has a text for `id` (studio.ui_language: every id of core's catalog has).
    bool has(std::string_view id) const { return find(id) != nullptr; }
    // The text of `id` in the window's language, its %1..%9 unfilled; empty
    // when the table lacks the id.
    QString pattern(std::string_view id) const;
    // The text of `id` in the window's language with `args` filled in;
    // nothing when the table lacks the id (the caller says core's words).
    std::optional<QString> text(std::string_view id, std::span<const std::string> args) const;

private:
    const TranslatedText* find(std::string_view id) const;

    const char* context_;
    std::span<const TranslatedText> table_;
};

// A text of core's that holds other texts (`within`: «в кадре N5» inside a
// diagnostic, a system error inside a file's problem), as core renders it:
// each part said first (`sayPart`, in the window's language too) and added
// after the text's own arguments; then the first table of `tables` with
// the id says it. An id none has is said in core's own words (`coreWords()`),
// so a text core gains before the desktop does still reads.
template <class Part, class SayPart, class CoreWords>
QString sayWithin(std::initializer_list<const TranslatedTexts*> tables, std::string_view id,
                  std::span<const std::string> args, const std::vector<Part>& within, SayPart&& sayPart,
                  CoreWords&& coreWords) {
    std::vector<std::string> all(args.begin(), args.end());
    for (const Part& w : within)
        all.push_back(sayPart(w).toStdString());
    for (const TranslatedTexts* table : tables)
        if (std::optional<QString> text = table->text(id, all))
            return *std::move(text);
    return coreWords();
}

} // namespace k528::studio
