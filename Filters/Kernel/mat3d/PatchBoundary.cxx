#include "PatchBoundary.h"

#include "geometry/ClosestPoint.h"

#include <algorithm>

namespace exactmat
{

namespace
{
// The nearest point of a flat triangle abc to x (the triangle is convex: its only local
// minimum), and whether it lies on the triangle's border. Closed form: the patch search
// is slow on the collapsed side of a triangle stored as a patch.
Vec3 nearestOnTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x, bool* border)
{
  const Vec3 ab = b - a, ac = c - a, n = ab.cross(ac);
  const Vec3 p = x - n * (n.dot(x - a) / n.squaredNorm());
  // Barycentric signs of the projection: inside when all three sub-triangles agree.
  const bool inside = n.dot((b - a).cross(p - a)) >= 0.0 && n.dot((c - b).cross(p - b)) >= 0.0 &&
    n.dot((a - c).cross(p - c)) >= 0.0;
  *border = !inside;
  if (inside)
    return p;
  Vec3 best = a;
  double bestDistance = INFINITY;
  const Vec3 corners[3] = { a, b, c };
  for (int i = 0; i < 3; ++i)
  {
    const Vec3 s = corners[i], e = corners[(i + 1) % 3] - s;
    const double t = std::clamp((x - s).dot(e) / e.squaredNorm(), 0.0, 1.0);
    const Vec3 q = s + t * e;
    if ((q - x).norm() < bestDistance)
    {
      bestDistance = (q - x).norm();
      best = q;
    }
  }
  return best;
}

bool flatTriangle(const Face3D& f, Vec3* corners)
{
  if (!f.triangle || f.triangle->degree != 1)
    return false;
  const TriangleNet& t = *f.triangle;
  corners[0] = euclidean(t.at(0, 0));
  corners[1] = euclidean(t.at(1, 0));
  corners[2] = euclidean(t.at(0, 1));
  return true;
}

PatchFootpoint nearestOnFace(const Face3D& f, const Vec3& x)
{
  Vec3 c[3];
  if (!flatTriangle(f, c))
    return closestPoint(f.patch, x);
  PatchFootpoint fp;
  fp.point = nearestOnTriangle(c[0], c[1], c[2], x, &fp.onBoundary);
  fp.distance = (fp.point - x).norm();
  return fp;
}
} // namespace

PatchBoundary::PatchBoundary(const Boundary3D& boundary)
  : Boundary(&boundary)
{
  std::vector<Box3> boxes;
  Box3 all;
  for (const Face3D& f : boundary.faces())
  {
    boxes.push_back(f.patch.boundingBox());
    all.extend(boxes.back());
  }
  Tree.build(boxes);
  Size = all.diagonal().norm();
  const Vec3 extent = all.diagonal().cwiseAbs();
  Aspect = extent.maxCoeff() / std::max(extent.minCoeff(), 1e-300 * extent.maxCoeff());
}

double PatchBoundary::distance(const Vec3& x) const
{
  double d = Unbounded;
  Tree.nearest(x, [&](int i) { return nearestOnFace(Boundary->faces()[i], x).distance; }, &d);
  return d;
}

Vec3 PatchBoundary::nearestPoint(const Vec3& x) const
{
  Vec3 nearest = x;
  double best = Unbounded;
  Tree.nearest(x,
    [&](int i) {
      const PatchFootpoint f = nearestOnFace(Boundary->faces()[i], x);
      if (f.distance < best)
      {
        best = f.distance;
        nearest = f.point;
      }
      return f.distance;
    },
    nullptr);
  return nearest;
}

std::vector<SolidBoundary::Contact> PatchBoundary::touchpoints(const Vec3& x, double radius) const
{
  std::vector<Minimum> minima;
  for (int i : Tree.candidatesWithin(x, radius))
  {
    Vec3 c[3];
    if (flatTriangle(Boundary->faces()[i], c))
    {
      const PatchFootpoint f = nearestOnFace(Boundary->faces()[i], x);
      if (f.distance <= radius)
        minima.push_back({ f.point, f.distance, f.onBoundary, i });
      continue;
    }
    for (const PatchFootpoint& f : patchFootpoints(Boundary->faces()[i].patch, x, radius))
      minima.push_back({ f.point, f.distance, f.onBoundary, i });
  }
  return distinctContacts(std::move(minima), x);
}

} // namespace exactmat
