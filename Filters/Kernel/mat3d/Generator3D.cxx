#include "Generator3D.h"

#include "geometry/ClosestPoint.h"

#include <algorithm>
#include <cmath>

namespace exactmat
{

namespace
{
// A face is planar when every control point lies within rounding of the plane through the
// patch's centre with its normal there (weights do not bend a planar net out of its plane).
bool isPlanar(const BezierPatch& patch, const Vec3& origin, const Vec3& normal, double tolerance)
{
  for (int i = 0; i <= patch.degreeU(); ++i)
    for (int j = 0; j <= patch.degreeV(); ++j)
      if (std::abs((patch.controlPoint(i, j) - origin).dot(normal)) > tolerance)
        return false;
  return true;
}
} // namespace

Generator3D::Generator3D(const Boundary3D& boundary, int face)
  : Boundary(&boundary)
  , Face(face)
{
  const BezierPatch& patch = boundary.faces()[face].patch;
  Origin = patch.evaluate(0.5, 0.5);
  const SurfaceDerivatives d = patch.derivatives(0.5, 0.5);
  const Vec3 outward = d.su.cross(d.sv);
  if (outward.norm() > 0.0)
  {
    Inward = -outward.normalized();
    // Planar to the input's rounding: a polyhedron far from the origin has its faces' corners
    // rounded off their plane by that much, and is still a polyhedron.
    const double tolerance = std::max(1e-12, 64.0 * boundary.userFrame().inputRounding()) * boundary.diagonal();
    Planar = isPlanar(patch, Origin, Inward, tolerance);
  }
  for (int side = 0; side < 4; ++side)
  {
    const BezierCurve c = patch.side(side);
    bool point = true;
    for (int i = 1; i <= c.degree(); ++i)
      point = point && (c.controlPoint(i) - c.controlPoint(0)).norm() <= 1e-14 * boundary.diagonal();
    Collapsed[side] = point;
  }
  if (Planar)
  {
    Axis0 = (d.su - d.su.dot(Inward) * Inward).normalized();
    Axis1 = Inward.cross(Axis0);
    setPolygon(patch, boundary.diagonal());
  }
}

// The face as a convex polygon in plane coordinates when every side is straight (linear
// triangles and planar bilinear quadrilaterals: polyhedra), so inside tests and distances
// are closed forms instead of patch searches.
void Generator3D::setPolygon(const BezierPatch& patch, double size)
{
  std::vector<Vec2> corners;
  std::vector<int> sides;
  for (int side = 0; side < 4; ++side)
  {
    if (Collapsed[side])
      continue;
    const BezierCurve c = patch.side(side);
    const Vec3 a = c.controlPoint(0), b = c.controlPoint(c.degree());
    for (int i = 1; i < c.degree(); ++i)
    {
      const Vec3 p = c.controlPoint(i);
      if ((p - a).cross(b - a).norm() > 1e-13 * size * (b - a).norm())
        return; // a curved side
    }
    corners.push_back(Vec2((a - Origin).dot(Axis0), (a - Origin).dot(Axis1)));
    sides.push_back(side);
  }
  const int n = static_cast<int>(corners.size());
  double area = 0.0;
  for (int i = 0; i < n; ++i)
  {
    const Vec2& p = corners[i];
    const Vec2& q = corners[(i + 1) % n];
    area += p.x() * q.y() - p.y() * q.x();
  }
  if (area < 0.0)
  {
    // Counter-clockwise in plane coordinates, each side keeping its patch side.
    std::reverse(corners.begin(), corners.end());
    std::reverse(sides.begin(), sides.end());
    // After reversing, side i runs from corner i to i+1 in the new order: the patch side
    // of the edge (c[i], c[i+1]) is the one that ran from c[i+1] to c[i] before.
    std::rotate(sides.begin(), sides.begin() + 1, sides.end());
  }
  for (int i = 0; i < n; ++i)
  {
    const Vec2 e = corners[(i + 1) % n] - corners[i], f = corners[(i + 2) % n] - corners[(i + 1) % n];
    if (e.x() * f.y() - e.y() * f.x() < 0.0)
      return; // not convex: keep the patch search
  }
  Polygon = corners;
  PolygonSide = sides;
}

Touch3D Generator3D::evaluate(const Vec2& q) const
{
  Touch3D t;
  if (Planar)
  {
    t.point = Origin + q.x() * Axis0 + q.y() * Axis1;
    t.normal = Inward;
    t.dPoint.col(0) = Axis0;
    t.dPoint.col(1) = Axis1;
    return t;
  }
  const SurfaceDerivatives d = Boundary->faces()[Face].patch.derivatives(q.x(), q.y());
  const Vec3 m = d.su.cross(d.sv);
  const double len = m.norm();
  t.point = d.point;
  t.normal = -m / len;
  t.dPoint.col(0) = d.su;
  t.dPoint.col(1) = d.sv;
  // n = −m/|m|: dn = −(dm − n̂(n̂·dm))/|m| with n̂ = m/|m| (the Weingarten map, from the
  // second derivatives; no curvature frame needed).
  const Vec3 mh = m / len;
  const Vec3 dmu = d.suu.cross(d.sv) + d.su.cross(d.suv);
  const Vec3 dmv = d.suv.cross(d.sv) + d.su.cross(d.svv);
  t.dNormal.col(0) = -(dmu - mh * mh.dot(dmu)) / len;
  t.dNormal.col(1) = -(dmv - mh * mh.dot(dmv)) / len;
  return t;
}

Vec2 Generator3D::parameterOf(const Vec3& x) const
{
  if (Planar)
    return Vec2((x - Origin).dot(Axis0), (x - Origin).dot(Axis1));
  const PatchFootpoint f = closestPoint(Boundary->faces()[Face].patch, x);
  return Vec2(f.u, f.v);
}

int Generator3D::exitSide(const Vec2& q, double tolerance) const
{
  double u = q.x(), v = q.y();
  if (!Polygon.empty())
  {
    // The side q lies farthest outside of (signed distance, inward positive).
    int worst = -1;
    double depth = -tolerance;
    const int n = static_cast<int>(Polygon.size());
    for (int i = 0; i < n; ++i)
    {
      const Vec2 e = (Polygon[(i + 1) % n] - Polygon[i]).normalized();
      const Vec2 w = q - Polygon[i];
      const double inside = e.x() * w.y() - e.y() * w.x();
      if (inside < depth)
      {
        depth = inside;
        worst = PolygonSide[i];
      }
    }
    return worst;
  }
  if (Planar)
  {
    const PatchFootpoint f = closestPoint(Boundary->faces()[Face].patch, evaluate(q).point);
    if (f.distance <= tolerance)
      return -1;
    u = f.u;
    v = f.v;
  }
  else
  {
    const double slack = 1e-12;
    if (u >= -slack && u <= 1.0 + slack && v >= -slack && v <= 1.0 + slack)
      return -1;
  }
  // The side the point has crossed (or is nearest, past a corner).
  double out[4] = { -v, u - 1.0, v - 1.0, -u };
  for (int side = 0; side < 4; ++side)
    if (Collapsed[side])
      out[side] = -INFINITY; // a corner, not a side: the crossing is through a neighbour side
  return static_cast<int>(std::max_element(out, out + 4) - out);
}

Vec3 Generator3D::nearestPoint(const Vec3& x) const
{
  if (Polygon.empty())
    return closestPoint(Boundary->faces()[Face].patch, x).point;
  const Vec2 q = parameterOf(x);
  if (exitSide(q, 0.0) < 0)
    return evaluate(q).point;
  // Outside: the nearest point of the nearest side.
  Vec2 best = Polygon[0];
  double bestDistance = INFINITY;
  const int n = static_cast<int>(Polygon.size());
  for (int i = 0; i < n; ++i)
  {
    const Vec2 a = Polygon[i], e = Polygon[(i + 1) % n] - a;
    const double t = std::clamp((q - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
    const Vec2 p = a + t * e;
    if ((p - q).norm() < bestDistance)
    {
      bestDistance = (p - q).norm();
      best = p;
    }
  }
  return evaluate(best).point;
}

double Generator3D::distance(const Vec3& x) const
{
  if (Polygon.empty())
    return closestPoint(Boundary->faces()[Face].patch, x).distance;
  return (nearestPoint(x) - x).norm();
}

std::string Generator3D::name() const
{
  return Boundary->faces()[Face].name();
}

} // namespace exactmat
