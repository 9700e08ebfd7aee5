// The project's JSON value, declared without nlohmann-json's full header (for
// headers that only hold or pass a value; code that reads or builds one
// includes util/json.h).
#pragma once

#include <nlohmann/json_fwd.hpp>

namespace k528 {

// Objects keep their insertion order (output is stable and diff-friendly);
// integers are exact (number_integer int64, number_unsigned uint64).
using Json = nlohmann::ordered_json;

} // namespace k528
