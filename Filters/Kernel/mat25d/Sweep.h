#pragma once
/// @file Sweep.h
/// @brief Extrusion and revolution of a planar profile (thesis ch. 5): the rigid motions
/// T_τ, τ ∈ [0, span], that carry the start profile face to the end one, the exact side
/// faces they sweep, and the span at which a maximal disk of the profile becomes a maximal
/// ball of the solid.
///
/// Profile points are in the frame of Boundary2D's plane. An extrusion moves them along
/// the plane's normal by τ ∈ [0, length]. A revolution turns them by τ ∈ [0, angle] about
/// an axis in the plane (right-handed about the axis direction); the axis must not touch
/// the profile. For a profile point p at distance ρ(p) from the axis, a ball of radius r
/// about T_τ(p) is at distance r from the start face when τ = r (extrusion) or
/// ρ·sin τ = r (revolution): capSpan(p, r) (§5.5.1).

#include "brep/Boundary2D.h"
#include "brep/Boundary3D.h"

#include <string>
#include <vector>

namespace exactmat
{

enum class SweepKind
{
  Extrusion,
  Revolution
};

const char* toString(SweepKind kind);

/// What the user asks for, in world coordinates.
struct Sweep
{
  SweepKind kind = SweepKind::Extrusion;
  double length = 1.0;             ///< extrusion, along the profile plane's normal
  double angle = 6.283185307179586; ///< revolution, radians in (0, 2π]
  Vec3 axisPoint = Vec3::Zero();   ///< revolution axis, in the profile's plane
  Vec3 axisDirection = Vec3::UnitY();

  static Sweep extrusion(double length);
  /// `degrees` in (0, 360]; the axis through `point` along `direction`.
  static Sweep revolution(double degrees, const Vec3& point = Vec3::Zero(),
    const Vec3& direction = Vec3::UnitY());
};

/// A sweep bound to a profile: validated, in the profile's frame.
class SweepMap
{
public:
  /// Throws InputError for a length or angle out of range, an axis that is not in the
  /// profile's plane, or one that touches or crosses the profile (naming the edge).
  SweepMap(const Boundary2D& profile, const Sweep& sweep);

  SweepKind kind() const { return S.kind; }
  /// length or angle
  double span() const { return Span; }
  /// A 360° revolution: no profile faces, the medial sheets close on themselves.
  bool closed() const { return Closed; }
  const Plane& plane() const { return Profile->plane(); }

  /// T_τ(p) in world coordinates (p in the profile frame).
  Vec3 place(const Vec2& p, double tau) const;
  /// Distance from profile point p to the axis (revolution; 1 for extrusions).
  double axisDistance(const Vec2& p) const;
  /// The τ at which the ball of radius r about T_τ(p) touches the start face: r, or
  /// asin(r/ρ(p)). The end face is touched at span() − capSpan.
  double capSpan(const Vec2& p, double r) const;

  /// The side faces of the solid, exact: per profile edge one rational Bézier patch of
  /// degrees (p, 1) for an extrusion, or (p, 2) per ≤ 90° of revolution. entity = the
  /// profile edge's entity (its EdgeId: the side's FaceId).
  /// With `splits` (per profile edge, sorted parameters in (0,1)) each side is cut there
  /// too, so it conforms with profile faces tiled at those parameters.
  std::vector<PatchPiece> sideFaces(const std::vector<std::vector<double>>& splits = {}) const;

  /// T_τ applied to a homogeneous control point of the profile frame (exact: rigid).
  Vec4 placeHomogeneous(const Vec4& h, double tau) const;

  /// The orthogonal projection of world point x on profile face `face` (0 start, 1 end),
  /// in the profile frame, and its distance to that face's plane. False when the
  /// projection is on the wrong side of the axis (revolutions), where the face cannot be
  /// nearest.
  bool projectOnProfileFace(int face, const Vec3& x, Vec2& foot, double& distance) const;

  /// "extrusion of length 3" / "revolution by 90°": for messages.
  std::string describe() const;

private:
  void checkAxis() const;
  void appendSides(const Edge2D& e, const BezierCurve& piece, std::vector<PatchPiece>& faces) const;

  const Boundary2D* Profile;
  Sweep S;
  double Span = 0.0;
  bool Closed = false;
  // Revolution frame: axis point a and direction d in the profile frame, m ⟂ d towards the
  // profile; world images A, D, M and N = D × M (the direction the profile moves in).
  Vec2 A2 = Vec2::Zero(), D2 = Vec2::UnitY(), M2 = Vec2::UnitX();
  Vec3 Aw = Vec3::Zero(), Dw = Vec3::UnitY(), Mw = Vec3::UnitX(), Nw = Vec3::UnitZ();
};

} // namespace exactmat
