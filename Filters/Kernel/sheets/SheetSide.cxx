#include "sheets/SheetSide.h"

#include "common/InputError.h"
#include "geometry/ClosestPoint.h"

#include <algorithm>
#include <limits>

namespace exactmat
{

namespace
{

// The faces one face generator g is one face with to the sheets: reached through smooth
// edges and in g's plane (a polygon split into a fan of triangles), or pieces of g's curved
// surface (a surface of revolution cut where MAT samples touch) — each piece tested against
// the neighbour it is reached from and the maps composed, so no extension is evaluated far
// from its own square. In the order found, g first; maps (when asked): each one's
// parameters in g's (curved g only).
std::vector<int> surfacePieces(const Boundary3D& boundary, const std::vector<Generator3D>& generators, int g,
  std::vector<ParameterMap>* maps)
{
  std::vector<int> members{ g };
  std::vector<ParameterMap> found{ ParameterMap() };
  if (generators[g].kind() != GeneratorKind3D::Face)
    return members;
  const bool planar = generators[g].planar();
  const double rounding = 64.0 * boundary.userFrame().inputRounding();
  const double tolerance = std::max(1e-9, rounding) * boundary.diagonal();
  const double piece = std::max(1e-10, rounding) * boundary.diagonal();
  auto patch = [&](int m) -> const BezierPatch& { return boundary.faces()[generators[m].entity()].patch; };
  for (size_t k = 0; k < members.size(); ++k)
    for (const Edge3D& e : boundary.edges())
    {
      if (e.kind != VertexKind::Smooth || (e.faceA != members[k] && e.faceB != members[k]))
        continue;
      const int other = e.faceA == members[k] ? e.faceB : e.faceA;
      if (std::find(members.begin(), members.end(), other) != members.end())
        continue;
      ParameterMap map;
      if (planar ? generators[other].planar() && generators[g].coplanar(generators[other], tolerance)
                 : !generators[other].planar() && piecesOfOneSurface(patch(members[k]), patch(other), piece, map))
      {
        members.push_back(other);
        found.push_back(found[k].after(map));
      }
    }
  if (maps)
    *maps = std::move(found);
  return members;
}

} // namespace

std::vector<int> sheetSide(const Boundary3D& boundary, const std::vector<Generator3D>& generators, int g)
{
  std::vector<int> members = surfacePieces(boundary, generators, g, nullptr);
  std::sort(members.begin(), members.end());
  return members;
}

namespace
{
// A box holding the member: a face's patch, a reflex edge's curve (the side of one of its
// faces: with positive weights inside its control points' box), a corner's point.
Box3 memberBox(const Boundary3D& boundary, const Generator3D& m)
{
  switch (m.kind())
  {
    case GeneratorKind3D::Face:
      return boundary.faces()[m.entity()].patch.boundingBox();
    case GeneratorKind3D::ReflexEdge:
    {
      const Edge3D& e = boundary.edges()[m.entity()];
      return boundary.faces()[e.faceA].patch.side(e.sideA).boundingBox();
    }
    case GeneratorKind3D::ReflexCorner:
    {
      const Vec3& p = boundary.vertices()[m.entity()].point;
      return Box3(p, p);
    }
  }
  return Box3();
}
} // namespace

SheetSide::SheetSide(const Boundary3D& boundary, const std::vector<Generator3D>& generators, const std::vector<int>& members)
  : B(&boundary)
{
  for (int g : members)
    Members.push_back(&generators[g]);
  for (const Generator3D* m : Members)
    Boxes.push_back(memberBox(boundary, *m));
  if (Members.size() > 1 && first().kind() == GeneratorKind3D::Face && !first().planar())
  {
    const BezierPatch& surface = boundary.faces()[first().entity()].patch;
    const SurfaceDerivatives d = surface.derivatives(0.5, 0.5);
    Speed = Vec2(d.su.norm(), d.sv.norm());
    if (!(Speed.minCoeff() > 0.0))
      Speed = Vec2(1.0, 1.0);
    std::vector<ParameterMap> maps;
    const std::vector<int> found = surfacePieces(boundary, generators, members.front(), &maps);
    for (size_t k = 0; k < members.size(); ++k)
    {
      const auto at = std::find(found.begin(), found.end(), members[k]);
      if (at == found.end())
        fail("3D MAT sheets: ", Members[k]->name(), " is not a piece of the surface of ", first().name());
      PieceMaps.push_back(maps[at - found.begin()]);
    }
  }
}

Touch3D SheetSide::evaluate(const Vec2& q) const
{
  if (PieceMaps.empty())
    return first().evaluate(q);
  // On the piece whose square holds q (the input's own surface there, not the first
  // piece's extension far from its square, which amplifies the input's rounding).
  const Vec2 s = q.cwiseQuotient(Speed);
  const size_t k = pieceHolding(s);
  const Eigen::Matrix2d into = PieceMaps[k].axes.inverse();
  Touch3D t = Members[k]->evaluate(into * (s - PieceMaps[k].origin));
  t.dPoint = t.dPoint * into;
  t.dNormal = t.dNormal * into;
  for (int c = 0; c < 2; ++c)
  {
    t.dPoint.col(c) /= Speed(c);
    t.dNormal.col(c) /= Speed(c);
  }
  return t;
}

Vec3 SheetSide::point(const Vec2& q) const
{
  if (!curvedFace())
    return evaluate(q).point;
  if (PieceMaps.empty())
    return B->faces()[first().entity()].patch.evaluate(q.x(), q.y());
  const Vec2 s = q.cwiseQuotient(Speed);
  const size_t k = pieceHolding(s);
  const Vec2 p = PieceMaps[k].inverse(s);
  return B->faces()[Members[k]->entity()].patch.evaluate(p.x(), p.y());
}

Vec2 SheetSide::parameterOf(const Vec3& x) const
{
  if (PieceMaps.empty())
    return first().parameterOf(x);
  // On the nearest piece, in the surface's parameters.
  double d = 0.0;
  const size_t nearest = nearestMember(x, d);
  return PieceMaps[nearest](Members[nearest]->parameterOf(x)).cwiseProduct(Speed);
}

Vec2 SheetSide::touchParameter(const Vec3& foot, const Vec3& centre) const
{
  return Members.size() == 1 ? first().touchParameter(foot, centre) : parameterOf(foot);
}

Vec3 SheetSide::nearestPoint(const Vec3& x) const
{
  double d = 0.0;
  return Members[nearestMember(x, d)]->nearestPoint(x);
}

double SheetSide::distance(const Vec3& x) const
{
  double d = 0.0;
  nearestMember(x, d);
  return d;
}

int SheetSide::exitSide(const Vec2& q, double tolerance) const
{
  if (Members.size() == 1)
    return first().exitSide(q, tolerance);
  if (!PieceMaps.empty())
  {
    for (size_t k = 0; k < Members.size(); ++k)
      if (Members[k]->exitSide(PieceMaps[k].inverse(q.cwiseQuotient(Speed)), tolerance) < 0)
        return -1;
    return 0;
  }
  // (Only members whose box x is within reach of: a face bounded by arcs decides by a
  // closest-point search, and a revolved profile's annuli are cut into a hundred pieces.)
  const Vec3 x = first().evaluate(q).point;
  for (size_t k = 0; k < Members.size(); ++k)
    if (distanceToBox(Boxes[k], x) <= tolerance && Members[k]->holds(Members[k]->parameterOf(x), tolerance))
      return -1;
  return 0;
}

std::string SheetSide::name() const
{
  std::string out = first().name();
  if (Members.size() > 1)
    out += " (with " + std::to_string(Members.size() - 1) +
      (PieceMaps.empty() ? " coplanar face(s)" : " other piece(s) of its surface") + " across smooth edges)";
  return out;
}

// The member nearest x and its distance d: members in the order of their boxes' distance,
// searched only while a box is nearer than the nearest found (the sliver pieces of a
// surface of revolution are dozens; a patch's nearest point is a Bernstein search).
size_t SheetSide::nearestMember(const Vec3& x, double& d) const
{
  if (Members.size() == 1)
  {
    d = first().distance(x);
    return 0;
  }
  std::vector<std::pair<double, size_t>> order;
  for (size_t k = 0; k < Members.size(); ++k)
    order.emplace_back(distanceToBox(Boxes[k], x), k);
  std::sort(order.begin(), order.end());
  size_t best = order.front().second;
  d = std::numeric_limits<double>::infinity();
  for (const auto& [boxDistance, k] : order)
  {
    if (boxDistance > d)
      break;
    if (const double dk = Members[k]->distanceWithin(x, d); dk < d)
    {
      d = dk;
      best = k;
    }
  }
  return best;
}

// The piece whose square holds s (the first's parameters), or the one it is least outside
// of; the last one found is asked first (Newton's steps stay on one piece).
size_t SheetSide::pieceHolding(const Vec2& s) const
{
  auto outside = [&](size_t k) {
    const Vec2 p = PieceMaps[k].inverse(s);
    return std::max({ 0.0, -p.x(), p.x() - 1.0, -p.y(), p.y() - 1.0 });
  };
  if (outside(LastPiece) == 0.0)
    return LastPiece;
  size_t best = LastPiece;
  double least = outside(LastPiece);
  for (size_t k = 0; k < PieceMaps.size() && least > 0.0; ++k)
    if (const double o = outside(k); o < least)
    {
      least = o;
      best = k;
    }
  LastPiece = best;
  return best;
}

} // namespace exactmat
