// Refactorings that keep a program store right: renumbering the
// frames of a program with every IF/GOTO target following its frame, and
// moving or copying a program to another number with the L calls that name
// it following. Pure functions over the model; the text comes back through
// the canonical formatter (format()).
#pragma once

#include <string>
#include <vector>

#include "program/model.h"
#include "util/text_catalog.h"

namespace k528::program {

struct RefactorResult {
    bool ok = true;
    std::string textId;            // why nothing was changed: an id of refactorTexts()
    std::vector<std::string> args; // its arguments (%1..)
    // Why nothing was changed, in a language ("" when it was done).
    std::string text(bool russian) const;
};

// Why a refactoring changed nothing: each id with its Russian and English
// (%1..%9 its arguments); the command line renders from it, the desktop
// through its translators (studio.ui_language compares their Russian).
util::TextCatalog refactorTexts();

// Gives every frame of `program` the number start, start+step, ... in order
// and rewrites every IF/GOTO target to the new number of the frame it named
// (the first frame with that N, as the interpreter jumps). A target that
// names no frame (message 53) is left as written. Fails, changing nothing,
// when the last number would pass 999 or start/step are not >= 1.
RefactorResult renumber(Program& program, int start = 1, int step = 1);

// Program `from` becomes program `to` (which must not exist); every L call
// in the store that named `from` names `to`. Fails, changing nothing, when
// `from` does not exist, `to` exists or is out of 1..99.
RefactorResult moveProgram(ProgramStore& store, int from, int to);

// A copy of program `from` is stored as `to` (which must not exist). Calls
// in other programs keep calling `from`; calls inside the copy that named
// `from` itself name `to`.
RefactorResult copyProgram(ProgramStore& store, int from, int to);

} // namespace k528::program
