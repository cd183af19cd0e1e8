#include "NurbsCurve.h"

#include "common/InputError.h"

#include <cmath>

namespace exactmat
{

double CurveDerivatives::curvature() const
{
  const double s = d1.norm();
  return d1.cross(d2).norm() / (s * s * s);
}

double CurveDerivatives::signedCurvature() const
{
  const double s = d1.head<2>().norm();
  return (d1.x() * d2.y() - d1.y() * d2.x()) / (s * s * s);
}

Vec3 CurveDerivatives::leftNormal() const
{
  const Vec3 t = tangent();
  return Vec3(-t.y(), t.x(), 0.0).normalized();
}

void rationalCurveDerivatives(const Vec4& a0, const Vec4& a1, const Vec4& a2,
  CurveDerivatives& out)
{
  const double w = a0.w();
  out.point = a0.head<3>() / w;
  out.d1 = (a1.head<3>() - a1.w() * out.point) / w;
  out.d2 = (a2.head<3>() - 2.0 * a1.w() * out.d1 - a2.w() * out.point) / w;
}

NurbsCurve::NurbsCurve(int degree, KnotVector knots, const Vec3List& points,
  const std::vector<double>& weights)
  : Degree(degree)
  , Knots(std::move(knots))
{
  Points.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i)
  {
    Points.push_back(homogeneous(points[i], weights.empty() ? 1.0 : weights[i]));
  }
  if (!weights.empty() && weights.size() != points.size())
  {
    fail("NURBS curve: ", weights.size(), " weights for ", points.size(), " control points");
  }
}

NurbsCurve::NurbsCurve(int degree, KnotVector knots, Vec4List homogeneousPoints)
  : Degree(degree)
  , Knots(std::move(knots))
  , Points(std::move(homogeneousPoints))
{
}

void NurbsCurve::validate(const std::string& entity) const
{
  for (size_t i = 0; i < Points.size(); ++i)
  {
    const double w = Points[i].w();
    if (!std::isfinite(w) || !(w > 0.0))
    {
      fail(entity, ": control point ", i, " has weight ", w, " (weights must be > 0)");
    }
    if (!Points[i].allFinite())
    {
      fail(entity, ": control point ", i, " has a NaN or infinite coordinate");
    }
  }
  validateKnots(Knots, Degree, controlPointCount(), entity);
}

bool NurbsCurve::isRational() const
{
  for (const Vec4& p : Points)
  {
    if (p.w() != Points.front().w())
    {
      return true;
    }
  }
  return false;
}

Vec3 NurbsCurve::evaluate(double t) const
{
  return derivatives(t).point;
}

CurveDerivatives NurbsCurve::derivatives(double t) const
{
  const int p = Degree;
  const int span = findSpan(Knots, p, controlPointCount(), t);
  t = std::min(std::max(t, domainStart()), domainEnd());
  double ders[3 * (MaxDegree + 1)];
  basisDerivatives(Knots, span, t, p, 2, ders);
  Vec4 a[3] = { Vec4::Zero(), Vec4::Zero(), Vec4::Zero() };
  for (int k = 0; k < 3; ++k)
  {
    for (int j = 0; j <= p; ++j)
    {
      a[k] += ders[k * (p + 1) + j] * Points[span - p + j];
    }
  }
  CurveDerivatives out;
  rationalCurveDerivatives(a[0], a[1], a[2], out);
  return out;
}

} // namespace exactmat
