#pragma once
/// @file RimSheet.h
/// @brief The sheet a closed rim bounds when the MAT has no seam (issue 11's ellipsoid: one
/// sheet inside its rim; no generator pair carries it, for the two touches sweep over every
/// face). Its domain is the plane fitted to the rim's centres: a point w of it stands for
/// the ball whose centre lies on the plane's normal through w and which touches the
/// boundary on both sides of the sheet — Newton on both touches (any faces: they change
/// as the touches move), the height and the radius, from a solved neighbour; or, where
/// that does not land, the deepest point of that normal inside the solid (the signed
/// distance is largest on the sheet) and its two contacts. The rim's balls are the border
/// (their two touches one osculating point); the domain is triangulated by CGAL and
/// refined by centroids until every triangle is within the tolerance of the exact sheet
/// (position and radius) and no edge is longer than maxEdge.

#include "sheets/SheetInterpolation.h"

namespace exactmat
{

/// The sheet bounded by `rim` (a closed curve: its last point may repeat its first). Throws
/// InputError naming the rim when the rim is not a graph over its plane or a point of
/// the domain has no ball touching the solid on both sides.
MedialSheetMesh interpolateRimSheet(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  const SheetBorderCurve& rim, const SheetOptions& options = {});

/// The MAT's closed rims when it has no seam (each bounds a sheet of its own), as border
/// curves (ids: the ball's index along the rim); empty when it has seams or an open rim.
std::vector<SheetBorderCurve> seamlessRims(const MAT3D& mat);
/// The same for a MAT read back as a complex (vtkMAT3DFilter's output): its closed
/// skeletal edge polylines when it has no seam polyline (ids: the complex's point ids).
std::vector<SheetBorderCurve> seamlessRims(const MedialComplex& mat);

} // namespace exactmat
