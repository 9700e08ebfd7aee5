// Why an operator function was refused, as an id and its arguments (the
// value and the limit): an OpResult's `id` is one of refusalTexts(). The
// command line says it in Russian or English from this catalog
// (OpResult::text), the desktop through its translators by the id
// (app/studio/session/core_texts.cpp: studio.ui_language fails on an id it
// lacks or says differently).
#pragma once

#include "util/text_catalog.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace k528::engine {

struct OpResult;
enum class Refusal : std::uint8_t;

// The catalog: each id with its Russian and English (%1..%9 its arguments).
util::TextCatalog refusalTexts();

// The id of a refusal's kind ("kind.wrong-mode", …; "" for None): what an
// OpResult without an id of its own says.
std::string_view refusalKindId(Refusal r);

// `r` in a language ("" when accepted); an id missing from the catalog says
// the id and its arguments (never thrown away).
std::string refusalText(const OpResult& r, bool russian);

} // namespace k528::engine
