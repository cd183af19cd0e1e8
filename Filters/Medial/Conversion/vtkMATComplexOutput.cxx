#include "vtkMATComplexOutput.h"

#include "vtkExactMATArrayNames.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace exactmat
{

void writeMedialComplex(const MedialComplex& mat, const Normalisation& frame,
  const std::function<std::string(const MedialElement&)>& governorNames, bool withSegmentId,
  vtkPolyData* out)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mat.points.size()));
  vtkNew<vtkDoubleArray> radius;
  radius->SetName(arrays::Radius);
  radius->SetNumberOfTuples(points->GetNumberOfPoints());
  vtkNew<vtkIntArray> type, touchpoints;
  type->SetName(arrays::PointType);
  type->SetNumberOfTuples(points->GetNumberOfPoints());
  touchpoints->SetName(arrays::Touchpoints);
  touchpoints->SetNumberOfTuples(points->GetNumberOfPoints());
  for (size_t i = 0; i < mat.points.size(); ++i)
  {
    const MedialPoint3D& p = mat.points[i];
    points->SetPoint(static_cast<vtkIdType>(i), frame.toUser(p.x).data());
    radius->SetValue(static_cast<vtkIdType>(i), frame.lengthToUser(p.radius));
    type->SetValue(static_cast<vtkIdType>(i), static_cast<int>(p.type));
    touchpoints->SetValue(static_cast<vtkIdType>(i), p.contacts);
  }

  // vtkPolyData orders cells verts, lines, polys: cell data is filled in that order.
  vtkNew<vtkCellArray> verts, lines, polys;
  vtkNew<vtkIntArray> elementType, elementId, segment;
  vtkNew<vtkStringArray> governors;
  elementType->SetName(arrays::ElementType);
  elementId->SetName(arrays::ElementId);
  segment->SetName(arrays::SegmentId);
  governors->SetName(arrays::Governors);
  auto addCellData = [&](size_t e) {
    const MedialElement& el = mat.elements[e];
    elementType->InsertNextValue(static_cast<int>(el.type));
    elementId->InsertNextValue(static_cast<int>(e));
    segment->InsertNextValue(el.profileSegment);
    governors->InsertNextValue(governorNames(el));
  };
  for (int pass = 0; pass < 3; ++pass)
  {
    for (size_t e = 0; e < mat.elements.size(); ++e)
    {
      const MedialElement& el = mat.elements[e];
      std::vector<vtkIdType> ids(el.points.begin(), el.points.end());
      // (Vertex cells: junctions, and a ball's centre — the whole MAT of a sphere.)
      const bool vertex = el.type == MedialElementType::Junction || el.type == MedialElementType::SphereCentre;
      if (pass == 0 && vertex)
      {
        verts->InsertNextCell(1, ids.data());
        addCellData(e);
      }
      else if (pass == 1 && !el.points.empty() && !vertex)
      {
        lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
        addCellData(e);
      }
      else if (pass == 2)
      {
        for (const auto& t : el.triangles)
        {
          const vtkIdType tri[3] = { t[0], t[1], t[2] };
          polys->InsertNextCell(3, tri);
          addCellData(e);
        }
      }
    }
  }
  out->SetPoints(points);
  out->SetVerts(verts);
  out->SetLines(lines);
  out->SetPolys(polys);
  out->GetPointData()->AddArray(radius);
  out->GetPointData()->SetScalars(radius);
  out->GetPointData()->AddArray(type);
  out->GetPointData()->AddArray(touchpoints);
  // The touchpoints (Footpoint0 … 2, user frame) where the producer recorded them: a seam
  // point's three, a junction's first three, a radius-0 or rim point's one repeated; NaN
  // where none is recorded.
  bool anyTouches = false;
  for (const MedialPoint3D& p : mat.points)
    anyTouches = anyTouches || !p.touches.empty();
  if (anyTouches)
  {
    const char* names[3] = { arrays::Footpoint0, arrays::Footpoint1, arrays::Footpoint2 };
    for (int k = 0; k < 3; ++k)
    {
      vtkNew<vtkDoubleArray> foot;
      foot->SetName(names[k]);
      foot->SetNumberOfComponents(3);
      foot->SetNumberOfTuples(points->GetNumberOfPoints());
      for (size_t i = 0; i < mat.points.size(); ++i)
      {
        const Vec3List& touches = mat.points[i].touches;
        const Vec3 x = touches.empty() ? Vec3::Constant(std::nan(""))
                                       : frame.toUser(touches[std::min<size_t>(k, touches.size() - 1)]);
        foot->SetTuple(static_cast<vtkIdType>(i), x.data());
      }
      out->GetPointData()->AddArray(foot);
    }
  }
  out->GetCellData()->AddArray(elementType);
  out->GetCellData()->AddArray(elementId);
  if (withSegmentId)
    out->GetCellData()->AddArray(segment);
  out->GetCellData()->AddArray(governors);
}

} // namespace exactmat
