#pragma once
/// @file SweptBoundary.h
/// @brief The exact boundary of an extruded or revolved solid, for checking its MAT
/// independently of how the MAT was built: the side faces as exact rational Bézier
/// patches (profile curve × sweep), the two profile faces as the profile region in its
/// start and end planes (point-in-profile decided on the exact curves).

#include "geometry/BoundingVolumeHierarchy.h"
#include "mat25d/Sweep.h"

#include <vector>

namespace exactmat
{

class SweptBoundary
{
public:
  SweptBoundary(const Boundary2D& profile, const SweepMap& sweep);

  /// Global distance from x to the solid's boundary.
  double distance(const Vec3& x) const;

  /// The distinct touchpoints of the ball of radius `radius` about x: local minima of the
  /// distance within `radius`, on the sides and on the profile faces. A one-sided minimum
  /// on a patch border that the next patch undercuts is not one.
  Vec3List touchpoints(const Vec3& x, double radius) const;

  /// True when profile point p (profile frame) is inside the profile or on its boundary.
  bool insideProfile(const Vec2& p) const;

  const std::vector<PatchPiece>& sides() const { return Sides; }
  /// Bounding-box diagonal of the solid.
  double size() const { return Size; }

private:
  /// Distance from x to profile face f, or +∞ where the face cannot be nearest.
  double faceDistance(int face, const Vec3& x, Vec3* foot) const;

  const Boundary2D* Profile;
  const SweepMap* Map;
  std::vector<PatchPiece> Sides;
  BoundingVolumeHierarchy SideTree, EdgeTree;
  double Size = 1.0;
};

} // namespace exactmat
