#include "backplot/line_cells.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace k528::backplot {

void setLines(vtkPolyData* data, const std::vector<float>& v, double z) {
    vtkNew<vtkPoints> pts;
    pts->SetDataTypeToFloat();
    const vtkIdType n = static_cast<vtkIdType>(v.size() / 4);
    pts->SetNumberOfPoints(2 * n);
    vtkNew<vtkCellArray> cells;
    cells->AllocateExact(n, 2 * n);
    for (vtkIdType i = 0; i < n; ++i) {
        const float* f = v.data() + 4 * i;
        pts->SetPoint(2 * i, f[0], f[1], z);
        pts->SetPoint(2 * i + 1, f[2], f[3], z);
        const vtkIdType ids[2] = {2 * i, 2 * i + 1};
        cells->InsertNextCell(2, ids);
    }
    data->Initialize();
    data->SetPoints(pts);
    data->SetLines(cells);
    data->Modified();
}

} // namespace k528::backplot
