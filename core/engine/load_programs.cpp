#include "engine/load_programs.h"

#include "engine/positioner.h"
#include "program/model.h"

namespace k528::engine {

void mergePrograms(program::ProgramStore& into, const program::ProgramStore& from) {
    for (const program::Program& p : from.programs())
        into.insert(p);
    for (const program::Message& m : from.messages.entries)
        into.messages.set(m.number, m.text);
}

OpResult loadPrograms(Positioner& ctl, const program::ProgramStore& from) {
    program::ProgramStore* store = ctl.editablePrograms();
    if (!store)
        return OpResult::refused(Refusal::ProgramActive, "program-active");
    mergePrograms(*store, from);
    return ctl.programsEdited();
}

} // namespace k528::engine
