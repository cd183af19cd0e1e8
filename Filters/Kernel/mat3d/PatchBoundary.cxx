#include "PatchBoundary.h"

#include "geometry/ClosestPoint.h"

#include <algorithm>

namespace exactmat
{

namespace
{
// The nearest point of a flat convex polygon (corners in order) to x — its only local
// minimum — and whether it lies on the polygon's border. Closed form: the patch search is
// slow on planar faces (a bilinear quad, or a triangle stored as a patch with a collapsed
// side), and most faces of real parts are planar.
Vec3 nearestOnPolygon(const Vec3* corners, int n, const Vec3& x, bool* border)
{
  Vec3 normal = Vec3::Zero();
  for (int i = 0; i < n; ++i) // Newell's normal: any convex polygon, either orientation
    normal += corners[i].cross(corners[(i + 1) % n]);
  const Vec3 p = x - normal * (normal.dot(x - corners[0]) / normal.squaredNorm());
  bool inside = true;
  for (int i = 0; i < n && inside; ++i)
    inside = normal.dot((corners[(i + 1) % n] - corners[i]).cross(p - corners[i])) >= 0.0;
  *border = !inside;
  if (inside)
    return p;
  Vec3 best = corners[0];
  double bestDistance = INFINITY;
  for (int i = 0; i < n; ++i)
  {
    const Vec3 s = corners[i], e = corners[(i + 1) % n] - s;
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

// The corners of a flat convex polygon face, in order: a linear triangle, or a bilinear
// patch whose four corners lie in one plane (to `flat`, a length) as a convex
// quadrilateral (a bilinear map, rational or not, takes the square onto exactly that
// quadrilateral then). 0 when the face is neither.
int flatPolygon(const Face3D& f, double flat, Vec3* corners)
{
  if (f.triangle)
  {
    if (f.triangle->degree != 1)
      return 0;
    const TriangleNet& t = *f.triangle;
    corners[0] = euclidean(t.at(0, 0));
    corners[1] = euclidean(t.at(1, 0));
    corners[2] = euclidean(t.at(0, 1));
    return 3;
  }
  if (f.patch.degreeU() != 1 || f.patch.degreeV() != 1)
    return 0;
  // Corners in order; a collapsed side (two corners at one point: a triangle tiled as a
  // quadrilateral) leaves a triangle.
  const Vec3 all[4] = { f.patch.controlPoint(0, 0), f.patch.controlPoint(1, 0), f.patch.controlPoint(1, 1),
    f.patch.controlPoint(0, 1) };
  int n = 0;
  for (const Vec3& c : all)
    if (n == 0 || (c - corners[n - 1]).norm() > flat)
      corners[n++] = c;
  if (n > 1 && (corners[n - 1] - corners[0]).norm() <= flat)
    --n;
  if (n < 3)
    return 0;
  Vec3 normal = Vec3::Zero();
  for (int i = 0; i < n; ++i)
    normal += corners[i].cross(corners[(i + 1) % n]);
  const double size = (all[2] - all[0]).norm() + (all[3] - all[1]).norm();
  if (!(normal.norm() > 1e-12 * size * size))
    return 0;
  const Vec3 unit = normal.normalized();
  for (int i = 0; i < n; ++i)
  {
    if (std::abs(unit.dot(corners[i] - corners[0])) > flat)
      return 0;
    if (unit.dot((corners[(i + 1) % n] - corners[i]).cross(corners[(i + 2) % n] - corners[(i + 1) % n])) <= 0.0)
      return 0; // not strictly convex
  }
  return n;
}

PatchFootpoint nearestOnFace(const Face3D& f, double flat, const Vec3& x)
{
  Vec3 c[4];
  const int n = flatPolygon(f, flat, c);
  if (n == 0)
    return closestPoint(f.patch, x);
  PatchFootpoint fp;
  fp.point = nearestOnPolygon(c, n, x, &fp.onBoundary);
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
  // A quadrilateral face is planar to the input's rounding (a part far from the origin has
  // its corners rounded off their plane by that much, and is still a polyhedron).
  Flat = std::max(1e-13, 64.0 * boundary.userFrame().inputRounding()) * boundary.diagonal();
  SharpSide.assign(boundary.faces().size(), { false, false, false, false });
  for (const Edge3D& e : boundary.edges())
    if (e.kind != VertexKind::Smooth)
    {
      SharpSide[e.faceA][e.sideA] = true;
      SharpSide[e.faceB][e.sideB] = true;
    }
}

double PatchBoundary::osculation(const Contact& contact, const Vec3& centre, double radius) const
{
  if (contact.source < 0)
    return NAN;
  const Face3D& face = Boundary->faces()[contact.source];
  Vec3 corners[4];
  if (flatPolygon(face, Flat, corners) > 0)
    return NAN;
  // (The contact's parameters when the search gave them: the closest point search is slow
  // at a contact of fourth order.)
  const Vec2 q = std::isnan(contact.parameters.x()) ? [&] {
    const PatchFootpoint f = closestPoint(face.patch, centre);
    return Vec2(f.u, f.v);
  }()
                                                     : contact.parameters;
  // Sides in BezierPatch's order: v = 0, u = 1, v = 1, u = 0.
  const double gap[4] = { q.y(), 1.0 - q.x(), 1.0 - q.y(), q.x() };
  for (int side = 0; side < 4; ++side)
    if (gap[side] <= 1e-9 && SharpSide[contact.source][side])
      return NAN;
  // Su×Sv points out of the material: a convex face bends away from it, k2 < 0 there.
  const SurfaceDerivatives d = face.patch.derivatives(q.x(), q.y());
  const SurfaceDerivatives::Curvatures c = d.principalCurvatures();
  const double k1 = -std::min(c.k1, c.k2);
  return std::abs(radius * k1 - 1.0);
}

double PatchBoundary::distance(const Vec3& x) const
{
  // A curved face is searched within a bound: the nearest face so far, or its own nearest
  // sample (corners, centre). Bounded, its search drops boxes outside that ball by the
  // ball polynomial and halves boxes across the ribbon beside an osculating touch
  // (ClosestPoint), where unbounded it would quarter them to its box limit.
  double best = Unbounded;
  Tree.nearest(x,
    [&](int i) {
      const Face3D& face = Boundary->faces()[i];
      Vec3 c[4];
      if (flatPolygon(face, Flat, c) > 0)
      {
        const double d = nearestOnFace(face, Flat, x).distance;
        best = std::min(best, d);
        return d;
      }
      double sample = (face.patch.evaluate(0.5, 0.5) - x).norm();
      for (const Vec2& uv : { Vec2(0, 0), Vec2(1, 0), Vec2(0, 1), Vec2(1, 1) })
        sample = std::min(sample, (face.patch.evaluate(uv.x(), uv.y()) - x).norm());
      const double bound = std::min(best, sample) * (1.0 + 1e-9) + 1e-300;
      const std::optional<PatchFootpoint> foot = closestPointWithin(face.patch, x, bound);
      // (None within a face's own sample: its search stopped short; the sample bounds the
      // distance from above, so a point that it leaves off is flagged, not passed.)
      const double d = foot ? foot->distance : sample <= best ? sample : Unbounded;
      best = std::min(best, d);
      return d;
    },
    nullptr);
  return best;
}

Vec3 PatchBoundary::nearestPoint(const Vec3& x) const
{
  Vec3 nearest = x;
  double best = Unbounded;
  Tree.nearest(x,
    [&](int i) {
      const PatchFootpoint f = nearestOnFace(Boundary->faces()[i], Flat, x);
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

bool PatchBoundary::comesWithin(const Vec3& x, double radius) const
{
  for (int i : Tree.candidatesWithin(x, radius))
  {
    Vec3 c[4];
    if (flatPolygon(Boundary->faces()[i], Flat, c) > 0 ? nearestOnFace(Boundary->faces()[i], Flat, x).distance < radius
                                                       : patchComesWithin(Boundary->faces()[i].patch, x, radius))
      return true;
  }
  return false;
}

SolidBoundary::Contact PatchBoundary::nearestContact(const Vec3& x) const
{
  Contact best;
  best.distance = Unbounded;
  Tree.nearest(x,
    [&](int i) {
      const PatchFootpoint f = nearestOnFace(Boundary->faces()[i], Flat, x);
      if (f.distance < best.distance)
      {
        best.point = f.point;
        best.distance = f.distance;
        best.source = i;
        Vec3 c[4];
        best.parameters = flatPolygon(Boundary->faces()[i], Flat, c) > 0 ? Vec2::Constant(NAN) : Vec2(f.u, f.v);
      }
      return f.distance;
    },
    nullptr);
  return best;
}

bool PatchBoundary::searchesCutShort() const
{
  thread_local std::uint64_t seen = 0;
  const std::uint64_t now = patchSearchesCutShort();
  const bool cut = now != seen;
  seen = now;
  return cut;
}

std::vector<SolidBoundary::Contact> PatchBoundary::touchpoints(const Vec3& x, double radius) const
{
  std::vector<Minimum> minima;
  for (int i : Tree.candidatesWithin(x, radius))
  {
    Vec3 c[4];
    if (flatPolygon(Boundary->faces()[i], Flat, c) > 0)
    {
      const PatchFootpoint f = nearestOnFace(Boundary->faces()[i], Flat, x);
      if (f.distance <= radius)
        minima.push_back({ f.point, f.distance, f.onBoundary, i });
      continue;
    }
    for (const PatchFootpoint& f : patchFootpoints(Boundary->faces()[i].patch, x, radius))
      minima.push_back({ f.point, f.distance, f.onBoundary, i, Vec2(f.u, f.v) });
  }
  return distinctContacts(std::move(minima), x);
}

} // namespace exactmat
