// What the parser and the validator say about a program text: one catalog
// of ids with their Russian and English (%1..%9 the arguments; a
// diagnostic's `within` fill the arguments after its own). The command line
// says a diagnostic from it (formatDiagnostic, `k528 check --json`), the
// desktop through its translators by the id
// (app/studio/session/diagnostic_texts.cpp: studio.ui_language fails on an
// id it lacks or says differently).
#pragma once

#include "program/diagnostic.h"
#include "util/text_catalog.h"

#include <string>

namespace k528::program {

// The catalog: each id with its Russian and English.
util::TextCatalog diagnosticTexts();

// The text of `d` (or of a part) in a language; an id missing from the
// catalog says the id and its arguments (never thrown away).
std::string diagnosticText(const Diagnostic& d, bool russian);
std::string diagnosticText(const DiagnosticPart& p, bool russian);

} // namespace k528::program
