// The trainer's names of the simulated machine's faults, translated: the one
// place the desktop turns core's fault id and arguments (machine::faultText)
// into words. The CLI keeps core's English (machine::describeFault).
#pragma once

#include <QString>

namespace k528::machine {
struct FaultSpec;
}

namespace k528::studio {

// E.g. "Encoder X: channel 1 broken" / «ДОС X: обрыв канала 1».
QString faultTitle(const machine::FaultSpec& f);

} // namespace k528::studio
