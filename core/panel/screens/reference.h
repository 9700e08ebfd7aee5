// ПРИВЯЗКА К БАЗОВОЙ ТОЧКЕ (2.6.4): one screen.
//
//   ПБТ X          100%*    «X»/«Z» (columns 5 and 7): the axis is homed
//                           line 2 is empty
//    X   234.567#3.124      mark, letter, current coordinate (3–11),
//   *Z-1065.124#5.050       «#» and the distance from leaving the cam to
//                           the zero mark (R246/R247) from column 13
#pragma once

#include "panel/screen.h"

namespace k528::panel {

class ReferenceScreen : public Screen {
public:
    void render(Canvas& c, const Context& ctx) const override;
    void key(KeyPress, Context&) override {}
};

} // namespace k528::panel
