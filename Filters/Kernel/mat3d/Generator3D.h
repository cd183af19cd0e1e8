#pragma once
/// @file Generator3D.h
/// @brief A boundary entity a medial ball of a solid touches (thesis §6.2: faces; reflex
/// edges and corners to come), seen through two parameters q: the touchpoint S(q), the unit
/// normal N(q) pointing into the material, and their derivatives. A ball of radius r
/// touching the entity at q has its centre at S(q) + r·N(q); a seam is where three such
/// centres coincide (thesis app. C.1, here with every touchpoint parameter unknown).
///
/// A planar face is parameterised by orthonormal coordinates in its plane, not by its
/// patch: a triangle stored as a patch with a collapsed side, or any planar patch whose
/// parameterisation degenerates at a corner, then still has a regular touchpoint map where
/// seams start (the convex vertices).

#include "brep/Boundary3D.h"

#include <Eigen/Core>
#include <string>

namespace exactmat
{

/// A touchpoint and the first derivatives of the touchpoint map.
struct Touch3D
{
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::Zero(); ///< unit, into the material
  Eigen::Matrix<double, 3, 2> dPoint = Eigen::Matrix<double, 3, 2>::Zero();
  Eigen::Matrix<double, 3, 2> dNormal = Eigen::Matrix<double, 3, 2>::Zero();
};

class Generator3D
{
public:
  /// Face `face` of `boundary` (which must outlive the generator).
  Generator3D(const Boundary3D& boundary, int face);

  int face() const { return Face; }
  bool planar() const { return Planar; }
  /// A convex planar face with straight sides (distances and inside tests in closed form).
  bool polygon() const { return !Polygon.empty(); }
  Touch3D evaluate(const Vec2& q) const;

  /// The parameters of the face's point nearest to x (planar: x projected on the plane).
  Vec2 parameterOf(const Vec3& x) const;

  /// −1 when the touchpoint at q lies on the face (within `tolerance`, a length), else the
  /// patch side (BezierPatch's numbering) it has crossed.
  int exitSide(const Vec2& q, double tolerance) const;

  /// Global distance from x to the face (closed form for a straight-sided planar face).
  double distance(const Vec3& x) const;
  /// The face's point nearest x.
  Vec3 nearestPoint(const Vec3& x) const;

  std::string name() const;

private:
  void setPolygon(const BezierPatch& patch, double size);

  const Boundary3D* Boundary;
  int Face;
  bool Planar = false;
  bool Collapsed[4] = { false, false, false, false }; ///< sides that are a point (triangles)
  /// A convex planar face with straight sides: its corners in plane coordinates, counter-
  /// clockwise, and the patch side of each polygon side (from corner i to i + 1), for
  /// closed-form inside tests and distances. Empty otherwise.
  std::vector<Vec2> Polygon;
  std::vector<int> PolygonSide;
  Vec3 Origin = Vec3::Zero(), Axis0 = Vec3::Zero(), Axis1 = Vec3::Zero(), Inward = Vec3::Zero();
};

} // namespace exactmat
