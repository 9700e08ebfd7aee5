#include "engine/interface_words.h"

#include <stdexcept>
#include <string>

namespace k528::engine {

bool InterfaceWords::holds(int a) {
    return (a >= 1000 && a <= 1013) || (a >= 1300 && a <= 1307) || (a >= 1900 && a <= 1907) ||
           (a >= 2000 && a <= 2008);
}

void InterfaceWords::notHeld(int a) {
    throw std::out_of_range("no interface word Z" + std::to_string(a));
}

} // namespace k528::engine
