// What the database module says, as ids and their arguments (db::ErrorText):
// an error's text and the words of `k528 db set`'s items. The command line
// renders them in its --lang from this catalog (Error::text), the desktop
// through its translators by the id (app/studio/session/database_texts.cpp:
// studio.ui_language fails on an id it lacks or says differently).
#pragma once

#include "util/text_catalog.h"

#include <span>
#include <string>
#include <string_view>

namespace k528::db {

// The catalog: each id with its Russian and English (%1..%9 its arguments).
util::TextCatalog dbTexts();

// The text `id` in a language; an id missing from the catalog says the id
// and its arguments (never thrown away).
std::string dbText(std::string_view id, std::span<const std::string> args, bool russian);

} // namespace k528::db
