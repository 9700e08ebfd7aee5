// Whether the window speaks Russian: the one switch for what core gives in
// both languages at once (an alarm's, a training text's, a check's Russian
// and English; a date's or a number's locale; a PDF in the window's
// language). A text of the desktop itself is tr(); a core text with an id
// is core_texts.h's.
#pragma once

namespace k528::studio {

bool russianWindow();

} // namespace k528::studio
