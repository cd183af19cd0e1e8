#pragma once
/// @file BezierPatch.h
/// @brief A rational tensor-product Bézier patch on [0,1]²: the unit every boundary face
/// is made of. Triangular Bézier patches are converted to it exactly (one collapsed edge).

#include "common/Types.h"
#include "nurbs/BezierCurve.h"
#include "nurbs/NurbsSurface.h"

namespace exactmat
{

/// Control net of a triangular Bézier patch of degree n: points P_{ijk}, i+j+k = n, stored
/// by index(i, j) (k = n − i − j). Corner k = n is V0, i = n is V1, j = n is V2.
struct TriangleNet
{
  int degree = 0;
  Vec4List points; ///< homogeneous, size (n+1)(n+2)/2

  static int index(int n, int i, int j) { return i * (n + 1) - i * (i - 1) / 2 + j; }
  const Vec4& at(int i, int j) const { return points[index(degree, i, j)]; }
};

/// A rational Bézier patch of degrees (p, q): net[i*(q+1)+j], i along u, j along v.
/// Boundary sides, in counter-clockwise parameter order: 0: v=0 (u 0→1), 1: u=1 (v 0→1),
/// 2: v=1 (u 1→0), 3: u=0 (v 1→0).
class BezierPatch
{
public:
  BezierPatch() = default;
  BezierPatch(int p, int q, Vec4List homogeneousNet)
    : P(p)
    , Q(q)
    , Net(std::move(homogeneousNet))
  {
  }
  /// Exact conversion of a triangular patch: S(u,v) = T(s = u, t = v(1−u)); the side u = 1
  /// collapses to the corner V1. Sides: v=0 is V0→V1, u=0 is V0→V2, v=1 is V2→V1.
  static BezierPatch fromTriangle(const TriangleNet& triangle);

  int degreeU() const { return P; }
  int degreeV() const { return Q; }
  const Vec4List& homogeneousNet() const { return Net; }
  const Vec4& homogeneousPoint(int i, int j) const { return Net[i * (Q + 1) + j]; }
  Vec3 controlPoint(int i, int j) const { return euclidean(homogeneousPoint(i, j)); }

  Vec3 evaluate(double u, double v) const;
  SurfaceDerivatives derivatives(double u, double v) const;
  /// Unit normal Su×Sv/|Su×Sv|, evaluated slightly inside the patch where the
  /// parameterisation is singular (collapsed edges, corners where Su ∥ Sv).
  Vec3 normal(double u, double v) const;

  /// The same patch re-parameterised (w_ij → s·w_ij·a^i·b^j, a rational re-parameterisation
  /// in u and in v) so that the corner weights w_00, w_p0, w_0q are 1; so is w_pq when the
  /// corner weights are those of a tensor product (w_00·w_pq = w_p0·w_0q: surfaces swept or
  /// revolved from rational curves, spheres, tori), and then every side is in
  /// BezierCurve::inStandardForm, so it agrees point for point with the standard form of the
  /// same curve cut from a neighbouring face.
  BezierPatch inStandardForm() const;
  /// The patch over [u0,u1]×[v0,v1], re-parameterised to [0,1]².
  BezierPatch subPatch(double u0, double u1, double v0, double v1) const;
  /// subPatch(u0, u1, v0, v1).boundingBox(), bit for bit, without building the patch (per-
  /// thread scratch; no allocation once warm): the subdivision search's pruning per box.
  Box3 subPatchBox(double u0, double u1, double v0, double v1) const;
  /// Boundary side s (0..3, see above) as a Bézier curve in counter-clockwise order.
  BezierCurve side(int s) const;
  /// The patch parameter (u, v) of parameter t along side s.
  static Vec2 sideParameter(int s, double t);
  Box3 boundingBox() const;
  NurbsSurface toNurbs() const;

private:
  int P = 0, Q = 0;
  Vec4List Net;
};

} // namespace exactmat
