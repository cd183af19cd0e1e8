#pragma once
/// @file SolidBoundary.h
/// @brief The exact boundary of a solid as the verification of any 3D MAT sees it (DESIGN.md
/// §4): the global distance from a point, and the distinct touchpoints of a ball. One
/// interface for the swept solids of 2.5D (SweptBoundary) and the free-form solids of 3D
/// (PatchBoundary), so both are checked by the same code (medial/Verification.h).

#include "common/Types.h"

#include <cmath>
#include <vector>

namespace exactmat
{

class SolidBoundary
{
public:
  virtual ~SolidBoundary() = default;

  /// A local minimum of the distance from a point to the boundary.
  struct Contact
  {
    Vec3 point = Vec3::Zero();
    double distance = 0.0;
    int source = -1; ///< the face (numbering of the implementation)
    Vec2 parameters = Vec2::Constant(NAN); ///< on that face, where the implementation knows them
  };

  /// Global distance from x to the boundary.
  virtual double distance(const Vec3& x) const = 0;

  /// Whether some boundary point lies strictly within `radius` of x: a decision, cheaper
  /// and more robust than the distance where a ball touches along a flat valley.
  virtual bool comesWithin(const Vec3& x, double radius) const { return distance(x) < radius; }

  /// The boundary point nearest x as a contact (its face and parameters where the
  /// implementation knows them): where a recorded touch lies, to check it.
  virtual Contact nearestContact(const Vec3& x) const
  {
    Contact c;
    c.point = nearestPoint(x);
    c.distance = (c.point - x).norm();
    return c;
  }

  /// Whether the touchpoint queries since the last call may have missed a touchpoint
  /// (a search stopped at its work limit); reading it resets it for this thread.
  virtual bool searchesCutShort() const { return false; }

  /// The distinct touchpoints of the ball of radius `radius` about x: local minima of the
  /// distance within `radius`, nearest first.
  virtual std::vector<Contact> touchpoints(const Vec3& x, double radius) const = 0;

  /// How far a ball of `radius` touching at `contact` is from osculating the boundary there
  /// in its most curved direction: |radius·κ1 − 1|, κ1 the largest principal curvature of
  /// the face at the contact (positive where convex). NaN where that is not defined: a flat
  /// face, or a contact on a sharp edge or vertex (a rim at a vertex, where the sheet of two
  /// reflex edges closes). The check of a skeletal edge's points (thesis §3.4).
  virtual double osculation(const Contact& /*contact*/, const Vec3& /*centre*/, double /*radius*/) const
  {
    return NAN;
  }

  /// Bounding-box diagonal of the solid.
  virtual double size() const = 0;
  /// The bounding box's longest edge over its shortest.
  virtual double aspect() const { return 1.0; }
  /// What the boundary's coordinates are known to, as a fraction of the size: the rounding
  /// of the input's coordinates in the frame it was given in (Normalisation::inputRounding;
  /// a part far from the origin has its faces' corners rounded off their planes by that).
  virtual double inputRounding() const { return 0.0; }

protected:
  /// A local minimum found on one face; `oneSided` when it lies on the face's border.
  struct Minimum
  {
    Vec3 point;
    double distance;
    bool oneSided;
    int source;
    Vec2 parameters = Vec2::Constant(NAN);
  };

  /// The boundary point nearest x (for the valley test between two close minima).
  virtual Vec3 nearestPoint(const Vec3& x) const = 0;

  /// The distinct contacts among the minima of every face about x: a border minimum that
  /// the neighbouring face undercuts is not one, and two minima close together are one
  /// when the boundary between them stays inside the ball (a flat valley), two when it
  /// bulges out.
  std::vector<Contact> distinctContacts(std::vector<Minimum> minima, const Vec3& x) const;

private:
  bool sameContact(const Vec3& x, double radius, const Vec3& a, const Vec3& b, double merge) const;
};

} // namespace exactmat
