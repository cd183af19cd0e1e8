#include "WindingNumber.h"

#include "common/GaussLegendre.h"

#include <cmath>
#include <limits>

namespace exactmat
{

namespace
{

// Gauss–Legendre, 8 points on [0,1].
const double* const GX = GaussLegendre8X;
const double* const GW = GaussLegendre8W;

constexpr int MaximumDepth = 40;

// The solid angle of patch [u0, u0 + h] × [v0, v0 + h] at p; NaN if p is on it.
double solidAngle(const BezierPatch& patch, double u0, double v0, double h, const Vec3& p, int depth)
{
  const Box3 box = patch.subPatch(u0, u0 + h, v0, v0 + h).boundingBox();
  // The quadrature's integrand is analytic on the piece as long as p is well away from it
  // compared with its size; the control box holds the piece (positive weights).
  if (box.exteriorDistance(p) <= 2.0 * box.diagonal().norm())
  {
    if (depth == MaximumDepth)
    {
      return std::numeric_limits<double>::quiet_NaN();
    }
    const double k = 0.5 * h;
    return solidAngle(patch, u0, v0, k, p, depth + 1) + solidAngle(patch, u0 + k, v0, k, p, depth + 1) +
      solidAngle(patch, u0, v0 + k, k, p, depth + 1) +
      solidAngle(patch, u0 + k, v0 + k, k, p, depth + 1);
  }
  double sum = 0.0;
  for (int a = 0; a < 8; ++a)
  {
    for (int b = 0; b < 8; ++b)
    {
      const SurfaceDerivatives d = patch.derivatives(u0 + h * GX[a], v0 + h * GX[b]);
      const Vec3 r = d.point - p;
      const double n = r.norm();
      sum += GW[a] * GW[b] * r.dot(d.su.cross(d.sv)) / (n * n * n);
    }
  }
  return sum * h * h;
}

} // namespace

double windingNumber(const std::vector<BezierPatch>& shell, const Vec3& p)
{
  double total = 0.0;
  for (const BezierPatch& patch : shell)
  {
    total += solidAngle(patch, 0.0, 0.0, 1.0, p, 0);
  }
  return total / (4.0 * Pi);
}

} // namespace exactmat
