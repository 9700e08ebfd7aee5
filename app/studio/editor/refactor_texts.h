// Why a refactoring changed nothing (core's program/refactor.h: an id and
// its arguments) in the window's language, through its translators. The
// command line says the same ids from core's catalog (refactorTexts()).
#pragma once

#include <QString>

#include <string_view>

namespace k528::program {
struct RefactorResult;
} // namespace k528::program

namespace k528::studio {

// E.g. «программы L7 нет»; "" when the refactoring was done.
QString refactorText(const program::RefactorResult& r);
// The id has a text here (studio.ui_language: every id of core's catalog has).
bool hasRefactorText(std::string_view id);

} // namespace k528::studio
