// What a machine constant's value means, in the words a technologist uses:
// C040 = 500000 -> "5000 мм/мин", C029 = 2047 -> "10.00 В", C017 = 3 ->
// "2-й модуль СР34.23, канал 1". Used by `k528 db show` and the desktop.
// (Not database-specific; it lives here until core/profile takes it.)
#pragma once

#include "db/error.h" // Lang
#include "profile/profile.h"

#include <string>
#include <string_view>

namespace k528::db {

// The meaning of C-parameter `number`'s value in `p` (one line, may be "").
std::string explainCValue(const profile::MachineProfile& p, int number, Lang lang);

// Fast-input functions of tables Е.1.1 (axis X, 1..10) and Е.1.2 (axis Z,
// 1..9); "" for an unknown number. `zAxis` selects table Е.1.2.
std::string_view fastInputFunction(int function, bool zAxis, Lang lang);

// The title of a program: the text in parentheses of its «%L<n> (title)»
// header, "" if none.
std::string programTitle(std::string_view text);

} // namespace k528::db
