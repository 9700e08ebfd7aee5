// The database's texts (core/db/db_texts.h: an error's id and arguments,
// the words of an edit's items) in the window's language, by tr(): the same
// ids the command line renders from core's catalog (studio.ui_language
// fails on an id this table lacks or says differently).
#pragma once

#include <QString>

#include <string>
#include <string_view>
#include <vector>

namespace k528::db {
struct ErrorText;
}

namespace k528::studio {

// The text `id` with its arguments; "" for an id this table lacks.
QString databaseText(std::string_view id, const std::vector<std::string>& args);
// An error's whole text: what it concerns ("PATH: "), the text, what follows
// ("; the file was left untouched"); "" when its id is not in the table.
QString databaseText(const db::ErrorText& t);
bool hasDatabaseText(std::string_view id);

} // namespace k528::studio
