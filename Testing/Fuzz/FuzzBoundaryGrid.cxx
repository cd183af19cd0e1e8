// libFuzzer target: bytes as a hand-built vtkUnstructuredGrid of boundary cells — any cell
// type the conversion knows (and one it does not), point ids in and out of range (negative
// too), `RationalWeights` / `HigherOrderDegrees` / `EdgeId` / `FaceId` arrays of any length,
// coordinates and weights from small integers up to NaN and 1e308 — through the grid-to-
// B-rep conversion and, for curves, the normalised 2D boundary. Bad grids must be
// InputErrors naming the cell; anything else that escapes, crashes (ASan reads past an
// array) or hangs is a finding.
#include "vtkExactMATArrayNames.h"
#include "vtkMATBoundaryConversion.h"

#include "brep/NormalisePieces.h"
#include "common/InputError.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace
{
double value(FuzzedDataProvider& in)
{
  switch (in.ConsumeIntegralInRange<int>(0, 15))
  {
    case 0:
      return std::numeric_limits<double>::quiet_NaN();
    case 1:
      return in.ConsumeBool() ? 1e308 : -1e308;
    case 2:
      return 0.0;
    case 3:
      return in.ConsumeFloatingPoint<double>();
    default:
      return in.ConsumeIntegralInRange<int>(-8, 8) * 0.25; // coincident and collinear points
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace exactmat;
  vtkObject::GlobalWarningDisplayOff();
  FuzzedDataProvider in(data, size);
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const int pointCount = in.ConsumeIntegralInRange<int>(0, 40);
  const bool planar = in.ConsumeBool();
  for (int i = 0; i < pointCount; ++i)
  {
    const double x = value(in), y = value(in), z = planar ? 0.0 : value(in);
    points->InsertNextPoint(x, y, z);
  }
  grid->SetPoints(points);
  static const int types[] = { VTK_BEZIER_CURVE, VTK_LINE, VTK_POLY_LINE, VTK_BEZIER_QUADRILATERAL,
    VTK_BEZIER_TRIANGLE, VTK_QUAD, VTK_TRIANGLE, VTK_VERTEX, VTK_BEZIER_HEXAHEDRON };
  const int cellCount = in.ConsumeIntegralInRange<int>(0, 12);
  grid->Allocate(cellCount);
  for (int c = 0; c < cellCount; ++c)
  {
    const int type = types[in.ConsumeIntegralInRange<int>(0, sizeof(types) / sizeof(int) - 1)];
    const int n = in.ConsumeIntegralInRange<int>(0, 20);
    vtkNew<vtkIdList> ids;
    for (int k = 0; k < n; ++k)
      ids->InsertNextId(in.ConsumeIntegralInRange<int>(-3, pointCount + 3));
    grid->InsertNextCell(type, ids);
  }
  if (in.ConsumeBool())
  {
    vtkNew<vtkDoubleArray> weights;
    weights->SetName(arrays::RationalWeights);
    const int n = in.ConsumeIntegralInRange<int>(0, pointCount + 2);
    for (int i = 0; i < n; ++i)
      weights->InsertNextValue(in.ConsumeBool() ? 1.0 : value(in));
    grid->GetPointData()->AddArray(weights);
  }
  if (in.ConsumeBool())
  {
    vtkNew<vtkIntArray> degrees;
    degrees->SetName(arrays::HigherOrderDegrees);
    degrees->SetNumberOfComponents(in.ConsumeBool() ? 3 : in.ConsumeIntegralInRange<int>(1, 4));
    const int n = in.ConsumeIntegralInRange<int>(0, cellCount + 2) * degrees->GetNumberOfComponents();
    for (int i = 0; i < n; ++i)
      degrees->InsertNextValue(in.ConsumeIntegralInRange<int>(-2, 40));
    grid->GetCellData()->AddArray(degrees);
  }
  for (const char* name : { arrays::EdgeId, arrays::FaceId })
  {
    if (!in.ConsumeBool())
      continue;
    vtkNew<vtkIntArray> ids;
    ids->SetName(name);
    const int n = in.ConsumeIntegralInRange<int>(0, cellCount + 2);
    for (int i = 0; i < n; ++i)
      ids->InsertNextValue(in.ConsumeIntegralInRange<int>(-2, 100));
    grid->GetCellData()->AddArray(ids);
  }
  try
  {
    if (gridHasSurfaceCells(grid))
      (void)patchPiecesFromGrid(grid);
    else
      (void)buildNormalised(curvePiecesFromGrid(grid));
  }
  catch (const InputError&)
  {
  }
  return 0;
}
