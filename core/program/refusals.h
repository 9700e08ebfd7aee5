// The combinations of words in one ISO frame the K528-05 refuses (appendix
// М, messages 34..36, 50..52, 58..64): one table, read by the validator
// (`k528 check`, the editor: every refusal a frame matches is an error at its
// word) and by the engine's interpreter (`k528 run`, the desktop: the first
// refusal of the table a frame matches is the alarm raised when the frame
// is reached). docs/program-language.md, "Refused combinations".
//
// A refusal names the words that must all be in the frame (`needs`) and
// the words that must not (`unless`). X of a frame with G04 is the dwell's
// time (table 5: «Задается по адресу X в секундах»), not a coordinate: the
// word `Coordinate X` is X without G04. `SubprogramEnd` is not a word but
// where the frame stands: the last frame of a subprogram (the validator:
// of a program some program of the store calls; the interpreter: of a
// program running as a called level).
#pragma once

#include "program/diagnostic.h"
#include "program/model.h"

#include <cstdint>
#include <span>
#include <string_view>

namespace k528::program {

namespace refusal {
enum Word : std::uint16_t {
    Dwell = 1u << 0,            // G04
    CoordinateX = 1u << 1,      // X without G04 (with G04, X is the dwell's time)
    Z = 1u << 2,                // Z
    Call = 1u << 3,             // L
    End = 1u << 4,              // M02
    SubprogramEnd = 1u << 5,    // M17
    EndRewind = 1u << 6,        // M30
    LastOfSubprogram = 1u << 7, // the frame is the last of a subprogram (not a word)
};
using Words = std::uint16_t;
} // namespace refusal

// The word a diagnostic of the refusal points at.
enum class RefusalSpot : std::uint8_t { X, Z, Call, M2, M17, M30 };

struct Refusal {
    int message;           // appendix М number
    Rule rule;             // the validator's rule
    refusal::Words needs;  // all of these in the frame
    refusal::Words unless; // none of these
    RefusalSpot spot;      // where the validator reports it
    // The diagnostic's text, an id of diagnostic_texts.h: %1 the program
    // named ("L2": the one the frame calls, or for LastOfSubprogram the
    // subprogram itself), %2 the frame («в кадре N5» / "in frame N5", or
    // without N).
    std::string_view textId;

    constexpr bool matches(refusal::Words w) const {
        return (w & needs) == needs && (w & unless) == 0;
    }
};

// The table, in the order the interpreter tries it.
std::span<const Refusal> refusals();

// The words of an ISO frame the table looks at (without LastOfSubprogram).
refusal::Words refusalWords(const IsoFrame& iso);

// The first refusal of the table `words` match, nullptr if none (the interpreter).
inline const Refusal* firstRefusal(refusal::Words words) {
    for (const Refusal& r : refusals())
        if (r.matches(words))
            return &r;
    return nullptr;
}

} // namespace k528::program
