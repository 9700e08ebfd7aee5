// Emptying an ISO frame that is filled again frame after frame: the one
// the parser reads each ISO frame into, the one the validator decodes each
// into (internal to core/program).
#pragma once

#include <memory>
#include <optional>
#include <type_traits>

#include "program/model.h"

namespace k528::program {

// The frame as a new IsoFrame is, without building one (assigning
// IsoFrame() copies all of its ~270 bytes): the word counts are zeroed
// and each optional word is made anew, empty, in its place. reset() would
// first test whether it holds a word, a branch that follows the words of
// the frame and was mispredicted about twice a frame; an empty optional of
// a trivially destructible word is one store of its flag.
inline void clearIsoFrame(IsoFrame& f) {
    static_assert(std::is_trivially_destructible_v<std::optional<Word>> &&
                      std::is_trivially_destructible_v<std::optional<Value>>,
                  "an optional word is made anew over the old one without ending it");
    f.g.clear();
    f.m.clear();
    std::construct_at(&f.message);
    std::construct_at(&f.call);
    std::construct_at(&f.x);
    std::construct_at(&f.fx);
    std::construct_at(&f.z);
    std::construct_at(&f.fz);
}

} // namespace k528::program
