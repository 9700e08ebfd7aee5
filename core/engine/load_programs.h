// Loading parsed programs into a store or a controller: the one way `run`,
// `check`, the desktop's program loader and the test rigs put a file's
// programs over the machine's.
#pragma once

#include "engine/types.h"

namespace k528::program {
class ProgramStore;
}

namespace k528::engine {

class Positioner;

// Copies every program and message of `from` into `into`; one with the same
// number replaces the one there, the others stay.
void mergePrograms(program::ProgramStore& into, const program::ProgramStore& from);

// The same into the controller's store, then Positioner::programsEdited().
// Refused (ProgramActive) while a program runs or is held: nothing changes.
OpResult loadPrograms(Positioner& ctl, const program::ProgramStore& from);

} // namespace k528::engine
