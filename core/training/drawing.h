// The drawing of an exercise as regions of the half profile (z, r): the
// nominal part, and the two limits its tolerances allow — the most material
// (every size at its limit towards more material) and the least. A part is
// within the drawing where it holds the least material and nothing beyond
// the most (docs/training-course.md).
//   - a contour: each element offset along its outward normal by its
//     deviation (a cylinder by half its diameter's), the offset lines met at
//     the corners; the ends on the axis stay on it;
//   - a bore: the ring between ring.z with the bore's diameter at its limits;
//   - the reference program's part: that part, grown and shrunk by the
//     uniform tolerance.
#pragma once

#include "proveout/actual.h"
#include "training/exercise.h"

#include <vector>

namespace k528::training {

using proveout::Shape;

struct DrawingShapes {
    bool present = false;
    std::vector<Shape> nominal, most, least;
};

// From the exercise's contour or bore (not for Kind::Reference).
DrawingShapes drawingShapes(const Exercise& e);
// From the part the reference program made.
DrawingShapes drawingFromPart(const std::vector<Shape>& part, const Tolerance& t);

} // namespace k528::training
