#include "ConicCarrier.h"

#include <algorithm>
#include <cmath>

namespace exactmat
{

std::optional<ConicCarrier> ConicCarrier::of(const BezierCurve& curve, double size)
{
  if (curve.degree() != 2)
    return std::nullopt;
  for (int i = 0; i <= 2; ++i)
    if (curve.controlPoint(i).z() != 0.0)
      return std::nullopt;
  const BezierCurve q = curve.inStandardForm();
  const double w = q.weight(1);
  // w near 1: an arc too flat to fix its conic (its centre runs off to infinity).
  if (!(w > 0.0 && 1.0 - w * w > 1e-8))
    return std::nullopt;
  const Vec2 p0 = q.controlPoint(0).head<2>(), p1 = q.controlPoint(1).head<2>(), p2 = q.controlPoint(2).head<2>();
  const Vec2 m = 0.5 * (p0 + p2);
  // In standard form the conic is O + U cos θ + V sin θ with the conjugate semi-diameters
  // U (through the shoulder point C(½)) and V (parallel to the chord P₀P₂): the chord's
  // middle is at cos θ = w along U, so O = (M − w²P₁)/(1 − w²), U = w(P₁ − M)/(1 − w²),
  // V = (P₂ − M)/√(1 − w²).
  const double s = 1.0 - w * w;
  ConicCarrier c;
  c.O = (m - w * w * p1) / s;
  const Vec2 u = w * (p1 - m) / s, v = (p2 - m) / std::sqrt(s);
  // Principal semi-axes: the singular values of [U V], from the eigenvalues of
  // [U V][U V]ᵀ (B from the determinant, which keeps its digits when B ≪ A).
  const double xx = u.x() * u.x() + v.x() * v.x(), yy = u.y() * u.y() + v.y() * v.y(),
               xy = u.x() * u.y() + v.x() * v.y();
  const double big = 0.5 * (xx + yy) + std::hypot(0.5 * (xx - yy), xy);
  c.A = std::sqrt(big);
  c.B = std::abs(u.x() * v.y() - u.y() * v.x()) / c.A;
  if (!(c.B > 1e-4 * c.A) || !std::isfinite(c.A))
    return std::nullopt; // a needle: the axis bound would lose too many digits
  // The eigenvector of the larger eigenvalue, from the better-conditioned of its two forms.
  const Vec2 e1(xy, big - xx), e2(big - yy, xy);
  c.Major = (e1.squaredNorm() >= e2.squaredNorm() ? e1 : e2).normalized();
  if (!c.Major.allFinite() || c.Major.squaredNorm() == 0.0)
    c.Major = Vec2::UnitX(); // a circle: any direction
  c.Circle = c.A - c.B <= 1e-12 * c.A;
  // The arc's distance from the carrier at its quarter points (|F| / |∇F| of the implicit
  // form); the ends and the shoulder point lie on it by construction.
  double fit = 0.0;
  for (const double t : { 0.25, 0.5, 0.75 })
  {
    const double b0 = (1 - t) * (1 - t), b1 = 2 * t * (1 - t) * w, b2 = t * t;
    const Vec2 d = (b0 * p0 + b1 * p1 + b2 * p2) / (b0 + b1 + b2) - c.O;
    const double x = d.dot(c.Major), y = d.x() * -c.Major.y() + d.y() * c.Major.x();
    const double f = x * x / (c.A * c.A) + y * y / (c.B * c.B) - 1.0;
    const double g = 2.0 * std::hypot(x / (c.A * c.A), y / (c.B * c.B));
    fit = std::max(fit, std::abs(f) / g);
  }
  if (!(fit <= 1e-10 * size))
    return std::nullopt;
  // The fit error measured, four times over (between the points), the circle's
  // own flattening and the rounding of the bound's few operations at this size.
  c.Slack = 4.0 * fit + (c.Circle ? 0.5 * (c.A - c.B) : 0.0) + 1e-14 * (size + c.A);
  c.RelativeSlack = 1e-15 + 8e-16 * (c.A / c.B) * (c.A / c.B);
  return c;
}

double ConicCarrier::distanceLowerBound(const Vec3& x) const
{
  const Vec2 d = x.head<2>() - O;
  if (Circle)
    return std::abs(0.5 * (A + B) - d.norm()) - Slack;
  const double X = d.dot(Major), Y = d.x() * -Major.y() + d.y() * Major.x();
  // From (X, 0) to (A cos θ, B sin θ): (A cos θ − X)² + B²(1 − cos θ)(1 + cos θ), a
  // convex quadratic in cos θ (A > B): its least value on [−1, 1], each term kept
  // positive (no cancellation when the disk is small).
  const double c = std::clamp(A * X / ((A - B) * (A + B)), -1.0, 1.0);
  const double onMajor = std::sqrt((A * c - X) * (A * c - X) + B * B * (1.0 - c) * (1.0 + c));
  // From (0, Y): A²(1 − s²) + (B s − Y)², concave in s = sin θ: least at s = ±1, B − |Y|
  // inside (|Y| ≤ B), |Y| − B outside.
  const double onMinor = std::abs(B - std::abs(Y));
  return std::max(onMajor * (1.0 - RelativeSlack) - std::abs(Y), onMinor - std::abs(X)) - Slack;
}

} // namespace exactmat
