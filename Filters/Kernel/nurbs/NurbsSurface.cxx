#include "NurbsSurface.h"

#include "common/InputError.h"

#include <Eigen/Dense>
#include <cmath>

namespace exactmat
{

SurfaceDerivatives::Curvatures SurfaceDerivatives::principalCurvatures() const
{
  const Vec3 n = normal();
  Eigen::Matrix2d first, second;
  first << su.dot(su), su.dot(sv), su.dot(sv), sv.dot(sv);
  second << suu.dot(n), suv.dot(n), suv.dot(n), svv.dot(n);
  // Principal curvatures are the eigenvalues of II relative to I (the shape operator).
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> solver(second, first);
  Curvatures c;
  const auto& values = solver.eigenvalues(); // ascending
  const auto& vectors = solver.eigenvectors();
  c.k1 = values(1);
  c.k2 = values(0);
  c.d1 = (vectors(0, 1) * su + vectors(1, 1) * sv).normalized();
  c.d2 = (vectors(0, 0) * su + vectors(1, 0) * sv).normalized();
  return c;
}

void rationalSurfaceDerivatives(const Vec4* a, SurfaceDerivatives& out)
{
  const double w = a[0].w(), wu = a[1].w(), wv = a[2].w();
  const double wuu = a[3].w(), wuv = a[4].w(), wvv = a[5].w();
  out.point = a[0].head<3>() / w;
  out.su = (a[1].head<3>() - wu * out.point) / w;
  out.sv = (a[2].head<3>() - wv * out.point) / w;
  out.suu = (a[3].head<3>() - 2.0 * wu * out.su - wuu * out.point) / w;
  out.svv = (a[5].head<3>() - 2.0 * wv * out.sv - wvv * out.point) / w;
  out.suv = (a[4].head<3>() - wu * out.sv - wv * out.su - wuv * out.point) / w;
}

NurbsSurface::NurbsSurface(int degreeU, int degreeV, KnotVector knotsU, KnotVector knotsV,
  int countU, int countV, Vec4List homogeneousNet)
  : DegreeU(degreeU)
  , DegreeV(degreeV)
  , CountU(countU)
  , CountV(countV)
  , KnotsU(std::move(knotsU))
  , KnotsV(std::move(knotsV))
  , Net(std::move(homogeneousNet))
{
}

NurbsSurface::NurbsSurface(int degreeU, int degreeV, KnotVector knotsU, KnotVector knotsV,
  int countU, int countV, const Vec3List& net, const std::vector<double>& weights)
  : DegreeU(degreeU)
  , DegreeV(degreeV)
  , CountU(countU)
  , CountV(countV)
  , KnotsU(std::move(knotsU))
  , KnotsV(std::move(knotsV))
{
  if (!weights.empty() && weights.size() != net.size())
  {
    fail("NURBS surface: ", weights.size(), " weights for ", net.size(), " control points");
  }
  Net.reserve(net.size());
  for (size_t i = 0; i < net.size(); ++i)
  {
    Net.push_back(homogeneous(net[i], weights.empty() ? 1.0 : weights[i]));
  }
}

void NurbsSurface::validate(const std::string& entity) const
{
  if (CountU < 1 || CountV < 1 || Net.size() != static_cast<size_t>(CountU) * CountV)
  {
    fail(entity, ": control net has ", Net.size(), " points, expected ", CountU, " x ", CountV);
  }
  for (size_t k = 0; k < Net.size(); ++k)
  {
    const double w = Net[k].w();
    if (!std::isfinite(w) || !(w > 0.0))
    {
      fail(entity, ": control point (", k / CountV, ", ", k % CountV, ") has weight ", w,
        " (weights must be > 0)");
    }
    if (!Net[k].allFinite())
    {
      fail(entity, ": control point (", k / CountV, ", ", k % CountV,
        ") has a NaN or infinite coordinate");
    }
  }
  validateKnots(KnotsU, DegreeU, CountU, entity + " (u direction)");
  validateKnots(KnotsV, DegreeV, CountV, entity + " (v direction)");
}

Vec3 NurbsSurface::evaluate(double u, double v) const
{
  return derivatives(u, v).point;
}

SurfaceDerivatives NurbsSurface::derivatives(double u, double v) const
{
  const int p = DegreeU, q = DegreeV;
  const int su = findSpan(KnotsU, p, CountU, u);
  const int sv = findSpan(KnotsV, q, CountV, v);
  u = std::min(std::max(u, uStart()), uEnd());
  v = std::min(std::max(v, vStart()), vEnd());
  double nu[3 * (MaxDegree + 1)], nv[3 * (MaxDegree + 1)];
  basisDerivatives(KnotsU, su, u, p, 2, nu);
  basisDerivatives(KnotsV, sv, v, q, 2, nv);
  // (k, l) orders in the order A, Au, Av, Auu, Auv, Avv.
  static const int orders[6][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 }, { 2, 0 }, { 1, 1 }, { 0, 2 } };
  Vec4 a[6];
  for (int d = 0; d < 6; ++d)
  {
    const int k = orders[d][0], l = orders[d][1];
    a[d].setZero();
    for (int i = 0; i <= p; ++i)
    {
      Vec4 row = Vec4::Zero();
      for (int j = 0; j <= q; ++j)
      {
        row += nv[l * (q + 1) + j] * homogeneousPoint(su - p + i, sv - q + j);
      }
      a[d] += nu[k * (p + 1) + i] * row;
    }
  }
  SurfaceDerivatives out;
  rationalSurfaceDerivatives(a, out);
  return out;
}

} // namespace exactmat
