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

Vec3 SweptBoundary::nearestPoint(const Vec3& x) const
{
  // The side patches only: the valley test looks between two close minima, and the
  // profile faces are planar (two minima on one of them are never a valley).
  Vec3 nearest = x;
  double d = Unbounded;
  SideTree.nearest(x,
    [&](int i) {
      const PatchFootpoint f = closestPoint(Sides[i].patch, x);
      if (f.distance < d)
      {
        d = f.distance;
        nearest = f.point;
      }
      return f.distance;
    },
    nullptr);
  return nearest;
}

std::vector<SolidBoundary::Contact> SweptBoundary::touchpoints(const Vec3& x, double radius) const
{
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
  return distinctContacts(std::move(minima), x);
}

} // namespace exactmat
