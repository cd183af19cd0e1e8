#pragma once
/// @file PatchBoundary.h
/// @brief The exact boundary of a solid given as a Boundary3D (rational Bézier faces), for
/// checking its MAT: global distance and distinct touchpoints through a BVH of the faces.

#include "brep/Boundary3D.h"
#include "geometry/BoundingVolumeHierarchy.h"
#include "medial/SolidBoundary.h"

#include <array>
#include <vector>

namespace exactmat
{

class PatchBoundary : public SolidBoundary
{
public:
  /// `boundary` must outlive this object.
  explicit PatchBoundary(const Boundary3D& boundary);

  double distance(const Vec3& x) const override;
  /// Contact sources are face indices.
  std::vector<Contact> touchpoints(const Vec3& x, double radius) const override;
  /// Planar faces by their polygon's distance, curved ones by patchComesWithin.
  bool comesWithin(const Vec3& x, double radius) const override;
  bool searchesCutShort() const override;
  Contact nearestContact(const Vec3& x) const override;
  double size() const override { return Size; }
  double aspect() const override { return Aspect; }
  double inputRounding() const override { return Boundary->userFrame().inputRounding(); }
  double osculation(const Contact& contact, const Vec3& centre, double radius) const override;

protected:
  Vec3 nearestPoint(const Vec3& x) const override;

private:
  const Boundary3D* Boundary;
  BoundingVolumeHierarchy Tree;
  double Size = 1.0, Aspect = 1.0;
  double Flat = 0.0; ///< how far off its plane a quadrilateral face may be and still count as flat
  std::vector<std::array<bool, 4>> SharpSide; ///< per face and patch side: a convex or reflex edge there
};

} // namespace exactmat
