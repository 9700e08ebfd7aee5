// The texts of a training grade in the desktop's language: core's catalog
// ids (catalog/training_texts.h) rendered through tr() — the one place the
// desktop turns a grade's text id and arguments into words; the CLI renders
// the same ids from core's catalog (training::render).
#pragma once

#include "training/texts.h"

#include <QString>

namespace k528::studio {

// The text in the desktop's language; an id it does not know: core's
// rendering (never empty, never thrown away).
QString trainingText(const training::Text& t);
// The desktop's template of an id (its %1..%9 the arguments), empty when it
// has none (a test holds it to the catalog).
QString trainingTextPattern(const std::string& id);

} // namespace k528::studio
