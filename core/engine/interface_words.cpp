#include "engine/interface_words.h"

#include <stdexcept>
#include <string>

namespace k528::engine {

bool InterfaceWords::holds(int a) {
    return slotOf(a) >= 0;
}

void InterfaceWords::notHeld(int a) {
    throw std::out_of_range("no interface word Z" + std::to_string(a));
}

} // namespace k528::engine
