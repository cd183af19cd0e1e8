#pragma once
/// @file SweptBoundary.h
/// @brief The exact boundary of an extruded or revolved solid, for checking its MAT
/// independently of how the MAT was built: the side faces as exact rational Bézier
/// patches (profile curve × sweep), the two profile faces as the profile region in its
/// start and end planes (point-in-profile decided on the exact curves).

#include "geometry/BoundingVolumeHierarchy.h"
#include "mat25d/Sweep.h"
#include "medial/SolidBoundary.h"

#include <vector>

namespace exactmat
{

class SweptBoundary : public SolidBoundary
{
public:
  SweptBoundary(const Boundary2D& profile, const SweepMap& sweep);

  double distance(const Vec3& x) const override;

  /// Contact sources: side patch index, or ProfileFace0 / ProfileFace1.
  static constexpr int ProfileFace0 = -1, ProfileFace1 = -2;

  /// On the sides and on the profile faces.
  std::vector<Contact> touchpoints(const Vec3& x, double radius) const override;

  /// True when profile point p (profile frame) is inside the profile or on its boundary.
  bool insideProfile(const Vec2& p) const;

  const std::vector<PatchPiece>& sides() const { return Sides; }
  double size() const override { return Size; }
  /// A 4 × 2 plate 1e-12 thick: 4e12.
  double aspect() const override { return Aspect; }

  /// Distance from x to profile face `face` (0 start, 1 end) and the foot of the
  /// perpendicular, or +∞ where the face cannot be nearest (foot outside the profile,
  /// 360° revolutions).
  double faceDistance(int face, const Vec3& x, Vec3* foot) const;

protected:
  Vec3 nearestPoint(const Vec3& x) const override;

private:

  double Aspect = 1.0;
  const Boundary2D* Profile;
  const SweepMap* Map;
  std::vector<PatchPiece> Sides;
  BoundingVolumeHierarchy SideTree, EdgeTree;
  double Size = 1.0;
};

} // namespace exactmat
