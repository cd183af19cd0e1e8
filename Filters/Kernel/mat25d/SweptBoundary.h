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

  /// A local minimum of the distance from a point to the boundary.
  struct Contact
  {
    Vec3 point = Vec3::Zero();
    double distance = 0.0;
    int source = -1; ///< side patch index, or ProfileFace0 / ProfileFace1
  };
  static constexpr int ProfileFace0 = -1, ProfileFace1 = -2;

  /// The distinct touchpoints of the ball of radius `radius` about x: local minima of the
  /// distance within `radius`, on the sides and on the profile faces, nearest first. A
  /// one-sided minimum on a patch border that the next patch undercuts is not one.
  std::vector<Contact> touchpoints(const Vec3& x, double radius) const;

  /// True when profile point p (profile frame) is inside the profile or on its boundary.
  bool insideProfile(const Vec2& p) const;

  const std::vector<PatchPiece>& sides() const { return Sides; }
  /// Bounding-box diagonal of the solid.
  double size() const { return Size; }
  /// The bounding box's longest edge over its shortest (a 4 × 2 plate 1e-12 thick: 4e12).
  double aspect() const { return Aspect; }

  /// Distance from x to profile face `face` (0 start, 1 end) and the foot of the
  /// perpendicular, or +∞ where the face cannot be nearest (foot outside the profile,
  /// 360° revolutions).
  double faceDistance(int face, const Vec3& x, Vec3* foot) const;

private:
  bool sameContact(const Vec3& x, double radius, const Vec3& a, const Vec3& b, double merge) const;

  double Aspect = 1.0;
  const Boundary2D* Profile;
  const SweepMap* Map;
  std::vector<PatchPiece> Sides;
  BoundingVolumeHierarchy SideTree, EdgeTree;
  double Size = 1.0;
};

} // namespace exactmat
