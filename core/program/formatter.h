// ProgramStore -> canonical program text (program-language.md, "Canonical
// form"). format(parse(t).store) is a fixed point: formatting its own
// output gives the same text. Comments, blank lines (runs collapsed to
// one), titles and the message table are kept; see docs/program-language.md
// for the layout.
#pragma once

#include <string>

#include "program/model.h"

namespace k528::program {

// The whole store: programs by number, then the %MESSAGES section. A store
// read from a text without %L header (headerless, one program) is written
// without a header again.
std::string format(const ProgramStore& store);

// One frame in canonical form without comments: "N12 G1 X5.342 FX50",
// "/N12 R75=2*R99", "N202 IF R1>0 GOTO 301". What the editor and the panel show.
std::string formatFrame(const Frame& frame);
void appendFrame(std::string& out, const Frame& frame);

// "X5.342", "X=R12": a value word with its address.
void appendValue(std::string& out, std::string_view address, const Value& v);

} // namespace k528::program
