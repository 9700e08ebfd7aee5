// The texts of a training grade (core/training: deductions, notes on the
// operator's procedure, what a step did not do): an id and its Russian and
// English template, %1..%9 its arguments (numbers, frame names, coordinates,
// texts of two languages — never words of one language). The CLI renders them
// from here (training::render); the desktop renders the same ids through
// tr() (app/studio/training/training_texts.cpp), its Russian in
// translations/pairs/training-texts.ru.tsv. Beside the positioner's messages
// (messages.h): one catalog of what core says.
#pragma once

#include <span>
#include <string_view>

namespace k528::catalog {

struct TrainingText {
    std::string_view id, ru, en;
};

// Every text a grade can show, one entry per id.
std::span<const TrainingText> trainingTexts();
// nullptr for an id the catalog does not hold.
const TrainingText* findTrainingText(std::string_view id);

} // namespace k528::catalog
