// The controller link's texts (client.h's LinkError and PushReport, the
// transports' words on a lost exchange, the line's failures): ids with their
// Russian and English, %1..%9 the arguments. A Said is one of them with its
// arguments, each argument a word of no language (a number, a register
// range, a file name) or another text. The command line renders a Said from
// this catalog in its --lang; the desktop renders the same ids through its
// translators (app/studio/controller/link_texts.cpp: studio.ui_language
// fails on an id it lacks or says differently).
#pragma once

#include "link/line_error.h"
#include "util/text_catalog.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace k528::program {
struct Diagnostic;
}
namespace k528::profile {
struct Problem;
}

namespace k528::link {

util::TextCatalog linkTexts();

// A text of the catalog with its arguments, or a word of no language (no
// id), or a program diagnostic or a profile problem (their own catalogs).
struct Said {
    Said() = default;
    Said(std::string word) : word(std::move(word)) {} // NOLINT: a word of no language
    Said(const char* word) : word(word) {}            // NOLINT
    Said(std::string_view id, std::vector<Said> args) : id(id), args(std::move(args)) {}

    std::string id;
    std::vector<Said> args;
    std::string word;
    std::shared_ptr<const program::Diagnostic> diagnostic;
    std::shared_ptr<const profile::Problem> problem;

    bool empty() const { return id.empty() && word.empty() && !diagnostic && !problem; }
};

// The text `id` of linkTexts() with its arguments.
inline Said say(std::string_view id, std::vector<Said> args = {}) { return Said(id, std::move(args)); }
Said saidDiagnostic(const program::Diagnostic& d);
Said saidProblem(const profile::Problem& p);

// `s` in a language, its arguments rendered first; an id the catalog lacks
// says the id and its arguments.
std::string render(const Said& s, bool russian);

// A line's failure as a plugin reports it (line_error.h: an id of this
// catalog and its arguments) as a Said; any other string is the system's
// own words, kept as they are.
Said decodeSaid(std::string_view text);

} // namespace k528::link
