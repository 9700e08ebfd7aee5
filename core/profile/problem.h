// What is wrong with a machine file, a constants CSV or one of their items,
// as an id and its arguments: the command line says it in Russian or English
// from the catalog below (problemTexts(): FileError::what(), the check...
// functions, problemText), the desktop says it in its window's language by
// the id (app/studio/session/core_texts.cpp). A new text gets its id here and
// its translation there; studio.ui_language fails on an id the desktop lacks
// or says differently.
#pragma once

#include "catalog/messages.h"
#include "util/text_catalog.h"
#include "util/text_pattern.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace k528::profile {

struct Problem {
    std::string id;                // one of problemTexts(); "" when nothing is wrong
    std::vector<std::string> args; // %1, %2 … (names, numbers, the file's own text)
    // A problem of a part that this one names ("title: %1", the part's
    // problem as the last argument).
    std::vector<Problem> within;

    bool empty() const { return id.empty(); }
    // English, e.g. "C022 = 9 is outside the range 10...5000 of «УСКОРЕНИЕ 1»".
    std::string text() const;
};

Problem problem(std::string id, std::vector<std::string> args = {});

// The catalog: each id with its Russian and English (%1..%9 its arguments; a
// problem's `within` fill the arguments after its own).
util::TextCatalog problemTexts();
// `p` in a language; an id missing from the catalog says the id and its
// arguments (never thrown away).
std::string problemText(const Problem& p, bool russian);
// util/text_pattern.h: the one filler of core's texts and of their
// translations in the desktop.
using util::fillPattern;

// The item checks as problems (validate.h's check... say their text()).
Problem nameProblem(std::string_view name);
Problem titleProblem(std::string_view title);
Problem cValueProblem(int number, std::int64_t value);
Problem rPresetProblem(int number, std::int64_t value);
Problem programProblem(int number, std::string_view text);
Problem messageProblem(int number, std::string_view text);
Problem plcTextProblem(catalog::PlcGroup group, int k, std::string_view text);
Problem settingProblem(std::string_view key, std::string_view value);
Problem settingKeyProblem(std::string_view key);
Problem settingValueProblem(std::string_view value);
Problem simulationValueProblem(std::string_view key, std::string_view value);

} // namespace k528::profile
