#pragma once
// Small helpers shared by the VTK-level tests.
#include "vtkExactMATArrayNames.h"
#include "vtkMATBoundaryConversion.h"

#include "brep/NormalisePieces.h"
#include "geometry/BoundingVolumeHierarchy.h"
#include "geometry/ClosestPoint.h"

#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkObject.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

/// Records VTK error events of an object so tests can assert on the message text.
class ErrorRecorder : public vtkCommand
{
public:
  static ErrorRecorder* New() { return new ErrorRecorder; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    if (data)
    {
      Messages += static_cast<const char*>(data);
    }
  }
  std::string Messages;

  static vtkSmartPointer<ErrorRecorder> watch(vtkObject* o)
  {
    auto r = vtkSmartPointer<ErrorRecorder>::Take(ErrorRecorder::New());
    o->AddObserver(vtkCommand::ErrorEvent, r);
    return r;
  }
};

// Largest |distance(point, solid) − Radius| / size over every `stride`-th output point; the
// solid's faces come from the source's grid, measured in the solid's unit frame (a solid
// far from the origin is measured where doubles can measure it).
inline double worstRadiusError(vtkUnstructuredGrid* solid, vtkPolyData* mat, int stride)
{
  std::vector<exactmat::PatchPiece> faces = exactmat::patchPiecesFromGrid(solid);
  const exactmat::Normalisation frame = exactmat::normalise(faces);
  std::vector<exactmat::Box3> boxes;
  exactmat::Box3 all;
  for (const exactmat::PatchPiece& f : faces)
  {
    boxes.push_back(f.patch.boundingBox());
    all.extend(boxes.back());
  }
  exactmat::BoundingVolumeHierarchy tree;
  tree.build(boxes);
  vtkDataArray* radius = mat->GetPointData()->GetArray(exactmat::arrays::Radius);
  double worst = 0.0;
  for (vtkIdType i = 0; i < mat->GetNumberOfPoints(); i += stride)
  {
    double x[3];
    mat->GetPoint(i, x);
    const exactmat::Vec3 p = frame.toUnit(exactmat::Vec3(x[0], x[1], x[2]));
    double d = 0.0;
    tree.nearest(p, [&](int k) { return exactmat::closestPoint(faces[k].patch, p).distance; }, &d);
    worst = std::max(worst, std::abs(d - frame.lengthToUnit(radius->GetTuple1(i))));
  }
  return worst / all.diagonal().norm();
}

