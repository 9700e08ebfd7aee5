// Why an exercise or course file cannot be read, as ids and their arguments
// (training::ExerciseError): the command line renders them in its --lang
// from this catalog (ExerciseError::text), the desktop through its
// translators by the id.
#pragma once

#include "util/text_catalog.h"

namespace k528::training {

// The catalog: each id with its Russian and English (%1..%9 its arguments).
util::TextCatalog exerciseTexts();

} // namespace k528::training
