#pragma once
/// @file ConicCarrier.h
/// @brief The whole ellipse (or circle) a rational quadratic arc lies on, and a lower
/// bound for the distance from a point to all of it.
///
/// A disk inscribed in an ellipse that touches it at two mirror points is centred on the
/// major axis, and its distance to the ellipse there is a quadratic in cos θ (below): that
/// lower bound decides, in a few flops, that every arc of the ellipse stays outside a
/// maximal disk of the ellipse's own MAT — what the emptiness test of each tracing step
/// otherwise proves by Bernstein polynomials (issue 14: an ellipse's MAT is little else).
/// For a circle the distance |R − |x − O|| is exact everywhere.

#include "nurbs/BezierCurve.h"

#include <optional>

namespace exactmat
{

class ConicCarrier
{
public:
  /// The ellipse or circle through a degree-2 curve in the plane z = 0 whose standard
  /// form has 0 < w₁ < 1 (an elliptic arc), when the arc lies on it to within 1e-10 of
  /// `size`, measured at its quarter points; otherwise nothing (parabolas, hyperbolas, arcs too
  /// flat to fix their conic, other degrees).
  static std::optional<ConicCarrier> of(const BezierCurve& curve, double size);

  /// A number ≤ the distance from x (z ignored) to every point of the whole conic,
  /// including the rounding of the carrier itself: for a circle |R − |x − O||; for an
  /// ellipse the larger of the exact distances from x's projections onto the two axes,
  /// less the projection's length (triangle inequality) — tight on the axes, where the
  /// ellipse's MAT lies. May be negative (then it says nothing).
  double distanceLowerBound(const Vec3& x) const;

  double majorRadius() const { return A; }
  double minorRadius() const { return B; }
  Vec2 centre() const { return O; }

private:
  Vec2 O = Vec2::Zero();
  Vec2 Major = Vec2::UnitX(); ///< unit direction of the major axis
  double A = 0.0, B = 0.0;    ///< semi-axes, A ≥ B > 0
  bool Circle = false;
  double Slack = 0.0; ///< subtracted from every bound: fit error and rounding
  /// Relative rounding of the axis bound: 1 − cos θ loses digits as (A/B)² near the
  /// centre of curvature, where the disk is smallest.
  double RelativeSlack = 0.0;
};

} // namespace exactmat
