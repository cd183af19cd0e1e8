// Build an exact free-form boundary from a user-defined NURBS curve, write it as VTK XML
// (.vtu, rational Bézier cells that ParaView renders as they are) and print what it holds.
//
//   ExactMATExampleBoundary out.vtu
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkNURBSSource.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cmath>
#include <iostream>

int main(int argc, char* argv[])
{
  const char* file = argc > 1 ? argv[1] : "boundary.vtu";

  // A closed cubic B-spline: 8 control points on a wobbly circle, the first 3 repeated and
  // uniform knots, so the curve closes with C² continuity.
  vtkNew<vtkPoints> points;
  const double r[8] = { 2.0, 1.2, 2.2, 1.0, 2.0, 1.3, 2.4, 1.1 };
  for (int i = 0; i < 11; ++i)
  {
    const double a = 2.0 * 3.14159265358979 * (i % 8) / 8.0;
    points->InsertNextPoint(r[i % 8] * std::cos(a), r[i % 8] * std::sin(a), 0.0);
  }
  vtkNew<vtkDoubleArray> knots;
  for (int i = 0; i < 15; ++i)
  {
    knots->InsertNextValue((i - 3) / 8.0);
  }

  vtkNew<vtkNURBSSource> source;
  source->SetShape(vtkNURBSSource::UserDefined);
  source->AddCurve(3, knots, points, nullptr);
  source->Update();
  vtkUnstructuredGrid* boundary = source->GetOutput();
  if (boundary->GetNumberOfCells() == 0)
  {
    std::cerr << "the source reported an error\n";
    return 1;
  }
  std::cout << "boundary: " << boundary->GetNumberOfCells() << " rational Bezier cells, "
            << boundary->GetNumberOfPoints() << " control points\n";

  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(boundary);
  writer->SetFileName(file);
  if (writer->Write() != 1)
  {
    return 1;
  }
  std::cout << "wrote " << file << "\n";
  return 0;
}
