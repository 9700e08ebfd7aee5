// Lines and triangles into a vtkPolyData: the one way the backplot's layers
// and the tool's edge fill their buffers.
#pragma once

#include <vector>

class vtkPolyData;

namespace k528::backplot {

// Replaces the contents of `data` with cells of `verticesPerCell` vertices at
// depth z, 2 floats (x, y) a vertex: 2 vertices make lines, 3 triangles.
void setCells(vtkPolyData* data, const std::vector<float>& v, int verticesPerCell, double z);

} // namespace k528::backplot
