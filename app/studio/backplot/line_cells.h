// Line segments into a vtkPolyData: the one way the backplot's layers and
// the tool's edge fill their buffers.
#pragma once

#include <vector>

class vtkPolyData;

namespace k528::backplot {

// Replaces the contents of `data` with lines (4 floats a line: x0, y0, x1, y1) at depth z.
void setLines(vtkPolyData* data, const std::vector<float>& v, double z);

} // namespace k528::backplot
