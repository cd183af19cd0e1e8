#include "SweptBoundary.h"

#include <algorithm>
#include <cmath>

namespace exactmat
{

SweptBoundary::SweptBoundary(const Boundary2D& profile, const SweepMap& sweep)
  : Profile(&profile)
  , Map(&sweep)
  , Sides(sweep.sideFaces())
{
  std::vector<Box3> boxes;
  Box3 all;
  for (const PatchPiece& p : Sides)
  {
    boxes.push_back(p.patch.boundingBox());
    all.extend(boxes.back());
  }
  SideTree.build(boxes);
  Size = all.diagonal().norm();
  const Vec3 extent = all.diagonal().cwiseAbs();
  Aspect = extent.maxCoeff() / std::max(extent.minCoeff(), 1e-300 * extent.maxCoeff());
  boxes.clear();
  for (const Edge2D& e : profile.edges())
    boxes.push_back(e.curve.boundingBox());
  EdgeTree.build(boxes);
}

bool SweptBoundary::insideProfile(const Vec2& p) const
{
  // The nearest point of the exact boundary decides: inside when p lies on the material
  // side of the edge's normal there; at a vertex, inside exactly when it is reflex (a
  // point whose nearest boundary point is a convex vertex lies outside).
  const Vec3 q(p.x(), p.y(), 0.0);
  const std::vector<Edge2D>& edges = Profile->edges();
  CurveFootpoint best;
  double distance = 0.0;
  const int e = EdgeTree.nearest(q,
    [&](int i) { return closestPoint(edges[i].curve, q).distance; }, &distance);
  if (e < 0)
    return false;
  best = closestPoint(edges[e].curve, q);
  if (best.distance <= 1e-14 * Size)
    return true;
  const double tol = 1e-12;
  if (best.t > tol && best.t < 1.0 - tol)
  {
    const Vec3 d = edges[e].curve.derivatives(best.t).d1;
    const Vec2 inward(-d.y(), d.x());
    return inward.dot(Vec2(p.x() - best.point.x(), p.y() - best.point.y())) > 0.0;
  }
  const int v = best.t <= tol ? edges[e].startVertex : edges[e].endVertex;
  const Vertex2D& vertex = Profile->vertices()[v];
  if (vertex.kind != VertexKind::Smooth)
    return vertex.kind == VertexKind::Reflex;
  const Vec3 d = edges[e].curve.endTangent(best.t > 0.5);
  const Vec2 inward(-d.y(), d.x());
  return inward.dot(Vec2(p.x() - best.point.x(), p.y() - best.point.y())) > 0.0;
}

double SweptBoundary::faceDistance(int face, const Vec3& x, Vec3* foot) const
{
  if (Map->closed())
    return Unbounded;
  Vec2 p;
  double d = 0.0;
  if (!Map->projectOnProfileFace(face, x, p, d) || !insideProfile(p))
    return Unbounded;
  if (foot)
    *foot = Map->place(p, face == 0 ? 0.0 : Map->span());
  return d;
}

double SweptBoundary::distance(const Vec3& x) const
{
  double d = Unbounded;
  SideTree.nearest(x, [&](int i) { return closestPoint(Sides[i].patch, x).distance; }, &d);
  for (int face = 0; face < 2; ++face)
    d = std::min(d, faceDistance(face, x, nullptr));
  return d;
}

bool SweptBoundary::sameContact(
  const Vec3& x, double radius, const Vec3& a, const Vec3& b, double merge) const
{
  const double gap = (a - b).norm();
  if (gap <= merge)
    return true;
  if (gap > 0.2 * radius)
    return false;
  // (radius here: the ball's radius plus rounding.)
  // Two minima close together are one contact when the boundary between them stays
  // inside the ball (a flat valley: the ball osculates there), two when it bulges out.
  const Vec3 mid = 0.5 * (a + b);
  Vec3 nearest = mid;
  double d = Unbounded;
  SideTree.nearest(mid,
    [&](int i) {
      const PatchFootpoint f = closestPoint(Sides[i].patch, mid);
      if (f.distance < d)
      {
        d = f.distance;
        nearest = f.point;
      }
      return f.distance;
    },
    nullptr);
  return (nearest - x).norm() <= radius;
}

std::vector<SweptBoundary::Contact> SweptBoundary::touchpoints(const Vec3& x, double radius) const
{
  struct Minimum
  {
    Vec3 point;
    double distance;
    bool oneSided;
    int source;
  };
  std::vector<Minimum> minima;
  for (int i : SideTree.candidatesWithin(x, radius))
  {
    for (const PatchFootpoint& f : patchFootpoints(Sides[i].patch, x, radius))
      minima.push_back({ f.point, f.distance, f.onBoundary, i });
  }
  for (int face = 0; face < 2; ++face)
  {
    Vec3 foot;
    const double d = faceDistance(face, x, &foot);
    if (d <= radius)
      minima.push_back({ foot, d, false, face == 0 ? ProfileFace0 : ProfileFace1 });
  }
  std::sort(minima.begin(), minima.end(),
    [](const Minimum& a, const Minimum& b) { return a.distance < b.distance; });
  std::vector<Contact> out;
  if (minima.empty())
    return out;
  // Distinctness is relative to the ball, not the solid: a ball of radius 1e-12 in a
  // sheet 1e-12 thin (or of radius 1 in a bar 1e12 long) touches points that are
  // distinct at its own scale.
  const double scale = std::min(Size, std::max(minima.front().distance, 1e-300));
  const double merge = 1e-7 * scale;
  for (const Minimum& m : minima)
  {
    bool keep = true;
    for (const Minimum& other : minima)
    {
      // A border minimum with a nearer minimum next to it (on the neighbouring patch) is
      // only the border of that patch, not a touchpoint of the solid.
      if (m.oneSided && other.distance < m.distance - 1e-13 * scale &&
        (other.point - m.point).norm() < 0.05 * std::max(m.distance, merge))
      {
        keep = false;
      }
    }
    // The valley test uses the ball's own radius (the nearest minimum), not the counting
    // tolerance: near an osculating point two true touchpoints are only a hair apart.
    const double valley = minima.front().distance + 1e-12 * scale;
    for (const Contact& q : out)
      keep = keep && !sameContact(x, valley, q.point, m.point, merge);
    if (keep)
      out.push_back({ m.point, m.distance, m.source });
  }
  return out;
}

} // namespace exactmat
