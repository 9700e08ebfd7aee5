// What is wrong with a machine description (description.h, the PLC's
// conditions, the equipment and prove-out sections) as an id and its
// arguments: a profile::Problem whose ids are those of descriptionTexts().
// The command line says it in Russian or English from this catalog
// (DescriptionError::text), the desktop through its translators by the id
// (app/studio/session/core_texts.cpp: studio.ui_language fails on an id it
// lacks or says differently).
#pragma once

#include "profile/problem.h"
#include "util/text_catalog.h"

#include <string>
#include <string_view>
#include <vector>

namespace k528::plc {

// The catalog: each id with its Russian and English (%1..%9 its arguments; a
// problem's `within` fill the arguments after its own).
util::TextCatalog descriptionTexts();

// `p` in a language; an id missing from the catalog says the id and its
// arguments (never thrown away).
std::string descriptionText(const profile::Problem& p, bool russian);

// The problem `id` with `args` and the text `textId` of this catalog as its
// last argument (a JSON type's name: "type.string", «строка»).
profile::Problem withText(std::string id, std::vector<std::string> args, std::string_view textId);

} // namespace k528::plc
