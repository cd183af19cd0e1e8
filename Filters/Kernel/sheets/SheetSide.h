#pragma once
/// @file SheetSide.h
/// @brief One side of a medial sheet's pair: a generator, or faces of one surface joined by
/// smooth edges that a ball touches as one face, with one parameter plane over them all.

#include "geometry/PatchContinuation.h"
#include "mat3d/Generator3D.h"

#include <string>
#include <vector>

namespace exactmat
{

/// One side of a sheet's pair as generator indices (medialGenerators' numbering): g
/// itself, or every face reached through smooth edges that is in g's plane (a polygon
/// split into a fan of triangles) or, for a curved face, a piece of g's surface (a surface
/// of revolution cut where MAT samples touch: PatchContinuation) — one face to the sheets —
/// sorted.
std::vector<int> sheetSide(const Boundary3D& boundary, const std::vector<Generator3D>& generators, int g);

/// One side of a sheet's pair: a generator, or faces of one surface joined by smooth
/// edges — planar faces in one plane (a polygon split into a fan of triangles), or curved
/// pieces of one Bézier surface (a surface of revolution cut where MAT samples touch) —
/// which a ball touches as one face. Parameters are the first member's: its plane's
/// coordinates, or its patch's polynomial extension, which every other piece is an affine
/// part of (PieceMaps take a piece's parameters there) — scaled there by the patch's speeds
/// at its centre, so a sheet's domain is not stretched 20-fold across the sliver pieces of
/// a surface of revolution (triangles shaped well in such a domain are needles on the
/// sheet: refinement without end, and an area a lantern of needles overstates).
class SheetSide
{
public:
  /// Throws InputError when curved members are not pieces of the first one's surface.
  SheetSide(const Boundary3D& boundary, const std::vector<Generator3D>& generators, const std::vector<int>& members);

  const Generator3D& first() const { return *Members.front(); }
  const std::vector<const Generator3D*>& members() const { return Members; }
  GeneratorKind3D kind() const { return first().kind(); }
  /// Whether the side is faces of one curved surface (one face, or pieces of it).
  bool curvedFace() const { return kind() == GeneratorKind3D::Face && !first().planar(); }
  /// The touch at q, evaluated on the piece whose square holds q.
  Touch3D evaluate(const Vec2& q) const;
  /// Only the point of the touch at q (curved faces: the patch, no derivatives).
  Vec3 point(const Vec2& q) const;
  Vec2 parameterOf(const Vec3& x) const;
  Vec2 touchParameter(const Vec3& foot, const Vec3& centre) const;
  Vec3 nearestPoint(const Vec3& x) const;
  double distance(const Vec3& x) const;
  /// −1 when the touch at q lies on one of the members (within `tolerance`), else ≥ 0.
  int exitSide(const Vec2& q, double tolerance) const;
  std::string name() const;

private:
  size_t nearestMember(const Vec3& x, double& d) const;
  size_t pieceHolding(const Vec2& s) const;

  const Boundary3D* B;
  std::vector<const Generator3D*> Members;
  mutable size_t LastPiece = 0;
  std::vector<Box3> Boxes;             ///< a box holding each member (patch, edge curve, corner point)
  std::vector<ParameterMap> PieceMaps; ///< curved members only: each piece's parameters → the first's
  Vec2 Speed = Vec2(1.0, 1.0);         ///< the side's parameters over the first's (curved members)
};

} // namespace exactmat
