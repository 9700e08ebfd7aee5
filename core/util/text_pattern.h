// Core's texts are patterns with %1..%9 (problems, revision notes, prove-out
// findings, training texts, program diagnostics): this fills them, for the
// command line from core's catalogs and for the desktop from its translations.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace k528::util {

// `pattern` with %1..%9 replaced by `args` (one missing by nothing), %% by a
// per cent sign; any other % stays. One pass: an argument's own "%2" stays.
std::string fillPattern(std::string_view pattern, std::span<const std::string> args);

} // namespace k528::util
