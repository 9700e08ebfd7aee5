// The machine constants as CSV, for spreadsheets:
//
//   number;axis;name;value;unit
//   1;X;НАЛИЧ.ОСИ;1;flag
//   9;X;"ПБТ В ""-""";1;flag
//
// Dialect (docs/profile-format.md): UTF-8 without byte-order mark (one is
// accepted on reading), ';' between fields (the separator spreadsheets use
// with a decimal comma), LF line ends (CRLF accepted), a header line, fields
// quoted with '"' when they hold ';', '"' or blanks at either end, '"' doubled
// inside quotes. All 152 parameters, one per row, in any order when read;
// `name` and `unit` are for people and ignored on reading; `axis` must match
// the parameter (it catches shifted rows).
#pragma once

#include "profile/profile.h"

#include <span>
#include <string>
#include <string_view>

namespace k528::profile {

// `c` is indexed by number (c[0] unused), e.g. MachineProfile::cValues().
std::string writeCParamsCsv(std::span<const std::int64_t> c);
// Throws FileError (profile/text_format.h) naming the line of the first
// problem; values are checked against their definitions.
CValues readCParamsCsv(std::string_view text, std::string_view source = "<csv>");

} // namespace k528::profile
