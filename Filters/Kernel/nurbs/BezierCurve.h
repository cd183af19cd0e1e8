#pragma once
/// @file BezierCurve.h
/// @brief A rational Bézier curve on [0,1]: the unit every boundary edge is made of.

#include "common/Types.h"
#include "nurbs/NurbsCurve.h"

#include <Eigen/Geometry>

namespace exactmat
{

using Box3 = Eigen::AlignedBox3d;

/// A rational Bézier curve of degree p = points.size() − 1 on t ∈ [0,1], homogeneous
/// control points. With positive weights the curve lies in the convex hull of its
/// Euclidean control points, which is what the bounding boxes below rely on.
class BezierCurve
{
public:
  BezierCurve() = default;
  explicit BezierCurve(Vec4List homogeneousPoints)
    : Points(std::move(homogeneousPoints))
    , Box(controlBox(Points))
  {
  }
  BezierCurve(const Vec3List& points, const std::vector<double>& weights);

  int degree() const { return static_cast<int>(Points.size()) - 1; }
  const Vec4List& homogeneousPoints() const { return Points; }
  Vec3 controlPoint(int i) const { return euclidean(Points[i]); }
  double weight(int i) const { return Points[i].w(); }
  Vec3 startPoint() const { return controlPoint(0); }
  Vec3 endPoint() const { return controlPoint(degree()); }

  Vec3 evaluate(double t) const;
  CurveDerivatives derivatives(double t) const;
  /// Unit tangent at an end (t = 0 or 1) that stays defined when the end control points
  /// coincide (then the first non-vanishing control polygon leg gives the direction).
  Vec3 endTangent(bool atEnd) const;

  /// The two halves at t (de Casteljau in homogeneous coordinates: exact).
  void split(double t, BezierCurve& left, BezierCurve& right) const;
  /// The piece over [t0, t1], re-parameterised to [0,1].
  BezierCurve segment(double t0, double t1) const;
  /// The same curve traversed backwards.
  BezierCurve reversed() const;
  /// The same curve with end weights 1 (a rational re-parameterisation w_k → w_k·c^k / w_0):
  /// two pieces cut from one curve at the same parameters then agree point for point, and
  /// a patch ruled between it and a polynomial curve has straight, linearly parameterised
  /// end rulings.
  BezierCurve inStandardForm() const;
  /// Bounding box of the Euclidean control points (contains the curve); kept, as every
  /// emptiness test and footpoint query starts with it.
  const Box3& boundingBox() const { return Box; }
  /// The curve as a one-span NurbsCurve on [0,1].
  NurbsCurve toNurbs() const;

private:
  static Box3 controlBox(const Vec4List& points);

  Vec4List Points;
  Box3 Box;
};

} // namespace exactmat
