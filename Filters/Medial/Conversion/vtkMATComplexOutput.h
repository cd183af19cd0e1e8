#pragma once
/// @file vtkMATComplexOutput.h
/// @brief Writes the MAT of a solid (a MedialComplex, swept or free-form) as vtkPolyData in
/// the user's frame: points with `Radius`, `PointType`, `Touchpoints`; junctions as vertex
/// cells, curves as polylines, sheets as triangles; cell data `ElementType`, `ElementId`,
/// `Governors` (and `SegmentId` when the producer has one).

#include "common/Normalisation.h"
#include "medial/MedialComplex.h"

#include <functional>
#include <string>

class vtkPolyData;

namespace exactmat
{

/// `governors` names an element's governing boundary entities ("3,7,start");
/// `withSegmentId` adds the 2.5D `SegmentId` array (the profile MAT segment).
void writeMedialComplex(const MedialComplex& mat, const Normalisation& frame,
  const std::function<std::string(const MedialElement&)>& governors, bool withSegmentId,
  vtkPolyData* out);

} // namespace exactmat
