#include "BezierPatch.h"

#include "nurbs/Bernstein.h"

#include <cmath>

namespace exactmat
{

BezierPatch BezierPatch::fromTriangle(const TriangleNet& tri)
{
  // s^i t^j r^k with s = u, t = v(1−u), r = (1−u)(1−v) is B^n_i(u)·B^{n−i}_j(v): row i of
  // the tensor net is the triangle's row i in v-degree n−i, elevated to degree n.
  const int n = tri.degree;
  Vec4List net(static_cast<size_t>(n + 1) * (n + 1));
  for (int i = 0; i <= n; ++i)
  {
    const int m = n - i;
    for (int d = 0; d < 4; ++d)
    {
      BernsteinPoly row;
      row.c.resize(m + 1);
      for (int j = 0; j <= m; ++j)
      {
        row.c[j] = tri.at(i, j)(d);
      }
      const BernsteinPoly e = row.elevatedTo(n);
      for (int j = 0; j <= n; ++j)
      {
        net[i * (n + 1) + j](d) = e.c[j];
      }
    }
  }
  return BezierPatch(n, n, std::move(net));
}

BezierPatch BezierPatch::inStandardForm() const
{
  if (P < 1 || Q < 1)
  {
    return *this;
  }
  const double w00 = homogeneousPoint(0, 0).w(), wp0 = homogeneousPoint(P, 0).w();
  const double w0q = homogeneousPoint(0, Q).w();
  const double a = std::pow(w00 / wp0, 1.0 / P), b = std::pow(w00 / w0q, 1.0 / Q);
  Vec4List net(Net.size());
  double ai = 1.0 / w00;
  for (int i = 0; i <= P; ++i)
  {
    double scale = ai;
    for (int j = 0; j <= Q; ++j)
    {
      net[i * (Q + 1) + j] = Net[i * (Q + 1) + j] * scale;
      scale *= b;
    }
    ai *= a;
  }
  BezierPatch out(P, Q, std::move(net));
  // Corner weights exactly 1 where they are 1 up to rounding, points unchanged.
  for (const auto& [i, j] : { std::pair{ 0, 0 }, { P, 0 }, { 0, Q }, { P, Q } })
  {
    Vec4& h = out.Net[i * (Q + 1) + j];
    if (std::abs(h.w() - 1.0) <= 1e-13)
    {
      h.head<3>() = euclidean(homogeneousPoint(i, j));
      h.w() = 1.0;
    }
  }
  return out;
}

Vec3 BezierPatch::evaluate(double u, double v) const
{
  return derivatives(u, v).point;
}

SurfaceDerivatives BezierPatch::derivatives(double u, double v) const
{
  double bu[3 * (MaxDegree + 1)], bv[3 * (MaxDegree + 1)];
  bernsteinWithDerivatives(P, u, bu);
  bernsteinWithDerivatives(Q, v, bv);
  // Each row's sums along v (value, first and second derivative) once, shared by the
  // three u-orders that use them: the same sums in the same order as summing per
  // derivative, half the work.
  Vec4 rows[3][MaxDegree + 1];
  for (int l = 0; l < 3; ++l)
    for (int i = 0; i <= P; ++i)
    {
      Vec4 row = Vec4::Zero();
      for (int j = 0; j <= Q; ++j)
      {
        row += bv[l * (Q + 1) + j] * homogeneousPoint(i, j);
      }
      rows[l][i] = row;
    }
  static const int orders[6][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 }, { 2, 0 }, { 1, 1 }, { 0, 2 } };
  Vec4 a[6];
  for (int d = 0; d < 6; ++d)
  {
    const int k = orders[d][0], l = orders[d][1];
    a[d].setZero();
    for (int i = 0; i <= P; ++i)
    {
      a[d] += bu[k * (P + 1) + i] * rows[l][i];
    }
  }
  SurfaceDerivatives out;
  rationalSurfaceDerivatives(a, out);
  return out;
}

Vec3 BezierPatch::normal(double u, double v) const
{
  // Step towards the patch centre until Su×Sv is non-degenerate (bounded: 40 halvings).
  double du = 0.0, dv = 0.0;
  for (int k = 0; k < 40; ++k)
  {
    const SurfaceDerivatives d = derivatives(u + du, v + dv);
    const Vec3 n = d.su.cross(d.sv);
    const double scale = d.su.norm() * d.sv.norm();
    if (n.norm() > 1e-10 * scale && scale > 0.0)
    {
      return n.normalized();
    }
    const double h = std::ldexp(1.0, -40 + k);
    du = (u < 0.5 ? h : -h);
    dv = (v < 0.5 ? h : -h);
  }
  return Vec3::Zero();
}

namespace
{
// de Casteljau along u (dir 0) or v (dir 1) keeping the part [t0, t1].
Vec4List restrict(const Vec4List& net, int p, int q, int dir, double t0, double t1)
{
  Vec4List out = net;
  const int lines = (dir == 0) ? q + 1 : p + 1;
  const int count = (dir == 0) ? p + 1 : q + 1;
  for (int l = 0; l < lines; ++l)
  {
    Vec4List curve(count);
    for (int i = 0; i < count; ++i)
    {
      curve[i] = (dir == 0) ? net[i * (q + 1) + l] : net[l * (q + 1) + i];
    }
    const BezierCurve piece = BezierCurve(curve).segment(t0, t1);
    for (int i = 0; i < count; ++i)
    {
      ((dir == 0) ? out[i * (q + 1) + l] : out[l * (q + 1) + i]) = piece.homogeneousPoints()[i];
    }
  }
  return out;
}
} // namespace

BezierPatch BezierPatch::subPatch(double u0, double u1, double v0, double v1) const
{
  Vec4List net = Net;
  if (u0 > 0.0 || u1 < 1.0)
  {
    net = restrict(net, P, Q, 0, u0, u1);
  }
  if (v0 > 0.0 || v1 < 1.0)
  {
    net = restrict(net, P, Q, 1, v0, v1);
  }
  return BezierPatch(P, Q, std::move(net));
}

namespace
{
// restrict()'s arithmetic on one line of `count` points with stride `step`, in place:
// BezierCurve::segment's two de Casteljau splits, operation for operation.
void segmentInPlace(Vec4* line, int count, std::ptrdiff_t step, double t0, double t1, Vec4List& b)
{
  const int p = count - 1;
  auto at = [&](int i) -> Vec4& { return line[i * step]; };
  b.resize(count);
  if (t1 < 1.0)
  {
    for (int i = 0; i < count; ++i)
      b[i] = at(i);
    for (int k = 1; k <= p; ++k)
    {
      for (int i = 0; i <= p - k; ++i)
        b[i] = (1.0 - t1) * b[i] + t1 * b[i + 1];
      at(k) = b[0]; // the left part: at(0) stays
    }
  }
  if (t0 <= 0.0)
    return;
  const double t = t0 / t1;
  for (int i = 0; i < count; ++i)
    b[i] = at(i);
  for (int k = 1; k <= p; ++k)
  {
    for (int i = 0; i <= p - k; ++i)
      b[i] = (1.0 - t) * b[i] + t * b[i + 1];
    at(p - k) = b[p - k]; // the right part: at(p) stays
  }
}
} // namespace

Box3 BezierPatch::subPatchBox(double u0, double u1, double v0, double v1) const
{
  thread_local Vec4List net, line;
  net.assign(Net.begin(), Net.end());
  if (u0 > 0.0 || u1 < 1.0)
  {
    for (int j = 0; j <= Q; ++j)
      segmentInPlace(net.data() + j, P + 1, Q + 1, u0, u1, line);
  }
  if (v0 > 0.0 || v1 < 1.0)
  {
    for (int i = 0; i <= P; ++i)
      segmentInPlace(net.data() + i * (Q + 1), Q + 1, 1, v0, v1, line);
  }
  Box3 box;
  for (const Vec4& h : net)
    box.extend(euclidean(h));
  return box;
}

BezierCurve BezierPatch::side(int s) const
{
  Vec4List c;
  switch (s)
  {
    case 0:
      for (int i = 0; i <= P; ++i)
        c.push_back(homogeneousPoint(i, 0));
      break;
    case 1:
      for (int j = 0; j <= Q; ++j)
        c.push_back(homogeneousPoint(P, j));
      break;
    case 2:
      for (int i = P; i >= 0; --i)
        c.push_back(homogeneousPoint(i, Q));
      break;
    default:
      for (int j = Q; j >= 0; --j)
        c.push_back(homogeneousPoint(0, j));
      break;
  }
  return BezierCurve(std::move(c));
}

Vec2 BezierPatch::sideParameter(int s, double t)
{
  switch (s)
  {
    case 0:
      return Vec2(t, 0.0);
    case 1:
      return Vec2(1.0, t);
    case 2:
      return Vec2(1.0 - t, 1.0);
    default:
      return Vec2(0.0, 1.0 - t);
  }
}

Box3 BezierPatch::boundingBox() const
{
  Box3 box;
  for (const Vec4& h : Net)
  {
    box.extend(euclidean(h));
  }
  return box;
}

NurbsSurface BezierPatch::toNurbs() const
{
  auto bezierKnots = [](int p) {
    KnotVector k(2 * (p + 1), 0.0);
    for (int i = p + 1; i < 2 * (p + 1); ++i)
      k[i] = 1.0;
    return k;
  };
  return NurbsSurface(P, Q, bezierKnots(P), bezierKnots(Q), P + 1, Q + 1, Net);
}

} // namespace exactmat
