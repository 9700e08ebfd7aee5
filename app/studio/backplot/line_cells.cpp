#include "backplot/line_cells.h"

#include <cassert>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace k528::backplot {

void setCells(vtkPolyData* data, const std::vector<float>& v, int verticesPerCell, double z) {
    assert(verticesPerCell == 2 || verticesPerCell == 3);
    const vtkIdType k = verticesPerCell;
    vtkNew<vtkPoints> pts;
    pts->SetDataTypeToFloat();
    const vtkIdType n = static_cast<vtkIdType>(v.size() / static_cast<std::size_t>(2 * k));
    pts->SetNumberOfPoints(k * n);
    vtkNew<vtkCellArray> cells;
    cells->AllocateExact(n, k * n);
    vtkIdType ids[3];
    for (vtkIdType i = 0; i < n; ++i) {
        const float* f = v.data() + 2 * k * i;
        for (vtkIdType j = 0; j < k; ++j) {
            pts->SetPoint(k * i + j, f[2 * j], f[2 * j + 1], z);
            ids[j] = k * i + j;
        }
        cells->InsertNextCell(k, ids);
    }
    data->Initialize();
    data->SetPoints(pts);
    if (k == 2)
        data->SetLines(cells);
    else
        data->SetPolys(cells);
    data->Modified();
}

} // namespace k528::backplot
