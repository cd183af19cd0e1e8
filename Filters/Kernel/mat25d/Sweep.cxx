#include "Sweep.h"

#include "common/Format.h"
#include "common/InputError.h"
#include "nurbs/Bernstein.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace exactmat
{

namespace
{
// True when the Bernstein polynomial is > 0 on all of [0,1]: coefficients decide, else
// subdivide (bounded depth: a polynomial still undecided at 2^-30 touches zero).
bool positiveOnUnit(const BernsteinPoly& f, int depth = 0)
{
  const auto [lo, hi] = std::minmax_element(f.c.begin(), f.c.end());
  if (*lo > 0.0)
    return true;
  if (f.c[0] <= 0.0 || f.c[f.c.size() - 1] <= 0.0 || *hi <= 0.0 || depth > 30)
    return false;
  BernsteinPoly left, right;
  f.split(0.5, left, right);
  return positiveOnUnit(left, depth + 1) && positiveOnUnit(right, depth + 1);
}

// The homogeneous control points of the rational quadratic arc that carries the point
// with homogeneous coordinates h about the axis (a, d) from angle t0 to t1 (≤ 90°):
// ends rotated, middle rotated to the mid angle and pushed out by 1/cos(Δ/2), with weight
// cos(Δ/2) (Piegl & Tiller §7.3). Linear in h, so a whole rational curve sweeps exactly.
void arcNet(const Vec4& h, const Vec3& a, const Vec3& d, const Vec3& m, const Vec3& n,
  double t0, double t1, Vec4 out[3])
{
  const double w = h.w();
  const Vec3 rel = h.head<3>() - w * a; // w·(x − a)
  const double along = rel.dot(d);
  const double rm = rel.dot(m), rn = rel.dot(n);
  const double half = 0.5 * (t1 - t0), c = std::cos(half);
  const double angles[3] = { t0, 0.5 * (t0 + t1), t1 };
  for (int k = 0; k < 3; ++k)
  {
    const double ca = std::cos(angles[k]), sa = std::sin(angles[k]);
    // rotate the radial part (rm, rn) in the (m, n) plane by the angle
    Vec3 radial = (rm * ca - rn * sa) * m + (rm * sa + rn * ca) * n;
    Vec3 p = w * a + along * d + (k == 1 ? radial / c : radial);
    const double weight = k == 1 ? c : 1.0;
    out[k] = Vec4(weight * p.x(), weight * p.y(), weight * p.z(), weight * w);
  }
}
} // namespace

Sweep Sweep::extrusion(double length)
{
  Sweep s;
  s.kind = SweepKind::Extrusion;
  s.length = length;
  return s;
}

Sweep Sweep::revolution(double degrees, const Vec3& point, const Vec3& direction)
{
  Sweep s;
  s.kind = SweepKind::Revolution;
  s.angle = degrees * Pi / 180.0;
  s.axisPoint = point;
  s.axisDirection = direction;
  return s;
}

const char* toString(SweepKind kind)
{
  return kind == SweepKind::Extrusion ? "extrusion" : "revolution";
}

SweepMap::SweepMap(const Boundary2D& profile, const Sweep& sweep)
  : Profile(&profile)
  , S(sweep)
{
  const double size = profile.diagonal();
  if (S.kind == SweepKind::Extrusion)
  {
    if (!(S.length > 0.0) || !std::isfinite(S.length))
      fail("extrusion: the length must be positive and finite (got ", format(S.length), ")");
    Span = S.length;
    return;
  }
  if (!(S.angle > 0.0) || !(S.angle <= 2.0 * Pi * (1.0 + 1e-12)))
  {
    fail("revolution: the angle must be in (0°, 360°] (got ", format(S.angle * 180.0 / Pi),
      "°)");
  }
  Span = std::min(S.angle, 2.0 * Pi);
  Closed = Span >= 2.0 * Pi * (1.0 - 1e-12);
  const Plane& plane = profile.plane();
  if (!S.axisPoint.allFinite() || !S.axisDirection.allFinite() || S.axisDirection.norm() == 0.0)
    fail("revolution: the axis needs a finite point and a non-zero direction");
  const Vec3 d = S.axisDirection.normalized();
  const double offPlane = std::abs(plane.toLocal(S.axisPoint).z());
  if (std::abs(d.dot(plane.normal)) > 1e-9 || offPlane > 1e-9 * size)
  {
    fail("revolution: the axis through ", format(S.axisPoint), " along ", format(d),
      " is not in the profile's plane (normal ", format(plane.normal), ")");
  }
  const Vec3 a = plane.toLocal(S.axisPoint);
  A2 = Vec2(a.x(), a.y());
  D2 = Vec2(d.dot(plane.e1), d.dot(plane.e2)).normalized();
  M2 = Vec2(D2.y(), -D2.x());
  // m points towards the profile: decided by any profile point, then checked for all.
  const Vec3 p0 = profile.edges().front().curve.startPoint();
  if ((Vec2(p0.x(), p0.y()) - A2).dot(M2) < 0.0)
    M2 = -M2;
  Aw = plane.toWorld(Vec3(A2.x(), A2.y(), 0.0));
  Dw = D2.x() * plane.e1 + D2.y() * plane.e2;
  Mw = M2.x() * plane.e1 + M2.y() * plane.e2;
  Nw = Dw.cross(Mw);
  checkAxis();
}

void SweepMap::checkAxis() const
{
  // ρ(C(t))·w(t) is a polynomial with Bernstein coefficients w_i·ρ(P_i).
  for (const Edge2D& e : Profile->edges())
  {
    const Vec4List& h = e.curve.homogeneousPoints();
    BernsteinPoly rho;
    rho.c.resize(h.size());
    for (size_t i = 0; i < h.size(); ++i)
      rho.c[i] = (Vec2(h[i].x(), h[i].y()) - h[i].w() * A2).dot(M2);
    if (!positiveOnUnit(rho))
    {
      fail("revolution: the axis through ", format(S.axisPoint), " touches or crosses the "
        "profile at ", e.name(), "; the axis must lie outside the profile");
    }
  }
}

Vec3 SweepMap::place(const Vec2& p, double tau) const
{
  if (S.kind == SweepKind::Extrusion)
    return plane().toWorld(Vec3(p.x(), p.y(), tau));
  const Vec2 rel = p - A2;
  const double along = rel.dot(D2), rho = rel.dot(M2);
  return Aw + along * Dw + rho * (std::cos(tau) * Mw + std::sin(tau) * Nw);
}

double SweepMap::axisDistance(const Vec2& p) const
{
  return S.kind == SweepKind::Extrusion ? 1.0 : (p - A2).dot(M2);
}

double SweepMap::capSpan(const Vec2& p, double r) const
{
  if (S.kind == SweepKind::Extrusion)
    return r;
  return std::asin(std::min(1.0, r / axisDistance(p)));
}

Vec4 SweepMap::placeHomogeneous(const Vec4& h, double tau) const
{
  const Vec3 x = place(Vec2(h.x() / h.w(), h.y() / h.w()), tau);
  return Vec4(h.w() * x.x(), h.w() * x.y(), h.w() * x.z(), h.w());
}

std::vector<PatchPiece> SweepMap::sideFaces(const std::vector<std::vector<double>>& splits) const
{
  std::vector<PatchPiece> faces;
  const std::vector<Edge2D>& edges = Profile->edges();
  for (size_t k = 0; k < edges.size(); ++k)
  {
    std::vector<double> cuts{ 0.0 };
    if (k < splits.size())
      cuts.insert(cuts.end(), splits[k].begin(), splits[k].end());
    cuts.push_back(1.0);
    for (size_t c = 0; c + 1 < cuts.size(); ++c)
      appendSides(edges[k], edges[k].curve.segment(cuts[c], cuts[c + 1]).inStandardForm(), faces);
  }
  return faces;
}

void SweepMap::appendSides(const Edge2D& e, const BezierCurve& piece, std::vector<PatchPiece>& faces) const
{
  const Plane& pl = plane();
  Vec4List world;
  for (const Vec4& h : piece.homogeneousPoints())
    world.push_back(pl.toWorldHomogeneous(h));
  const int p = static_cast<int>(world.size()) - 1;
  if (S.kind == SweepKind::Extrusion)
  {
    Vec4List net;
    for (const Vec4& h : world)
    {
      net.push_back(h);
      const Vec3 moved = h.head<3>() + h.w() * S.length * pl.normal;
      net.push_back(Vec4(moved.x(), moved.y(), moved.z(), h.w()));
    }
    faces.push_back({ BezierPatch(p, 1, net), std::nullopt, e.entity });
    return;
  }
  const int spans = std::max(1, static_cast<int>(std::ceil(Span / (0.5 * Pi) - 1e-9)));
  for (int k = 0; k < spans; ++k)
  {
    const double t0 = Span * k / spans, t1 = Span * (k + 1) / spans;
    Vec4List net;
    for (const Vec4& h : world)
    {
      Vec4 arc[3];
      arcNet(h, Aw, Dw, Mw, Nw, t0, t1, arc);
      net.insert(net.end(), arc, arc + 3);
    }
    faces.push_back({ BezierPatch(p, 2, net), std::nullopt, e.entity });
  }
}

bool SweepMap::projectOnProfileFace(int face, const Vec3& x, Vec2& foot, double& distance) const
{
  if (S.kind == SweepKind::Extrusion)
  {
    const Vec3 l = plane().toLocal(x);
    foot = Vec2(l.x(), l.y());
    distance = std::abs(face == 0 ? l.z() : S.length - l.z());
    return true;
  }
  // Turn x back so the face lies in the (D, M) half-plane, then project.
  const Vec3 rel = x - Aw;
  const double along = rel.dot(Dw), rm = rel.dot(Mw), rn = rel.dot(Nw);
  const double t = face == 0 ? 0.0 : -Span;
  const double u = rm * std::cos(t) - rn * std::sin(t), v = rm * std::sin(t) + rn * std::cos(t);
  if (u <= 0.0)
    return false;
  foot = A2 + along * D2 + u * M2;
  distance = std::abs(v);
  return true;
}

std::string SweepMap::describe() const
{
  if (S.kind == SweepKind::Extrusion)
    return "extrusion of length " + format(Span);
  return "revolution by " + format(Span * 180.0 / Pi) + "°";
}

} // namespace exactmat
