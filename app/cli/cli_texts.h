// What the command line itself says — the reports of `k528 db`, the lines of
// `k528 shop`, the option errors of the commands — as ids with their Russian
// and English (core's util::TextCatalog, %1..%9 the arguments). Core's own
// texts (a database's refusal, a link error, a program diagnostic) come from
// core's catalogs; these are the words the command line adds around them.
// Every id a command says is in the catalog and every text has both
// languages (test cli.texts), so a Russian run never falls back to English.
#pragma once

#include "util/text_catalog.h"

#include <initializer_list>
#include <string>
#include <string_view>

namespace k528::cli {

util::TextCatalog cliTexts();

// The text `id` in a language, %1..%9 filled with `args`.
std::string cliText(std::string_view id, std::initializer_list<std::string> args, bool russian);
// The same in the command line's language (russianCommandLine(), args.cpp).
std::string cliText(std::string_view id, std::initializer_list<std::string> args = {});
// A text without arguments as the catalog holds it, nothing allocated: what
// is said when memory ran out. An id the catalog lacks is said itself.
std::string_view cliWords(std::string_view id, bool russian);

} // namespace k528::cli
