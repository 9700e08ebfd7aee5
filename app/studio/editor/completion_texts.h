// What a completion of the program editor means (core's editing/completion.h:
// an id and its arguments, or a text shown as it is) in the window's
// language, through its translators; core's catalog (completionTexts()) says
// the same ids (studio.ui_language fails on an id this table lacks or says
// differently).
#pragma once

#include <QString>

#include <string_view>

namespace k528::editing {
struct CompletionItem;
} // namespace k528::editing

namespace k528::studio {

// E.g. «подача (ось X)», «параметр пользователя», a program's title.
QString completionDetail(const editing::CompletionItem& item);
// The id has a text here (studio.ui_language: every id of core's catalog has).
bool hasCompletionText(std::string_view id);

} // namespace k528::studio
