#include "Generator3D.h"

#include "common/Format.h"
#include "geometry/ClosestPoint.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

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

// The unit normal of a wide triangle of the control net (from a corner, the point farthest
// from it, then the point farthest from that line), turned like `hint`, and that triangle's
// height (how well it fixes the normal: to the rounding over it). The plane of a planar face
// as well as its net fixes it; a sliver's own derivatives fix it only to the rounding over
// its width (a fillet's piece 1e-4 wide is tilted by 1e-8).
Vec3 controlNetNormal(const BezierPatch& patch, const Vec3& hint, double& width)
{
  Vec3List net;
  for (int i = 0; i <= patch.degreeU(); ++i)
    for (int j = 0; j <= patch.degreeV(); ++j)
      net.push_back(patch.controlPoint(i, j));
  const Vec3 a = net.front();
  Vec3 b = a;
  for (const Vec3& p : net)
    if ((p - a).squaredNorm() > (b - a).squaredNorm())
      b = p;
  Vec3 best = Vec3::Zero();
  for (const Vec3& p : net)
    if (const Vec3 n = (b - a).cross(p - a); n.squaredNorm() > best.squaredNorm())
      best = n;
  width = 0.0;
  if (!(best.squaredNorm() > 0.0))
    return hint;
  width = best.norm() / (b - a).norm();
  best.normalize();
  return best.dot(hint) < 0.0 ? Vec3(-best) : best;
}

// The inward normal of a (curved) patch at (u, v) and its derivatives: n = −m/|m| with
// m = Su × Sv, dn = −(dm − m̂(m̂·dm))/|m| (the Weingarten map from the second derivatives; no
// curvature frame needed).
Touch3D patchTouch(const BezierPatch& patch, const Vec2& q)
{
  Touch3D t;
  const SurfaceDerivatives d = patch.derivatives(q.x(), q.y());
  const Vec3 m = d.su.cross(d.sv);
  const double len = m.norm();
  t.point = d.point;
  t.normal = -m / len;
  t.dPoint.col(0) = d.su;
  t.dPoint.col(1) = d.sv;
  const Vec3 mh = m / len;
  const Vec3 dmu = d.suu.cross(d.sv) + d.su.cross(d.suv);
  const Vec3 dmv = d.suv.cross(d.sv) + d.su.cross(d.svv);
  t.dNormal.col(0) = -(dmu - mh * mh.dot(dmu)) / len;
  t.dNormal.col(1) = -(dmv - mh * mh.dot(dmv)) / len;
  return t;
}

// Two unit vectors orthogonal to the unit vector n and to each other.
void frameAbout(const Vec3& n, Vec3& a, Vec3& b)
{
  const Vec3 helper = std::abs(n.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
  a = n.cross(helper).normalized();
  b = n.cross(a);
}
} // namespace

Generator3D::Generator3D(const Boundary3D& boundary, GeneratorKind3D kind, int entity)
  : Boundary(&boundary)
  , Kind(kind)
  , Entity(entity)
{
}

Generator3D Generator3D::reflexEdge(const Boundary3D& boundary, int edge)
{
  Generator3D g(boundary, GeneratorKind3D::ReflexEdge, edge);
  const Edge3D& e = boundary.edges()[edge];
  g.Faces = { e.faceA, e.faceB };
  g.EdgeCurve = boundary.faces()[e.faceA].patch.side(e.sideA);
  g.Straight = g.EdgeCurve.degree() == 1 && g.EdgeCurve.weight(0) == g.EdgeCurve.weight(1);
  g.EdgeSide[0] = e.sideA;
  g.EdgeSide[1] = e.sideB;
  for (int which = 0; which < 2; ++which)
  {
    const Generator3D face(boundary, g.Faces[which]);
    g.EdgePlanar[which] = face.planar();
    g.EdgeFaceNormal[which] = face.Inward;
  }
  return g;
}

Generator3D Generator3D::reflexCorner(const Boundary3D& boundary, int vertex)
{
  Generator3D g(boundary, GeneratorKind3D::ReflexCorner, vertex);
  const Vertex3D& v = boundary.vertices()[vertex];
  g.Origin = v.point;
  Vec3 sum = Vec3::Zero();
  for (int e : v.edges)
  {
    const Edge3D& edge = boundary.edges()[e];
    for (int f : { edge.faceA, edge.faceB })
      if (std::find(g.Faces.begin(), g.Faces.end(), f) == g.Faces.end())
        g.Faces.push_back(f);
    if (edge.kind != VertexKind::Reflex)
      continue;
    // The edge's direction leaving the vertex.
    const BezierCurve c = boundary.faces()[edge.faceA].patch.side(edge.sideA);
    const Vec3 tau = edge.startVertex == vertex ? c.endTangent(false) : Vec3(-c.endTangent(true));
    g.CornerEdges.push_back(e);
    g.CornerTangents.push_back(tau);
    sum += tau;
  }
  // The cone {d : d·τ ≤ 0 for every τ} (the polar of the convex cone the reflex edges span
  // outside the material) holds −Σ τ whenever it has an interior.
  g.Inward = sum.norm() > 0.0 ? Vec3(-sum.normalized()) : Vec3::Zero();
  frameAbout(g.Inward.norm() > 0.0 ? g.Inward : Vec3::UnitZ(), g.Axis0, g.Axis1);
  return g;
}

bool Generator3D::cornerHasCone() const
{
  if (Kind != GeneratorKind3D::ReflexCorner || CornerTangents.size() < 3 || Inward.norm() == 0.0)
    return false;
  for (const Vec3& tau : CornerTangents)
    if (!(Inward.dot(tau) < -1e-6))
      return false;
  return true;
}

Generator3D::Generator3D(const Boundary3D& boundary, int face)
  : Boundary(&boundary)
  , Entity(face)
  , Faces{ face }
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
    NetNormal = controlNetNormal(patch, Inward, NetWidth);
    Planar = isPlanar(patch, Origin, NetNormal, tolerance);
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
  switch (Kind)
  {
    case GeneratorKind3D::ReflexEdge:
      return evaluateEdge(q);
    case GeneratorKind3D::ReflexCorner:
      return evaluateCorner(q);
    default:
      return evaluateFace(q);
  }
}

Touch3D Generator3D::evaluateFace(const Vec2& q) const
{
  if (!Planar)
    return patchTouch(Boundary->faces()[Entity].patch, q);
  Touch3D t;
  t.point = Origin + q.x() * Axis0 + q.y() * Axis1;
  t.normal = Inward;
  t.dPoint.col(0) = Axis0;
  t.dPoint.col(1) = Axis1;
  return t;
}

void Generator3D::edgeNormal(int which, double t, Vec3& normal, Vec3& derivative) const
{
  if (EdgePlanar[which])
  {
    normal = EdgeFaceNormal[which];
    derivative = Vec3::Zero();
    return;
  }
  // Face B runs along the edge backwards: its side parameter is 1 − t.
  const int side = EdgeSide[which];
  const double s = which == 0 ? t : 1.0 - t;
  const Vec2 along = BezierPatch::sideParameter(side, 1.0) - BezierPatch::sideParameter(side, 0.0);
  const Touch3D touch = patchTouch(Boundary->faces()[Faces[which]].patch, BezierPatch::sideParameter(side, s));
  normal = touch.normal;
  derivative = touch.dNormal * along * (which == 0 ? 1.0 : -1.0);
}

double Generator3D::edgeAngle(double t) const
{
  Vec3 na, nb, dna, dnb;
  edgeNormal(0, t, na, dna);
  edgeNormal(1, t, nb, dnb);
  return std::atan2((nb - na.dot(nb) * na).norm(), na.dot(nb));
}

Touch3D Generator3D::evaluateEdge(const Vec2& q) const
{
  const double t = q.x(), theta = q.y();
  Vec3 na, nb, dna, dnb;
  edgeNormal(0, t, na, dna);
  edgeNormal(1, t, nb, dnb);
  // W = P/|P|, P = N_B − (N_A·N_B) N_A: the unit vector ⟂ N_A in the plane of the normals.
  const double c = na.dot(nb);
  const Vec3 p = nb - c * na;
  const double len = p.norm();
  const Vec3 w = p / len;
  const double dc = dna.dot(nb) + na.dot(dnb);
  const Vec3 dp = dnb - dc * na - c * dna;
  const Vec3 dw = (dp - w * w.dot(dp)) / len;
  const CurveDerivatives curve = EdgeCurve.derivatives(t);
  Touch3D touch;
  touch.point = curve.point;
  touch.dPoint.col(0) = curve.d1;
  touch.normal = std::cos(theta) * na + std::sin(theta) * w;
  touch.dNormal.col(0) = std::cos(theta) * dna + std::sin(theta) * dw;
  touch.dNormal.col(1) = -std::sin(theta) * na + std::cos(theta) * w;
  return touch;
}

Touch3D Generator3D::evaluateCorner(const Vec2& q) const
{
  // Gnomonic: N = m/|m|, m = axis + a·e0 + b·e1.
  const Vec3 m = Inward + q.x() * Axis0 + q.y() * Axis1;
  const double len = m.norm();
  Touch3D touch;
  touch.point = Origin;
  touch.normal = m / len;
  touch.dNormal.col(0) = (Axis0 - touch.normal * touch.normal.dot(Axis0)) / len;
  touch.dNormal.col(1) = (Axis1 - touch.normal * touch.normal.dot(Axis1)) / len;
  return touch;
}

Vec2 Generator3D::parameterOf(const Vec3& x) const
{
  if (Kind != GeneratorKind3D::Face)
    return touchParameter(nearestPoint(x), x);
  if (Planar)
    return Vec2((x - Origin).dot(Axis0), (x - Origin).dot(Axis1));
  const PatchFootpoint f = closestPoint(Boundary->faces()[Entity].patch, x);
  return Vec2(f.u, f.v);
}

Vec2 Generator3D::touchParameter(const Vec3& foot, const Vec3& centre) const
{
  if (Kind == GeneratorKind3D::Face)
    return parameterOf(foot);
  const Vec3 d = centre - foot;
  if (Kind == GeneratorKind3D::ReflexCorner)
  {
    const double along = d.dot(Inward);
    if (!(along > 0.0))
      return Vec2::Zero();
    return Vec2(d.dot(Axis0) / along, d.dot(Axis1) / along);
  }
  double t = 0.0;
  if (Straight)
  {
    const Vec3 a = EdgeCurve.startPoint(), e = EdgeCurve.endPoint() - a;
    t = (foot - a).dot(e) / e.squaredNorm();
  }
  else
    t = closestPoint(EdgeCurve, foot).t;
  Vec3 na, nb, dna, dnb;
  edgeNormal(0, t, na, dna);
  edgeNormal(1, t, nb, dnb);
  const Vec3 w = (nb - na.dot(nb) * na).normalized();
  return Vec2(t, d.norm() > 0.0 ? std::atan2(d.dot(w), d.dot(na)) : 0.0);
}

int Generator3D::exitSide(const Vec2& q, double tolerance) const
{
  const double slack = tolerance / Boundary->diagonal();
  if (Kind == GeneratorKind3D::ReflexEdge)
  {
    // The angle against slack, the edge parameter against the tolerance over the edge's
    // length (a parameter step of 1 is that long).
    const double chord = std::max((EdgeCurve.endPoint() - EdgeCurve.startPoint()).norm(), 1e-300);
    const double out[4] = { -q.y() / slack, (q.y() - edgeAngle(q.x())) / slack, -q.x() * chord / tolerance,
      (q.x() - 1.0) * chord / tolerance };
    const int worst = static_cast<int>(std::max_element(out, out + 4) - out);
    return out[worst] > 1.0 ? worst : -1;
  }
  if (Kind == GeneratorKind3D::ReflexCorner)
  {
    const Vec3 n = evaluateCorner(q).normal;
    int worst = -1;
    double most = slack;
    for (size_t i = 0; i < CornerTangents.size(); ++i)
      if (n.dot(CornerTangents[i]) > most)
      {
        most = n.dot(CornerTangents[i]);
        worst = static_cast<int>(i);
      }
    return worst;
  }
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
    const PatchFootpoint f = closestPoint(Boundary->faces()[Entity].patch, evaluate(q).point);
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
    // Outside by no more than the tolerance as a distance on the surface (a sliver piece of
    // a surface split where MAT samples touch is 1e-6 of the size across its parameter
    // range: 1e-12 of that range is far below the solve's rounding, and a touch running
    // along its side would cross back and forth).
    const Eigen::Matrix<double, 3, 2> d = evaluate(q).dPoint;
    const double du = std::max({ -u, u - 1.0, 0.0 }) * d.col(0).norm(),
                 dv = std::max({ -v, v - 1.0, 0.0 }) * d.col(1).norm();
    if (std::max(du, dv) <= tolerance)
      return -1;
  }
  // The side the point has crossed (or is nearest, past a corner).
  double out[4] = { -v, u - 1.0, v - 1.0, -u };
  for (int side = 0; side < 4; ++side)
    if (Collapsed[side])
      out[side] = -INFINITY; // a corner, not a side: the crossing is through a neighbour side
  return static_cast<int>(std::max_element(out, out + 4) - out);
}

bool Generator3D::holds(const Vec2& q, double tolerance) const
{
  if (Kind == GeneratorKind3D::Face && Polygon.empty() && Planar)
  {
    const auto f = closestPointWithin(Boundary->faces()[Entity].patch, evaluate(q).point, tolerance);
    return f && f->distance <= tolerance;
  }
  return exitSide(q, tolerance) < 0;
}

Vec3 Generator3D::nearestPoint(const Vec3& x) const
{
  if (Kind == GeneratorKind3D::ReflexCorner)
    return Origin;
  if (Kind == GeneratorKind3D::ReflexEdge)
  {
    if (!Straight)
      return closestPoint(EdgeCurve, x).point;
    const Vec3 a = EdgeCurve.startPoint(), e = EdgeCurve.endPoint() - a;
    return a + std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0) * e;
  }
  if (Polygon.empty())
    return closestPoint(Boundary->faces()[Entity].patch, x).point;
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
  if (Kind != GeneratorKind3D::Face)
    return (nearestPoint(x) - x).norm();
  if (Polygon.empty())
    return closestPoint(Boundary->faces()[Entity].patch, x).distance;
  return (nearestPoint(x) - x).norm();
}

double Generator3D::distanceWithin(const Vec3& x, double bound) const
{
  if (Kind == GeneratorKind3D::Face && Polygon.empty() && std::isfinite(bound))
  {
    const auto foot = closestPointWithin(Boundary->faces()[Entity].patch, x, bound);
    return foot && foot->distance < bound ? foot->distance : std::numeric_limits<double>::infinity();
  }
  const double d = distance(x);
  return d < bound ? d : std::numeric_limits<double>::infinity();
}

bool Generator3D::coplanar(const Generator3D& other, double tolerance) const
{
  if (Kind != GeneratorKind3D::Face || other.Kind != GeneratorKind3D::Face || !Planar || !other.Planar ||
    !(NetNormal.dot(other.NetNormal) > 0.0))
    return false;
  // The narrower face's control points within `tolerance` of the wider face's plane
  // (distances, not an angle between normals: a sliver's plane is known only to the
  // rounding over its width, a wide face's to far less).
  const Generator3D& wide = NetWidth >= other.NetWidth ? *this : other;
  const Generator3D& narrow = &wide == this ? other : *this;
  const BezierPatch& patch = narrow.Boundary->faces()[narrow.Entity].patch;
  for (int i = 0; i <= patch.degreeU(); ++i)
    for (int j = 0; j <= patch.degreeV(); ++j)
      if (!(std::abs((patch.controlPoint(i, j) - wide.Origin).dot(wide.NetNormal)) <= tolerance))
        return false;
  return true;
}

std::string Generator3D::name() const
{
  if (Kind == GeneratorKind3D::Face)
    return Boundary->faces()[Entity].name();
  std::ostringstream s;
  if (Kind == GeneratorKind3D::ReflexEdge)
    s << "the reflex edge between " << Boundary->faces()[Faces[0]].name() << " and "
      << Boundary->faces()[Faces[1]].name();
  else
    s << "the reflex corner at " << format(Boundary->userPoint(Origin));
  return s.str();
}

std::vector<Generator3D> medialGenerators(const Boundary3D& boundary)
{
  std::vector<Generator3D> out;
  for (int f = 0; f < static_cast<int>(boundary.faces().size()); ++f)
    out.emplace_back(boundary, f);
  for (int e = 0; e < static_cast<int>(boundary.edges().size()); ++e)
    if (boundary.edges()[e].kind == VertexKind::Reflex)
      out.push_back(Generator3D::reflexEdge(boundary, e));
  for (int v = 0; v < static_cast<int>(boundary.vertices().size()); ++v)
  {
    bool convex = false, reflex = false;
    for (int e : boundary.vertices()[v].edges)
    {
      convex = convex || boundary.edges()[e].kind == VertexKind::Convex;
      reflex = reflex || boundary.edges()[e].kind == VertexKind::Reflex;
    }
    if (convex || !reflex)
      continue;
    Generator3D corner = Generator3D::reflexCorner(boundary, v);
    if (corner.cornerHasCone())
      out.push_back(std::move(corner));
  }
  return out;
}

} // namespace exactmat
