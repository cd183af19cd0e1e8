#pragma once
/// @file CapSheet.h
/// @brief The sheet between a planar cap and the canal face whose centre curve ends on it
/// (a cylinder's cone sheets: a shaft's flat end). Where a centre curve (CentreCurve.h)
/// stops because its ball reaches a planar face, that ball touches the whole circle and
/// the cap at one point: the apex of a sheet whose balls touch the cap at every point of it
/// and the canal face once, and whose border is the cap's convex edges (radius 0). Its
/// domain is the cap itself (plane coordinates); over a point q of it the ball touching
/// the cap at q has the radius where its distance from the canal face equals the radius
/// (a monotone function of the radius: bracketed, then Newton). The apex is a vertex; the
/// domain is triangulated by CGAL and refined by centroids until every triangle is within
/// the tolerance of the exact sheet and no edge is longer than maxEdge. Every ball is
/// checked to be empty of the whole boundary (a seam crossing the cap, which this sheet
/// does not model, fails the sheet by name instead of filling past it).

#include "sheets/SheetInterpolation.h"

namespace exactmat
{

/// A centre curve's end whose ball touches a planar face as well as its circle.
struct CapEnd
{
  Vec3 centre = Vec3::Zero();
  double radius = 0.0;
  Vec3 circleTouch = Vec3::Zero(); ///< a point of the circle of contact
  Vec3 capTouch = Vec3::Zero();    ///< where the ball touches the cap
  int id = -1;                     ///< the caller's number of the end's point (kept on the apex vertex)
};

/// The ends of the MAT's centre curves whose ball touches one planar face off its circle of
/// contact (node ids as `id`): a shaft's flat end, or a fillet's spine where it meets the
/// face across the fillet's end (its ball touches the faces the fillet rounds too, at the
/// ends of its arc). The planar faces are asked for the touch the end's record lacks.
std::vector<CapEnd> capEnds(const MAT3D& mat, const Boundary3D& boundary, const std::vector<Generator3D>& generators);
/// The same for a MAT read back as a complex: CircleCentre points ending a CentreCurve
/// element (the complex's point ids).
std::vector<CapEnd> capEnds(const MedialComplex& mat, const Boundary3D& boundary,
  const std::vector<Generator3D>& generators);

/// The cone sheet at `end`. Throws InputError naming the cap when the end's second touch is
/// not on a planar face, a side of the cap is not a convex edge with the canal face, or a
/// ball of the sheet is not empty.
MedialSheetMesh interpolateCapSheet(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  const CapEnd& end, const SheetOptions& options = {});

/// Leaves out the groups no seam lists (sheets found from convex edges) that a built cap
/// sheet is: one side within its cap, the other within its canal face.
void dropCapGroups(std::vector<SheetGroup>& groups, const std::vector<MedialSheetMesh>& capSheets);

} // namespace exactmat
