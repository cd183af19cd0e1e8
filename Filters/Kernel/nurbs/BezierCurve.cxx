#include "BezierCurve.h"

#include <cmath>

#include "nurbs/Bernstein.h"

namespace exactmat
{

BezierCurve::BezierCurve(const Vec3List& points, const std::vector<double>& weights)
{
  Points.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i)
  {
    Points.push_back(homogeneous(points[i], weights.empty() ? 1.0 : weights[i]));
  }
  Box = controlBox(Points);
}

Vec3 BezierCurve::evaluate(double t) const
{
  return derivatives(t).point;
}

CurveDerivatives BezierCurve::derivatives(double t) const
{
  const int p = degree();
  if (p == 1)
  {
    // A straight edge (every edge of a polygon, evaluated at every tracing step): the
    // general path's own arithmetic, operation for operation — B = (1 − t, t),
    // B' = (−1, 1), B'' = 0 — without building the Bernstein triangle. Bit-identical.
    const double s = 1.0 - t;
    Vec4 a[3] = { Vec4::Zero(), Vec4::Zero(), Vec4::Zero() };
    a[0] += (s * 1.0) * Points[0];
    a[0] += (t * 1.0) * Points[1];
    a[1] += (1 * (0.0 - 1.0)) * Points[0];
    a[1] += (1 * (1.0 - 0.0)) * Points[1];
    a[2] += 0.0 * Points[0];
    a[2] += 0.0 * Points[1];
    CurveDerivatives out;
    rationalCurveDerivatives(a[0], a[1], a[2], out);
    return out;
  }
  // De Casteljau down to the last three points Q0, Q1, Q2 (a quadratic in t): the second
  // homogeneous derivative is p(p − 1)(Q2 − 2 Q1 + Q0), one more level gives R0, R1 with
  // the first derivative p(R1 − R0), and the point is their blend. Convex combinations
  // only (stable), and for the conics of most profiles (p = 2) no level before Q at all:
  // the Bernstein triangle and three sums over the net cost twice as much.
  CurveDerivatives out;
  if (p == 0)
  {
    rationalCurveDerivatives(Points[0], Vec4::Zero(), Vec4::Zero(), out);
    return out;
  }
  const double s = 1.0 - t;
  Vec4 reduced[MaxDegree + 1];
  const Vec4* q = Points.data();
  if (p > 2)
  {
    for (int i = 0; i < p; ++i)
      reduced[i] = s * Points[i] + t * Points[i + 1];
    for (int level = p - 1; level > 2; --level)
      for (int i = 0; i < level; ++i)
        reduced[i] = s * reduced[i] + t * reduced[i + 1];
    q = reduced;
  }
  const Vec4 r0 = s * q[0] + t * q[1];
  const Vec4 r1 = s * q[1] + t * q[2];
  const double pp = static_cast<double>(p);
  const Vec4 a0 = s * r0 + t * r1;
  const Vec4 a1 = pp * (r1 - r0);
  const Vec4 a2 = (pp * (pp - 1.0)) * (q[2] - 2.0 * q[1] + q[0]);
  rationalCurveDerivatives(a0, a1, a2, out);
  return out;
}

Vec3 BezierCurve::endTangent(bool atEnd) const
{
  const int p = degree();
  const Vec3 base = atEnd ? controlPoint(p) : controlPoint(0);
  for (int k = 1; k <= p; ++k)
  {
    const Vec3 other = atEnd ? controlPoint(p - k) : controlPoint(k);
    const Vec3 leg = atEnd ? Vec3(base - other) : Vec3(other - base);
    if (leg.norm() > 1e-14 * (1.0 + base.norm()))
    {
      return leg.normalized();
    }
  }
  return Vec3::Zero();
}

void BezierCurve::split(double t, BezierCurve& left, BezierCurve& right) const
{
  const int p = degree();
  Vec4List b = Points;
  Vec4List l(p + 1), r(p + 1);
  l[0] = b[0];
  r[p] = b[p];
  for (int k = 1; k <= p; ++k)
  {
    for (int i = 0; i <= p - k; ++i)
    {
      b[i] = (1.0 - t) * b[i] + t * b[i + 1];
    }
    l[k] = b[0];
    r[p - k] = b[p - k];
  }
  left = BezierCurve(std::move(l));
  right = BezierCurve(std::move(r));
}

BezierCurve BezierCurve::inStandardForm() const
{
  const int p = degree();
  if (p < 1)
    return *this;
  const double w0 = Points.front().w(), wp = Points.back().w();
  const double c = std::pow(w0 / wp, 1.0 / p);
  Vec4List out(Points.size());
  double scale = 1.0 / w0;
  for (int k = 0; k <= p; ++k)
  {
    out[k] = Points[k] * scale;
    scale *= c;
  }
  out.back().w() = 1.0; // exactly, not to rounding
  out.back().head<3>() = euclidean(Points.back());
  return BezierCurve(out);
}

BezierCurve BezierCurve::segment(double t0, double t1) const
{
  BezierCurve a, b, c, d;
  if (t1 < 1.0)
  {
    split(t1, a, b);
  }
  else
  {
    a = *this;
  }
  if (t0 <= 0.0)
  {
    return a;
  }
  a.split(t0 / t1, c, d);
  return d;
}

BezierCurve BezierCurve::reversed() const
{
  return BezierCurve(Vec4List(Points.rbegin(), Points.rend()));
}

Box3 BezierCurve::controlBox(const Vec4List& points)
{
  Box3 box;
  for (const Vec4& h : points)
  {
    box.extend(euclidean(h));
  }
  return box;
}

NurbsCurve BezierCurve::toNurbs() const
{
  const int p = degree();
  KnotVector knots(2 * (p + 1), 0.0);
  for (int i = p + 1; i < 2 * (p + 1); ++i)
  {
    knots[i] = 1.0;
  }
  return NurbsCurve(p, knots, Points);
}

} // namespace exactmat
