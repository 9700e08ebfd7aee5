// The texts of a training grade (core/training: deductions, notes on the
// operator's procedure, what a step did not do): an id and its Russian and
// English template, %1..%9 its arguments (numbers, frame names, coordinates,
// texts of two languages — never words of one language). The CLI renders them
// from here (training::render); the desktop renders the same ids through
// tr() (app/studio/training/training_texts.cpp), its Russian in
// translations/pairs/training-texts.ru.tsv. Beside the positioner's messages
// (messages.h): one catalog of what core says.
#pragma once

#include "util/text_catalog.h"

namespace k528::catalog {

// Every text a grade can show, one entry per id.
util::TextCatalog trainingTexts();

} // namespace k528::catalog
