#include "Bisector.h"

#include <Eigen/Dense>
#include <cmath>

namespace exactmat
{

Vec2 Bisector::point(const BisectorState& y) const
{
  const GeneratorPoint a = G->evaluate(A, y.sa);
  return a.p + y.r * a.n;
}

Vec2 Bisector::residual(const BisectorState& y) const
{
  const GeneratorPoint a = G->evaluate(A, y.sa), b = G->evaluate(B, y.sb);
  return a.p + y.r * a.n - b.p - y.r * b.n;
}

Eigen::Vector3d Bisector::tangent(const BisectorState& y, int dirA, int dirB) const
{
  return tangent(G->evaluate(A, y.sa), G->evaluate(B, y.sb), y.r, dirA, dirB);
}

Eigen::Vector3d Bisector::tangent(const GeneratorPoint& a, const GeneratorPoint& b, double r, int dirA, int dirB) const
{
  const Vec2 ca = a.dp + r * a.dn, cb = -(b.dp + r * b.dn), cr = a.n - b.n;
  const Eigen::Vector3d row0(ca.x(), cb.x(), cr.x()), row1(ca.y(), cb.y(), cr.y());
  Eigen::Vector3d t = row0.cross(row1);
  const double n = t.norm();
  if (!(n > 0.0))
  {
    return Eigen::Vector3d::Zero();
  }
  t /= n;
  // Orient by the front that moves most clearly.
  const double wa = dirA * t(0), wb = dirB * t(1);
  if ((std::abs(wa) >= std::abs(wb) ? wa : wb) < 0.0)
  {
    t = -t;
  }
  return t;
}

double Bisector::motion(const BisectorState& y, const Eigen::Vector3d& t) const
{
  return motion(G->evaluate(A, y.sa), G->evaluate(B, y.sb), y.r, t);
}

double Bisector::motion(const GeneratorPoint& a, const GeneratorPoint& b, double r, const Eigen::Vector3d& t) const
{
  const Vec2 dx = (a.dp + r * a.dn) * t(0) + a.n * t(2);
  const double m = std::max({ dx.norm(), (a.dp * t(0)).norm(), (b.dp * t(1)).norm(),
    r * (a.dn * t(0)).norm(), r * (b.dn * t(1)).norm() });
  return m;
}

bool Bisector::correct(BisectorState& y, int fixed, double tolerance, GeneratorPoint* atA, GeneratorPoint* atB) const
{
  for (int it = 0; it < 30; ++it)
  {
    const GeneratorPoint a = G->evaluate(A, y.sa), b = G->evaluate(B, y.sb);
    const Vec2 e = a.p + y.r * a.n - b.p - y.r * b.n;
    if (e.squaredNorm() <= tolerance * tolerance)
    {
      if (atA)
        *atA = a;
      if (atB)
        *atB = b;
      return true;
    }
    const Vec2 cols[3] = { a.dp + y.r * a.dn, -(b.dp + y.r * b.dn), a.n - b.n };
    const int i = (fixed == 0) ? 1 : 0, j = (fixed == 2) ? 1 : 2;
    // The 2×2 system [cols[i] cols[j]]·d = e by Cramer's rule.
    const Vec2 &u = cols[i], &v = cols[j];
    const double det = u.x() * v.y() - v.x() * u.y();
    if (!(std::abs(det) > 1e-300))
    {
      return false;
    }
    double* unknown[3] = { &y.sa, &y.sb, &y.r };
    *unknown[i] -= (e.x() * v.y() - v.x() * e.y()) / det;
    *unknown[j] -= (u.x() * e.y() - e.x() * u.y()) / det;
    if (!(y.sa > -0.5 && y.sa < 1.5 && y.sb > -0.5 && y.sb < 1.5 && y.r > -1e-9) ||
      !std::isfinite(y.r))
    {
      return false;
    }
  }
  return false;
}

} // namespace exactmat

namespace exactmat
{

bool polishBranchPoint(const Generators& G, int& ga, int& gb, int& gc, double& sa, double& sb,
  double& sc, double& r, double tolerance)
{
  Eigen::Vector4d y(sa, sb, sc, r);
  int g[3] = { ga, gb, gc };
  // Moves to a neighbour are bounded: a footpoint at a junction could be handed back and
  // forth by rounding.
  int moves = 0;
  constexpr int MaxMoves = 6;
  for (int it = 0; it < 30 + 4 * MaxMoves; ++it)
  {
    const GeneratorPoint a = G.evaluate(g[0], y(0)), b = G.evaluate(g[1], y(1)),
                         c = G.evaluate(g[2], y(2));
    const Vec2 xa = a.p + y(3) * a.n;
    const Vec2 e1 = xa - b.p - y(3) * b.n, e2 = xa - c.p - y(3) * c.n;
    if (std::max(e1.norm(), e2.norm()) <= tolerance)
    {
      if (y(0) < -1e-9 || y(0) > 1 + 1e-9 || y(1) < -1e-9 || y(1) > 1 + 1e-9 || y(2) < -1e-9 ||
        y(2) > 1 + 1e-9 || y(3) < 0.0)
        return false;
      ga = g[0];
      gb = g[1];
      gc = g[2];
      sa = std::min(1.0, std::max(0.0, y(0)));
      sb = std::min(1.0, std::max(0.0, y(1)));
      sc = std::min(1.0, std::max(0.0, y(2)));
      r = y(3);
      return true;
    }
    const Vec2 ca = a.dp + y(3) * a.dn, cb = b.dp + y(3) * b.dn, cc = c.dp + y(3) * c.dn;
    Eigen::Matrix4d J;
    J << ca.x(), -cb.x(), 0.0, a.n.x() - b.n.x(), //
      ca.y(), -cb.y(), 0.0, a.n.y() - b.n.y(),    //
      ca.x(), 0.0, -cc.x(), a.n.x() - c.n.x(),    //
      ca.y(), 0.0, -cc.y(), a.n.y() - c.n.y();
    const Eigen::FullPivLU<Eigen::Matrix4d> lu(J);
    if (!lu.isInvertible())
      return false;
    y -= lu.solve(Eigen::Vector4d(e1.x(), e1.y(), e2.x(), e2.y()));
    if (!y.allFinite())
      return false;
    // Past an end by more than rounding: go on along the neighbour, as far (in length)
    // as past the end. Within rounding of it the end is the footpoint (clamped above).
    constexpr double Past = 1e-12;
    for (int k = 0; k < 3 && moves < MaxMoves; ++k)
    {
      const Generator& gen = G[g[k]];
      const bool forward = y(k) > 1.0 + Past && gen.endJunction != VertexKind::Convex;
      const bool backward = y(k) < -Past && gen.startJunction != VertexKind::Convex;
      const int to = forward ? gen.next : (backward ? gen.prev : -1);
      if (to < 0)
        continue;
      const double past = forward ? y(k) - 1.0 : -y(k);
      const double speedHere = G.evaluate(g[k], forward ? 1.0 : 0.0).dp.norm();
      const double speedThere = G.evaluate(to, forward ? 0.0 : 1.0).dp.norm();
      const double there = speedThere > 0.0 ? std::min(0.5, past * speedHere / speedThere) : 0.0;
      g[k] = to;
      y(k) = forward ? there : 1.0 - there;
      ++moves;
    }
  }
  return false;
}

} // namespace exactmat
