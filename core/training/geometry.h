// The Boost.Geometry types of the half profile for the grade's sources: the
// prove-out's (proveout/polygons.h), where the material along the actual path
// is cut.
#pragma once

#include "proveout/polygons.h"

namespace k528::training {
namespace geo = proveout::geo;
} // namespace k528::training
