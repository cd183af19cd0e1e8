#pragma once
/// @file NurbsCurve.h
/// @brief Rational B-spline curves of any degree, with derivatives and curvature.

#include "common/Types.h"
#include "nurbs/KnotVector.h"

#include <string>

namespace exactmat
{

/// A point of a curve with its first two derivatives with respect to the parameter.
struct CurveDerivatives
{
  Vec3 point = Vec3::Zero();
  Vec3 d1 = Vec3::Zero(); ///< C'(t)
  Vec3 d2 = Vec3::Zero(); ///< C''(t)

  /// Unit tangent C'/|C'|.
  Vec3 tangent() const { return d1.normalized(); }
  /// Curvature |C'×C''|/|C'|³ (≥ 0) of the space curve.
  double curvature() const;
  /// Signed curvature of the curve's projection on the xy-plane: (x'y''−y'x'')/|C'|³,
  /// positive where the curve turns left (counter-clockwise). A circle traced
  /// counter-clockwise has +1/R.
  double signedCurvature() const;
  /// Unit normal in the xy-plane pointing to the left of the direction of travel: the
  /// tangent turned by +90° about z. For a domain whose material lies on the left of its
  /// edges (DESIGN.md §2) this is the inward normal.
  Vec3 leftNormal() const;
};

/// A NURBS curve: degree p, knots U (n+p+2 values for n+1 control points), homogeneous
/// control points (w·x, w·y, w·z, w). Parameter domain [U[p], U[n+1]].
class NurbsCurve
{
public:
  NurbsCurve() = default;
  /// Builds from Euclidean control points and weights (empty weights = all 1).
  NurbsCurve(int degree, KnotVector knots, const Vec3List& points,
    const std::vector<double>& weights = {});
  /// Builds from homogeneous control points.
  NurbsCurve(int degree, KnotVector knots, Vec4List homogeneousPoints);

  /// Throws InputError naming `entity` when the data is not a valid NURBS curve: degree,
  /// knot vector, control point count, non-finite coordinates, weights ≤ 0.
  void validate(const std::string& entity) const;

  int degree() const { return Degree; }
  const KnotVector& knots() const { return Knots; }
  const Vec4List& homogeneousPoints() const { return Points; }
  int controlPointCount() const { return static_cast<int>(Points.size()); }
  Vec3 controlPoint(int i) const { return euclidean(Points[i]); }
  double weight(int i) const { return Points[i].w(); }
  bool isRational() const;
  double domainStart() const { return Knots[Degree]; }
  double domainEnd() const { return Knots[Points.size()]; }

  Vec3 evaluate(double t) const;
  CurveDerivatives derivatives(double t) const;

private:
  int Degree = 0;
  KnotVector Knots;
  Vec4List Points;
};

/// Euclidean derivatives of a rational entity from the derivatives of its homogeneous form
/// (A4.2): C = A/w, C' = (A' − w'C)/w, C'' = (A'' − 2w'C' − w''C)/w.
void rationalCurveDerivatives(const Vec4& a0, const Vec4& a1, const Vec4& a2,
  CurveDerivatives& out);

} // namespace exactmat
