#pragma once
/// @file NurbsSurface.h
/// @brief Tensor-product rational B-spline surfaces with derivatives, normals and
/// principal curvatures.

#include "common/Types.h"
#include "nurbs/KnotVector.h"

#include <string>

namespace exactmat
{

/// A surface point with its first and second partial derivatives.
struct SurfaceDerivatives
{
  Vec3 point = Vec3::Zero();
  Vec3 su = Vec3::Zero(), sv = Vec3::Zero();
  Vec3 suu = Vec3::Zero(), suv = Vec3::Zero(), svv = Vec3::Zero();

  /// Unit normal Su×Sv/|Su×Sv| (orientation of the parameterisation).
  Vec3 normal() const { return su.cross(sv).normalized(); }

  /// Principal curvatures k1 ≥ k2 and unit principal directions (tangent 3-vectors).
  /// Sign convention: a curvature is positive where the surface bends towards normal(),
  /// so a sphere parameterised with outward normal has k1 = k2 = −1/R.
  struct Curvatures
  {
    double k1 = 0.0, k2 = 0.0;
    Vec3 d1 = Vec3::Zero(), d2 = Vec3::Zero();
  };
  Curvatures principalCurvatures() const;
};

/// Euclidean partial derivatives of a rational surface from those of its homogeneous form.
/// Inputs in the order A, Au, Av, Auu, Auv, Avv.
void rationalSurfaceDerivatives(const Vec4* a, SurfaceDerivatives& out);

/// A NURBS surface: degrees (p, q), knot vectors U, V, and an nu×nv net of homogeneous
/// control points stored row by row along u: index i*nv + j (i along u, j along v).
class NurbsSurface
{
public:
  NurbsSurface() = default;
  NurbsSurface(int degreeU, int degreeV, KnotVector knotsU, KnotVector knotsV, int countU,
    int countV, Vec4List homogeneousNet);
  /// Euclidean net + weights (empty = all 1), same layout.
  NurbsSurface(int degreeU, int degreeV, KnotVector knotsU, KnotVector knotsV, int countU,
    int countV, const Vec3List& net, const std::vector<double>& weights = {});

  /// Throws InputError naming `entity` for invalid degrees, knots, counts, non-finite
  /// coordinates or weights ≤ 0.
  void validate(const std::string& entity) const;

  int degreeU() const { return DegreeU; }
  int degreeV() const { return DegreeV; }
  int countU() const { return CountU; }
  int countV() const { return CountV; }
  const KnotVector& knotsU() const { return KnotsU; }
  const KnotVector& knotsV() const { return KnotsV; }
  const Vec4List& homogeneousNet() const { return Net; }
  const Vec4& homogeneousPoint(int i, int j) const { return Net[i * CountV + j]; }
  double uStart() const { return KnotsU[DegreeU]; }
  double uEnd() const { return KnotsU[CountU]; }
  double vStart() const { return KnotsV[DegreeV]; }
  double vEnd() const { return KnotsV[CountV]; }

  Vec3 evaluate(double u, double v) const;
  SurfaceDerivatives derivatives(double u, double v) const;

private:
  int DegreeU = 0, DegreeV = 0, CountU = 0, CountV = 0;
  KnotVector KnotsU, KnotsV;
  Vec4List Net;
};

} // namespace exactmat
